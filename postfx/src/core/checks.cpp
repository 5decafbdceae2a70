#include "core/checks.h"

#include "core/target_formats.h"

#include <glm/gtc/matrix_transform.hpp>

#include <sstream>

namespace postfx {

std::string formatName(VkFormat format) {
    switch (format) {
#define POSTFX_FORMAT(name) \
    case VK_FORMAT_##name:  \
        return "VK_FORMAT_" #name;
        POSTFX_FORMAT(UNDEFINED)
        POSTFX_FORMAT(R8_UNORM)
        POSTFX_FORMAT(R8G8B8A8_UNORM)
        POSTFX_FORMAT(R8G8B8A8_SRGB)
        POSTFX_FORMAT(B8G8R8A8_UNORM)
        POSTFX_FORMAT(B8G8R8A8_SRGB)
        POSTFX_FORMAT(A2B10G10R10_UNORM_PACK32)
        POSTFX_FORMAT(A2R10G10B10_UNORM_PACK32)
        POSTFX_FORMAT(R16_SFLOAT)
        POSTFX_FORMAT(R16G16_SFLOAT)
        POSTFX_FORMAT(R16G16B16_SFLOAT)
        POSTFX_FORMAT(R16G16B16A16_UNORM)
        POSTFX_FORMAT(R16G16B16A16_SFLOAT)
        POSTFX_FORMAT(R32_SFLOAT)
        POSTFX_FORMAT(R32G32_SFLOAT)
        POSTFX_FORMAT(R32G32B32_SFLOAT)
        POSTFX_FORMAT(R32G32B32A32_SFLOAT)
        POSTFX_FORMAT(B10G11R11_UFLOAT_PACK32)
        POSTFX_FORMAT(E5B9G9R9_UFLOAT_PACK32)
        POSTFX_FORMAT(D16_UNORM)
        POSTFX_FORMAT(X8_D24_UNORM_PACK32)
        POSTFX_FORMAT(D32_SFLOAT)
        POSTFX_FORMAT(S8_UINT)
        POSTFX_FORMAT(D16_UNORM_S8_UINT)
        POSTFX_FORMAT(D24_UNORM_S8_UINT)
        POSTFX_FORMAT(D32_SFLOAT_S8_UINT)
#undef POSTFX_FORMAT
        default:
            return "VkFormat " + std::to_string(int(format));
    }
}

namespace core {
namespace {

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

bool isShadowFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_R32_SFLOAT ||
           f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D24_UNORM_S8_UINT;
}

const char* usageName(VkImageUsageFlags usage) {
    return usage == VK_IMAGE_USAGE_STORAGE_BIT ? "VK_IMAGE_USAGE_STORAGE_BIT" : "VK_IMAGE_USAGE_SAMPLED_BIT";
}

struct ImageRule {
    const char* name;             // "FrameInfo.color"
    bool (*formatOk)(VkFormat);   // accepted formats
    const char* formats;          // their names, for the message
    VkImageUsageFlags usage;      // usage postfx needs
    const VkExtent2D* maxExtent;  // null: any size
};

Status checkImage(const ImageInput& image, const ImageRule& rule) {
    const std::string n = rule.name;
    if (!image.present()) return invalid(n + ".image is VK_NULL_HANDLE");
    if (!image.view) return invalid(n + ".view is VK_NULL_HANDLE");
    if (!rule.formatOk(image.format))
        return invalid(n + ".format " + formatName(image.format) + " is not supported (expected " +
                       rule.formats + ")");
    if (image.samples != VK_SAMPLE_COUNT_1_BIT)
        return invalid(n + ".samples " + std::to_string(uint32_t(image.samples)) +
                       ": postfx reads single-sampled images only; resolve the image first (for depth: "
                       "VK_KHR_depth_stencil_resolve, or a pass taking the nearest sample)");
    if (image.extent.width == 0 || image.extent.height == 0)
        return invalid(n + ".extent is " + extentText(image.extent));
    if (rule.maxExtent &&
        (image.extent.width > rule.maxExtent->width || image.extent.height > rule.maxExtent->height))
        return invalid(n + ".extent " + extentText(image.extent) + " exceeds ContextCreateInfo.maxExtent " +
                       extentText(*rule.maxExtent));
    if (!knownImageLayout(image.layout))
        return invalid(n + ".layout " + std::to_string(int64_t(image.layout)) + " is not a VkImageLayout");
    if (image.layout == VK_IMAGE_LAYOUT_UNDEFINED || image.layout == VK_IMAGE_LAYOUT_PREINITIALIZED)
        return invalid(n + ".layout is UNDEFINED/PREINITIALIZED: postfx needs the image's contents");
    if (rule.usage && !(image.usage & rule.usage))
        return invalid(n + ".usage lacks " + usageName(rule.usage) + " (postfx " +
                       (rule.usage == VK_IMAGE_USAGE_STORAGE_BIT ? "reads and writes it as a storage image"
                                                                 : "samples it") +
                       "; set ImageInput::usage to the usage the image was created with)");
    return Status::success();
}

// Length >= 1e-6, in double: a float dot product of a vector like (1e30, 0, 0) would overflow.
// In place (core/target.h): color and output STORAGE. Through postfx.target: the color TRANSFER_SRC (it is
// blitted in), the image written (the output, else the color) TRANSFER_DST.
Status checkTargetUsage(const FrameInfo& frame) {
    const bool separate = frame.output.present();
    if (compositesInPlace(frame.color)) {
        if (separate && !(frame.output.usage & VK_IMAGE_USAGE_STORAGE_BIT))
            return invalid(
                "FrameInfo.output.usage lacks VK_IMAGE_USAGE_STORAGE_BIT (postfx writes it as a "
                "storage image, as the color; set ImageInput::usage to the usage the image was "
                "created with)");
        return Status::success();
    }
    const std::string why = " (FrameInfo.color is " + formatName(frame.color.format) +
                            (frame.color.usage & VK_IMAGE_USAGE_STORAGE_BIT ? "" : " without STORAGE usage") +
                            ": postfx composites in its own RGBA16F image, blitted from the color and back "
                            "into " +
                            (separate ? "the output" : "the color") +
                            "; set ImageInput::usage to the usage the image was created with)";
    if (!(frame.color.usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
        return invalid("FrameInfo.color.usage lacks VK_IMAGE_USAGE_TRANSFER_SRC_BIT" + why);
    const ImageInput& written = separate ? frame.output : frame.color;
    if (!(written.usage & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        return invalid(std::string(separate ? "FrameInfo.output" : "FrameInfo.color") +
                       ".usage lacks VK_IMAGE_USAGE_TRANSFER_DST_BIT" + why);
    return Status::success();
}

bool longEnough(const Vec3& v) {
    const glm::dvec3 d(v);
    return glm::dot(d, d) >= 1e-12;
}

bool sameExtent(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

}  // namespace

Status checkLight(const LocalLight& light, const std::string& n) {
    if (light.type != LightType::Point && light.type != LightType::Spot)
        return invalid(n + ".type " + std::to_string(uint32_t(light.type)) + " is not Point or Spot");
    for (int c = 0; c < 3; ++c)
        if (Status s = checkRange((n + ".position").c_str(), light.position[c], -kMaxWorldCoordinate,
                                  kMaxWorldCoordinate);
            !s)
            return s;
    if (!allFinite(light.direction)) return invalid(n + ".direction: is not finite");
    if (light.type == LightType::Spot && !longEnough(light.direction))
        return invalid(n + ".direction: is the zero vector (length below 1e-6)");
    for (int c = 0; c < 3; ++c)
        if (Status s = checkRange((n + ".intensity").c_str(), light.intensity[c], 0.0, 1e9); !s) return s;
    if (!std::isfinite(light.range) || light.range <= 0.0f)
        return invalid(n + ".range: " + numberText(light.range) + " must be finite and > 0");
    if (!(light.sourceRadius > 0.0f) || light.sourceRadius > light.range)
        return invalid(n + ".sourceRadius: " + numberText(light.sourceRadius) + " must be in (0, range]");
    if (Status s = checkRange((n + ".outerConeAngle").c_str(), light.outerConeAngle, 0.0, 1.5707963); !s)
        return s;
    if (Status s =
            checkRange((n + ".innerConeAngle").c_str(), light.innerConeAngle, 0.0, light.outerConeAngle);
        !s)
        return s;
    return Status::success();
}

std::string extentText(VkExtent2D e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height);
}

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

Status checkRange(const char* field, double v, double lo, double hi) {
    if (std::isnan(v)) return invalid(std::string(field) + ": is NaN");
    if (v < lo || v > hi)
        return invalid(std::string(field) + ": " + numberText(v) + " is outside [" + numberText(lo) + ", " +
                       numberText(hi) + "]");
    return Status::success();
}

ProjectedDepth projectedDepth(const Mat4& projection) {
    // The view-space points of the view's centre at depth 0 and 1 (Vulkan NDC), and their distances; a
    // point at infinity (w = 0: an infinite far plane) has none.
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(projection));
    double distance[2];
    for (int z = 0; z < 2; ++z) {
        const glm::dvec4 p = inverse * glm::dvec4(0.0, 0.0, double(z), 1.0);
        const double length = glm::length(glm::dvec3(p));
        distance[z] = std::abs(p.w) > 1e-12 * length ? length / std::abs(p.w) : INFINITY;
    }
    ProjectedDepth out;
    out.reversedZ = distance[1] < distance[0];
    out.near = std::min(distance[0], distance[1]);
    out.far = std::max(distance[0], distance[1]);
    return out;
}

namespace {

std::string conventionText(bool reversedZ, bool infiniteFar) {
    return std::string(reversedZ ? "reversed Z" : "standard Z") +
           (infiniteFar ? ", infinite far" : ", finite far");
}

}  // namespace

Status checkDepthConvention(const Mat4& projection, const DepthConvention& depth) {
    // Perspective only: an affine projection (w independent of the point, the default identity among
    // them) has no distance that a depth of 0 or 1 must mean.
    if (projection[0][3] == 0.0f && projection[1][3] == 0.0f && projection[2][3] == 0.0f)
        return Status::success();
    const ProjectedDepth p = projectedDepth(projection);
    // A far plane beyond 1e5 near distances passes for either: in float, one beyond about 1e7 reads as
    // infinite (and postfx treats both alike: the far value means no geometry).
    const bool mismatch = p.reversedZ != depth.reversedZ || (depth.infiniteFar && p.far < 1e5 * p.near);
    if (!mismatch) return Status::success();
    const std::string projected = conventionText(p.reversedZ, std::isinf(p.far)) + ": depth " +
                                  (p.reversedZ ? "1" : "0") + " at " + numberText(p.near) + ", depth " +
                                  (p.reversedZ ? "0" : "1") + " at " + numberText(p.far);
    return invalid("ContextCreateInfo.depth (" + conventionText(depth.reversedZ, depth.infiniteFar) +
                   ") differs from FrameInfo.camera.projection (" + projected +
                   " view units): create the context with the projection's convention");
}

Status checkCamera(const CameraInput& camera, const std::string& prefix, double unitsPerMetre) {
    for (int c = 0; c < 3; ++c)
        if (Status s = checkRange((prefix + ".position").c_str(), camera.position[c], -kMaxWorldCoordinate,
                                  kMaxWorldCoordinate);
            !s)
            return s;
    if (!allFinite(camera.view)) return invalid(prefix + ".view: is not finite");
    if (!allFinite(camera.projection)) return invalid(prefix + ".projection: is not finite");
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const glm::dmat4 clip = glm::dmat4(camera.projection) * rotation;
    if (std::abs(glm::determinant(rotation)) < 1e-30)
        return invalid(prefix + ".view: its rotation is singular");
    if (std::abs(glm::determinant(glm::dmat4(camera.projection))) < 1e-30 ||
        std::abs(glm::determinant(clip)) < 1e-30)
        return invalid(prefix + ".projection: projection · view rotation is not invertible");
    // The effects reconstruct view rays through the inverse, which the GPU gets in float.
    glm::dmat4 inverse = glm::inverse(clip);
    for (int c = 0; c < 4; ++c)
        inverse[c] = glm::dvec4(glm::dvec3(inverse[c]) / unitsPerMetre, inverse[c].w);
    if (!finiteAsFloat(inverse))
        return invalid(prefix + ".projection: projection · view rotation is nearly singular (its inverse " +
                       "is not finite in float)");
    return Status::success();
}

Status checkLighting(const SunInput& sun, const Vec3& ambient, const std::string& prefix) {
    const std::string toSun = prefix + "sun.toSun", illuminance = prefix + "sun.illuminance",
                      ambientName = prefix + "ambient";
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(sun.toSun[c])) return invalid(toSun + ": is not finite");
        if (Status s = checkRange(illuminance.c_str(), sun.illuminance[c], 0.0, 1e7); !s) return s;
        if (Status s = checkRange(ambientName.c_str(), ambient[c], 0.0, 1e7); !s) return s;
    }
    if (!longEnough(sun.toSun)) return invalid(toSun + ": is the zero vector (length below 1e-6)");
    return Status::success();
}

Status checkTime(double timeSeconds, const std::string& field) {
    if (!std::isfinite(timeSeconds)) return invalid(field + ": is not finite");
    return checkRange(field.c_str(), timeSeconds, -kMaxTimeSeconds, kMaxTimeSeconds);
}

Status checkShadowTransform(const DMat4& worldToClip, const DVec3& camera, const std::string& field,
                            double unitsPerMetre) {
    if (!allFinite(worldToClip)) return invalid(field + ": is not finite");
    glm::dmat4 relative = glm::dmat4(worldToClip) * glm::translate(glm::dmat4(1.0), glm::dvec3(camera));
    for (int c = 0; c < 3; ++c)
        relative[c] *= unitsPerMetre;
    if (!finiteAsFloat(relative))
        return invalid(field + ": worldToClip · translate(camera.position) is not finite in float");
    return Status::success();
}

bool knownImageLayout(VkImageLayout layout) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_UNDEFINED:
        case VK_IMAGE_LAYOUT_GENERAL:
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
        case VK_IMAGE_LAYOUT_PREINITIALIZED:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR:
        case VK_IMAGE_LAYOUT_SHARED_PRESENT_KHR:
        case VK_IMAGE_LAYOUT_FRAGMENT_DENSITY_MAP_OPTIMAL_EXT:
        case VK_IMAGE_LAYOUT_FRAGMENT_SHADING_RATE_ATTACHMENT_OPTIMAL_KHR:
        case VK_IMAGE_LAYOUT_ATTACHMENT_FEEDBACK_LOOP_OPTIMAL_EXT:
            return true;
        default:
            return false;
    }
}

