#include "core/gpu_resources.h"

#include "core/barriers.h"

#include <string>
#include <utility>

namespace postfx::core {

Status Gpu::init(const ContextCreateInfo& info) {
    instance = info.instance;
    physicalDevice = info.physicalDevice;
    device = info.device;
    allocator = info.allocator;
    pipelineCache = info.pipelineCache;
    deviceMemory = info.deviceMemory;
    if (Status s = fn.load(info.instance, info.getInstanceProcAddr, info.device, info.getDeviceProcAddr); !s)
        return s;
    if (info.debugLabels)
        if (Status s = fn.loadDebugLabels(info.instance, info.getInstanceProcAddr); !s) return s;
    fn.vkGetPhysicalDeviceProperties(info.physicalDevice, &properties);
    fn.vkGetPhysicalDeviceMemoryProperties(info.physicalDevice, &memory);
    return Status::success();
}

Status Gpu::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required, uint32_t& index) const {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required) {
            index = i;
            return Status::success();
        }
    }
    return {Result::Unsupported, "no memory type with flags " + std::to_string(required) +
                                     " among allowed types " + std::to_string(typeBits)};
}

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& other) noexcept {
    if (this != &other) {
        reset();
        gpu_ = std::exchange(other.gpu_, nullptr);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::move(other.memory_);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

Status GpuBuffer::create(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                         const char* name) {
    reset();
    gpu_ = &gpu;
    size_ = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    // Handles are kept only from calls that succeeded: Vulkan leaves a failed call's outputs undefined.
    VkBuffer buffer = VK_NULL_HANDLE;
    Status s = vulkanStatus(gpu.fn.vkCreateBuffer(gpu.device, &info, gpu.allocator, &buffer),
                            (std::string("vkCreateBuffer for ") + name).c_str());
    if (!s) return reset(), s;
    buffer_ = buffer;
    VkMemoryRequirements req;
    gpu.fn.vkGetBufferMemoryRequirements(gpu.device, buffer_, &req);
    // Host-written buffers (uniforms, written through the mapping, read by every pass) go to memory that
    // is device-local too where the device has such a type (resizable BAR, or its 256 MB window; every
    // integrated GPU), else to system memory, read across PCIe (on an H100 that cost a frame's first pass
    // 0.6 µs; docs/effects/atmosphere.md, "Benchmark").
    constexpr VkMemoryPropertyFlags kHostWrite =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t preferred = 0;
    VkMemoryPropertyFlags flags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (hostVisible)
        flags = gpu.findMemoryType(req.memoryTypeBits, kHostWrite | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                   preferred)
                    ? kHostWrite | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT
                    : kHostWrite;
    if (!(s = memory_.allocate(gpu, req, flags, hostVisible, name))) return reset(), s;
    if (!(s = vulkanStatus(gpu.fn.vkBindBufferMemory(gpu.device, buffer_, memory_.memory(), memory_.offset()),
                           (std::string("vkBindBufferMemory for ") + name).c_str())))
        return reset(), s;
    return Status::success();
}

void GpuBuffer::reset() {
    if (!gpu_) return;
    if (buffer_) gpu_->fn.vkDestroyBuffer(gpu_->device, buffer_, gpu_->allocator);
    memory_.reset();  // after what is bound to it
    gpu_ = nullptr;
    buffer_ = VK_NULL_HANDLE;
    size_ = 0;
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
    if (this != &other) {
        reset();
        gpu_ = std::exchange(other.gpu_, nullptr);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        memory_ = std::move(other.memory_);
        desc_ = other.desc_;
    }
    return *this;
}

Status GpuImage::create(const Gpu& gpu, const ImageDesc& desc, const char* name) {
    reset();
    gpu_ = &gpu;
    desc_ = desc;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = desc.type;
    info.format = desc.format;
    info.extent = desc.extent;
    info.mipLevels = 1;
    info.arrayLayers = desc.layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    // Handles are kept only from calls that succeeded: Vulkan leaves a failed call's outputs undefined.
    VkImage image = VK_NULL_HANDLE;
    Status s = vulkanStatus(gpu.fn.vkCreateImage(gpu.device, &info, gpu.allocator, &image),
                            (std::string("vkCreateImage for ") + name).c_str());
    if (!s) return reset(), s;
    image_ = image;
    VkMemoryRequirements req;
    gpu.fn.vkGetImageMemoryRequirements(gpu.device, image_, &req);
    if (!(s = memory_.allocate(gpu, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, false, name)))
        return reset(), s;
    if (!(s = vulkanStatus(gpu.fn.vkBindImageMemory(gpu.device, image_, memory_.memory(), memory_.offset()),
                           (std::string("vkBindImageMemory for ") + name).c_str())))
        return reset(), s;
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image_;
    viewInfo.viewType = desc.type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D
                        : desc.layers > 1             ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                      : VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = desc.format;
    viewInfo.subresourceRange = {aspectOfFormat(desc.format), 0, 1, 0, desc.layers};
    VkImageView view = VK_NULL_HANDLE;
    if (!(s = vulkanStatus(gpu.fn.vkCreateImageView(gpu.device, &viewInfo, gpu.allocator, &view),
                           (std::string("vkCreateImageView for ") + name).c_str())))
        return reset(), s;
    view_ = view;
    return Status::success();
}

void GpuImage::reset() {
    if (!gpu_) return;
    if (view_) gpu_->fn.vkDestroyImageView(gpu_->device, view_, gpu_->allocator);
    if (image_) gpu_->fn.vkDestroyImage(gpu_->device, image_, gpu_->allocator);
    memory_.reset();  // after what is bound to it
    gpu_ = nullptr;
    image_ = VK_NULL_HANDLE;
    view_ = VK_NULL_HANDLE;
}

}  // namespace postfx::core
