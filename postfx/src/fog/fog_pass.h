// The ray-marched fog as recorded into the host's command buffer: validation of its inputs, its part of
// the frame plan, the resources it owns (pipelines, uniform ring, samplers, noise texture, scatter image, a
// 1-texel noise stand-in when noise is off) and the barriers around the host's images.
#pragma once

#include <postfx/context.h>
#include <postfx/frame_plan.h>

#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"
#include "core/pass_timer.h"
#include "core/retirement.h"
#include "fog/fog_noise.h"

namespace postfx::fog {

class FogPass {
public:
    FogPass() = default;
    FogPass(const FogPass&) = delete;
    FogPass& operator=(const FogPass&) = delete;
    ~FogPass() { release(); }

    // Checks everything the fog reads in `frame` (settings, lighting, camera, shadow map); InvalidArgument
    // naming the field otherwise. Records nothing.
    static Status validate(const FrameInfo& frame);

    // Whether the fog records anything for `frame`: enabled, and a medium that is not empty everywhere
    // (density 0, noise multiplier 0 or threshold 1). Otherwise it has no pass, pipeline or memory.
    static bool runs(const FrameInfo& frame);

    // Appends the fog's passes and resources for `frame` (validated, quality resolved, runs()) to `plan`.
    // `existing` is the context's FogPass, null when none is held (then nothing is generated yet).
    static void plan(const FrameInfo& frame, const FogPass* existing, uint32_t framesInFlight,
                     FramePlan& plan);

    // Records the fog for `frame` (validated, runs()) as plan() lists it. Creates resources on first need;
    // a noise texture no longer needed (size changed, noise off) goes to `retirement`.
    Status record(const core::Gpu& gpu, const ContextCreateInfo& info, core::DescriptorArena& arena,
                  core::PassTimer& timer, core::Retirement& retirement, const FrameInfo& frame);

    void release();  // frees every GPU object it holds (callers retire the FogPass instead while in use)

    const FogNoise* noise() const { return noise_.get(); }  // null when no noise texture is held

private:
    // The fog's compute shaders; each has an RGBA16F and an RGBA32F variant (the color format).
    enum class Kernel { Raymarch, RaymarchReduced, Upsample };
    Status createResources(const core::Gpu& gpu, const ContextCreateInfo& info);
    // The pipeline of `kernel` for `colorFormat`, created on first use.
    Status pipeline(Kernel kernel, VkFormat colorFormat, core::ComputePipeline*& out);
    // Makes sure scatter_ is a `format` image of `extent`; an old one goes to `retirement`.
    Status prepareScatter(core::Retirement& retirement, uint64_t frameIndex, VkFormat format,
                          VkExtent3D extent);

    const core::Gpu* gpu_ = nullptr;
    core::ComputePipeline pipelines_[3][2];    // [Kernel][0: RGBA16F, 1: RGBA32F]
    std::unique_ptr<core::GpuImage> scatter_;  // reduced resolution only
    core::GpuBuffer uniforms_;  // one kUniformSlotBytes slot per frame in flight, persistently mapped
    uint32_t slots_ = 0;
    VkSampler nearestClamp_ = VK_NULL_HANDLE;
    VkSampler linearRepeat_ = VK_NULL_HANDLE;
    // 1×1×1 stand-in bound when noise is off (never sampled: the flags skip it); created on first need.
    std::unique_ptr<core::GpuImage> noNoise_;
    bool noNoiseReady_ = false;
    std::unique_ptr<FogNoise> noise_;
};

}  // namespace postfx::fog
