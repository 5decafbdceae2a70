// CloudSettings' table (postfx/settings_table.h): every setting of the clouds, the nested structs' with
// dotted keys. `history`: what the temporal key hashes (clouds_effect.cpp adds the extent, the format and
// the atmosphere's LUT settings); the wind moves the history instead of resetting it, and the shadow map,
// the accumulation's own settings and quality (applied before) do not key it.
#include "clouds/clouds_settings.h"
#include "common/medium_table.h"
#include "core/checks.h"

#include <postfx/clouds.h>

namespace postfx {
namespace {

using namespace clouds;
using S = CloudSettings;

constexpr SettingChoice kQualityChoices[] = {
    {"custom", "Custom", uint32_t(CloudQuality::Custom)}, {"low", "Low", uint32_t(CloudQuality::Low)},
    {"medium", "Medium", uint32_t(CloudQuality::Medium)}, {"high", "High", uint32_t(CloudQuality::High)},
    {"ultra", "Ultra", uint32_t(CloudQuality::Ultra)},    {"auto", "Auto", uint32_t(CloudQuality::Auto)},
};
constexpr SettingChoice kShapeChoices[] = {
    {"layer", "Layer", uint32_t(CloudShape::Layer)},
    {"box", "Box", uint32_t(CloudShape::Box)},
};
constexpr SettingChoice kModelChoices[] = {
    {"slab", "Slab", uint32_t(CloudScatteringModel::Slab)},
    {"octaves", "Octaves", uint32_t(CloudScatteringModel::Octaves)},
};
static_assert(sizeof(CloudQuality) == 4 && sizeof(CloudShape) == 4 && sizeof(CloudScatteringModel) == 4);

using F = SettingField;
using K = SettingKind;

// A Float row: key, member, unit, [lo, hi] (lo excluded with loOpen), default, history, meaning.
constexpr F real(const char* key, const char* member, const char* unit, double lo, double hi, double def,
                 bool history, void* (*address)(void*), const char* meaning, bool loOpen = false) {
    return {.key = key,
            .member = member,
            .kind = K::Float,
            .unit = unit,
            .min = lo,
            .max = hi,
            .minOpen = loOpen,
            .defaults = {def},
            .history = history,
            .meaning = meaning,
            .address = address};
}
// A Uint row in [lo, hi].
constexpr F count(const char* key, const char* member, const char* unit, double lo, double hi, double def,
                  bool history, void* (*address)(void*), const char* meaning) {
    return {.key = key,
            .member = member,
            .kind = K::Uint,
            .unit = unit,
            .min = lo,
            .max = hi,
            .defaults = {def},
            .history = history,
            .meaning = meaning,
            .address = address};
}
// `f` with the editor's range and scale.
constexpr F ui(F f, double lo, double hi, bool log = false) {
    f.uiMin = lo;
    f.uiMax = hi;
    f.logScale = log;
    return f;
}
constexpr std::array<SettingField, 49> cloudFields() {
    const CloudSettings s{};
    const CloudBox& b = s.box;
    const CloudMultipleScattering& m = s.multipleScattering;
    const CloudNoiseSettings& n = s.noise;
    const CloudCoverageMap& c = s.coverageMap;
    constexpr double world = core::kMaxWorldCoordinate;
    return {{
        {.key = "enabled",
         .member = "enabled",
         .kind = K::Bool,
         .defaults = {double(s.enabled)},
         .meaning = "draw the clouds",
         .address = POSTFX_SETTING_ADDRESS(S, enabled)},
        {.key = "shape",
         .member = "shape",
         .kind = K::Enum,
         .defaults = {double(s.shape)},
         .history = true,
         .meaning = "a layer around the planet, or a box",
         .choices = kShapeChoices,
         .typeName = "CloudShape",
         .address = POSTFX_SETTING_ADDRESS(S, shape)},
        ui(real("bottom_height", "bottomHeight", "m", 0.0, kMaxHeight, s.bottomHeight, true,
                POSTFX_SETTING_ADDRESS(S, bottomHeight), "the layer's bottom above the ground"),
           0.0, 2e4),
        // Greater than bottomHeight: checked beside the table.
        ui(real("top_height", "topHeight", "m", 0.0, kMaxHeight, s.topHeight, true,
                POSTFX_SETTING_ADDRESS(S, topHeight), "the layer's top above the ground"),
           0.0, 2e4),
        {.key = "box.center",
         .member = "box.center",
         .kind = K::DVec3,
         .unit = "m",
         .min = -world,
         .max = world,
         .defaults = {b.center.x, b.center.y, b.center.z},
         .history = true,
         .uiMin = -2e4,
         .uiMax = 2e4,
         .meaning = "Box: world position",
         .address = POSTFX_SETTING_ADDRESS(S, box.center)},
        {.key = "box.half_size",
         .member = "box.halfSize",
         .kind = K::Vec3,
         .unit = "m",
         .min = 0.0,
         .max = kMaxBoxHalfSize,
         .minOpen = true,
         .defaults = {b.halfSize.x, b.halfSize.y, b.halfSize.z},
         .history = true,
         .uiMin = 1.0,
         .uiMax = 1e4,
         .meaning = "Box: half extents along its own axes",
         .address = POSTFX_SETTING_ADDRESS(S, box.halfSize)},
        real("box.yaw_deg", "box.yawDeg", "deg", -360.0, 360.0, b.yawDeg, true,
             POSTFX_SETTING_ADDRESS(S, box.yawDeg), "Box: rotation about world y"),
        real("box.pitch_deg", "box.pitchDeg", "deg", -360.0, 360.0, b.pitchDeg, true,
             POSTFX_SETTING_ADDRESS(S, box.pitchDeg), "Box: then about its x"),
        real("coverage", "coverage", "1", 0.0, 1.0, s.coverage, true, POSTFX_SETTING_ADDRESS(S, coverage),
             "fraction of the sky covered"),
        real("cloud_type", "cloudType", "1", 0.0, 1.0, s.cloudType, true,
             POSTFX_SETTING_ADDRESS(S, cloudType), "height profile: 0 stratus, 1 cumulus"),
        ui(real("density", "density", "1/m", 0.0, kMaxDensity, s.density, true,
                POSTFX_SETTING_ADDRESS(S, density), "σt where the density field is 1"),
           1e-4, 1.0, true),
        real("albedo", "albedo", "1", 0.0, 1.0, s.albedo, true, POSTFX_SETTING_ADDRESS(S, albedo),
             "single-scattering albedo σs/σt"),
        real("anisotropy_forward", "anisotropyForward", "1", 0.0, kMaxAnisotropy, s.anisotropyForward, true,
             POSTFX_SETTING_ADDRESS(S, anisotropyForward), "the forward lobe's g"),
        real("anisotropy_back", "anisotropyBack", "1", -kMaxAnisotropy, 0.0, s.anisotropyBack, true,
             POSTFX_SETTING_ADDRESS(S, anisotropyBack), "the back lobe's g"),
        real("lobe_mix", "lobeMix", "1", 0.0, 1.0, s.lobeMix, true, POSTFX_SETTING_ADDRESS(S, lobeMix),
             "weight of the back lobe"),
        {.key = "multiple_scattering.model",
         .member = "multipleScattering.model",
         .kind = K::Enum,
         .defaults = {double(m.model)},
         .history = true,
         .meaning = "the model of the light scattered more than once",
         .choices = kModelChoices,
         .typeName = "CloudScatteringModel",
         .address = POSTFX_SETTING_ADDRESS(S, multipleScattering.model)},
        count("multiple_scattering.octaves", "multipleScattering.octaves", "", 1.0, kMaxOctaves, m.octaves,
              true, POSTFX_SETTING_ADDRESS(S, multipleScattering.octaves),
              "Octaves: octaves; 1 = single scattering"),
        real("multiple_scattering.attenuation", "multipleScattering.attenuation", "1", 0.0, 1.0,
             m.attenuation, true, POSTFX_SETTING_ADDRESS(S, multipleScattering.attenuation), "Octaves: a",
             true),
        // At most attenuation: checked beside the table.
        real("multiple_scattering.contribution", "multipleScattering.contribution", "1", 0.0, 1.0,
             m.contribution, true, POSTFX_SETTING_ADDRESS(S, multipleScattering.contribution),
             "Octaves: b, at most a"),
        real("multiple_scattering.eccentricity", "multipleScattering.eccentricity", "1", 0.0, 1.0,
             m.eccentricity, true, POSTFX_SETTING_ADDRESS(S, multipleScattering.eccentricity), "Octaves: c"),
        ui(count("steps", "steps", "", 1.0, kMaxSteps, s.steps, true, POSTFX_SETTING_ADDRESS(S, steps),
                 "samples along each view ray inside the layer"),
           1.0, 256.0),
        count("light_steps", "lightSteps", "", 1.0, kMaxLightSteps, s.lightSteps, true,
              POSTFX_SETTING_ADDRESS(S, lightSteps), "samples of the march toward the sun"),
        ui(real("light_distance", "lightDistance", "m", 0.0, kMaxLightDistance, s.lightDistance, true,
                POSTFX_SETTING_ADDRESS(S, lightDistance), "length of the march toward the sun", true),
           100.0, 5e4, true),
        ui(real("max_distance", "maxDistance", "m", 0.0, kMaxDistance, s.maxDistance, true,
                POSTFX_SETTING_ADDRESS(S, maxDistance), "view rays are marched to here at most", true),
           1e3, 1e6, true),
        {.key = "wind",
         .member = "wind",
         .kind = K::Vec3,
         .unit = "m/s",
         .min = -kMaxWind,
         .max = kMaxWind,
         .defaults = {s.wind.x, s.wind.y, s.wind.z},
         .uiMin = -100.0,
         .uiMax = 100.0,
         .meaning = "velocity of the density field",
         .address = POSTFX_SETTING_ADDRESS(S, wind)},
        {.key = "jitter",
         .member = "jitter",
         .kind = K::Bool,
         .defaults = {double(s.jitter)},
         .history = true,
         .meaning = "IGN offset of each pixel's first sample per frame",
         .address = POSTFX_SETTING_ADDRESS(S, jitter)},
        {.key = "quality",
         .member = "quality",
         .kind = K::Enum,
         .defaults = {double(s.quality)},
         .meaning =
             "a preset replaces `steps`, `lightSteps`, `resolutionScale`, `temporal.enabled`, `updateBlock`",
         .choices = kQualityChoices,
         .typeName = "CloudQuality",
         .address = POSTFX_SETTING_ADDRESS(S, quality)},
        {.key = "auto_budget_ms",
         .member = "autoBudgetMs",
         .kind = K::Float,
         .unit = "ms",
         .min = 0.0,
         .minOpen = true,
         .defaults = {s.autoBudgetMs},
         .uiMin = 0.05,
         .uiMax = 50.0,
         .logScale = true,
         .meaning = "Auto only: GPU time budget of the clouds' passes",
         .address = POSTFX_SETTING_ADDRESS(S, autoBudgetMs)},
        real("resolution_scale", "resolutionScale", "1", kMinResolutionScale, 1.0, s.resolutionScale, true,
             POSTFX_SETTING_ADDRESS(S, resolutionScale), "march at this fraction of width and height"),
        {.key = "temporal.enabled",
         .member = "temporal.enabled",
         .kind = K::Bool,
         .defaults = {double(s.temporal.enabled)},
         .meaning = "accumulate over frames (docs/temporal.md)",
         .address = POSTFX_SETTING_ADDRESS(S, temporal.enabled)},
        ui(real("temporal.blend_weight", "temporal.blendWeight", "1", 0.0, 1.0, s.temporal.blendWeight, false,
                POSTFX_SETTING_ADDRESS(S, temporal.blendWeight),
                "weight of the current frame in the accumulation", true),
           0.01, 1.0, true),
        // 1, 2 or 4 (a power of two): checked beside the table.
        {.key = "update_block",
         .member = "updateBlock",
         .kind = K::Uint,
         .unit = "texels",
         .min = 1.0,
         .max = kMaxUpdateBlock,
         .defaults = {double(s.updateBlock)},
         .activeIf = "temporal.enabled",
         .customCheck = true,
         .meaning = "the march updates one texel of each block this wide per frame (1, 2 or 4)",
         .address = POSTFX_SETTING_ADDRESS(S, updateBlock)},
        {.key = "cast_shadows",
         .member = "castShadows",
         .kind = K::Bool,
         .defaults = {double(s.castShadows)},
         .meaning = "the shadow map dims the sun in both fogs and on the host's surfaces",
         .address = POSTFX_SETTING_ADDRESS(S, castShadows)},
        ui(count("shadow_map.size", "shadowMap.size", "texels", kMinShadowSize, kMaxShadowSize,
                 s.shadowMap.size, false, POSTFX_SETTING_ADDRESS(S, shadowMap.size), "the shadow map's edge"),
           kMinShadowSize, 2048.0),
        ui(real("shadow_map.extent", "shadowMap.extent", "m", kMinShadowExtent, kMaxShadowExtent,
                s.shadowMap.extent, false, POSTFX_SETTING_ADDRESS(S, shadowMap.extent),
                "the shadow map's edge, centred on the camera"),
           kMinShadowExtent, 1e5, true),
        {.key = "noise.enabled",
         .member = "noise.enabled",
         .kind = K::Bool,
         .defaults = {double(n.enabled)},
         .history = true,
         .meaning = "the noise shapes the density field",
         .address = POSTFX_SETTING_ADDRESS(S, noise.enabled)},
        // Powers of two besides the range: checked beside the table.
        count("noise.base_size", "noise.baseSize", "texels", kMinBaseSize, kMaxBaseSize, n.baseSize, true,
              POSTFX_SETTING_ADDRESS(S, noise.baseSize), "edge of the base-shape texture (a power of two)"),
        count("noise.detail_size", "noise.detailSize", "texels", kMinDetailSize, kMaxDetailSize, n.detailSize,
              true, POSTFX_SETTING_ADDRESS(S, noise.detailSize),
              "edge of the detail texture (a power of two)"),
        count("noise.seed", "noise.seed", "", 0.0, 4294967295.0, n.seed, true,
              POSTFX_SETTING_ADDRESS(S, noise.seed), "generator seed"),
        ui(real("noise.tiling", "noise.tiling", "m", kMinTiling, kMaxTiling, n.tiling, true,
                POSTFX_SETTING_ADDRESS(S, noise.tiling),
                "the base texture's period; the detail's is tiling / 8"),
           1e3, 1e5, true),
        real("noise.detail_strength", "noise.detailStrength", "1", 0.0, 1.0, n.detailStrength, true,
             POSTFX_SETTING_ADDRESS(S, noise.detailStrength), "how much the detail erodes the base shape"),
        {.key = nullptr,
         .member = "noise.hostBaseTexture",
         .kind = K::Opaque,
         .history = true,
         .meaning = "the host's base texture instead",
         .size = sizeof(VkImageView),
         .address = POSTFX_SETTING_ADDRESS(S, noise.hostBaseTexture)},
        {.key = nullptr,
         .member = "noise.hostDetailTexture",
         .kind = K::Opaque,
         .history = true,
         .meaning = "the host's detail texture instead",
         .size = sizeof(VkImageView),
         .address = POSTFX_SETTING_ADDRESS(S, noise.hostDetailTexture)},
        {.key = nullptr,
         .member = "noise.hostTextureLayout",
         .kind = K::Opaque,
         .defaults = {double(n.hostTextureLayout)},
         .customCheck = true,
         .meaning = "the layout the host's textures are in",
         .size = sizeof(VkImageLayout),
         .address = POSTFX_SETTING_ADDRESS(S, noise.hostTextureLayout)},
        {.key = nullptr,
         .member = "coverageMap.texture",
         .kind = K::Opaque,
         .history = true,
         .meaning = "the host's 2D coverage map",
         .size = sizeof(VkImageView),
         .address = POSTFX_SETTING_ADDRESS(S, coverageMap.texture)},
        {.key = nullptr,
         .member = "coverageMap.layout",
         .kind = K::Opaque,
         .defaults = {double(c.layout)},
         .customCheck = true,
         .meaning = "the layout the coverage map is in",
         .size = sizeof(VkImageLayout),
         .address = POSTFX_SETTING_ADDRESS(S, coverageMap.layout)},
        {.key = nullptr,
         .member = "coverageMap.size",
         .kind = K::Float,
         .unit = "m",
         .min = 1.0,
         .max = kMaxTiling,
         .defaults = {c.size},
         .history = true,
         .meaning = "edge of the area the map covers",
         .address = POSTFX_SETTING_ADDRESS(S, coverageMap.size)},
        {.key = nullptr,
         .member = "coverageMap.originX",
         .kind = K::Double,
         .unit = "m",
         .min = -world,
         .max = world,
         .defaults = {c.originX},
         .history = true,
         .meaning = "world x of the map's u = 0 edge",
         .address = POSTFX_SETTING_ADDRESS(S, coverageMap.originX)},
        {.key = nullptr,
         .member = "coverageMap.originZ",
         .kind = K::Double,
         .unit = "m",
         .min = -world,
         .max = world,
         .defaults = {c.originZ},
         .history = true,
         .meaning = "world z of the map's v = 0 edge",
         .address = POSTFX_SETTING_ADDRESS(S, coverageMap.originZ)},
    }};
}

constexpr uint32_t kBoxShape[] = {uint32_t(CloudShape::Box)};
constexpr uint32_t kOctavesModel[] = {uint32_t(CloudScatteringModel::Octaves)};
constexpr uint32_t kCustomQuality[] = {uint32_t(CloudQuality::Custom)};
constexpr uint32_t kAutoQuality[] = {uint32_t(CloudQuality::Auto)};

// The box's fields with shape Box; the octave model's constants with model Octaves; what a quality preset
// replaces (applyCloudQuality) with quality Custom; the budget with Auto.
constexpr auto kCloudTable = common::usedOnlyWith(
    common::usedOnlyWith(
        common::usedOnlyWith(
            common::usedOnlyWith(cloudFields(), {"box.center", "box.halfSize", "box.yawDeg", "box.pitchDeg"},
                                 "shape", kBoxShape),
            {"multipleScattering.octaves", "multipleScattering.attenuation",
             "multipleScattering.contribution", "multipleScattering.eccentricity"},
            "multipleScattering.model", kOctavesModel),
        {"steps", "lightSteps", "resolutionScale", "temporal.enabled", "updateBlock"}, "quality",
        kCustomQuality),
    {"autoBudgetMs"}, "quality", kAutoQuality);

}  // namespace

std::span<const SettingField> cloudSettingsTable() {
    return kCloudTable;
}

}  // namespace postfx
