#include "core/checks.h"

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

bool isColorFormat(VkFormat f) {
    return f == VK_FORMAT_R16G16B16A16_SFLOAT || f == VK_FORMAT_R32G32B32A32_SFLOAT;
}

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
    if (image.extent.width == 0 || image.extent.height == 0)
        return invalid(n + ".extent is " + extentText(image.extent));
    if (rule.maxExtent &&
        (image.extent.width > rule.maxExtent->width || image.extent.height > rule.maxExtent->height))
        return invalid(n + ".extent " + extentText(image.extent) + " exceeds ContextCreateInfo.maxExtent " +
                       extentText(*rule.maxExtent));
    if (image.layout == VK_IMAGE_LAYOUT_UNDEFINED || image.layout == VK_IMAGE_LAYOUT_PREINITIALIZED)
        return invalid(n + ".layout is UNDEFINED/PREINITIALIZED: postfx needs the image's contents");
    if (!(image.usage & rule.usage))
        return invalid(n + ".usage lacks " + usageName(rule.usage) + " (postfx " +
                       (rule.usage == VK_IMAGE_USAGE_STORAGE_BIT ? "reads and writes it as a storage image"
                                                                 : "samples it") +
                       "; set ImageInput::usage to the usage the image was created with)");
    return Status::success();
}

bool sameExtent(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

Status checkLight(const LocalLight& light, uint32_t index) {
    const std::string n = "FrameInfo.lights[" + std::to_string(index) + "]";
    if (light.type != LightType::Point && light.type != LightType::Spot)
        return invalid(n + ".type " + std::to_string(uint32_t(light.type)) + " is not Point or Spot");
    if (!allFinite(light.position)) return invalid(n + ".position: is not finite");
    if (!allFinite(light.direction)) return invalid(n + ".direction: is not finite");
    if (light.type == LightType::Spot && glm::dot(light.direction, light.direction) < 1e-12f)
        return invalid(n + ".direction: is the zero vector");
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

}  // namespace

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

Status checkCamera(const CameraInput& camera, const std::string& prefix) {
    if (!allFinite(camera.position)) return invalid(prefix + ".position: is not finite");
    if (!allFinite(camera.view)) return invalid(prefix + ".view: is not finite");
    if (!allFinite(camera.projection)) return invalid(prefix + ".projection: is not finite");
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    if (std::abs(glm::determinant(glm::dmat4(camera.projection))) < 1e-30 ||
        std::abs(glm::determinant(glm::dmat4(camera.projection) * rotation)) < 1e-30)
        return invalid(prefix + ".projection: projection · view rotation is not invertible");
    return Status::success();
}

Status checkLighting(const SunInput& sun, const Vec3& ambient) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(sun.toSun[c])) return invalid("sun.toSun: is not finite");
        if (Status s = checkRange("sun.illuminance", sun.illuminance[c], 0.0, 1e7); !s) return s;
        if (Status s = checkRange("ambient", ambient[c], 0.0, 1e7); !s) return s;
    }
    if (glm::dot(sun.toSun, sun.toSun) < 1e-12f) return invalid("sun.toSun: is the zero vector");
    return Status::success();
}

Status checkSharedInputs(const FrameInfo& frame, const ContextCreateInfo& info) {
    if (frame.structSize != sizeof(FrameInfo))
        return invalid("FrameInfo.structSize " + std::to_string(frame.structSize) +
                       " differs from the library's " + std::to_string(sizeof(FrameInfo)) +
                       ": the host was compiled with another postfx header or struct packing");
    const ImageRule color{"FrameInfo.color", isColorFormat,
                          "VK_FORMAT_R16G16B16A16_SFLOAT or VK_FORMAT_R32G32B32A32_SFLOAT",
                          VK_IMAGE_USAGE_STORAGE_BIT, &info.maxExtent};
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
        if (Status s =
                checkImage(frame.output, {"FrameInfo.output", isColorFormat,
                                          "VK_FORMAT_R16G16B16A16_SFLOAT or VK_FORMAT_R32G32B32A32_SFLOAT",
                                          VK_IMAGE_USAGE_STORAGE_BIT, &info.maxExtent});
            !s)
            return s;
        if (frame.output.format != frame.color.format)
            return invalid("FrameInfo.output.format " + formatName(frame.output.format) +
                           " differs from FrameInfo.color.format " + formatName(frame.color.format));
        if (!sameExtent(frame.output.extent, frame.color.extent))
            return invalid("FrameInfo.output.extent " + extentText(frame.output.extent) +
                           " differs from FrameInfo.color.extent " + extentText(frame.color.extent));
    }
    if (!std::isfinite(frame.timeSeconds)) return invalid("FrameInfo.timeSeconds: is not finite");
    if (Status s = checkCamera(frame.camera, "FrameInfo.camera"); !s) return s;
    if (Status s = checkLighting(frame.sun, frame.ambient); !s) return s;
    const ShadowMapInput& shadow = frame.shadowMap;
    if (shadow.image.present()) {
        const ImageRule rule{"FrameInfo.shadowMap.image", isShadowFormat,
                             "VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, "
                             "VK_FORMAT_D24_UNORM_S8_UINT or VK_FORMAT_R32_SFLOAT",
                             VK_IMAGE_USAGE_SAMPLED_BIT, nullptr};
        if (Status s = checkImage(shadow.image, rule); !s) return s;
        if (!allFinite(shadow.worldToClip)) return invalid("FrameInfo.shadowMap.worldToClip: is not finite");
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
        if (Status s = checkLight(frame.lights[i], i); !s) return s;
    return Status::success();
}

}  // namespace core
}  // namespace postfx