// FrameInfo::volumetricsLookup (postfx/volumetrics_lookup.h), checked when enabled.
Status checkVolumetricsLookup(const VolumetricsLookupSettings& s) {
    if (!s.enabled) return Status::success();
    const std::string name = "FrameInfo.volumetricsLookup.";
    const uint32_t largest[3] = {kMaxLookupExtentXY, kMaxLookupExtentXY, kMaxLookupExtentZ};
    const uint32_t smallest[3] = {1, 1, 2};
    for (int i = 0; i < 3; ++i)
        if (s.extent[i] < smallest[i] || s.extent[i] > largest[i])
            return invalid(name + "extent." + "xyz"[i] + ": " + std::to_string(s.extent[i]) +
                           " is outside [" + std::to_string(smallest[i]) + ", " + std::to_string(largest[i]) +
                           "]");
    if (uint64_t(s.extent.x) * s.extent.y * s.extent.z > kMaxLookupFroxels)
        return invalid(name + "extent: " + std::to_string(s.extent.x) + "x" + std::to_string(s.extent.y) +
                       "x" + std::to_string(s.extent.z) + " froxels exceed " +
                       std::to_string(kMaxLookupFroxels) + " (2 × 8 bytes each)");
    if (!(s.nearDistance >= kMinLookupNear && s.nearDistance <= kMaxLookupNear))
        return invalid(name + "nearDistance: " + numberText(s.nearDistance) + " is outside [" +
                       numberText(kMinLookupNear) + ", " + numberText(kMaxLookupNear) + "]");
    if (!(s.maxDistance > s.nearDistance && s.maxDistance <= kMaxLookupDistance))
        return invalid(name + "maxDistance: " + numberText(s.maxDistance) + " must be above nearDistance (" +
                       numberText(s.nearDistance) + ") and at most " + numberText(kMaxLookupDistance));
    return Status::success();
}

