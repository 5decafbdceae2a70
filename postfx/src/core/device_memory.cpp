#include "core/device_memory.h"

#include <string>
#include <utility>

namespace postfx::core {

DeviceMemory& DeviceMemory::operator=(DeviceMemory&& other) noexcept {
    if (this != &other) {
        reset();
        gpu_ = std::exchange(other.gpu_, nullptr);
        allocation_ = std::exchange(other.allocation_, DeviceAllocation{});
        bytes_ = std::exchange(other.bytes_, 0);
        fromHost_ = std::exchange(other.fromHost_, false);
    }
    return *this;
}

Status DeviceMemory::allocate(const Gpu& gpu, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags,
                              bool mapped, const char* name) {
    reset();
    const DeviceMemoryCallbacks& host = gpu.deviceMemory;
    if (host.allocate) {
        DeviceAllocation a;
        Status s = vulkanStatus(host.allocate(host.userData, req, flags, a),
                                (std::string("DeviceMemoryCallbacks.allocate for ") + name).c_str());
        if (!s) return s;
        // What postfx binds at must be usable: a block, aligned, and mapped when it is to be written.
        std::string wrong;
        if (!a.memory)
            wrong = "returned VK_SUCCESS with a null memory";
        else if (req.alignment && a.offset % req.alignment)
            wrong = "returned offset " + std::to_string(a.offset) + ", not a multiple of the alignment " +
                    std::to_string(req.alignment);
        else if (mapped && !a.mapped)
            wrong = "returned no mapped pointer for a HOST_VISIBLE request";
        if (!wrong.empty()) {
            if (a.memory) host.free(host.userData, a);
            return {Result::InvalidArgument,
                    std::string("DeviceMemoryCallbacks.allocate for ") + name + " " + wrong};
        }
        if (!mapped) a.mapped = nullptr;  // not postfx's to use
        gpu_ = &gpu;
        allocation_ = a;
        bytes_ = req.size;
        fromHost_ = true;
        return Status::success();
    }
    uint32_t type = 0;
    Status s = gpu.findMemoryType(req.memoryTypeBits, flags, type);
    if (!s) return {s.code, std::string(name) + ": " + s.message};
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;  // kept only on success (a failed call's output is undefined)
    if (!(s = vulkanStatus(gpu.fn.vkAllocateMemory(gpu.device, &info, gpu.allocator, &memory),
                           (std::string("vkAllocateMemory for ") + name).c_str())))
        return s;
    gpu_ = &gpu;
    allocation_.memory = memory;
    bytes_ = req.size;
    if (!mapped) return Status::success();
    void* pointer = nullptr;
    if (!(s = vulkanStatus(gpu.fn.vkMapMemory(gpu.device, memory, 0, VK_WHOLE_SIZE, 0, &pointer),
                           (std::string("vkMapMemory for ") + name).c_str())))
        return reset(), s;
    allocation_.mapped = pointer;
    return Status::success();
}

void DeviceMemory::reset() {
    if (!gpu_) return;
    if (fromHost_) {
        gpu_->deviceMemory.free(gpu_->deviceMemory.userData, allocation_);
    } else {
        if (allocation_.mapped) gpu_->fn.vkUnmapMemory(gpu_->device, allocation_.memory);
        gpu_->fn.vkFreeMemory(gpu_->device, allocation_.memory, gpu_->allocator);
    }
    gpu_ = nullptr;
    allocation_ = {};
    bytes_ = 0;
    fromHost_ = false;
}

}  // namespace postfx::core
