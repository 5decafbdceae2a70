// FogSettings' table (postfx/settings_table.h): the ray-marched fog's own settings, the temporal
// accumulation's and the shared medium's (common/medium_table.h).
#include "common/medium_table.h"
#include "fog/fog_settings.h"

namespace postfx {
namespace {

constexpr SettingChoice kQualityChoices[] = {
    {"custom", "Custom", uint32_t(FogQuality::Custom)}, {"low", "Low", uint32_t(FogQuality::Low)},
    {"medium", "Medium", uint32_t(FogQuality::Medium)}, {"high", "High", uint32_t(FogQuality::High)},
    {"ultra", "Ultra", uint32_t(FogQuality::Ultra)},    {"auto", "Auto", uint32_t(FogQuality::Auto)},
};
static_assert(sizeof(FogQuality) == sizeof(uint32_t));

using S = FogSettings;

constexpr std::array<SettingField, 1> fogEnabledField() {
    return {{{.key = "enabled",
              .member = "enabled",
              .kind = SettingKind::Bool,
              .defaults = {double(FogSettings{}.enabled)},
              .meaning = "record the fog at all",
              .address = POSTFX_SETTING_ADDRESS(S, enabled)}}};
}

// In the order the scene files' messages list the keys: "enabled", the medium's, the fog's own.
constexpr std::array<SettingField, 8> fogOwnFields() {
    const FogSettings s{};
    return {{
        {.key = "steps",
         .member = "steps",
         .kind = SettingKind::Uint,
         .min = 1.0,
         .max = 4096.0,
         .defaults = {double(s.steps)},
         .history = true,
         .uiMin = 1.0,
         .uiMax = 256.0,
         .meaning = "march steps per pixel, independent of distance",
         .address = POSTFX_SETTING_ADDRESS(S, steps)},
        {.key = "jitter",
         .member = "jitter",
         .kind = SettingKind::Bool,
         .defaults = {double(s.jitter)},
         .history = true,
         .meaning = "IGN start offset per pixel and frame",
         .address = POSTFX_SETTING_ADDRESS(S, jitter)},
        {.key = "resolution_scale",
         .member = "resolutionScale",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 0.25,
         .max = 1.0,
         .defaults = {s.resolutionScale},
         .history = true,
         .meaning = "march at this fraction of width and height, then upsample depth-aware",
         .address = POSTFX_SETTING_ADDRESS(S, resolutionScale)},
        {.key = "transmittance_cutoff",
         .member = "transmittanceCutoff",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 0.0,
         .max = 1.0,
         .maxOpen = true,
         .defaults = {s.transmittanceCutoff},
         .history = true,
         .uiMin = 0.0,
         .uiMax = 0.1,
         .meaning = "stop marching below this transmittance",
         .address = POSTFX_SETTING_ADDRESS(S, transmittanceCutoff)},
        {.key = "skip_empty_space",
         .member = "skipEmptySpace",
         .kind = SettingKind::Bool,
         .defaults = {double(s.skipEmptySpace)},
         .history = true,
         .meaning = "march only the part of each ray below the medium's top",
         .address = POSTFX_SETTING_ADDRESS(S, skipEmptySpace)},
        // Odd sizes only: checked in fog::validateSettings.
        {.key = "shadow_kernel",
         .member = "shadowKernel",
         .kind = SettingKind::Uint,
         .unit = "texels",
         .min = 1.0,
         .max = 7.0,
         .defaults = {double(s.shadowKernel)},
         .history = true,
         .customCheck = true,
         .meaning = "shadow-map filter: kernel × kernel comparisons per step",
         .address = POSTFX_SETTING_ADDRESS(S, shadowKernel)},
        {.key = "quality",
         .member = "quality",
         .kind = SettingKind::Enum,
         .defaults = {double(s.quality)},
         .meaning = "a preset replaces `steps`, `jitter`, `shadowKernel`, `resolutionScale`",
         .choices = kQualityChoices,
         .typeName = "FogQuality",
         .address = POSTFX_SETTING_ADDRESS(S, quality)},
        {.key = "auto_budget_ms",
         .member = "autoBudgetMs",
         .kind = SettingKind::Float,
         .unit = "ms",
         .min = 0.0,
         .minOpen = true,
         .defaults = {s.autoBudgetMs},
         .uiMin = 0.05,
         .uiMax = 50.0,
         .logScale = true,
         .meaning = "Auto only: GPU time budget of the fog's passes",
         .address = POSTFX_SETTING_ADDRESS(S, autoBudgetMs)},
    }};
}

constexpr uint32_t kCustomQuality[] = {uint32_t(FogQuality::Custom)};
constexpr uint32_t kAutoQuality[] = {uint32_t(FogQuality::Auto)};

// A quality preset replaces steps, jitter, shadow kernel, resolution scale and temporal.enabled
// (applyFogQuality); the budget is Auto's.
constexpr auto kFogTable = common::usedOnlyWith(
    common::usedOnlyWith(common::concatFields(fogEnabledField(), common::mediumFields<S>(), fogOwnFields(),
                                              common::temporalFields<S>(FogSettings{}.temporal)),
                         {"steps", "jitter", "shadowKernel", "resolutionScale", "temporal.enabled"},
                         "quality", kCustomQuality),
    {"autoBudgetMs"}, "quality", kAutoQuality);
constexpr auto kMediumTable = common::mediumFields<FogMedium>();

}  // namespace

std::span<const SettingField> fogSettingsTable() {
    return kFogTable;
}

std::span<const SettingField> fogMediumSettingsTable() {
    return kMediumTable;
}

}  // namespace postfx
