// A test interposer between postfx and the host's Vulkan: postfx gets, through the wrapped
// vkGetInstanceProcAddr / vkGetDeviceProcAddr of ContextCreateInfo, one wrapper per entry point of
// postfx/src/core/device_functions.h's lists. The wrappers count every object created and destroyed by
// kind, count the commands recorded, and can make the Nth fallible call (one returning VkResult with an
// error code the specification lists for that command) fail.
//
// On an injected failure a creating call writes a poison handle into its output (the specification leaves
// outputs undefined on failure, except for pipelines and descriptor sets, which it sets to null), so code
// that destroys or uses what a failed call "returned" is caught: a destroy of a handle the interposer
// never saw is recorded in errors() and not passed on.
#pragma once

#include <postfx/context.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace test {

enum class VkObjectKind : uint8_t {
    Buffer,
    Image,
    ImageView,
    Sampler,
    DeviceMemory,
    MemoryMapping,
    ShaderModule,
    DescriptorSetLayout,
    PipelineLayout,
    Pipeline,
    DescriptorPool,
    QueryPool,
    Count
};
const char* objectKindName(VkObjectKind kind);

struct InjectedFault {
    bool fired = false;
    uint64_t ordinal = 0;  // N: the fallible call's index since arm()
    std::string call;      // "vkCreateImage"
    VkResult result = VK_SUCCESS;
};

class VulkanInterposer {
public:
    // Installs the interposer over the host's loader entry points (one at a time: the wrappers are plain
    // functions, so their state is global). Uninstalls when destroyed.
    VulkanInterposer(PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                     PFN_vkGetDeviceProcAddr getDeviceProcAddr);
    ~VulkanInterposer();
    VulkanInterposer(const VulkanInterposer&) = delete;
    VulkanInterposer& operator=(const VulkanInterposer&) = delete;

    // `info` with the interposer's vkGetInstanceProcAddr / vkGetDeviceProcAddr.
    postfx::ContextCreateInfo wrap(postfx::ContextCreateInfo info) const;

    // Restarts counting fallible calls; the one with index `n` (0 = the next) fails, once.
    void arm(uint64_t n);
    void disarm();  // no further call fails; fault() still tells what failed
    const InjectedFault& fault() const;
    uint64_t fallibleCalls() const;  // since arm()

    uint64_t live(VkObjectKind kind) const;
    uint64_t created(VkObjectKind kind) const;  // since construction
    uint64_t pipelinesWithCache() const;  // pipelines created with a VkPipelineCache, since construction
    uint64_t liveTotal() const;           // every kind but mappings
    uint64_t peakLiveTotal() const;       // since resetPeak()
    void resetPeak();
    std::string liveSummary() const;  // "Image 2, ImageView 2, ..." (kinds with live objects)
    uint64_t commands() const;        // vkCmd* calls recorded through the interposer
    // Misuse seen: destroying or unmapping what was never created or mapped, and the like.
    const std::vector<std::string>& errors() const;
};

}  // namespace test
