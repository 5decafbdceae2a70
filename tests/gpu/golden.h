// Golden images: tests/golden/<name>.exr (linear radiance). Tolerance: relative RMSE below 1% and at most
// 0.5% of pixels off by more than 2% (shadow-edge texels may differ between drivers). On failure the
// actual image and a diff image are written to golden-failures/ in the test's working directory.
// POSTFX_ACCEPT_GOLDENS=1 (scripts/accept-goldens.sh) writes the new image as the golden instead.
#pragma once

#include "host/renderer.h"

#include <string>

namespace test {

void expectMatchesGolden(const demo::ImageF& image, const std::string& name);

}  // namespace test
