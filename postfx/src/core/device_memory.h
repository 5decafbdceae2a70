// The device memory of one postfx image or buffer: its own vkAllocateMemory, or a block from the host's
// DeviceMemoryCallbacks (ContextCreateInfo::deviceMemory), bound at the block's offset.
#pragma once

#include "core/gpu.h"

namespace postfx::core {

class DeviceMemory {
public:
    DeviceMemory() = default;
    DeviceMemory(DeviceMemory&& other) noexcept { *this = std::move(other); }
    DeviceMemory& operator=(DeviceMemory&& other) noexcept;
    ~DeviceMemory() { reset(); }

    // Memory for `req` of a type with every flag of `flags`; `mapped`: host-visible and mapped (postfx's
    // own: vkMapMemory; the host's: its pointer). `name` is the resource's, for messages.
    Status allocate(const Gpu& gpu, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags, bool mapped,
                    const char* name);
    // Frees it (unmapping postfx's own mapping); call after destroying what is bound to it.
    void reset();

    VkDeviceMemory memory() const { return allocation_.memory; }
    VkDeviceSize offset() const { return allocation_.offset; }
    void* mapped() const { return allocation_.mapped; }
    VkDeviceSize bytes() const { return bytes_; }  // VkMemoryRequirements::size asked for

private:
    const Gpu* gpu_ = nullptr;
    DeviceAllocation allocation_;
    VkDeviceSize bytes_ = 0;
    bool fromHost_ = false;  // from DeviceMemoryCallbacks: freed through them, never unmapped
};

}  // namespace postfx::core
