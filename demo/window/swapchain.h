// The window's swapchain: FIFO, images usable as transfer destination (the tonemapped frame is blitted or
// copied in) and color attachment (the UI overlay draws on top). Recreated on resize / out-of-date.
#pragma once

#include "host/vulkan_host.h"

#include <cstdint>
#include <string>
#include <vector>

namespace demo::window {

class Swapchain {
public:
    Swapchain() = default;
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;
    ~Swapchain() { destroy(); }

    // Creates the swapchain for `surface`, or recreates it (passing the old one as oldSwapchain). The
    // device must be idle. `framebufferSize` is used when the surface leaves the extent to the swapchain.
    bool create(const VulkanHost& host, VkSurfaceKHR surface, VkExtent2D framebufferSize, std::string& error);
    void destroy();

    VkSwapchainKHR handle = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    uint32_t minImageCount = 0;  // as requested at creation
    // false: a UNORM format, the frame is blitted in (the blit converts the channel order). true: only an
    // sRGB format was offered; the tonemapped (already encoded) bytes are copied in unchanged, as a blit
    // would encode them a second time.
    bool srgb = false;
    bool bgr = false;  // B8G8R8A8 channel order (the copy path swaps red and blue in the tonemap)
    std::vector<VkImage> images;
    std::vector<VkImageView> views;  // for the overlay's framebuffers
    // One per image: signalled by the frame's submission, waited by its present. Kept across recreation
    // (only grown), since a present may still reference one until the device is idle.
    std::vector<VkSemaphore> renderFinished;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    void destroyViews();
};

}  // namespace demo::window
