#include "host/metering.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace demo {

Metering meterHalfImage(const uint16_t* rgba, size_t pixels) {
    Metering m;
    std::vector<float> lit;
    lit.reserve(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        float v = 0.0f;
        for (int c = 0; c < 3; ++c) {
            const float x = glm::unpackHalf1x16(rgba[p * 4 + c]);
            if (!std::isnan(x)) v = std::max(v, x);  // +Inf counts as clipped
        }
        m.largest = std::max(m.largest, double(v));
        if (v > 0.0f) lit.push_back(v);
    }
    if (!lit.empty()) {
        auto middle = lit.begin() + std::ptrdiff_t(lit.size() / 2);
        std::nth_element(lit.begin(), middle, lit.end());
        m.median = *middle;
    }
    return m;
}

double meteredPreExposure(const Metering& m, double trial, double wanted, double lowest, double highest) {
    const auto limited = [&](double p) {
        return std::clamp(std::exp2(std::floor(std::log2(p))), lowest, highest);
    };
    if (m.clipped()) return limited(trial * 0x1p-16);
    if (!(m.largest > 0.0)) return trial <= 0x1p-10 ? limited(trial * 0x1p16) : trial;
    const double largest = m.largest / trial, median = m.median / trial;  // physical units
    double p = wanted;
    if (median * p < kMedianFloor) p = kMedianTarget / median;
    if (largest * p > kLargestFit) p = kLargestTarget / largest;
    return limited(p);
}

}  // namespace demo