Status checkSharedInputs(const FrameInfo& frame, const ContextCreateInfo& info) {
    if (frame.structSize != sizeof(FrameInfo))
        return invalid("FrameInfo.structSize " + std::to_string(frame.structSize) +
                       " differs from the library's " + std::to_string(sizeof(FrameInfo)) +
                       ": the host was compiled with another postfx header or struct packing");
    // The color's usage decides how postfx composites into it (core/target.h): checked below.
    const ImageRule color{"FrameInfo.color", isBlitTargetFormat, blitTargetFormatNames(), 0, &info.maxExtent};
    if (Status s = checkImage(frame.color, color); !s) return s;
    const ImageRule depth{"FrameInfo.depth", isDepthFormat,
                          "VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, "
                          "VK_FORMAT_D24_UNORM_S8_UINT or VK_FORMAT_D32_SFLOAT_S8_UINT",
                          VK_IMAGE_USAGE_SAMPLED_BIT, &info.maxExtent};
    if (Status s = checkImage(frame.depth, depth); !s) return s;
    if (!sameExtent(frame.depth.extent, frame.color.extent))
        return invalid("FrameInfo.depth.extent " + extentText(frame.depth.extent) +
                       " differs from FrameInfo.color.extent " + extentText(frame.color.extent));
    if (frame.output.present()) {
        if (frame.output.image == frame.color.image)
            return invalid("FrameInfo.output is FrameInfo.color: leave output empty to composite in place");
        if (Status s = checkImage(frame.output, {"FrameInfo.output", isBlitTargetFormat,
                                                 blitTargetFormatNames(), 0, &info.maxExtent});
            !s)
            return s;
        if (frame.output.format != frame.color.format)
            return invalid("FrameInfo.output.format " + formatName(frame.output.format) +
                           " differs from FrameInfo.color.format " + formatName(frame.color.format));
        if (!sameExtent(frame.output.extent, frame.color.extent))
            return invalid("FrameInfo.output.extent " + extentText(frame.output.extent) +
                           " differs from FrameInfo.color.extent " + extentText(frame.color.extent));
    }
    if (Status s = checkTargetUsage(frame); !s) return s;
    if (Status s = checkTime(frame.timeSeconds, "FrameInfo.timeSeconds"); !s) return s;
    if (Status s = checkVolumetricsLookup(frame.volumetricsLookup); !s) return s;
    if (!(frame.budgetMs >= 0.0f && frame.budgetMs <= kMaxBudgetMs))
        return invalid("FrameInfo.budgetMs: " + numberText(frame.budgetMs) + " is outside [0, " +
                       numberText(kMaxBudgetMs) + "]");
    const double units = info.world.unitsPerMetre;
    if (Status s = checkCamera(frame.camera, "FrameInfo.camera", units); !s) return s;
    if (Status s = checkDepthConvention(frame.camera.projection, info.depth); !s) return s;
    if (Status s = checkLighting(frame.sun, frame.ambient, "FrameInfo."); !s) return s;
    const ShadowMapInput& shadow = frame.shadowMap;
    if (shadow.image.present()) {
        const ImageRule rule{"FrameInfo.shadowMap.image", isShadowFormat,
                             "VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, "
                             "VK_FORMAT_D24_UNORM_S8_UINT or VK_FORMAT_R32_SFLOAT",
                             VK_IMAGE_USAGE_SAMPLED_BIT, nullptr};
        if (Status s = checkImage(shadow.image, rule); !s) return s;
        if (Status s = checkShadowTransform(shadow.worldToClip, frame.camera.position,
                                            "FrameInfo.shadowMap.worldToClip", units);
            !s)
            return s;
        if (!(shadow.depthBias >= 0.0f) || !std::isfinite(shadow.depthBias))
            return invalid("FrameInfo.shadowMap.depthBias: " + numberText(shadow.depthBias) +
                           " must be finite and >= 0");
    }
    if (frame.lightCount > kMaxLocalLights)
        return invalid("FrameInfo.lightCount " + std::to_string(frame.lightCount) +
                       " exceeds kMaxLocalLights (" + std::to_string(kMaxLocalLights) + ")");
    if (frame.lightCount > 0 && !frame.lights)
        return invalid("FrameInfo.lights is null with lightCount " + std::to_string(frame.lightCount));
    for (uint32_t i = 0; i < frame.lightCount; ++i)
        if (Status s = checkLight(frame.lights[i], "FrameInfo.lights[" + std::to_string(i) + "]"); !s)
            return s;
    if (Status s = checkLocalShadows(frame, units); !s) return s;
    return checkPreExposure(frame);
}

