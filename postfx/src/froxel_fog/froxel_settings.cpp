// FroxelFogSettings' checks (its settings table's ranges, the medium's rules, the volumes') and the grid's
// slice distribution (docs/effects/froxel-fog.md).
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
    return Status::success();
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
