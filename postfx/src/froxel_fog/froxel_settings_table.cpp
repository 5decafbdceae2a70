// FroxelFogSettings' and FogVolume's tables (postfx/settings_table.h): the froxel fog's own settings, the
// temporal accumulation's and the shared medium's (common/medium_table.h). The grid and the tile size key
// the history through the grid they give (froxelGridSize), not as set: froxel_effect.cpp hashes that.
#include "common/medium_table.h"

#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>

namespace postfx {
namespace {

constexpr SettingChoice kDistributionChoices[] = {
    {"power", "Power", uint32_t(FroxelDepthDistribution::Power)},
    {"log", "Log", uint32_t(FroxelDepthDistribution::Log)},
};
constexpr SettingChoice kShapeChoices[] = {
    {"box", "Box", uint32_t(FogVolumeShape::Box)},
    {"sphere", "Sphere", uint32_t(FogVolumeShape::Sphere)},
};
static_assert(sizeof(FroxelDepthDistribution) == sizeof(uint32_t) &&
              sizeof(FogVolumeShape) == sizeof(uint32_t));

using S = FroxelFogSettings;

constexpr std::array<SettingField, 1> froxelEnabledField() {
    return {{{.key = "enabled",
              .member = "enabled",
              .kind = SettingKind::Bool,
              .defaults = {double(FroxelFogSettings{}.enabled)},
              .meaning = "record the froxel fog at all",
              .address = POSTFX_SETTING_ADDRESS(S, enabled)}}};
}

// In the order the scene files' messages list the keys: "enabled", the medium's, the froxel fog's own.
constexpr std::array<SettingField, 8> froxelOwnFields() {
    const FroxelFogSettings s{};
    return {{
        {.key = "grid",
         .member = "grid",
         .kind = SettingKind::UVec3,
         .unit = "froxels",
         .min = 1.0,
         .max = double(kMaxFroxelGridSize),
         .defaults = {double(s.grid.x), double(s.grid.y), double(s.grid.z)},
         .uiMin = 1.0,
         .uiMax = 256.0,
         .meaning = "froxels along x, y and depth; x and y replaced by `tileSizePx`",
         .address = POSTFX_SETTING_ADDRESS(S, grid)},
        {.key = "tile_size_px",
         .member = "tileSizePx",
         .kind = SettingKind::Uint,
         .unit = "px",
         .min = 0.0,
         .max = 4096.0,
         .defaults = {double(s.tileSizePx)},
         .uiMin = 0.0,
         .uiMax = 64.0,
         .meaning = "0: grid x, y as set, else ceil(extent / tile)",
         .address = POSTFX_SETTING_ADDRESS(S, tileSizePx)},
        {.key = "depth_distribution",
         .member = "depthDistribution",
         .kind = SettingKind::Enum,
         .defaults = {double(s.depthDistribution)},
         .history = true,
         .meaning = "how the depth slices are spread between the near plane and `max_distance`",
         .choices = kDistributionChoices,
         .typeName = "FroxelDepthDistribution",
         .address = POSTFX_SETTING_ADDRESS(S, depthDistribution)},
        {.key = "depth_exponent",
         .member = "depthExponent",
         .kind = SettingKind::Float,
         .unit = "1",
         .min = 1.0,
         .max = 8.0,
         .defaults = {s.depthExponent},
         .history = true,
         .meaning = "k of the power distribution (checked for Log too)",
         .address = POSTFX_SETTING_ADDRESS(S, depthExponent)},
        {.key = "tricubic",
         .member = "tricubic",
         .kind = SettingKind::Bool,
         .defaults = {double(s.tricubic)},
         .meaning = "tricubic B-spline instead of trilinear in the apply pass",
         .address = POSTFX_SETTING_ADDRESS(S, tricubic)},
        {.key = "jitter",
         .member = "jitter",
         .kind = SettingKind::Bool,
         .defaults = {double(s.jitter)},
         .history = true,
         .meaning = "Halton (2, 3, 5) sample inside each froxel per frame",
         .address = POSTFX_SETTING_ADDRESS(S, jitter)},
        {.key = "local_shadow_filter",
         .member = "localShadowFilter",
         .kind = SettingKind::Bool,
         .defaults = {double(s.localShadowFilter)},
         .history = true,
         .meaning = "local lights' shadows: 2×2 bilinear PCF instead of one texel",
         .address = POSTFX_SETTING_ADDRESS(S, localShadowFilter)},
        {.key = "light_list_min_lights",
         .member = "lightListMinLights",
         .kind = SettingKind::Uint,
         .unit = "lights",
         .min = 1.0,
         .max = double(kMaxLocalLights + 1),
         .defaults = {double(s.lightListMinLights)},
         .meaning = "light lists with at least this many lights (257: never)",
         .address = POSTFX_SETTING_ADDRESS(S, lightListMinLights)},
    }};
}

constexpr uint32_t kPowerDistribution[] = {uint32_t(FroxelDepthDistribution::Power)};
// The exponent is the power distribution's only (and still checked with Log).
constexpr auto kFroxelTable = common::usedOnlyWith(
    common::concatFields(froxelEnabledField(), common::mediumFields<S>(), froxelOwnFields(),
                         common::temporalFields<S>(FroxelFogSettings{}.temporal)),
    {"depthExponent"}, "depthDistribution", kPowerDistribution);

using V = FogVolume;
constexpr double kMaxCoordinate = 1e9;  // volume centres, as local lights' positions [m]
constexpr double kMaxVolumeSize = 1e7;  // half sizes, radii, edge falloff [m]

// The history hashes every volume's fields (froxel_effect.cpp), so `history` is set on each.
constexpr std::array<SettingField, 6> volumeFields() {
    const FogVolume v{};
    return {{
        {.key = "shape",
         .member = "shape",
         .kind = SettingKind::Enum,
         .defaults = {double(v.shape)},
         .history = true,
         .meaning = "box or sphere",
         .choices = kShapeChoices,
         .typeName = "FogVolumeShape",
         .address = POSTFX_SETTING_ADDRESS(V, shape)},
        {.key = "center",
         .member = "center",
         .kind = SettingKind::DVec3,
         .unit = "m",
         .min = -kMaxCoordinate,
         .max = kMaxCoordinate,
         .defaults = {v.center.x, v.center.y, v.center.z},
         .history = true,
         .uiMin = -100.0,
         .uiMax = 100.0,
         .meaning = "world position",
         .address = POSTFX_SETTING_ADDRESS(V, center)},
        {.key = "half_size",
         .member = "halfSize",
         .kind = SettingKind::Vec3,
         .unit = "m",
         .min = 0.0,
         .max = kMaxVolumeSize,
         .defaults = {v.halfSize.x, v.halfSize.y, v.halfSize.z},
         .history = true,
         .uiMin = 0.0,
         .uiMax = 100.0,
         .meaning = "box: half extent along world x, y, z (0: empty)",
         .address = POSTFX_SETTING_ADDRESS(V, halfSize)},
        {.key = "radius",
         .member = "radius",
         .kind = SettingKind::Float,
         .unit = "m",
         .min = 0.0,
         .max = kMaxVolumeSize,
         .defaults = {v.radius},
         .history = true,
         .uiMin = 0.0,
         .uiMax = 100.0,
         .meaning = "sphere: radius (0: empty)",
         .address = POSTFX_SETTING_ADDRESS(V, radius)},
        {.key = "density",
         .member = "density",
         .kind = SettingKind::Float,
         .unit = "1/m",
         .min = 0.0,
         .max = 1e6,
         .defaults = {v.density},
         .history = true,
         .uiMin = 1e-4,
         .uiMax = 1.0,
         .logScale = true,
         .meaning = "extinction added at full strength",
         .address = POSTFX_SETTING_ADDRESS(V, density)},
        {.key = "edge_falloff",
         .member = "edgeFalloff",
         .kind = SettingKind::Float,
         .unit = "m",
         .min = 0.0,
         .max = kMaxVolumeSize,
         .defaults = {v.edgeFalloff},
         .history = true,
         .uiMin = 0.0,
         .uiMax = 20.0,
         .meaning = "depth inside over which the density ramps up (0: hard edge)",
         .address = POSTFX_SETTING_ADDRESS(V, edgeFalloff)},
    }};
}

constexpr uint32_t kBoxVolume[] = {uint32_t(FogVolumeShape::Box)};
constexpr uint32_t kSphereVolume[] = {uint32_t(FogVolumeShape::Sphere)};
constexpr auto kVolumeTable =
    common::usedOnlyWith(common::usedOnlyWith(volumeFields(), {"halfSize"}, "shape", kBoxVolume), {"radius"},
                         "shape", kSphereVolume);

}  // namespace

std::span<const SettingField> froxelFogSettingsTable() {
    return kFroxelTable;
}

std::span<const SettingField> fogVolumeSettingsTable() {
    return kVolumeTable;
}

}  // namespace postfx
