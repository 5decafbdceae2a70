// A march at a reduced resolution (the ray-marched fog's and the clouds'; the GLSL side is
// shaders/common/reduced_resolution.glsl): its extent for a color image and a resolution scale.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace postfx::common {

// ceil(size · scale) per axis, at least 1; the scale clamped to [0, 1], NaN read as 1 [px].
inline glm::uvec2 reducedExtent(uint32_t width, uint32_t height, float resolutionScale) {
    const double scale = std::isnan(resolutionScale) ? 1.0 : std::clamp(double(resolutionScale), 0.0, 1.0);
    auto axis = [&](uint32_t size) { return std::max(1u, uint32_t(std::ceil(double(size) * scale))); };
    return {axis(width), axis(height)};
}

}  // namespace postfx::common
