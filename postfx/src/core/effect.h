// One effect behind the context's boundary (docs/architecture.md, "Effects"). The context holds one
// instance of each registered effect (postfx/src/effects.cpp, in composite order) and asks it, every
// frame, for its settings' checks, its quality presets and its declaration: the resources and passes
// it needs for the frame (core/frame_graph.h). The context derives the frame plan, the barriers and the
// recorded commands from those declarations; an effect records nothing itself.
#pragma once

#include <postfx/context.h>

#include <cstdint>
#include <string>
#include <vector>

namespace postfx::core {

class FrameBuilder;
class WorldScratch;
class WorldTransform;

// Frames an effect adds to Context::prewarm's (Effect::prewarmVariants): `frames`, whose pointers may
// point into `lights` (each inner vector keeps its storage when `lights` grows).
struct PrewarmVariants {
    std::vector<FrameInfo> frames;
    std::vector<std::vector<LocalLight>> lights;
};

// How the frame asks an effect's quality to be chosen.
struct QualityRequest {
    enum class Kind { Custom, Preset, Auto };
    Kind kind = Kind::Custom;  // Custom: the settings as given
    uint32_t preset = 0;       // Preset: its index, 0 = lowest
    float budgetMs = 0.0f;     // Auto: GPU time budget of the effect's passes [ms]
};

class Effect {
public:
    virtual ~Effect() = default;

    // "fog": the prefix of its passes and resources in the frame plan and the timings.
    virtual const char* name() const = 0;

    // Checks the effect's settings in `frame` (the shared inputs are already checked); InvalidArgument
    // naming the field. Called every frame, whether or not the effect runs.
    virtual Status validate(const FrameInfo& frame) const = 0;

    // Whether the effect has work in `frame` (enabled, and not empty). An effect that is not active
    // declares nothing, so it holds nothing.
    virtual bool active(const FrameInfo& frame) const = 0;

    // Quality presets (core/auto_quality.h), lowest first; none by default.
    virtual uint32_t presetCount() const { return 0; }
    virtual QualityRequest quality(const FrameInfo& /*frame*/) const { return {}; }
    // Sets the knobs preset `preset` sets in `frame`'s copy of the effect's settings.
    virtual void applyPreset(FrameInfo& /*frame*/, uint32_t /*preset*/) const {}
    // Each preset's error on the effect's committed accuracy–cost front (relative RMSE against its double
    // reference, a fraction), lowest first: what one budget for the frame (FrameInfo::budgetMs) weighs.
    virtual std::vector<double> presetErrors() const { return {}; }
    // The preset Auto uses when the context has no GPU timings.
    virtual uint32_t fallbackPreset() const { return 0; }
    // Bits of `frame` besides the color extent that change the presets' cost; Auto measures each
    // combination separately.
    virtual uint32_t autoFeatures(const FrameInfo& /*frame*/) const { return 0; }

    // Converts the world-space fields of the effect's own settings in `frame` (checked, still in the host's
    // world frame) into postfx's (core/world_frame.h): positions, sizes and directions of what it places in
    // the world; an array they point to is copied into `scratch` first. Media properties stay as they are.
    // Called for every effect, once per record() and plan(), when the host's frame is not postfx's.
    virtual void toPostfxFrame(const WorldTransform& /*world*/, FrameInfo& /*frame*/,
                               WorldScratch& /*scratch*/) const {}

    // Declares the frame's resources and passes into `builder` (frame validated, preset applied, the
    // effect active). Must not create GPU objects or change the effect: plan() calls it too.
    virtual Status declare(FrameBuilder& builder) const = 0;

    // Context::prewarm: frames with `frame`'s settings whose passes may use other pipelines than its own,
    // through what changes between frames without a change of settings, besides what the context varies
    // itself (presets on Auto, camera cuts, the sun lit or dark). Appends to `out`; none by default.
    virtual void prewarmVariants(const FrameInfo& /*frame*/, PrewarmVariants& /*out*/) const {}

    // Inputs of `frame` (validated, in postfx's frame, the effect active) that the effect uses other than
    // as given, where its documentation says so rather than refusing them (a camera below the ground drawn
    // from the ground): one line each, naming the field, appended to `out` (FramePlan::adjusted).
    virtual void adjusted(const FrameInfo& /*frame*/, std::vector<std::string>& /*out*/) const {}

    // Called once record() has recorded `frame` (validated, presets applied), for every effect, whether
    // `active` or not: an effect with a temporal history moves its state on (core/temporal.h). plan()
    // never calls it.
    virtual void recorded(const FrameInfo& /*frame*/, bool /*active*/) {}
};

}  // namespace postfx::core
