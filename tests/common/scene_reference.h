// A demo scene's GPU frame against the demo's CPU reference of the same frame (Renderer::renderReference):
// per channel the mean relative difference Σ|gpu - ref| / Σ ref per pixel (the jitter's one-frame noise
// and reduced-resolution edges included), the same over the means of blocks of pixels (what the eye sees:
// noise averaged out), and the bias Σ(gpu - ref) / Σ ref.
#pragma once

#include "host/renderer.h"

#include <array>
#include <cstdint>
#include <string>

namespace test {

struct ReferenceDifference {
    std::array<double, 3> perPixel{}, blocks{}, bias{};  // fractions, per RGB channel
    std::array<double, 3> referenceSum{};                // Σ ref per channel (> 0 for a meaningful ratio)
    bool finite = true;                                  // every GPU value finite
};

// Blocks of blockW × blockH pixels (the image's last partial blocks included).
ReferenceDifference referenceDifference(const demo::ImageF& gpu, const demo::ImageF& reference,
                                        uint32_t blockW = 8, uint32_t blockH = 6);

// "R G B: per pixel a% b% c%, 8x6 blocks ..., signed ..." for a test's log line.
std::string describe(const ReferenceDifference& d);

}  // namespace test