Status checkLocalShadows(const FrameInfo& frame, double unitsPerMetre) {
    const LocalShadowAtlasInput& atlas = frame.localShadows;
    for (uint32_t i = 0; i < frame.lightCount; ++i) {
        const uint32_t shadow = frame.lights[i].shadow;
        if (shadow != kNoLocalShadow && shadow >= atlas.shadowCount)
            return invalid("FrameInfo.lights[" + std::to_string(i) + "].shadow: " + std::to_string(shadow) +
                           " is neither kNoLocalShadow nor below FrameInfo.localShadows.shadowCount (" +
                           std::to_string(atlas.shadowCount) + ")");
    }
    if (!atlas.image.present() && atlas.shadowCount == 0) return Status::success();
    const ImageRule rule{"FrameInfo.localShadows.image", isShadowFormat,
                         "VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, "
                         "VK_FORMAT_D24_UNORM_S8_UINT or VK_FORMAT_R32_SFLOAT",
                         VK_IMAGE_USAGE_SAMPLED_BIT, nullptr};
    if (Status s = checkImage(atlas.image, rule); !s) return s;
    return checkLocalShadowList(atlas.shadows, atlas.shadowCount, atlas.image.extent.width,
                                atlas.image.extent.height, frame.camera.position,
                                "FrameInfo.localShadows.shadows", unitsPerMetre);
}

