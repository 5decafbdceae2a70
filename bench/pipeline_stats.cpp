#include "pipeline_stats.h"

#include "core/compute_pipeline.h"
#include "core/gpu.h"
#include "fog/fog_effect.h"
#include "host/vulkan_host.h"

#include <vulkan/vulkan.h>

#include <cinttypes>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace bench {
namespace {

// One VkInstance and VkDevice with VK_KHR_pipeline_executable_properties, destroyed on scope exit.
struct StatsDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t family = 0;
    ~StatsDevice() {
        if (device) vkDestroyDevice(device, nullptr);
        if (instance) vkDestroyInstance(instance, nullptr);
    }
};

std::string error(const char* what, VkResult r) {
    return std::string(what) + " failed (VkResult " + std::to_string(int(r)) + ")";
}

bool createDevice(StatsDevice& d, std::string& message) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "postfx-bench --pipeline-stats";
    app.apiVersion = VK_API_VERSION_1_2;
    VkInstanceCreateInfo ii{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ii.pApplicationInfo = &app;
    if (VkResult r = vkCreateInstance(&ii, nullptr, &d.instance); r != VK_SUCCESS)
        return message = error("vkCreateInstance", r), false;
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(d.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(d.instance, &count, devices.data());
    for (VkPhysicalDevice p : devices)
        if (demo::hasDeviceExtension(p, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
            d.physical = p;
            break;
        }
    if (!d.physical) return message = "no device offers VK_KHR_pipeline_executable_properties", false;
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &families, props.data());
    while (d.family < families && !(props[d.family].queueFlags & VK_QUEUE_COMPUTE_BIT))
        ++d.family;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qi.queueFamilyIndex = d.family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    executable.pipelineExecutableInfo = VK_TRUE;
    const char* extension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    di.pNext = &executable;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    di.enabledExtensionCount = 1;
    di.ppEnabledExtensionNames = &extension;
    if (VkResult r = vkCreateDevice(d.physical, &di, nullptr, &d.device); r != VK_SUCCESS)
        return message = error("vkCreateDevice", r), false;
    return true;
}

std::string statisticText(const VkPipelineExecutableStatisticKHR& s) {
    char b[64];
    switch (s.format) {
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
            return s.value.b32 ? "true" : "false";
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
            std::snprintf(b, sizeof b, "%" PRId64, s.value.i64);
            return b;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
            std::snprintf(b, sizeof b, "%" PRIu64, s.value.u64);
            return b;
        default:
            std::snprintf(b, sizeof b, "%g", s.value.f64);
            return b;
    }
}

}  // namespace

int runPipelineStats() {
    StatsDevice d;
    std::string message;
    if (!createDevice(d, message)) {
        std::fprintf(stderr, "postfx-bench --pipeline-stats: %s\n", message.c_str());
        return 1;
    }
    postfx::ContextCreateInfo info;
    info.instance = d.instance;
    info.physicalDevice = d.physical;
    info.device = d.device;
    info.queueFamilyIndex = d.family;
    info.getInstanceProcAddr = vkGetInstanceProcAddr;
    info.getDeviceProcAddr = vkGetDeviceProcAddr;
    postfx::core::Gpu gpu;
    if (postfx::Status s = gpu.init(info); !s) {
        std::fprintf(stderr, "postfx-bench --pipeline-stats: %s\n", s.message.c_str());
        return 1;
    }
    auto getProperties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
        vkGetDeviceProcAddr(d.device, "vkGetPipelineExecutablePropertiesKHR"));
    auto getStatistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
        vkGetDeviceProcAddr(d.device, "vkGetPipelineExecutableStatisticsKHR"));
    if (!getProperties || !getStatistics) {
        std::fprintf(stderr, "postfx-bench --pipeline-stats: the extension's functions are missing\n");
        return 1;
    }
    std::printf("device: %s\n", gpu.properties.deviceName);
    // Each march pipeline as postfx creates it for fog_default at Medium (flags: jitter, noise, shadow
    // map, analytic tail, empty-space skipping; shadow kernel 1), and without its specialization
    // constants (every flag read from the uniforms).
    namespace fogGpu = postfx::gpu;
    postfx::core::PipelineConstants medium;
    medium.values[fogGpu::kFogConstantFlags] = fogGpu::kFogFlagJitter | fogGpu::kFogFlagNoise |
                                               fogGpu::kFogFlagShadowMap | fogGpu::kFogFlagAnalyticTail |
                                               fogGpu::kFogFlagSkipEmptySpace;
    medium.values[fogGpu::kFogConstantShadowRadius] = 0;
    medium.count = 2;
    const std::pair<const char*, postfx::core::PipelineConstants> specializations[] = {
        {"specialized for fog_default, Medium", medium}, {"flags from the uniforms", {}}};
    for (const auto& [specialization, constants] : specializations)
        for (const auto& [variant, desc] : postfx::fog::marchPipelines()) {
            postfx::core::ComputePipeline pipeline;
            if (postfx::Status s =
                    pipeline.create(gpu, *desc, VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR, constants);
                !s) {
                std::fprintf(stderr, "postfx-bench --pipeline-stats: %s\n", s.message.c_str());
                return 1;
            }
            VkPipelineInfoKHR pi{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
            pi.pipeline = pipeline.handle();
            uint32_t executables = 0;
            getProperties(d.device, &pi, &executables, nullptr);
            std::vector<VkPipelineExecutablePropertiesKHR> props(
                executables, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
            getProperties(d.device, &pi, &executables, props.data());
            for (uint32_t e = 0; e < executables; ++e) {
                std::printf("%s (%s, RGBA16F, %s) executable %u: %s (subgroup %u)\n", desc->name, variant,
                            specialization, e, props[e].name, props[e].subgroupSize);
                VkPipelineExecutableInfoKHR ei{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
                ei.pipeline = pipeline.handle();
                ei.executableIndex = e;
                uint32_t count = 0;
                getStatistics(d.device, &ei, &count, nullptr);
                std::vector<VkPipelineExecutableStatisticKHR> stats(
                    count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
                getStatistics(d.device, &ei, &count, stats.data());
                for (const VkPipelineExecutableStatisticKHR& s : stats)
                    std::printf("  %-32s %12s  %s\n", s.name, statisticText(s).c_str(), s.description);
            }
        }
    return 0;
}

}  // namespace bench
