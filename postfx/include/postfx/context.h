// The postfx context: one per VkDevice, created from handles the host lends.
//
// Lifecycle (as AMD FidelityFX): Context::create once, Context::record once per frame into the host's
// command buffer, destroy (the unique_ptr) after the host has waited for the device to go idle.
// postfx loads every device-level function through the host's vkGetDeviceProcAddr and every
// instance-level function through the host's vkGetInstanceProcAddr; it links no Vulkan loader.
#pragma once

#include <postfx/fog.h>
#include <postfx/frame_plan.h>
#include <postfx/result.h>
#include <postfx/types.h>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace postfx {

struct ContextCreateInfo {
    // Borrowed handles; the host keeps ownership and must outlive the context.
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;  // for physical-device queries
    PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;      // every device call goes through this
    uint32_t queueFamilyIndex = 0;  // family of the queue that will execute recorded command buffers;
                                    // must support compute
    const VkAllocationCallbacks* allocator = nullptr;  // optional, used for every Vulkan object

    VkExtent2D maxExtent = {3840, 2160};  // largest color/depth extent that record() accepts [pixels]
    DepthConvention depth;
    uint32_t framesInFlight = 2;  // frames the host may record before waiting on the oldest, 1..8
    bool gpuTimings = true;       // write timestamp queries around each pass (see readPassTimings)

    MessageCallback messageCallback = nullptr;  // optional
    void* messageUserData = nullptr;
};

// Everything postfx needs for one frame.
struct FrameInfo {
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;  // recording, outside a render pass
    uint64_t frameIndex = 0;  // increases by one per frame; selects per-frame resources and noise seeds

    // HDR scene color, linear radiance [W/(sr·m²) or cd/m², the host's choice, used consistently].
    // Formats: R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, usage STORAGE. Effects composite into it.
    ImageInput color;
    // Scene depth, D32_SFLOAT / D16_UNORM / D24_UNORM_S8_UINT / X8_D24_UNORM_PACK32, usage SAMPLED,
    // same extent as color, in the context's DepthConvention.
    ImageInput depth;
    // Optional: when present, the result goes here (same extent, a color format, usage STORAGE) and
    // `color` is only read. When absent, effects composite into `color` in place.
    ImageInput output;

    double timeSeconds = 0.0;  // host time [s], moves the noise with the wind; finite
    CameraInput camera;
    SunInput sun;
    glm::vec3 ambient{0.0f};  // uniform incident radiance for ambient in-scattering; each >= 0
    ShadowMapInput shadowMap;

    FogSettings fog;  // ray-marched fog (docs/effects/fog.md); off by default
};

// GPU time of one postfx pass in one frame.
struct PassTiming {
    std::string name;  // "fog.raymarch" (effect.pass)
    double milliseconds = 0.0;
};

class Context {
public:
    // Creates a context; on failure `out` stays empty and the status names the problem.
    static Status create(const ContextCreateInfo& info, std::unique_ptr<Context>& out);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Records this frame's passes into frame.commandBuffer. The host must have waited until the
    // frame recorded framesInFlight frames ago has completed on the GPU.
    Status record(const FrameInfo& frame);

    // What record(frame) would record now (docs/frame-plan.md): its passes in order, with what each reads
    // and writes, and every resource postfx would hold afterwards with its size. Checks `frame` like
    // record() (its command buffer may be null); records nothing, creates nothing. An effect that is off,
    // or whose medium is empty, has no pass and no resource; a separate output image that no effect
    // writes gets postfx.copy. Work on slow inputs (fog.noise) is listed only in the frame that redoes it.
    // With fog quality Auto: the preset record() would use now (still measuring: the one whose turn it is).
    Status plan(const FrameInfo& frame, FramePlan& out) const;

    // Timings of the passes recorded for `frameIndex`. Returns NotReady while the GPU has not finished
    // that frame, InvalidArgument if that frame's queries were overwritten by a newer frame (more than
    // framesInFlight ago) or were never written. Does not wait.
    Status readPassTimings(uint64_t frameIndex, std::vector<PassTiming>& out) const;

    // The preset FogQuality::Auto chose for the last recorded frame's (color extent, noise on, shadow map
    // present): NotReady while that key's presets are still being measured (or no Auto frame has been
    // recorded). Medium when GPU timings are off.
    Status fogAutoQuality(FogQuality& chosen) const;

    // Auto's measurements, for a host that keeps them between runs, as engines keep the result of their
    // quality auto-detection: every key measured so far (all four presets) or given. Key them by device,
    // driver and postfx version where they are stored: the presets' cost depends on all three.
    std::vector<FogAutoTimings> fogAutoTimings() const;
    // Adds `timings` to Auto's cache (replacing keys it has), so frames with those keys choose from the
    // first frame instead of measuring. InvalidArgument naming the entry for a zero extent or a time that
    // is negative or not finite; then nothing is added.
    Status setFogAutoTimings(const std::vector<FogAutoTimings>& timings);

    // Records a copy of the fog's generated noise texture (R8, size³ bytes, x fastest, then y, then z)
    // into `buffer` at `offset` (usage TRANSFER_DST); the host submits and reads it, e.g. to give the
    // CPU reference the same noise data. `size` receives the texture's edge. InvalidArgument when no
    // texture has been generated (fog with generated noise has not been recorded yet).
    Status recordFogNoiseReadback(VkCommandBuffer commandBuffer, VkBuffer buffer, VkDeviceSize offset,
                                  uint32_t& size) const;

    // The fog's generated noise texture (3D, R8_UNORM, repeat-tileable), for hosts that want to sample the
    // same noise: in SHADER_READ_ONLY_OPTIMAL once the frame that generated it has executed.
    // VK_NULL_HANDLE when none is held (fog or generated noise off).
    VkImageView fogNoiseView() const;

    const ContextCreateInfo& createInfo() const;

    struct Impl;  // internal; defined in postfx/src/core

private:
    explicit Context(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace postfx
