// FroxelFogSettings' checks (its settings table's ranges, the medium's rules, the volumes') and the grid's
// slice distribution (docs/effects/froxel-fog.md).
#include "froxel_fog/froxel_settings.h"
#include "common/medium.h"
#include "common/medium_table.h"
#include "core/checks.h"
#include "core/settings_check.h"

#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>
#include <postfx/settings_table.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace postfx {

Status validateFroxelFogSettings(const FroxelFogSettings& s) {
    const std::string p = "FrameInfo.froxelFog";
    if (Status r = core::checkSettings(froxelFogSettingsTable(), &s, p); !r) return r;
    if (Status r = common::checkMediumRules(s, p); !r) return r;
    if (s.volumeCount > kMaxFogVolumes)
        return core::invalid(p + ".volumeCount: " + std::to_string(s.volumeCount) +
                             " exceeds kMaxFogVolumes (" + std::to_string(kMaxFogVolumes) + ")");
    if (s.volumeCount > 0 && !s.volumes)
        return core::invalid(p + ".volumes: null with volumeCount " + std::to_string(s.volumeCount));
    for (uint32_t i = 0; i < s.volumeCount; ++i)
        if (Status r = core::checkSettings(fogVolumeSettingsTable(), &s.volumes[i],
                                           p + ".volumes[" + std::to_string(i) + "]");
            !r)
            return r;
    if (s.tileSizePx == 0) return checkFroxelCount(s.grid, p + ".grid", "");
    return Status::success();
}

Status checkFroxelCount(const UVec3& grid, const std::string& field, const std::string& from) {
    const uint64_t froxels = uint64_t(grid.x) * grid.y * grid.z;
    if (froxels <= kMaxFroxels) return Status::success();
    return core::invalid(field + ": " + from + std::to_string(grid.x) + "x" + std::to_string(grid.y) + "x" +
                         std::to_string(grid.z) + " = " + std::to_string(froxels) +
                         " froxels, more than kMaxFroxels (" + std::to_string(kMaxFroxels) + ")");
}

Status checkFroxelTiles(const FroxelFogSettings& s, uint32_t width, uint32_t height) {
    if (s.tileSizePx == 0) return Status::success();
    const std::string field = "FrameInfo.froxelFog.tileSizePx";
    const uint32_t tile = s.tileSizePx;
    const UVec3 grid{(width + tile - 1) / tile, (height + tile - 1) / tile, s.grid.z};
    const std::string from =
        std::to_string(tile) + " px at " + std::to_string(width) + "x" + std::to_string(height) + " gives ";
    if (grid.x > kMaxFroxelGridSize || grid.y > kMaxFroxelGridSize) {
        const uint32_t least = (std::max(width, height) + kMaxFroxelGridSize - 1) / kMaxFroxelGridSize;
        return core::invalid(field + ": " + from + std::to_string(grid.x) + "x" + std::to_string(grid.y) +
                             " froxels, more than " + std::to_string(kMaxFroxelGridSize) +
                             " across or down (kMaxFroxelGridSize): at least " + std::to_string(least) +
                             " px at this extent");
    }
    return checkFroxelCount(grid, field, from);
}

double froxelSliceDepth(const FroxelFogSettings& s, double nearPlane, double z01) {
    const double far = s.maxDistance;
    if (!(nearPlane > 0.0) || !(nearPlane < far)) return nearPlane;
    const double z = std::clamp(std::isnan(z01) ? 0.0 : z01, 0.0, 1.0);
    if (s.depthDistribution == FroxelDepthDistribution::Log) return nearPlane * std::pow(far / nearPlane, z);
    return nearPlane + (far - nearPlane) * std::pow(z, double(s.depthExponent));
}

UVec3 froxelGridSize(const FroxelFogSettings& s, uint32_t width, uint32_t height) {
    if (s.tileSizePx == 0) return s.grid;
    auto tiles = [&](uint32_t size) {
        return std::clamp((size + s.tileSizePx - 1) / s.tileSizePx, 1u, kMaxFroxelGridSize);
    };
    return {tiles(width), tiles(height), s.grid.z};
}

double froxelSliceCoordinate(const FroxelFogSettings& s, double nearPlane, double depth) {
    const double far = s.maxDistance;
    if (!(nearPlane > 0.0) || !(nearPlane < far)) return 0.0;
    const double d = std::clamp(std::isnan(depth) ? nearPlane : depth, nearPlane, far);
    if (s.depthDistribution == FroxelDepthDistribution::Log)
        return std::log(d / nearPlane) / std::log(far / nearPlane);
    return std::pow((d - nearPlane) / (far - nearPlane), 1.0 / double(s.depthExponent));
}

}  // namespace postfx
