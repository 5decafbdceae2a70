#include "common/reference_image.h"

#include "core/checks.h"

#include <cmath>
#include <limits>
#include <string>

namespace postfx::reference::detail {

using glm::dvec3;
using glm::dvec4;

Status checkCount(const char* field, size_t count, uint64_t expected, const char* what) {
    if (count == expected) return Status::success();
    return core::invalid(std::string(field) + ": " + std::to_string(count) + " values, expected " +
                         std::to_string(expected) + " (" + what + ")");
}

Status checkImage(const std::string& prefix, uint32_t width, uint32_t height, std::span<const float> color,
                  std::span<const float> depth) {
    if (width == 0 || height == 0)
        return core::invalid(prefix + ".width/height: " + std::to_string(width) + "x" +
                             std::to_string(height) + " image is empty");
    const uint64_t pixels = uint64_t(width) * height;
    if (Status s = checkCount((prefix + ".color").c_str(), color.size(), pixels * 4, "width·height·4"); !s)
        return s;
    if (Status s = checkCount((prefix + ".depth").c_str(), depth.size(), pixels, "width·height"); !s)
        return s;
    for (size_t i = 0; i < depth.size(); ++i)
        if (!std::isfinite(depth[i]))
            return core::invalid(prefix + ".depth: value " + std::to_string(i) + " is not finite");
    return Status::success();
}

Status checkCloudShadow(const char* prefix, std::span<const float> texels, uint32_t width, uint32_t height,
                        const CloudShadowTransform& rows) {
    if (texels.empty()) return Status::success();
    const std::string field = std::string(prefix) + ".cloudShadow";
    if (Status s = checkCount(field.c_str(), texels.size(), uint64_t(width) * height,
                              "cloudShadowWidth·cloudShadowHeight");
        !s)
        return s;
    for (size_t i = 0; i < texels.size(); ++i)
        if (!std::isfinite(texels[i]))
            return core::invalid(field + ": value " + std::to_string(i) + " is not finite");
    if (!core::allFinite(glm::dvec4(rows.u)) || !core::allFinite(glm::dvec4(rows.v)))
        return core::invalid(std::string(prefix) + ".cloudShadowRows: not finite");
    return Status::success();
}

glm::dmat4 clipToView(const CameraInput& camera) {
    glm::dmat4 rotation(camera.view);
    rotation[3] = dvec4(0.0, 0.0, 0.0, 1.0);
    return glm::inverse(glm::dmat4(camera.projection) * rotation);
}

PixelRay pixelRay(const glm::dmat4& clipToView, double farDepth, uint32_t width, uint32_t height, uint32_t i,
                  uint32_t j, double z) {
    const double nx = (i + 0.5) / width * 2.0 - 1.0, ny = (j + 0.5) / height * 2.0 - 1.0;
    const bool geometry = z != farDepth;
    const dvec4 p = clipToView * dvec4(nx, ny, geometry ? z : 0.5, 1.0);
    const dvec3 x = dvec3(p) / p.w;
    const double length = glm::length(x);
    // A surface that reconstructs to infinity (not a valid depth) is treated as no geometry.
    if (!geometry || !std::isfinite(length) || length == 0.0)
        return {glm::normalize(dvec3(clipToView * dvec4(nx, ny, 0.5, 1.0))),
                std::numeric_limits<double>::infinity()};
    return {x / length, length};
}

void composite(const dvec3& L, double T, const float* color, float* out) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (int c = 0; c < 3; ++c) {
        if (std::isnan(color[c])) {
            out[c] = color[c];
            continue;
        }
        const double bounded = std::clamp(double(color[c]), -kMax, kMax);
        out[c] = float(std::clamp(bounded * T + L[c], -kMax, kMax));
    }
    out[3] = color[3];
}

}  // namespace postfx::reference::detail
