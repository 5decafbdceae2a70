// Vulkan entry points postfx uses, loaded from the host's vkGetInstanceProcAddr / vkGetDeviceProcAddr.
// postfx is compiled with VK_NO_PROTOTYPES: no call can bypass this table.
#pragma once

#include <postfx/result.h>
#include <vulkan/vulkan.h>

namespace postfx::core {

#define POSTFX_INSTANCE_FUNCTIONS(X)            \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetPhysicalDeviceFormatProperties)

#define POSTFX_DEVICE_FUNCTIONS(X)   \
    X(vkCreateBuffer)                \
    X(vkDestroyBuffer)               \
    X(vkCreateImage)                 \
    X(vkDestroyImage)                \
    X(vkCreateImageView)             \
    X(vkDestroyImageView)            \
    X(vkCreateSampler)               \
    X(vkDestroySampler)              \
    X(vkGetBufferMemoryRequirements) \
    X(vkGetImageMemoryRequirements)  \
    X(vkAllocateMemory)              \
    X(vkFreeMemory)                  \
    X(vkBindBufferMemory)            \
    X(vkBindImageMemory)             \
    X(vkMapMemory)                   \
    X(vkUnmapMemory)                 \
    X(vkCreateShaderModule)          \
    X(vkDestroyShaderModule)         \
    X(vkCreateDescriptorSetLayout)   \
    X(vkDestroyDescriptorSetLayout)  \
    X(vkCreatePipelineLayout)        \
    X(vkDestroyPipelineLayout)       \
    X(vkCreateComputePipelines)      \
    X(vkDestroyPipeline)             \
    X(vkCreateDescriptorPool)        \
    X(vkDestroyDescriptorPool)       \
    X(vkResetDescriptorPool)         \
    X(vkAllocateDescriptorSets)      \
    X(vkUpdateDescriptorSets)        \
    X(vkCreateQueryPool)             \
    X(vkDestroyQueryPool)            \
    X(vkGetQueryPoolResults)         \
    X(vkCmdResetQueryPool)           \
    X(vkCmdWriteTimestamp)           \
    X(vkCmdBindPipeline)             \
    X(vkCmdBindDescriptorSets)       \
    X(vkCmdPushConstants)            \
    X(vkCmdDispatch)                 \
    X(vkCmdPipelineBarrier)          \
    X(vkCmdCopyBufferToImage)        \
    X(vkCmdCopyImageToBuffer)        \
    X(vkCmdBlitImage)                \
    X(vkCmdCopyImage)                \
    X(vkCmdFillBuffer)

struct DeviceFunctions {
#define POSTFX_DECLARE(name) PFN_##name name = nullptr;
    POSTFX_INSTANCE_FUNCTIONS(POSTFX_DECLARE)
    POSTFX_DEVICE_FUNCTIONS(POSTFX_DECLARE)
#undef POSTFX_DECLARE

    // VK_EXT_debug_utils' labels: loaded only when the host enabled the extension
    // (ContextCreateInfo::debugLabels), else null and never called.
    PFN_vkCmdBeginDebugUtilsLabelEXT vkCmdBeginDebugUtilsLabelEXT = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT vkCmdEndDebugUtilsLabelEXT = nullptr;

    // Loads every entry point; names the first one missing.
    Status load(VkInstance instance, PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkDevice device,
                PFN_vkGetDeviceProcAddr getDeviceProcAddr);
    // Loads the debug-utils label commands (instance extension commands, through vkGetInstanceProcAddr).
    Status loadDebugLabels(VkInstance instance, PFN_vkGetInstanceProcAddr getInstanceProcAddr);
};

// A debug-utils label around commands; does nothing when the label commands are not loaded.
void beginLabel(const DeviceFunctions& fn, VkCommandBuffer cmd, const char* name);
void endLabel(const DeviceFunctions& fn, VkCommandBuffer cmd);

// "vkCreateImage failed: VK_ERROR_OUT_OF_DEVICE_MEMORY" as a Status (Success for VK_SUCCESS).
Status vulkanStatus(VkResult result, const char* what);
const char* vkResultName(VkResult result);

}  // namespace postfx::core
