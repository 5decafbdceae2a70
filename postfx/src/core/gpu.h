// The device postfx borrows, as every internal helper sees it.
#pragma once

#include "core/device_functions.h"

#include <postfx/context.h>

namespace postfx::core {

struct Gpu {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator = nullptr;
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;  // the host's, for every pipeline (or none)
    DeviceMemoryCallbacks deviceMemory;              // the host's allocator (both null: postfx's own)
    DeviceFunctions fn;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};

    // Loads the function table and queries the physical device from the host's handles.
    Status init(const ContextCreateInfo& info);

    // Index of a memory type allowed by `typeBits` with all of `required` flags.
    Status findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required, uint32_t& index) const;
};

}  // namespace postfx::core
