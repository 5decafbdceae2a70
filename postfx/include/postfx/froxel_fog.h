// Froxel volumetric fog: settings (docs/effects/froxel-fog.md), FrameInfo::froxelFog. The medium and its
// light are evaluated once per froxel of a camera-aligned grid, integrated front to back and applied per
// pixel; the CPU reference is reference::renderFroxelFog (postfx/reference.h).
//
// Every setting: unit, default, valid range, checked by validateFroxelFogSettings with an error naming
// the field by its C++ path ("FrameInfo.froxelFog.grid[2]: 0 is outside [1, 512]"); the ranges are
// froxelFogSettingsTable()'s and fogVolumeSettingsTable()'s (postfx/settings_table.h).
#pragma once

#include <postfx/export.h>
#include <postfx/fog.h>
#include <postfx/result.h>
#include <postfx/types.h>

#include <cstdint>

namespace postfx {

enum class FogVolumeShape : uint32_t { Box, Sphere };  // another value (cast from an int) is rejected

// A local fog volume: extinction added to the medium's inside a box or a sphere (additive density). Placed
// in the host's world frame and units (ContextCreateInfo::world), its density per metre.
struct FogVolume {
    FogVolumeShape shape = FogVolumeShape::Box;
    DVec3 center{0.0};  // world position [host units]; each component in [-1e9, 1e9]
    Vec3 halfSize{
        1.0f};  // box: half extent along the host's x, y, z [host units]; each in [0, 1e7] (0: empty)
    float radius = 1.0f;   // sphere: [host units]; in [0, 1e7] (0: empty)
    float density = 0.1f;  // extinction added at full strength [1/m]; in [0, 1e6]
    // The density ramps with a smoothstep from 0 at the surface to full at this depth inside (distance
    // to the nearest face for a box, radius - |x - center| for a sphere) [host units]; in [0, 1e7]. 0 = hard
    // edge.
    float edgeFalloff = 0.0f;
};

// At most this many volumes per frame (FroxelFogSettings::volumeCount): each is tested per froxel on the
// GPU without a volume list, and 64 covers the rooms and patches a scene places by hand.
inline constexpr uint32_t kMaxFogVolumes = 64;

// How the grid's depth slices are spread between the near plane and max_distance (froxelSliceDepth).
enum class FroxelDepthDistribution : uint32_t {
    Power,  // d(z) = near + (far - near)·z^k, k = depth_exponent (Wronski 2014: k = 2)
    Log,    // d(z) = near·(far/near)^z: slices of equal relative thickness (as Unreal)
};

// Largest grid size along each axis: the stability cases need 1×1×1 and 512 slices.
inline constexpr uint32_t kMaxFroxelGridSize = 512;
// Most froxels in the grid (x·y·z, as set or from tileSizePx): 240×135×256 (an 8-px tile at 1920×1080,
// twice the default's slices) and 480×270×64 fit; with temporal 40 bytes each, 320 MiB at most, and about
// 10 s per frame on lavapipe with lights (docs/reliability.md, "Memory and cost budget").
inline constexpr uint64_t kMaxFroxels = uint64_t(1) << 23;

// The froxel fog: the shared medium (FogMedium, the same keys and ranges as the ray-marched fog, named
// "FrameInfo.froxelFog.*") and its grid. max_distance is the grid's far end.
struct FroxelFogSettings : FogMedium {
    bool enabled = false;
    // Froxels along the view's x, y and depth [1]; each in [1, 512], x·y·z at most kMaxFroxels. x and y
    // are replaced by tileSizePx.
    UVec3 grid{160, 90, 128};
    // 0: grid.x, grid.y as set; otherwise grid.x, grid.y = ceil(extent / tileSizePx) of the color image
    // [px]; in [0, 4096]. A tile that gives more than 512 froxels across or down, or more than
    // kMaxFroxels in all, is an error (record() names tileSizePx with the extent), not clamped.
    uint32_t tileSizePx = 0;
    FroxelDepthDistribution depthDistribution = FroxelDepthDistribution::Power;
    float depthExponent = 2.0f;  // k of the power distribution [1]; in [1, 8] (checked for Log too)
    bool tricubic = false;       // apply: tricubic B-spline instead of trilinear filtering of the volume
    bool jitter = true;          // the sample inside each froxel moves per frame (Halton 2, 3, 5)
    // Light lists (docs/effects/froxel-fog.md#light-lists): a pass bins the lights into clusters of 8×8
    // froxels × 16 slices when the frame has at least this many lights with a non-zero intensity; with
    // fewer, every froxel loops over all of them [lights]; in [1, 257] (257: never, 1: always). 24: the
    // fewest lights from which the lists (their pass and the scatter) measured faster than the loop, on
    // the H100 at 1920×1080 with the default grid (postfx-bench --froxel, docs/effects/froxel-fog.md,
    // "Benchmark"); below, their pass costs more than the loop it shortens.
    uint32_t lightListMinLights = 24;
    // Local lights' shadows (FrameInfo.localShadows): false, one texel per sample (the sun's one tap);
    // true, the 2×2 texels around it weighted bilinearly (percentage-closer filtering), so a shadow's edge
    // ramps over a texel instead of stepping.
    bool localShadowFilter = false;
    // volumeCount local fog volumes (may be null when 0), read during record(); count in [0, 64].
    const FogVolume* volumes = nullptr;
    uint32_t volumeCount = 0;
    // Temporal accumulation of the scattering volume (docs/effects/froxel-fog.md#temporal): on by
    // default, 5% of each froxel new per frame (as the seed and Wronski 2014).
    TemporalSettings temporal{true, 0.05f};
};

// Checks every setting against its documented range (the medium's as FogMedium's, named
// "FrameInfo.froxelFog.*", the noise's when it is enabled, every volume's); InvalidArgument naming the first
// bad field.
POSTFX_API Status validateFroxelFogSettings(const FroxelFogSettings& settings);

// Distance along the view ray of the slice boundary at z01 ∈ [0, 1] (0: the near plane, 1: far =
// max_distance) [m]: Power: near + (far - near)·z01^k; Log: near·(far/near)^z01. z01 is clamped to [0, 1];
// near must be in (0, far) (otherwise near is returned).
POSTFX_API double froxelSliceDepth(const FroxelFogSettings& settings, double nearPlane, double z01);
// Its inverse: z01 ∈ [0, 1] of distance `depth` along the ray, clamped to [near, far].
POSTFX_API double froxelSliceCoordinate(const FroxelFogSettings& settings, double nearPlane, double depth);
// The grid's froxels along x, y and depth for a color image of width × height [px]: settings.grid, or
// with tileSizePx > 0, x and y = ceil(extent / tileSizePx) (each clamped to 512, which record() refuses
// rather than use). The froxels always span the image exactly.
POSTFX_API UVec3 froxelGridSize(const FroxelFogSettings& settings, uint32_t width, uint32_t height);

// The froxel fog's generated noise texture (as kFogNoiseTexture, the shared medium's noise), for
// Context::imageView and Context::recordImageReadback: held while froxel fog with generated noise runs.
inline constexpr ResourceName kFroxelFogNoiseTexture{"froxel_fog.noise"};

}  // namespace postfx
