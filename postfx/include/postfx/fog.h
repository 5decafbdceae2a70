// Ray-marched post-process fog: settings and per-frame inputs. The model is in docs/effects/fog.md.
//
// Every setting: unit, default, valid range. Out-of-range values are rejected by Context::record with
// an error naming the field, except where "clamped" is written.
#pragma once

#include <postfx/result.h>
#include <postfx/types.h>

#include <glm/glm.hpp>

#include <cstdint>

namespace postfx {

struct FogNoiseSettings {
    bool enabled = false;  // false: noise(x) = 1 (no texture is generated or read)
    // Edge of the cubic noise texture postfx generates [texels]; power of two in [16, 256].
    uint32_t textureSize = 128;
    uint32_t seed = 1;  // generator seed; any value
    // Texture coordinate = (x - wind·time) · 0.01 · tiling, so with tiling 1 the texture repeats every
    // 100 m [1/100 m]; > 0 and <= 1000.
    float tiling = 1.0f;
    float threshold = 0.1f;   // noise(x) = clamp(n - threshold, 0, 1) · multiplier [1]; in [0, 1]
    float multiplier = 1.0f;  // [1]; in [0, 1e3]
    glm::vec3 wind{0.0f};     // velocity of the noise field [m/s]; each component in [-1e3, 1e3]
    // Optional host texture instead of the generated one: a 3D view (first channel read, values in
    // [0, 1]), sampled with trilinear filtering and repeat addressing, in `hostTextureLayout`.
    VkImageView hostTexture = VK_NULL_HANDLE;
    VkImageLayout hostTextureLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
};

// Quality presets: each sets steps, jitter, shadowKernel and resolutionScale
// (docs/effects/fog.md#quality-presets). Low = 32 steps at resolution scale 0.5; Medium = 32 steps;
// High = 64 steps; Ultra = 128 steps, at scale 1; all with jitter and shadow kernel 1 (measured:
// docs/accuracy-cost/README.md). The defaults of those four settings below are Medium's.
enum class FogQuality {
    Custom,  // steps, jitter, shadowKernel and resolutionScale as set
    Low,
    Medium,
    High,
    Ultra,
    // The context measures Low..Ultra on the running device (the first twelve frames of every new
    // (color extent, noise on, shadow map present): the presets in turn, three frames each, median),
    // then uses the highest preset whose fog passes take at most autoBudgetMs, or Low if none fits
    // (see Context::fogAutoQuality). Without GPU timings: Medium.
    Auto,
};

struct FogSettings {
    bool enabled = false;
    // Custom uses steps/jitter/shadowKernel/resolutionScale below; a preset replaces those four.
    FogQuality quality = FogQuality::Custom;
    // Auto only: GPU time budget for the fog's passes (excluding noise generation) [ms]; > 0 and finite
    // (checked whatever the quality).
    float autoBudgetMs = 0.5f;
    // Extinction σt at base_height where noise = 1 [1/m]; in [0, 1e6]. 0.02 gives a visibility of ~150 m.
    float density = 0.02f;
    glm::vec3 albedo{0.9f};  // single-scattering albedo σs/σt per RGB channel [1]; each in [0, 1]
    // Henyey–Greenstein asymmetry g [1]; in [-1, 1], clamped to [-0.999, 0.999].
    // g > 0 scatters forward: brightest looking toward the sun.
    float anisotropy = 0.6f;
    // Height fog: σt ∝ exp(-height_falloff · (y - base_height)) [1/m]; in [0, 10]. 0 = homogeneous.
    float heightFalloff = 0.1f;
    float baseHeight = 0.0f;  // [m]; finite
    // Rays are marched to the surface or to this distance, whichever is nearer [m]; in (0, 1e7].
    float maxDistance = 200.0f;
    uint32_t steps = 32;  // march steps per pixel, independent of distance; in [1, 4096]
    bool jitter = true;   // offset the march start by interleaved gradient noise of pixel and frame
    // March at this fraction of the color image's width and height (rounded up), then composite at full
    // resolution with a depth-aware upsample (docs/effects/fog.md#resolution-scale) [1]; in [0.25, 1].
    // 1: every pixel marches its own ray in one pass; 0.5 marches a quarter of the rays.
    float resolutionScale = 1.0f;
    // Stop marching once the transmittance is below this [1]; in [0, 1). 0 = never stop early.
    float transmittanceCutoff = 0.001f;
    // Sun visibility also includes the fog's own transmittance toward the sun (closed form of the
    // height term; noise not included).
    bool selfShadow = false;
    // Beyond max_distance (up to the surface, or to infinity for pixels with no geometry), add the
    // height fog's closed-form contribution (no noise, no shadow map), so fog does not end at a wall.
    bool analyticTail = true;
    // Empty-space skipping (docs/effects/fog.md#empty-space): march only the part of each ray below the
    // height above which the medium's extinction is negligible (its optical depth over max_distance below
    // 1e-4), spending every step there; rays that never go below it take no step. false marches all of
    // [0, min(surface, max_distance)] (for comparison; the image differs only by the march's own error).
    bool skipEmptySpace = true;
    // Shadow-map filter: kernel × kernel texels around the sample, each compared, averaged; odd, 1..7.
    // The march's many samples already soften shafts: on the H100, 1 instead of 3 halves the march's time
    // at the same error (docs/accuracy-cost/README.md).
    uint32_t shadowKernel = 1;
    FogNoiseSettings noise;
};

// FogQuality::Auto's measurements for one (color extent, noise on, shadow map present): the median GPU
// time of each preset's fog passes (Context::fogAutoTimings, setFogAutoTimings).
struct FogAutoTimings {
    uint32_t width = 0, height = 0;  // color image extent [px]; each >= 1
    bool noise = false;              // fog.noise.enabled
    bool shadowMap = false;          // FrameInfo::shadowMap.image present
    float presetMs[4] = {};          // Low, Medium, High, Ultra [ms]; each finite, >= 0
};

// The sun as the fog sees it.
struct SunInput {
    glm::vec3 toSun{0.0f, 1.0f, 0.0f};  // unit direction toward the sun (normalised by postfx)
    glm::vec3 illuminance{0.0f};        // [lux] on a surface facing the sun; each >= 0
};

// The host's sun shadow map. Optional: with no image the sun is unshadowed (visibility 1).
//
// Each PCF tap tests the fog sample's shadow depth z = c.z/c.w (c = worldToClip · x) against one texel:
//   - inside the map's depth range (z in [0, 1]): lit when z - depthBias <= stored (reversed Z:
//     z + depthBias >= stored);
//   - beyond the far plane (z > 1; reversed Z: z < 0): in shadow where the texel holds a caster, lit
//     where it holds the cleared far value (1; reversed Z: 0), so fog under a caster with no receiver
//     below it inside the map is shadowed;
//   - before the near plane (z < 0; reversed Z: z > 1): lit.
// Outside the map's u, v in [0, 1] the sample is lit. So the map's volume must hold every caster (its
// receivers need not be inside), with texels where nothing was drawn at the cleared far value; fog before
// the near plane is lit even under a caster that depth clamping flattened onto it.
struct ShadowMapInput {
    // Depth image (D32_SFLOAT, D16_UNORM or R32_SFLOAT), usage SAMPLED, any square or rectangular size.
    ImageInput image;
    // World -> shadow clip space: x, y in [-1, 1] map to u, v = (x, y)/2 + 1/2, z/w is the stored depth.
    glm::dmat4 worldToClip{1.0};
    bool reversedZ = false;  // true: larger stored depth is nearer the sun
    float depthBias = 0.0f;  // added toward "lit" before comparing [shadow depth units]; >= 0
};

// The camera that rendered color and depth.
struct CameraInput {
    glm::dvec3 position{0.0};    // world position [m] (double: postfx marches camera-relative)
    glm::mat4 view{1.0f};        // world -> view; only its rotation is used (position gives the translation)
    glm::mat4 projection{1.0f};  // view -> Vulkan clip, in the context's DepthConvention
};

// Checks every setting against its documented range; InvalidArgument naming the first bad field with
// its scene-file name ("fog.noise.tiling: 0 must be > 0"). Context::record runs the same check.
Status validateFogSettings(const FogSettings& settings);

// Size of the fog's march for a color image of `width`×`height` at `resolutionScale` [px]:
// max(1, ceil(size · scale)) per axis; the image's own size at scale 1 (then the fog runs one pass).
glm::uvec2 fogMarchExtent(uint32_t width, uint32_t height, float resolutionScale);

// `settings` with steps, jitter, shadowKernel and resolutionScale set by preset `quality`; Custom and
// Auto: unchanged.
FogSettings applyFogQuality(const FogSettings& settings, FogQuality quality);

}  // namespace postfx
