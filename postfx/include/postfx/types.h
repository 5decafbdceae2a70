// Plain types shared by the public headers.
#pragma once

#include <vulkan/vulkan.h>

namespace postfx {

// How the host's depth buffer maps view distance to [0, 1]. Fixed at create time.
struct DepthConvention {
    bool reversedZ = true;     // true: near plane at depth 1, far at 0 (recommended with D32_SFLOAT)
    bool infiniteFar = false;  // true: projection has no far plane (far at depth 0 / 1 reached at infinity)
};

// One host image handed to postfx for one record() call. postfx never owns it: it uses the view the
// host created and leaves the image in `layout` when the recorded commands have run.
struct ImageInput {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D view of mip 0, layer 0
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent = {0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // layout at the point record() is recorded

    bool present() const { return image != VK_NULL_HANDLE; }
};

}  // namespace postfx
