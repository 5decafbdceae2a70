#include "fog/fog_settings.h"

#include "common/medium.h"
#include "common/reduced_resolution.h"
#include "core/checks.h"
#include "core/temporal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace postfx::fog {
namespace {

using core::checkRange;

Status bad(const std::string& field, const std::string& why) {
    return core::invalid(field + ": " + why);
}

std::string text(double v) {
    return core::numberText(v);
}

// The quality presets, the one place their values are written (docs/effects/fog.md#quality-presets).
struct QualityPreset {
    FogQuality quality;
    uint32_t steps;
    bool jitter;
    uint32_t shadowKernel;
    float resolutionScale;
    bool temporal;  // temporal.enabled: it pays at every preset (docs/accuracy-cost/README.md, "In motion")
    // Its relative RMSE against the reference after 16 frames, the mean over fog_default, fog_height,
    // fog_shadowed and fog_valley of the H100 run's preset= rows
    // (docs/accuracy-cost/h100-presets/results.csv; tests/frame/test_frame_fronts.cpp holds them equal):
    // what FrameInfo::budgetMs weighs.
    double error;
};
// FogSettings' defaults are Medium's values (tests/fog/test_fog_scene.cpp checks it), but temporal, off
// by default (a host that does not call record() every frame, or has its own temporal filter, opts in).
// Chosen by postfx-bench's rule from the H100 run in docs/accuracy-cost/h100/ (README.md there: timed on
// fog_default at 1920×1080, lowest 16-frame error averaged over the scenes within 0.25 / 0.5 / 1 / 2 ms),
// after issue 23's faster march; measured as presets in docs/accuracy-cost/h100-presets/.
constexpr QualityPreset kQualityPresets[] = {
    {FogQuality::Low, 64, true, 1, 0.5f, true, 0.005094},
    {FogQuality::Medium, 32, true, 1, 1.0f, true, 0.002829},
    {FogQuality::High, 128, true, 1, 1.0f, true, 0.000954},
    {FogQuality::Ultra, 256, true, 1, 1.0f, true, 0.000771},
};

}  // namespace

std::vector<double> qualityPresetErrors() {
    std::vector<double> out;
    for (const QualityPreset& p : kQualityPresets)
        out.push_back(p.error);
    return out;
}

Status validateSettings(const FogSettings& s) {
    if (uint32_t(s.quality) > uint32_t(FogQuality::Auto))
        return bad("fog.quality", std::to_string(uint32_t(s.quality)) +
                                      " is not a FogQuality (Custom, Low, Medium, High, Ultra or Auto)");
    if (s.steps < 1 || s.steps > 4096)
        return bad("fog.steps", std::to_string(s.steps) + " is outside [1, 4096]");
    if (Status r = checkRange("fog.resolution_scale", s.resolutionScale, 0.25, 1.0); !r) return r;
    if (!std::isfinite(s.autoBudgetMs)) return bad("fog.auto_budget_ms", "is not finite");
    if (s.autoBudgetMs <= 0.0f) return bad("fog.auto_budget_ms", text(s.autoBudgetMs) + " must be > 0");
    if (Status r = checkRange("fog.transmittance_cutoff", s.transmittanceCutoff, 0.0, 1.0); !r) return r;
    if (s.transmittanceCutoff >= 1.0f) return bad("fog.transmittance_cutoff", "must be < 1");
    if (s.shadowKernel < 1 || s.shadowKernel > 7 || s.shadowKernel % 2 == 0)
        return bad("fog.shadow_kernel", std::to_string(s.shadowKernel) + " must be odd, in [1, 7]");
    if (Status r = common::validateTemporal(s.temporal, "fog"); !r) return r;
    return common::validateMedium(s, "fog");
}

}  // namespace postfx::fog

namespace postfx {
Status validateFogSettings(const FogSettings& settings) {
    return fog::validateSettings(settings);
}

namespace fog {}  // namespace fog

UVec2 fogMarchExtent(uint32_t width, uint32_t height, float resolutionScale) {
    const glm::uvec2 e = common::reducedExtent(width, height, resolutionScale);
    return {e.x, e.y};
}

FogSettings applyFogQuality(const FogSettings& settings, FogQuality quality) {
    FogSettings s = settings;
    for (const fog::QualityPreset& p : fog::kQualityPresets)
        if (p.quality == quality) {
            s.steps = p.steps;
            s.jitter = p.jitter;
            s.shadowKernel = p.shadowKernel;
            s.resolutionScale = p.resolutionScale;
            s.temporal.enabled = p.temporal;
        }
    return s;
}
}  // namespace postfx
