// The settings-table rows both fogs share (postfx/settings_table.h): the medium (FogMedium, its noise
// included) and the temporal accumulation (TemporalSettings), written once as templates over the settings
// struct that holds them (FogSettings, FroxelFogSettings), so each fog's table lists them with accessors
// of its own struct.
#pragma once

#include <postfx/fog.h>
#include <postfx/settings_table.h>
#include <postfx/temporal.h>

#include "common/medium.h"

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string_view>

// The address function of member path `m` of struct `S` (SettingField::address).
#define POSTFX_SETTING_ADDRESS(S, m) [](void* p) -> void* { return &static_cast<S*>(p)->m; }

namespace postfx::common {

// The tables' rows in one array (a table is its own rows followed by shared ones).
template <size_t... N>
constexpr auto concatFields(const std::array<SettingField, N>&... parts) {
    std::array<SettingField, (N + ...)> out{};
    size_t i = 0;
    (([&] {
         for (const SettingField& f : parts)
             out[i++] = f;
     }()),
     ...);
    return out;
}

// `fields` with the rows whose member is one of `members` used only while Enum member `mode` holds one of
// `choices` (SettingField::usedWith): the fields a quality preset replaces, a shape's own fields.
template <size_t N>
constexpr std::array<SettingField, N> usedOnlyWith(std::array<SettingField, N> fields,
                                                   std::initializer_list<std::string_view> members,
                                                   const char* mode, std::span<const uint32_t> choices) {
    for (SettingField& f : fields)
        for (std::string_view m : members)
            if (m == f.member) {
                f.usedWith = mode;
                f.usedWithChoices = choices;
            }
    return fields;
}

// FogMedium's rows. noise.textureSize and noise.hostTextureLayout have checks of their own
// (checkMediumRules); the noise's fields are checked and hashed only while the noise is on.
template <class S>
constexpr std::array<SettingField, 17> mediumFields() {
    const FogMedium m{};
    const FogNoiseSettings& n = m.noise;
    return {{
        {.key = "density",
         .member = "density",
         .kind = SettingKind::Float,
         .unit = "1/m",
         .min = 0.0,
         .max = 1e6,
         .defaults = {m.density},
         .history = true,
         .uiMin = 1e-4,
         .uiMax = 1.0,
         .logScale = true,
         .meaning = "extinction σt at `base_height` where noise = 1",
         .address = POSTFX_SETTING_ADDRESS(S, density)},
        {.key = "albedo",
         .member = "albedo",
         .kind = SettingKind::Color,
         .unit = "1",
         .min = 0.0,
         .max = 1.0,
         .defaults = {m.albedo.x, m.albedo.y, m.albedo.z},
         .history = true,
         .meaning = "σs/σt per RGB channel",
         .address = POSTFX_SETTING_ADDRESS(S, albedo)},
        {.key = "anisotropy",
         .member = "anisotropy",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = -double(kMaxAnisotropy),
         .max = double(kMaxAnisotropy),
         .defaults = {m.anisotropy},
         .history = true,
         .uiMin = -0.99,
         .uiMax = 0.99,
         .meaning = "Henyey–Greenstein g; > 0 scatters forward (±1 would be a delta)",
         .address = POSTFX_SETTING_ADDRESS(S, anisotropy)},
        {.key = "height_falloff",
         .member = "heightFalloff",
         .kind = SettingKind::Float,
         .unit = "1/m",
         .min = 0.0,
         .max = 10.0,
         .defaults = {m.heightFalloff},
         .history = true,
         .uiMin = 0.0,
         .uiMax = 1.0,
         .logScale = true,
         .meaning = "exponential height falloff; 0 = homogeneous",
         .address = POSTFX_SETTING_ADDRESS(S, heightFalloff)},
        {.key = "base_height",
         .member = "baseHeight",
         .kind = SettingKind::Float,
         .unit = "m",
         .defaults = {m.baseHeight},
         .history = true,
         .uiMin = -50.0,
         .uiMax = 50.0,
         .meaning = "height where σt = density",
         .address = POSTFX_SETTING_ADDRESS(S, baseHeight)},
        {.key = "max_distance",
         .member = "maxDistance",
         .kind = SettingKind::Float,
         .unit = "m",
         .min = 0.0,
         .max = 1e7,
         .minOpen = true,
         .defaults = {m.maxDistance},
         .history = true,
         .uiMin = 1.0,
         .uiMax = 2000.0,
         .logScale = true,
         .meaning = "march length limit (then the analytic tail)",
         .address = POSTFX_SETTING_ADDRESS(S, maxDistance)},
        {.key = "self_shadow",
         .member = "selfShadow",
         .kind = SettingKind::Bool,
         .defaults = {double(m.selfShadow)},
         .history = true,
         .meaning = "include the fog's own transmittance toward the sun",
         .address = POSTFX_SETTING_ADDRESS(S, selfShadow)},
        {.key = "analytic_tail",
         .member = "analyticTail",
         .kind = SettingKind::Bool,
         .defaults = {double(m.analyticTail)},
         .history = true,
         .meaning = "closed-form height fog beyond `max_distance`",
         .address = POSTFX_SETTING_ADDRESS(S, analyticTail)},
        {.key = "noise.enabled",
         .member = "noise.enabled",
         .kind = SettingKind::Bool,
         .defaults = {double(n.enabled)},
         .history = true,
         .meaning = "modulate σt by the noise texture",
         .address = POSTFX_SETTING_ADDRESS(S, noise.enabled)},
        {.key = "noise.texture_size",
         .member = "noise.textureSize",
         .kind = SettingKind::Uint,
         .unit = "texels",
         .min = 16.0,
         .max = 256.0,
         .defaults = {double(n.textureSize)},
         .history = true,
         .activeIf = "noise.enabled",
         .customCheck = true,
         .meaning = "edge of the generated cubic texture",
         .address = POSTFX_SETTING_ADDRESS(S, noise.textureSize)},
        {.key = "noise.seed",
         .member = "noise.seed",
         .kind = SettingKind::Uint,
         .min = 0.0,
         .max = 4294967295.0,
         .defaults = {double(n.seed)},
         .history = true,
         .activeIf = "noise.enabled",
         .meaning = "generator seed",
         .address = POSTFX_SETTING_ADDRESS(S, noise.seed)},
        {.key = "noise.tiling",
         .member = "noise.tiling",
         .kind = SettingKind::Float,
         .unit = "1/(100 m)",
         .min = 0.0,
         .max = 1000.0,
         .minOpen = true,
         .defaults = {n.tiling},
         .history = true,
         .activeIf = "noise.enabled",
         .uiMin = 0.1,
         .uiMax = 50.0,
         .logScale = true,
         .meaning = "texture repeats every 100/tiling metres",
         .address = POSTFX_SETTING_ADDRESS(S, noise.tiling)},
        {.key = "noise.threshold",
         .member = "noise.threshold",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 0.0,
         .max = 1.0,
         .defaults = {n.threshold},
         .history = true,
         .activeIf = "noise.enabled",
         .meaning = "subtracted from the texel value",
         .address = POSTFX_SETTING_ADDRESS(S, noise.threshold)},
        {.key = "noise.multiplier",
         .member = "noise.multiplier",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 0.0,
         .max = 1000.0,
         .defaults = {n.multiplier},
         .history = true,
         .activeIf = "noise.enabled",
         .uiMin = 0.0,
         .uiMax = 10.0,
         .meaning = "scales the thresholded value",
         .address = POSTFX_SETTING_ADDRESS(S, noise.multiplier)},
        {.key = "noise.wind",
         .member = "noise.wind",
         .kind = SettingKind::Vec3,
         .unit = "m/s",
         .min = -1000.0,
         .max = 1000.0,
         .defaults = {n.wind.x, n.wind.y, n.wind.z},
         .history = true,
         .activeIf = "noise.enabled",
         .uiMin = -100.0,
         .uiMax = 100.0,
         .meaning = "velocity of the noise field",
         .address = POSTFX_SETTING_ADDRESS(S, noise.wind)},
        {.key = nullptr,
         .member = "noise.hostTexture",
         .kind = SettingKind::Opaque,
         .history = true,
         .activeIf = "noise.enabled",
         .meaning = "the host's own noise texture instead",
         .size = sizeof(VkImageView),
         .address = POSTFX_SETTING_ADDRESS(S, noise.hostTexture)},
        {.key = nullptr,
         .member = "noise.hostTextureLayout",
         .kind = SettingKind::Opaque,
         .defaults = {double(n.hostTextureLayout)},
         .history = true,
         .activeIf = "noise.enabled",
         .customCheck = true,
         .meaning = "the layout the host's texture is in",
         .size = sizeof(VkImageLayout),
         .address = POSTFX_SETTING_ADDRESS(S, noise.hostTextureLayout)},
    }};
}

// TemporalSettings' rows, with the effect's defaults. History: the accumulation's own settings do not
// key the history (core::History reads them).
template <class S>
constexpr std::array<SettingField, 2> temporalFields(const TemporalSettings& t) {
    return {{
        {.key = "temporal.enabled",
         .member = "temporal.enabled",
         .kind = SettingKind::Bool,
         .defaults = {double(t.enabled)},
         .meaning = "accumulate over frames (docs/temporal.md)",
         .address = POSTFX_SETTING_ADDRESS(S, temporal.enabled)},
        {.key = "temporal.blend_weight",
         .member = "temporal.blendWeight",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 0.0,
         .max = 1.0,
         .minOpen = true,
         .defaults = {t.blendWeight},
         .uiMin = 0.01,
         .uiMax = 1.0,
         .logScale = true,
         .meaning = "weight of the current frame in the accumulation",
         .address = POSTFX_SETTING_ADDRESS(S, temporal.blendWeight)},
    }};
}

// The medium's rows of a fog's table (the shared part of both fogs' tables).
inline constexpr size_t kMediumFieldCount = 17;

}  // namespace postfx::common
