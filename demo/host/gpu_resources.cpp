#include "host/gpu_resources.h"

#include <algorithm>
#include <vector>

namespace demo {
namespace {

uint32_t findMemoryType(const VulkanHost& host, uint32_t typeBits, VkMemoryPropertyFlags need,
                        VkMemoryPropertyFlags prefer) {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(host.physicalDevice, &mp);
    uint32_t fallback = UINT32_MAX;
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i) {
        const VkMemoryPropertyFlags flags = mp.memoryTypes[i].propertyFlags;
        if (!(typeBits & (1u << i)) || (flags & need) != need) continue;
        if ((flags & prefer) == prefer) return i;
        if (fallback == UINT32_MAX) fallback = i;
    }
    return fallback;
}

bool allocate(const VulkanHost& host, const VkMemoryRequirements& req, VkMemoryPropertyFlags need,
              VkMemoryPropertyFlags prefer, VkDeviceMemory& memory, std::string& error) {
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = findMemoryType(host, req.memoryTypeBits, need, prefer);
    if (ai.memoryTypeIndex == UINT32_MAX) {
        error = "no suitable Vulkan memory type";
        return false;
    }
    return vkCheck(vkAllocateMemory(host.device, &ai, nullptr, &memory), "vkAllocateMemory", error);
}

}  // namespace

bool createDescriptorSet(VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings,
                         VkDescriptorSetLayout& layout, VkDescriptorPool& pool, VkDescriptorSet& set,
                         std::string& error) {
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(bindings.size());
    lci.pBindings = bindings.data();
    if (!vkCheck(vkCreateDescriptorSetLayout(device, &lci, nullptr, &layout), "vkCreateDescriptorSetLayout",
                 error))
        return false;
    std::vector<VkDescriptorPoolSize> sizes;  // one per descriptor type, its bindings' count summed
    for (const VkDescriptorSetLayoutBinding& b : bindings) {
        auto it = std::find_if(sizes.begin(), sizes.end(),
                               [&](const VkDescriptorPoolSize& s) { return s.type == b.descriptorType; });
        if (it == sizes.end()) it = sizes.insert(sizes.end(), {b.descriptorType, 0});
        it->descriptorCount += b.descriptorCount;
    }
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = 1;
    pci.poolSizeCount = uint32_t(sizes.size());
    pci.pPoolSizes = sizes.data();
    if (!vkCheck(vkCreateDescriptorPool(device, &pci, nullptr, &pool), "vkCreateDescriptorPool", error))
        return false;
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    return vkCheck(vkAllocateDescriptorSets(device, &ai, &set), "vkAllocateDescriptorSets", error);
}

bool vkCheck(VkResult r, const char* what, std::string& error) {
    if (r == VK_SUCCESS) return true;
    error = std::string(what) + " failed: " + vkResultName(r);
    return false;
}

bool createBuffer(const VulkanHost& host, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                  GpuBuffer& out, std::string& error) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    out.size = size;
    if (!vkCheck(vkCreateBuffer(host.device, &bci, nullptr, &out.buffer), "vkCreateBuffer", error))
        return false;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(host.device, out.buffer, &req);
    const VkMemoryPropertyFlags need =
        hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    const VkMemoryPropertyFlags prefer = hostVisible ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
    if (!allocate(host, req, need, prefer, out.memory, error)) return false;
    if (!vkCheck(vkBindBufferMemory(host.device, out.buffer, out.memory, 0), "vkBindBufferMemory", error))
        return false;
    if (hostVisible)
        return vkCheck(vkMapMemory(host.device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped), "vkMapMemory",
                       error);
    return true;
}

bool createImage(const VulkanHost& host, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                 GpuImage& out, std::string& error) {
    const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM;
    out.format = format;
    out.usage = usage;
    out.extent = extent;
    out.aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {extent.width, extent.height, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (!vkCheck(vkCreateImage(host.device, &ici, nullptr, &out.image), "vkCreateImage", error)) return false;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(host.device, out.image, &req);
    if (!allocate(host, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, out.memory, error)) return false;
    if (!vkCheck(vkBindImageMemory(host.device, out.image, out.memory, 0), "vkBindImageMemory", error))
        return false;
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = out.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = format;
    vci.subresourceRange = {out.aspect, 0, 1, 0, 1};
    return vkCheck(vkCreateImageView(host.device, &vci, nullptr, &out.view), "vkCreateImageView", error);
}

void destroyBuffer(VkDevice device, GpuBuffer& b) {
    if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device, b.memory, nullptr);  // unmaps implicitly
    b = {};
}

void destroyImage(VkDevice device, GpuImage& i) {
    if (i.view) vkDestroyImageView(device, i.view, nullptr);
    if (i.image) vkDestroyImage(device, i.image, nullptr);
    if (i.memory) vkFreeMemory(device, i.memory, nullptr);
    i = {};
}

bool createShaderModule(VkDevice device, std::span<const uint32_t> spirv, VkShaderModule& out,
                        std::string& error) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = spirv.size_bytes();
    ci.pCode = spirv.data();
    return vkCheck(vkCreateShaderModule(device, &ci, nullptr, &out), "vkCreateShaderModule", error);
}

bool createComputePipeline(VkDevice device, std::span<const uint32_t> spirv, VkPipelineLayout layout,
                           const char* what, VkPipeline& out, std::string& error) {
    VkShaderModule module = VK_NULL_HANDLE;
    if (!createShaderModule(device, spirv, module, error)) return false;
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = module;
    ci.stage.pName = "main";
    ci.layout = layout;
    const VkResult r = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &out);
    vkDestroyShaderModule(device, module, nullptr);
    return vkCheck(r, what, error);
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = oldLayout;
    b.newLayout = newLayout;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

void imageBarrier(VkCommandBuffer cmd, const GpuImage& image, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    imageBarrier(cmd, image.image, image.aspect, oldLayout, newLayout, srcStage, srcAccess, dstStage,
                 dstAccess);
}

void bufferBarrier(VkCommandBuffer cmd, const GpuBuffer& buffer, VkPipelineStageFlags srcStage,
                   VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.buffer = buffer.buffer;
    b.offset = 0;
    b.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 1, &b, 0, nullptr);
}

}  // namespace demo