Status checkPreExposure(const FrameInfo& frame) {
    const double p = frame.preExposure;
    if (!(p >= kMinPreExposure && p <= kMaxPreExposure))
        return invalid("FrameInfo.preExposure: " + numberText(frame.preExposure) + " is outside [" +
                       numberText(float(kMinPreExposure)) + ", " + numberText(float(kMaxPreExposure)) + "]");
    // The light pre-exposed stays within the ranges of the light itself (the effects' arithmetic is
    // checked for those).
    auto within = [&](const Vec3& light, double limit, const std::string& name) -> Status {
        for (int c = 0; c < 3; ++c)
            if (double(light[c]) * p > limit)
                return invalid("FrameInfo.preExposure: " + numberText(frame.preExposure) + " × " + name +
                               " " + numberText(light[c]) + " exceeds " + numberText(float(limit)));
        return Status::success();
    };
    if (Status s = within(frame.sun.illuminance, kMaxPreExposedLight, "sun.illuminance"); !s) return s;
    if (Status s = within(frame.ambient, kMaxPreExposedLight, "ambient"); !s) return s;
    for (uint32_t i = 0; i < frame.lightCount; ++i)
        if (Status s = within(frame.lights[i].intensity, kMaxPreExposedIntensity,
                              "lights[" + std::to_string(i) + "].intensity");
            !s)
            return s;
    return Status::success();
}

