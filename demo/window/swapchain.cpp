#include "window/swapchain.h"

#include "host/gpu_resources.h"

#include <algorithm>
#include <array>

namespace demo::window {
namespace {

struct FormatChoice {
    VkFormat format;
    bool srgb;
    bool bgr;
};

// UNORM formats first: the tonemap already applies the sRGB OETF. sRGB formats only as a fallback,
// filled by a raw copy so that the hardware does not encode a second time.
constexpr std::array<FormatChoice, 5> kFormats{{
    {VK_FORMAT_B8G8R8A8_UNORM, false, true},
    {VK_FORMAT_R8G8B8A8_UNORM, false, false},
    {VK_FORMAT_A8B8G8R8_UNORM_PACK32, false, false},
    {VK_FORMAT_B8G8R8A8_SRGB, true, true},
    {VK_FORMAT_R8G8B8A8_SRGB, true, false},
}};

bool formatHas(const VulkanHost& host, VkFormat format, VkFormatFeatureFlags need) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(host.physicalDevice, format, &props);
    return (props.optimalTilingFeatures & need) == need;
}

}  // namespace

bool Swapchain::create(const VulkanHost& host, VkSurfaceKHR surface, VkExtent2D framebufferSize,
                       std::string& error) {
    device_ = host.device;
    VkSurfaceCapabilitiesKHR caps;
    if (!vkCheck(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(host.physicalDevice, surface, &caps),
                 "vkGetPhysicalDeviceSurfaceCapabilitiesKHR", error))
        return false;
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if ((caps.supportedUsageFlags & usage) != usage) {
        error = "the surface's images do not support transfer destination + color attachment usage";
        return false;
    }

    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physicalDevice, surface, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physicalDevice, surface, &n, formats.data());
    const FormatChoice* chosen = nullptr;
    for (const FormatChoice& c : kFormats) {
        const VkFormatFeatureFlags need =
            VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | (c.srgb ? 0 : VK_FORMAT_FEATURE_BLIT_DST_BIT);
        const bool offered = std::any_of(formats.begin(), formats.end(), [&](const VkSurfaceFormatKHR& f) {
            return (f.format == c.format || f.format == VK_FORMAT_UNDEFINED) &&
                   f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
        });
        if (offered && formatHas(host, c.format, need)) {
            chosen = &c;
            break;
        }
    }
    if (!chosen) {
        error = "the surface offers no 8-bit RGBA/BGRA format (UNORM or sRGB) in the sRGB color space";
        return false;
    }

    VkExtent2D ext = caps.currentExtent;
    if (ext.width == UINT32_MAX) {
        ext.width = std::clamp(framebufferSize.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        ext.height =
            std::clamp(framebufferSize.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (ext.width == 0 || ext.height == 0) {
        error = "the surface has a zero extent (minimised window)";
        return false;
    }
    uint32_t count = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface;
    ci.minImageCount = count;
    ci.imageFormat = chosen->format;
    ci.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    ci.imageExtent = ext;
    ci.imageArrayLayers = 1;
    ci.imageUsage = usage;
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
    ci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    for (VkCompositeAlphaFlagBitsKHR a :
         {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
          VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
        if (caps.supportedCompositeAlpha & a) {
            ci.compositeAlpha = a;
            break;
        }
    }
    ci.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = handle;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    const VkResult r = vkCreateSwapchainKHR(device_, &ci, nullptr, &created);
    // The old swapchain is retired either way.
    destroyViews();
    if (handle) vkDestroySwapchainKHR(device_, handle, nullptr);
    handle = VK_NULL_HANDLE;
    images.clear();
    if (!vkCheck(r, "vkCreateSwapchainKHR", error)) return false;
    handle = created;
    format = chosen->format;
    srgb = chosen->srgb;
    bgr = chosen->bgr;
    extent = ext;
    minImageCount = count;

    vkGetSwapchainImagesKHR(device_, handle, &n, nullptr);
    images.resize(n);
    vkGetSwapchainImagesKHR(device_, handle, &n, images.data());
    for (VkImage image : images) {
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = image;
        vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vci.format = format;
        vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        if (!vkCheck(vkCreateImageView(device_, &vci, nullptr, &view), "vkCreateImageView (swapchain)",
                     error))
            return false;
        views.push_back(view);
    }
    while (renderFinished.size() < images.size()) {
        VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s = VK_NULL_HANDLE;
        if (!vkCheck(vkCreateSemaphore(device_, &sci, nullptr, &s), "vkCreateSemaphore", error)) return false;
        renderFinished.push_back(s);
    }
    return true;
}

void Swapchain::destroyViews() {
    for (VkImageView v : views)
        vkDestroyImageView(device_, v, nullptr);
    views.clear();
}

void Swapchain::destroy() {
    if (!device_) return;
    destroyViews();
    if (handle) vkDestroySwapchainKHR(device_, handle, nullptr);
    handle = VK_NULL_HANDLE;
    images.clear();
    for (VkSemaphore s : renderFinished)
        vkDestroySemaphore(device_, s, nullptr);
    renderFinished.clear();
    device_ = VK_NULL_HANDLE;
}

}  // namespace demo::window
