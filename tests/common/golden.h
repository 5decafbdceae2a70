// Golden images: tests/<group>/golden/<name>.exr (linear radiance), beside the group's tests. Tolerance:
// relative RMSE below 1% and at most 0.5% of pixels off by more than 2% (shadow-edge texels may differ
// between drivers). On failure the actual image and a diff image are written to golden-failures/ in the
// test's working directory.
// POSTFX_ACCEPT_GOLDENS=1 (scripts/accept-goldens.sh) writes the new image as the golden instead.
#pragma once

#include "host/renderer.h"

#include <string>

namespace test {

// `group`: the tests/ folder the golden image lies in (demo, fog, ...); `name`: its file name without .exr.
void expectMatchesGolden(const demo::ImageF& image, const std::string& group, const std::string& name);

}  // namespace test
