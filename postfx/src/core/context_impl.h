// What a postfx::Context holds: the borrowed device, the registered effects, the frame graph with the
// resources it holds between frames, quality Auto, the pass timer and the per-frame descriptor sets.
// Nothing here knows an effect by name.
#pragma once

#include <postfx/context.h>

#include "core/auto_quality.h"
#include "core/compute_pipeline.h"
#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"
#include "core/pass_timer.h"
#include "core/retirement.h"
#include "core/world_frame.h"

#include <memory>
#include <vector>

namespace postfx {

struct POSTFX_INTERNAL Context::Impl {
    ContextCreateInfo info;
    core::Gpu gpu;
    core::PassTimer timer;
    std::vector<std::unique_ptr<core::DescriptorArena>> arenas;  // one per frame in flight
    std::vector<std::unique_ptr<core::Effect>> effects;          // in composite order
    core::AutoQuality autoQuality;
    core::FrameGraph graph;
    core::Frame frame;           // record()'s declarations, reused from frame to frame
    FrameInfo resolved;          // record()'s frame with presets applied, in postfx's world frame
    core::WorldTransform world;  // ContextCreateInfo::world
    // The converted frames' arrays (lights, shadows, an effect's), record()'s and plan()'s apart: a plan()
    // between two record()s leaves record()'s frame as it was.
    core::WorldScratch recordScratch;
    mutable core::WorldScratch planScratch;
    bool warnedAutoWithoutTimings = false;
    std::vector<std::string> adjusted;  // the last recorded frame's FramePlan::adjusted lines
    // The last recorded frame's volumetrics lookup (Context::volumetricsLookup).
    bool lookupRecorded = false;
    uint64_t lookupFrame = 0;
    core::Retirement retirement;  // objects frames in flight may still use; declared last, freed first

    // Adds an effect after the registered ones (tests add test-only effects; call before recording).
    void addEffect(std::unique_ptr<core::Effect> effect);

    void warn(const std::string& message) const;
    // FramePlan::adjusted of `resolved` (prepareFrame's): each active effect's lines, in composite order.
    std::vector<std::string> adjustedInputs(const FrameInfo& resolved) const;

    // `frame` checked, each active effect's preset chosen (Auto: by `autoQuality`) and applied into
    // `resolved`, converted into postfx's world frame (its arrays into `scratch`), and the frame declared
    // and compiled into `out`. `measuring` receives, per effect, the
    // Auto key and preset to report after recording (preset ~0u: none).
    struct AutoUse {
        core::AutoQualityKey key;
        uint32_t preset = ~0u;
    };
    Status prepareFrame(const FrameInfo& frame, core::AutoQuality& autoQuality, FrameInfo& resolved,
                        core::WorldScratch& scratch, core::Frame& out, std::vector<AutoUse>* measuring) const;

    core::DescriptorArena& arena(uint64_t frameIndex) { return *arenas[frameIndex % arenas.size()]; }
    int effectIndex(std::string_view name) const;

    // Quality Auto's timings measured here: this library's version, this device and driver.
    TimingsOrigin timingsOrigin() const;
    // Empty when timings of `origin` hold here (0 device fields: any); otherwise what differs, in words.
    std::string otherOrigin(const TimingsOrigin& origin) const;
};

// The context's internals, for postfx's own code and tests (e.g. adding a test-only effect).
struct POSTFX_INTERNAL ContextAccess {
    static Context::Impl& of(Context& context) { return *context.impl_; }
};

}  // namespace postfx
