#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace test {

std::string ImageStats::summary() const {
    char text[256];
    std::snprintf(
        text, sizeof text, "relative RMSE %.4g%%, max abs error %.4g, pixels off %.4g%%, non-finite %llu",
        relativeRmse * 100.0, maxAbsError, fractionOff * 100.0, static_cast<unsigned long long>(nonFinite));
    return text;
}

ImageStats compareImages(std::span<const float> actual, std::span<const float> expected, uint32_t width,
                         uint32_t height, double pixelTolerance, double floor) {
    ImageStats stats;
    const size_t pixels = size_t(width) * height;
    if (actual.size() < pixels * 4 || expected.size() < pixels * 4 || pixels == 0) {
        stats.relativeRmse = stats.maxAbsError = stats.fractionOff = INFINITY;
        return stats;
    }
    double errorSquared = 0.0, referenceSquared = 0.0;
    size_t off = 0;
    for (size_t p = 0; p < pixels; ++p) {
        double magnitude = floor;
        for (int c = 0; c < 3; ++c)
            magnitude = std::max(magnitude, std::abs(double(expected[p * 4 + c])));
        bool pixelOff = false;
        for (int c = 0; c < 3; ++c) {
            const double a = actual[p * 4 + c], b = expected[p * 4 + c];
            if (!std::isfinite(a)) {
                ++stats.nonFinite;
                pixelOff = true;
                continue;
            }
            const double d = std::abs(a - b);
            errorSquared += d * d;
            referenceSquared += b * b;
            stats.maxAbsError = std::max(stats.maxAbsError, d);
            pixelOff = pixelOff || d > pixelTolerance * magnitude;
        }
        off += pixelOff ? 1 : 0;
    }
    stats.relativeRmse = referenceSquared > 0.0 ? std::sqrt(errorSquared / referenceSquared)
                                                : (errorSquared > 0.0 ? INFINITY : 0.0);
    stats.fractionOff = double(off) / double(pixels);
    return stats;
}

std::vector<float> diffImage(std::span<const float> actual, std::span<const float> expected, double scale) {
    const size_t n = std::min(actual.size(), expected.size()) / 4;
    std::vector<float> out(n * 4, 1.0f);
    for (size_t p = 0; p < n; ++p) {
        double d = 0.0;
        for (int c = 0; c < 3; ++c)
            d += std::abs(double(actual[p * 4 + c]) - double(expected[p * 4 + c]));
        const float v = std::isfinite(d) ? float(std::min(1.0, d / scale)) : 1.0f;
        out[p * 4 + 0] = v;                               // red: error
        out[p * 4 + 1] = std::isfinite(d) ? 0.0f : 1.0f;  // yellow: non-finite
        out[p * 4 + 2] = 0.0f;
    }
    return out;
}

}  // namespace test
