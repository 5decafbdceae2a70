// postfx-bench --froxel: the scenes and settings it measures (docs/accuracy-cost/README.md, "Froxel
// fog"). Plain C++ over the demo's scene description (no Vulkan): the froxel version of a fog scene, the
// sweep's points, the froxel knobs applied to a scene, and the point lights of the light-count sweep.
#pragma once

#include "bench_types.h"

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// The froxel fog's knobs swept (--froxel-grids, --froxel-slices, --froxel-distributions,
// --froxel-tricubic): their cross product.
struct FroxelSweepOptions {
    std::vector<std::pair<uint32_t, uint32_t>> grids = {{80, 45}, {160, 90}, {240, 135}};  // froxels x, y
    std::vector<uint32_t> slices = {64, 128, 256};
    std::vector<bool> logSlices = {false, true};  // power, log
    std::vector<bool> tricubic = {false, true};
};

// The sweep's settings for one scene: `base` (scene, noise size, lights as the scene has them) with each
// point of the cross product, grid outermost, then slices, distribution, tricubic. lightLists is what
// postfx does with the scene's lights at the default lightListMinLights.
std::vector<Setting> froxelSweep(const Setting& base, const FroxelSweepOptions& options);

// The froxel version of a scene file's scene: with effects.froxel_fog, the scene as it is; with
// effects.fog (the ray-marched fog), the froxel fog with that medium (every FogMedium key: density,
// albedo, anisotropy, height falloff and base, max distance, self-shadow, analytic tail, noise) and
// postfx's default grid, the ray-marched fog off. False with `error` when the scene has neither fog.
bool froxelScene(const demo::Scene& scene, demo::Scene& out, std::string& error);

// `scene` (a froxel scene) with a Froxel setting's knobs: grid, depth distribution, tricubic, and for
// a light-sweep row lightListMinLights 1 (lists) or 257 (every froxel loops over every light).
demo::Scene withFroxelKnobs(const demo::Scene& scene, const Setting& setting);

// The light-count sweep's lights: `count` point lights (at most postfx::kMaxLocalLights) spread over a
// disc of kSweepLightDisc m radius around the camera's look-at point (a Vogel spiral: the same density
// everywhere for any count), 0.5 to 4 m above it, each of range kSweepLightRange m, source radius
// 0.1 m and kSweepLightIntensity cd in one of six colours. Deterministic.
inline constexpr float kSweepLightDisc = 25.0f;      // [m]
inline constexpr float kSweepLightRange = 10.0f;     // [m]
inline constexpr float kSweepLightIntensity = 2e4f;  // [cd], the brightest channel
std::vector<demo::Light> sweepLights(const demo::Camera& camera, uint32_t count);

// The number of local lights postfx's froxel fog counts in `scene`: those with a non-zero intensity.
uint32_t froxelLightCount(const demo::Scene& scene);

}  // namespace bench
