#include "core/device_functions.h"

#include <string>

namespace postfx::core {

Status DeviceFunctions::load(VkInstance instance, PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                             VkDevice device, PFN_vkGetDeviceProcAddr getDeviceProcAddr) {
#define POSTFX_LOAD_INSTANCE(fn)                                         \
    fn = reinterpret_cast<PFN_##fn>(getInstanceProcAddr(instance, #fn)); \
    if (!fn) return {Result::Unsupported, "vkGetInstanceProcAddr returned null for " #fn};
#define POSTFX_LOAD_DEVICE(fn)                                       \
    fn = reinterpret_cast<PFN_##fn>(getDeviceProcAddr(device, #fn)); \
    if (!fn) return {Result::Unsupported, "vkGetDeviceProcAddr returned null for " #fn};
    POSTFX_INSTANCE_FUNCTIONS(POSTFX_LOAD_INSTANCE)
    POSTFX_DEVICE_FUNCTIONS(POSTFX_LOAD_DEVICE)
#undef POSTFX_LOAD_INSTANCE
#undef POSTFX_LOAD_DEVICE
    return Status::success();
}

Status DeviceFunctions::loadDebugLabels(VkInstance instance, PFN_vkGetInstanceProcAddr getInstanceProcAddr) {
    vkCmdBeginDebugUtilsLabelEXT = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        getInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    vkCmdEndDebugUtilsLabelEXT = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        getInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    if (vkCmdBeginDebugUtilsLabelEXT && vkCmdEndDebugUtilsLabelEXT) return Status::success();
    vkCmdBeginDebugUtilsLabelEXT = nullptr;
    vkCmdEndDebugUtilsLabelEXT = nullptr;
    return {
        Result::Unsupported,
        "ContextCreateInfo.debugLabels is set but vkGetInstanceProcAddr returned null for "
        "vkCmdBeginDebugUtilsLabelEXT or vkCmdEndDebugUtilsLabelEXT (is VK_EXT_debug_utils enabled on the "
        "instance?)"};
}

void beginLabel(const DeviceFunctions& fn, VkCommandBuffer cmd, const char* name) {
    if (!fn.vkCmdBeginDebugUtilsLabelEXT) return;
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name;
    fn.vkCmdBeginDebugUtilsLabelEXT(cmd, &label);
}

void endLabel(const DeviceFunctions& fn, VkCommandBuffer cmd) {
    if (fn.vkCmdEndDebugUtilsLabelEXT) fn.vkCmdEndDebugUtilsLabelEXT(cmd);
}

const char* vkResultName(VkResult result) {
    switch (result) {
#define POSTFX_CASE(r) \
    case r:            \
        return #r;
        POSTFX_CASE(VK_SUCCESS)
        POSTFX_CASE(VK_NOT_READY)
        POSTFX_CASE(VK_TIMEOUT)
        POSTFX_CASE(VK_INCOMPLETE)
        POSTFX_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        POSTFX_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        POSTFX_CASE(VK_ERROR_INITIALIZATION_FAILED)
        POSTFX_CASE(VK_ERROR_DEVICE_LOST)
        POSTFX_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        POSTFX_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        POSTFX_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        POSTFX_CASE(VK_ERROR_FRAGMENTED_POOL)
        POSTFX_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        POSTFX_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef POSTFX_CASE
        default:
            return "VkResult(unknown)";
    }
}

Status vulkanStatus(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return Status::success();
    Result code = Result::VulkanError;
    if (result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY)
        code = Result::OutOfMemory;
    return {code, std::string(what) + " failed: " + vkResultName(result) + " (" +
                      std::to_string(static_cast<int>(result)) + ")"};
}

}  // namespace postfx::core
