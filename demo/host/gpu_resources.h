// Small Vulkan helpers of the demo host renderer: buffers, images, barriers, shader modules.
// One allocation per resource (the demo has a handful).
#pragma once

#include "host/vulkan_host.h"

#include <cstdint>
#include <span>
#include <string>

namespace demo {

struct GpuBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // persistently mapped when created host-visible
};

struct GpuImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D view of mip 0 / layer 0
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageAspectFlags aspect = 0;
    VkImageUsageFlags usage = 0;  // as created
};

// hostVisible: HOST_VISIBLE | HOST_COHERENT (HOST_CACHED preferred), mapped; else DEVICE_LOCAL.
bool createBuffer(const VulkanHost& host, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                  GpuBuffer& out, std::string& error);
bool createImage(const VulkanHost& host, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                 GpuImage& out, std::string& error);
void destroyBuffer(VkDevice device, GpuBuffer& buffer);
void destroyImage(VkDevice device, GpuImage& image);

bool createShaderModule(VkDevice device, std::span<const uint32_t> spirv, VkShaderModule& out,
                        std::string& error);
// A compute pipeline of `spirv` (entry point main) with `layout`; `what` names it in errors.
bool createComputePipeline(VkDevice device, std::span<const uint32_t> spirv, VkPipelineLayout layout,
                           const char* what, VkPipeline& out, std::string& error);

// One descriptor set of `bindings` from a pool of its own, sized for exactly that set: its layout, pool
// and set. The caller destroys the pool (which frees the set) and the layout.
bool createDescriptorSet(VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings,
                         VkDescriptorSetLayout& layout, VkDescriptorPool& pool, VkDescriptorSet& set,
                         std::string& error);

// One image memory barrier (whole image, the image's aspect).
void imageBarrier(VkCommandBuffer cmd, const GpuImage& image, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);
// The same for an image the demo does not own (a swapchain image, the renderer's HDR image): one mip
// level, one layer, `aspect`.
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);
// One buffer memory barrier (whole buffer).
void bufferBarrier(VkCommandBuffer cmd, const GpuBuffer& buffer, VkPipelineStageFlags srcStage,
                   VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// Returns false and sets `error` to "<what> failed: VK_..." unless r is VK_SUCCESS.
bool vkCheck(VkResult r, const char* what, std::string& error);

}  // namespace demo
