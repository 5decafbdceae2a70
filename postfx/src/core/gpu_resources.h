// GPU buffers and images that postfx owns (its intermediate and cached resources; never host images).
// Move-only RAII wrappers: destroyed with the Gpu they were created on.
#pragma once

#include "core/device_memory.h"
#include "core/gpu.h"

namespace postfx::core {

class GpuBuffer {
public:
    GpuBuffer() = default;
    GpuBuffer(GpuBuffer&& other) noexcept { *this = std::move(other); }
    GpuBuffer& operator=(GpuBuffer&& other) noexcept;
    ~GpuBuffer() { reset(); }

    // hostVisible: HOST_VISIBLE|HOST_COHERENT memory, persistently mapped (mapped() != nullptr).
    Status create(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                  const char* name);
    void reset();

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return memory_.mapped(); }
    VkDeviceSize bytes() const { return memory_.bytes(); }  // device memory it holds

private:
    const Gpu* gpu_ = nullptr;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    DeviceMemory memory_;
    VkDeviceSize size_ = 0;
};

struct ImageDesc {
    VkImageType type = VK_IMAGE_TYPE_2D;  // 2D or 3D
    VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
    VkExtent3D extent = {1, 1, 1};
    uint32_t layers = 1;  // array layers (2D only); more than one: a 2D-array view
    VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    // The setting that sizes it, as its settings-table key with the effect's prefix
    // ("froxel_fog.grid"): what the memory budget's error names (core/memory_budget.h). Null: the
    // resource's own name. Not part of the image: images of two keys with the same fields are alike.
    const char* sizedBy = nullptr;
};

class GpuImage {
public:
    GpuImage() = default;
    GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
    GpuImage& operator=(GpuImage&& other) noexcept;
    ~GpuImage() { reset(); }

    // Device-local image with one mip and desc.layers layers, and a view of all of them. Starts in layout
    // UNDEFINED.
    Status create(const Gpu& gpu, const ImageDesc& desc, const char* name);
    void reset();

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    const ImageDesc& desc() const { return desc_; }
    VkDeviceSize bytes() const { return memory_.bytes(); }  // device memory it holds

private:
    const Gpu* gpu_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    DeviceMemory memory_;
    ImageDesc desc_;
};

}  // namespace postfx::core
