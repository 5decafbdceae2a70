// Comparison of two linear-radiance RGBA images, for golden-image and reference tests.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace test {

struct ImageStats {
    double relativeRmse = 0.0;    // sqrt(Σ(a-b)²) / sqrt(Σ b²) over RGB of all pixels
    double maxAbsError = 0.0;     // largest |a-b| of any RGB channel
    double fractionOff = 0.0;     // fraction of pixels whose RGB differ by more than `pixelTolerance`
    uint64_t nonFinite = 0;       // NaN/Inf channel values in `actual`
    std::string summary() const;  // one line
};

// `pixelTolerance` is relative to the pixel's reference luminance-ish magnitude max(|b|, floor):
// a pixel is off when any channel has |a-b| > pixelTolerance * max(max_c |b_c|, floor).
ImageStats compareImages(std::span<const float> actual, std::span<const float> expected, uint32_t width,
                         uint32_t height, double pixelTolerance, double floor);

// Per-pixel |a-b| summed over RGB, scaled so that `scale` maps to white, as RGBA floats (for a diff image).
std::vector<float> diffImage(std::span<const float> actual, std::span<const float> expected, double scale);

}  // namespace test
