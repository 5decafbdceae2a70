// FroxelFogSettings' checks and the grid's slice distribution (docs/effects/froxel-fog.md).
#include "common/medium.h"
#include "core/checks.h"

#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace postfx {
namespace {

using core::checkRange;
using core::invalid;

constexpr double kMaxCoordinate = 1e9;  // volume centres, as local lights' positions [m]
constexpr double kMaxVolumeSize = 1e7;  // half sizes, radii, edge falloff [m]

Status checkVolume(const FogVolume& v, uint32_t index) {
    const std::string n = "froxel_fog.volumes[" + std::to_string(index) + "]";
    if (v.shape != FogVolumeShape::Box && v.shape != FogVolumeShape::Sphere)
        return invalid(n + ".shape: " + std::to_string(uint32_t(v.shape)) + " is not box or sphere");
    for (int c = 0; c < 3; ++c)
        if (Status s = checkRange((n + ".center").c_str(), v.center[c], -kMaxCoordinate, kMaxCoordinate); !s)
            return s;
    for (int c = 0; c < 3; ++c)
        if (Status s = checkRange((n + ".half_size").c_str(), v.halfSize[c], 0.0, kMaxVolumeSize); !s)
            return s;
    if (Status s = checkRange((n + ".radius").c_str(), v.radius, 0.0, kMaxVolumeSize); !s) return s;
    if (Status s = checkRange((n + ".density").c_str(), v.density, 0.0, 1e6); !s) return s;
    if (Status s = checkRange((n + ".edge_falloff").c_str(), v.edgeFalloff, 0.0, kMaxVolumeSize); !s)
        return s;
    return Status::success();
}

}  // namespace

Status validateFroxelFogSettings(const FroxelFogSettings& s) {
    if (Status r = common::validateMedium(s, "froxel_fog"); !r) return r;
    if (Status r = common::validateTemporal(s.temporal, "froxel_fog"); !r) return r;
    for (int a = 0; a < 3; ++a)
        if (s.grid[a] < 1 || s.grid[a] > kMaxFroxelGridSize)
            return invalid("froxel_fog.grid[" + std::to_string(a) + "]: " + std::to_string(s.grid[a]) +
                           " is outside [1, " + std::to_string(kMaxFroxelGridSize) + "]");
    if (s.tileSizePx > 4096)
        return invalid("froxel_fog.tile_size_px: " + std::to_string(s.tileSizePx) + " is outside [0, 4096]");
    if (s.depthDistribution != FroxelDepthDistribution::Power &&
        s.depthDistribution != FroxelDepthDistribution::Log)
        return invalid("froxel_fog.depth_distribution: " + std::to_string(uint32_t(s.depthDistribution)) +
                       " is not power or log");
    if (Status r = checkRange("froxel_fog.depth_exponent", s.depthExponent, 1.0, 8.0); !r) return r;
    if (s.lightListMinLights < 1 || s.lightListMinLights > kMaxLocalLights + 1)
        return invalid("froxel_fog.light_list_min_lights: " + std::to_string(s.lightListMinLights) +
                       " is outside [1, " + std::to_string(kMaxLocalLights + 1) + "]");
    if (s.volumeCount > kMaxFogVolumes)
        return invalid("froxel_fog.volumes: " + std::to_string(s.volumeCount) +
                       " volumes exceed kMaxFogVolumes (" + std::to_string(kMaxFogVolumes) + ")");
    if (s.volumeCount > 0 && !s.volumes)
        return invalid("froxel_fog.volumes: null with volumeCount " + std::to_string(s.volumeCount));
    for (uint32_t i = 0; i < s.volumeCount; ++i)
        if (Status r = checkVolume(s.volumes[i], i); !r) return r;
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
