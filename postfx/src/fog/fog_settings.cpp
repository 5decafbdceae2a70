#include "fog/fog_settings.h"

#include "common/medium.h"
#include "common/reduced_resolution.h"
#include "core/checks.h"
#include "core/settings_check.h"
#include "core/temporal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace postfx::fog {
namespace {

Status bad(const std::string& field, const std::string& why) {
    return core::invalid(field + ": " + why);
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
    const std::string p = "FrameInfo.fog";
    if (Status r = core::checkSettings(fogSettingsTable(), &s, p); !r) return r;
    if (s.shadowKernel < 1 || s.shadowKernel > 7 || s.shadowKernel % 2 == 0)
        return bad(p + ".shadowKernel", std::to_string(s.shadowKernel) + " must be odd, in [1, 7]");
    return common::checkMediumRules(s, p);
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