Status checkLocalShadowList(const LocalShadow* shadows, uint32_t count, uint32_t width, uint32_t height,
                            const DVec3& camera, const std::string& name, double unitsPerMetre) {
    if (count > kMaxLocalLights)
        return invalid(name + ": " + std::to_string(count) + " shadows exceed kMaxLocalLights (" +
                       std::to_string(kMaxLocalLights) + ")");
    if (count > 0 && !shadows) return invalid(name + " is null with " + std::to_string(count) + " shadows");
    for (uint32_t i = 0; i < count; ++i) {
        const LocalShadow& shadow = shadows[i];
        const std::string n = name + "[" + std::to_string(i) + "]";
        if (shadow.faceCount < 1 || shadow.faceCount > kMaxLocalShadowFaces)
            return invalid(n + ".faceCount: " + std::to_string(shadow.faceCount) + " is outside [1, " +
                           std::to_string(kMaxLocalShadowFaces) + "]");
        if (!(shadow.depthBias >= 0.0f) || !std::isfinite(shadow.depthBias))
            return invalid(n + ".depthBias: " + numberText(shadow.depthBias) + " must be finite and >= 0");
        for (uint32_t f = 0; f < shadow.faceCount; ++f) {
            const LocalShadowFace& face = shadow.faces[f];
            const std::string fn = n + ".faces[" + std::to_string(f) + "]";
            if (face.extent.x < 1 || face.extent.y < 1)
                return invalid(fn + ".extent " + std::to_string(face.extent.x) + "x" +
                               std::to_string(face.extent.y) + " is empty");
            const uint64_t right = uint64_t(face.offset.x) + face.extent.x,
                           bottom = uint64_t(face.offset.y) + face.extent.y;
            if (right > width || bottom > height)
                return invalid(fn + ": offset (" + std::to_string(face.offset.x) + ", " +
                               std::to_string(face.offset.y) + ") + extent " + std::to_string(face.extent.x) +
                               "x" + std::to_string(face.extent.y) + " is outside the atlas " +
                               (std::to_string(width) + "x" + std::to_string(height)));
            if (Status s = checkShadowTransform(face.worldToClip, camera, fn + ".worldToClip", unitsPerMetre);
                !s)
                return s;
            const glm::dmat4 m(face.worldToClip);
            const double det = glm::determinant(m);
            if (!(std::abs(det) > 0.0) || !allFinite(glm::inverse(m)))
                return invalid(fn + ".worldToClip: is not invertible (determinant " + numberText(float(det)) +
                               ")");
        }
    }
    return Status::success();
}

}  // namespace core
}  // namespace postfx
