// What a postfx::Context holds. Effects reach the device, the per-frame descriptor sets and the pass
// timer through it.
#pragma once

#include <postfx/context.h>

#include "core/compute_pipeline.h"
#include "core/copy_pass.h"
#include "core/gpu.h"
#include "core/pass_timer.h"
#include "core/retirement.h"
#include "fog/fog_auto_quality.h"
#include "fog/fog_pass.h"

#include <memory>
#include <vector>

namespace postfx {

struct Context::Impl {
    ContextCreateInfo info;
    core::Gpu gpu;
    core::PassTimer timer;
    std::vector<std::unique_ptr<core::DescriptorArena>> arenas;  // one per frame in flight
    std::unique_ptr<fog::FogPass> fog;                           // null while the fog is off
    fog::AutoQuality fogAutoQuality;                             // FogQuality::Auto's measurements
    core::CopyPass copy;  // postfx.copy: its pipeline is created on first need and kept
    bool warnedAutoWithoutTimings = false;
    core::Retirement retirement;  // objects frames in flight may still use; declared last, freed first

    // Sends a failed status to the host's message callback and returns it unchanged.
    Status report(Status status) const;
    // Everything record() checks in `frame` (quality resolved) but the command buffer.
    Status validateFrame(const FrameInfo& frame) const;
    // The plan of `frame` (validated, quality resolved) given what the context holds now. record() takes
    // the same decisions (FogPass::runs and the fog's own, needsCopy) without building it.
    void buildPlan(const FrameInfo& frame, FramePlan& plan) const;
    void warn(const std::string& message) const;

    core::DescriptorArena& arena(uint64_t frameIndex) { return *arenas[frameIndex % arenas.size()]; }
};

}  // namespace postfx
