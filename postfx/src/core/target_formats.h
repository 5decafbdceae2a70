// Which color targets postfx composites into in place, and which it takes through its own image
// (core/target.h): the formats alone, for the checks of the frame's inputs.
#pragma once

#include <vulkan/vulkan.h>

#include <postfx/types.h>

namespace postfx::core {

// The host's color is composited in place (no postfx.target): RGBA16F or RGBA32F with STORAGE usage.
inline bool compositesInPlace(const ImageInput& color) {
    return (color.format == VK_FORMAT_R16G16B16A16_SFLOAT || color.format == VK_FORMAT_R32G32B32A32_SFLOAT) &&
           (color.usage & VK_IMAGE_USAGE_STORAGE_BIT);
}

// A format postfx takes as a color target through postfx.target.
inline bool isBlitTargetFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32:
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_A8B8G8R8_UNORM_PACK32:
        case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
        case VK_FORMAT_R16G16B16A16_UNORM:
            return true;
        default:
            return false;
    }
}

// Their names, for messages.
inline const char* blitTargetFormatNames() {
    return "R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT, B10G11R11_UFLOAT_PACK32, A2B10G10R10_UNORM_PACK32, "
           "A2R10G10B10_UNORM_PACK32, R8G8B8A8_UNORM/SRGB, B8G8R8A8_UNORM/SRGB, A8B8G8R8_UNORM/SRGB_PACK32 "
           "or R16G16B16A16_UNORM";
}

}  // namespace postfx::core
