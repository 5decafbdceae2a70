// Context::prewarm: every pipeline frames with the given settings may record, found by declaring the
// frame once per variant of what changes between such frames (the presets quality Auto cycles through, a
// camera cut, the sun lit or dark, each effect's own variants), and created ahead of record().
#include "core/context_impl.h"

#include <algorithm>
#include <string>

namespace postfx {
namespace {

using PipelineUse = core::FrameGraph::PipelineUse;

// The pipelines of every pass `frame` declares, recorded this frame or not (a persistent image's build
// runs only in the frames that rebuild it), added to `uses` once each.
Status collect(const Context::Impl& impl, const FrameInfo& frame, core::AutoQuality& autoQuality,
               std::vector<PipelineUse>& uses) {
    FrameInfo resolved;
    core::Frame declared;
    if (Status s = impl.prepareFrame(frame, autoQuality, resolved, impl.planScratch, declared, nullptr); !s)
        return s;
    for (const core::PassDecl& p : declared.passes) {
        if (p.transfer != core::TransferOp::None) continue;  // a blit or a copy: no pipeline
        const PipelineUse use{p.pipeline, p.constants, p.effect};
        if (std::find(uses.begin(), uses.end(), use) == uses.end()) uses.push_back(use);
    }
    return Status::success();
}

// `frame` with the sun lit when it is dark and dark when it is lit (an effect may read the shadow map only
// while the sun gives light), within the pre-exposed illuminance's range.
FrameInfo sunToggled(const FrameInfo& frame) {
    FrameInfo v = frame;
    const Vec3 e = frame.sun.illuminance;
    const bool lit = e.r > 0.0f || e.g > 0.0f || e.b > 0.0f;
    v.sun.illuminance = Vec3(lit ? 0.0f : float(std::min(1.0, 1e6 / double(frame.preExposure))));
    return v;
}

}  // namespace

Status Context::prewarm(const FrameInfo& frame) {
    Impl& impl = *impl_;
    core::AutoQuality autoQuality = impl.autoQuality;  // a copy: nothing is measured or chosen for real
    std::vector<PipelineUse> uses;
    // The frame as given, checked as plan() checks it.
    if (Status s = collect(impl, frame, autoQuality, uses); !s) return s;

    // Every combination of presets of the effects on Auto (alone or under one budget for the frame).
    std::vector<size_t> autoEffects;
    for (size_t e = 0; e < impl.effects.size(); ++e) {
        const core::Effect& effect = *impl.effects[e];
        if (effect.active(frame) && effect.presetCount() > 0 &&
            effect.quality(frame).kind == core::QualityRequest::Kind::Auto)
            autoEffects.push_back(e);
    }
    std::vector<uint32_t> preset(autoEffects.size(), 0);
    for (bool more = true; more;) {
        FrameInfo base = frame;
        base.budgetMs = 0.0f;  // the presets are set: nothing left to choose
        std::string name = "prewarm";
        for (size_t i = 0; i < autoEffects.size(); ++i) {
            const core::Effect& effect = *impl.effects[autoEffects[i]];
            effect.applyPreset(base, preset[i]);
            name += std::string(i ? ", " : " (") + effect.name() + " preset " + std::to_string(preset[i]);
        }
        name += autoEffects.empty() ? ": " : "): ";
        // A camera cut (histories dropped) and a continued view; the sun lit and dark.
        for (int variant = 0; variant < 4; ++variant) {
            FrameInfo v = variant & 2 ? sunToggled(base) : base;
            v.cameraCut = variant & 1 ? !frame.cameraCut : frame.cameraCut;
            core::PrewarmVariants extra;
            extra.frames.push_back(v);
            for (const auto& effect : impl.effects)
                if (effect->active(v)) effect->prewarmVariants(v, extra);
            for (const FrameInfo& f : extra.frames)
                if (Status s = collect(impl, f, autoQuality, uses); !s) return {s.code, name + s.message};
        }
        // The next combination (the first effect's preset fastest).
        more = false;
        for (size_t i = 0; i < autoEffects.size() && !more; ++i) {
            more = ++preset[i] < impl.effects[autoEffects[i]]->presetCount();
            if (!more) preset[i] = 0;
        }
    }
    return impl.graph.prewarm(uses);
}

}  // namespace postfx
