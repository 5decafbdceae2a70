// postfx.copy (shaders/core/copy.comp): output = color, for a frame with a separate output image that no
// effect writes (docs/frame-plan.md). Its pipeline is created on first need.
#pragma once

#include <postfx/context.h>
#include <postfx/frame_plan.h>

#include "core/compute_pipeline.h"
#include "core/pass_timer.h"

namespace postfx::core {

class CopyPass {
public:
    // The pass as the frame plan lists it.
    static PlannedPass plan(const FrameInfo& frame);

    Status record(const Gpu& gpu, DescriptorArena& arena, PassTimer& timer, const FrameInfo& frame);

private:
    ComputePipeline pipelines_[2];  // [0: RGBA16F, 1: RGBA32F]
};

}  // namespace postfx::core
