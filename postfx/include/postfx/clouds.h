// Volumetric clouds: settings (FrameInfo::clouds). A layer of clouds between two altitudes (or inside an
// oriented box), density from tileable Perlin–Worley noise eroded by Worley detail, lit by the sun through
// a short march toward it with a multiple-scattering approximation, composited over the host's color in
// front of the sky and behind nearer geometry. The model is in docs/effects/clouds.md; the CPU reference
// is reference::renderClouds (postfx/reference.h).
//
// Every setting: unit, default, valid range. Out-of-range values are rejected (validateCloudSettings) with
// an error naming the field by its C++ path ("FrameInfo.clouds.topHeight"); the ranges are
// cloudSettingsTable()'s (postfx/settings_table.h).
#pragma once

#include <postfx/export.h>
#include <postfx/result.h>
#include <postfx/temporal.h>
#include <postfx/types.h>

#include <cstdint>

namespace postfx {

// Where the clouds are. A value cast from another int is rejected.
enum class CloudShape : uint32_t {
    // Between bottom_height and top_height above the ground: spherical shells around the planet's centre
    // when the atmosphere is on (they follow its curvature), horizontal planes at height (along the host's
    // up axis) bottom / top when off.
    Layer,
    // Inside an oriented box (the seed's cloud); bottom/top heights are the box's own bottom and top.
    Box,
};

// Quality presets (docs/effects/clouds.md, "Quality presets"): each sets steps, light_steps,
// resolution_scale and temporal.enabled to values chosen from the benchmark's measurements. The defaults of
// those four settings below are Medium's. A value cast from another int is rejected.
enum class CloudQuality : uint32_t {
    Custom,  // steps, light_steps, resolution_scale and temporal as set
    Low,
    Medium,
    High,
    Ultra,
    // The context measures Low..Ultra on the running device (the first twelve frames of every new color
    // extent: the presets in turn, three frames each, median), then uses the highest preset whose clouds
    // passes take at most autoBudgetMs, or Low if none fits (Context::autoQuality("clouds", preset)).
    // With FrameInfo::budgetMs set, the frame's one budget chooses instead. Without GPU timings: Medium.
    Auto,
};

// The box of CloudShape::Box, placed in the host's world frame and units (ContextCreateInfo::world). The
// defaults are postfx's own frame's (y up, metres).
struct CloudBox {
    DVec3 center{0.0, 2000.0, 0.0};  // world position [host units]; each component in [-1e9, 1e9]
    // Half extents along the box's own axes, the host's x, y, z before the rotation [host units]; each in
    // (0, 1e7].
    Vec3 halfSize{2000.0f, 500.0f, 2000.0f};
    // Rotation of the box about the world's up axis (yaw), then about its x (pitch) [deg]: the box's axes
    // are R_up(yaw)·R_x(pitch) applied to the host's x, y, z, each rotation by the right-hand rule on the
    // host's coordinates (glm::rotate); each in [-360, 360].
    float yawDeg = 0.0f;
    float pitchDeg = 0.0f;
};

// The density field's noise (docs/effects/clouds.md, "Density"). Off: the field is 1 everywhere inside the
// shape (with coverage 1, a homogeneous layer).
struct CloudNoiseSettings {
    bool enabled = true;
    // Edge of the base-shape texture (Perlin–Worley) postfx generates [texels]; power of two in [16, 256].
    uint32_t baseSize = 128;
    // Edge of the detail texture (Worley fBm) [texels]; power of two in [8, 128].
    uint32_t detailSize = 32;
    uint32_t seed = 1;  // generator seed; any value
    // The base texture repeats every `tiling` metres along each world axis (postfx's: the host's x, up and
    // other horizontal axis); the detail texture every tiling / 8 [m]; in [1, 1e7].
    float tiling = 12000.0f;
    // How much the detail noise erodes the base shape's edges [1]; in [0, 1]. 0: none.
    float detailStrength = 0.35f;
    // Optional host textures instead of the generated ones (each on its own): 3D views whose first
    // channel holds values in [0, 1], repeat-tileable, sampled with trilinear filtering and repeat
    // addressing over the same periods (tiling, tiling / 8), in `hostTextureLayout`. base_size,
    // detail_size and seed then do not apply to that texture.
    VkImageView hostBaseTexture = VK_NULL_HANDLE;
    VkImageView hostDetailTexture = VK_NULL_HANDLE;
    // With a host texture: SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL.
    VkImageLayout hostTextureLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
};

// A host's 2D coverage map (a weather map, docs/effects/clouds.md, "Density"): where its value m is
// given, the local coverage is coverage × m (m = 0: no cloud there, and no noise is read), and with the
// noise off the field is m. It lies on the world's horizontal plane, u along the host's +x and v along its
// other horizontal axis (+z when y is up, +y when z is up: ContextCreateInfo::world), its texel (0, 0)
// corner at (origin_x, origin_z) on those two axes, repeating every `size`, and moves with the wind like
// the rest of the field. A curved layer reads it at each point's world (x, z) (z: the other axis).
struct CloudCoverageMap {
    // 2D view whose first channel holds values in [0, 1], sampled with bilinear filtering and repeat
    // addressing, in `layout`. VK_NULL_HANDLE: no map (the coverage is the same everywhere).
    VkImageView texture = VK_NULL_HANDLE;
    // SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL.
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    float size = 50000.0f;  // edge of the area the map covers [host units]; in [1, 1e7]
    double originX = 0.0;   // world x of the map's u = 0 edge [host units]; in [-1e9, 1e9]
    // The map's v = 0 edge on the host's other horizontal axis (z when y is up, y when z is up) [host
    // units]; in [-1e9, 1e9].
    double originZ = 0.0;
};

// How the light scattered more than once is modelled (docs/effects/clouds.md, "Multiple scattering"). A
// value cast from another int is rejected.
enum class CloudScatteringModel : uint32_t {
    // The δ-Eddington two-stream solution of a plane-parallel slab around each sample (Joseph, Wiscombe and
    // Weinman 1976; the source-function technique of Toon et al. 1989): the sun's single scattering from
    // the march toward it, the forward-scattered light near the sun's direction, and the diffuse light of
    // all orders from the slab's closed form. Within 6% of a path tracer on the published layer.
    Slab,
    // Wrenninge's octaves (2015, below): art-directable, far too dark in optically thick clouds.
    Octaves,
};

// The multiple scattering: the model, and the octaves' parameters (used by CloudScatteringModel::Octaves
// only). Wrenninge's approximation (2015, "Art-directable multiple volumetric scattering"): octave i adds
// contribution^i × the single-scattering term with extinction toward the sun scaled by attenuation^i and
// the phase's asymmetry by eccentricity^i. contribution <= attenuation conserves energy.
struct CloudMultipleScattering {
    CloudScatteringModel model = CloudScatteringModel::Slab;
    uint32_t octaves = 2;       // 1: single scattering only; in [1, 8]
    float attenuation = 0.5f;   // a [1]; in (0, 1]
    float contribution = 0.5f;  // b [1]; in [0, 1], at most attenuation
    float eccentricity = 0.5f;  // c [1]; in [0, 1]
};

// The clouds' shadow map (docs/effects/clouds.md, "Shadows"): the transmittance toward the sun through the
// clouds over a square around the camera, which both fogs' sunlight and a host's surface lighting read.
struct CloudShadowMapSettings {
    uint32_t size = 512;      // edge [texels]; in [16, 2048]
    float extent = 20000.0f;  // edge [m], centred on the camera; in [100, 1e6]. Beyond it: no cloud shadow.
};

struct CloudSettings {
    bool enabled = false;
    // Custom uses steps, light_steps, resolution_scale and temporal.enabled below; a preset replaces them.
    CloudQuality quality = CloudQuality::Custom;
    // Auto only: GPU time budget for the clouds' passes (excluding noise generation) [ms]; > 0 and finite
    // (checked whatever the quality). Not used when FrameInfo::budgetMs is set.
    float autoBudgetMs = 0.5f;
    CloudShape shape = CloudShape::Layer;
    // The layer's bottom and top above the ground (the host's plane up = 0) [m, whatever the host's units]:
    // bottom in [0, 1e6], top in (bottom, 1e6].
    float bottomHeight = 1500.0f;
    float topHeight = 4000.0f;
    CloudBox box;  // CloudShape::Box only
    // Fraction of the sky the clouds cover [1]; in [0, 1]. 0: no clouds (the effect records nothing).
    // With a coverage map, the map's value multiplies it.
    float coverage = 0.5f;
    CloudCoverageMap coverageMap;
    // Cloud type: the height profile of the density in the layer [1]; in [0, 1]. 0: stratus (dense near
    // the bottom, thinning upward), 1: cumulus (full height, rounded top).
    float cloudType = 0.5f;
    // Extinction coefficient σt where the density field is 1 [1/m]; in [0, 1e3]. 0.02: a 1 km cloud has an
    // optical depth of 20.
    float density = 0.02f;
    float albedo = 0.99f;  // single-scattering albedo σs/σt [1]; in [0, 1]
    // Dual-lobe Henyey–Greenstein phase: (1 - lobe_mix)·HG(g_forward) + lobe_mix·HG(g_back), cosθ between
    // the view direction (from the eye) and the direction toward the sun: g > 0 is brightest toward the sun.
    float anisotropyForward = 0.8f;  // [1]; in [0, 0.999]
    float anisotropyBack = -0.3f;    // [1]; in [-0.999, 0]
    float lobeMix = 0.2f;            // weight of the back lobe [1]; in [0, 1]
    CloudMultipleScattering multipleScattering;
    // Samples along each view ray inside the layer, however long its path through it [1]; in [1, 1024].
    uint32_t steps = 80;
    // Samples of the march toward the sun from each view sample [1]; in [1, 64].
    uint32_t lightSteps = 8;
    // The march toward the sun stops this far from the sample (or where it leaves the layer) [m]; in
    // (0, 1e6]: cloud farther toward the sun casts no shadow on the sample.
    float lightDistance = 6000.0f;
    // View rays are marched to the nearer of the geometry and this distance [m]; in (0, 1e7].
    float maxDistance = 100000.0f;
    // Velocity of the density field along the host's axes [m/s]; each component in [-1e3, 1e3]. The field at
    // time t is the one at t = 0 moved by wind·t (FrameInfo::timeSeconds).
    Vec3 wind{10.0f, 0.0f, 0.0f};
    // Offset each pixel's first sample by interleaved gradient noise of pixel and frame (the temporal
    // accumulation averages it out); false: at the step's midpoint.
    bool jitter = true;
    // March at this fraction of the color image's width and height (rounded up), then composite at full
    // resolution with a depth-aware upsample (docs/effects/clouds.md, "Resolution and temporal") [1]; in
    // [0.25, 1]. 0.5 marches a quarter of the rays, 0.25 a sixteenth.
    float resolutionScale = 0.5f;
    // Temporal accumulation of the march's (L, T), reprojected at the clouds' mean distance and moved by
    // the wind (docs/temporal.md): on by default for the clouds; blend weight in (0, 1].
    TemporalSettings temporal{true, 0.1f};
    // Sparse update, with temporal on: each frame the march updates one texel of every updateBlock ×
    // updateBlock block of its image (in Bayer order, so each is updated once in updateBlock² frames)
    // and the others keep their reprojected history (docs/effects/clouds.md, "Sparse update") [texels];
    // 1, 2 or 4. 1 marches every texel every frame. A frame without history (the first, a camera cut or
    // a reset) marches every texel.
    uint32_t updateBlock = 1;
    // Cast shadows: the shadow map (clouds.shadow_map) dims the sun in both fogs and, through
    // cloudShadowTransform, on the host's surfaces.
    bool castShadows = true;
    CloudShadowMapSettings shadowMap;
    CloudNoiseSettings noise;
};

// Quality Auto's feature bits for the clouds (AutoQualityTimings::features): what changes their presets'
// cost.
inline constexpr uint32_t kCloudAutoFeatureAtmosphere = 1;  // FrameInfo::atmosphere.enabled
inline constexpr uint32_t kCloudAutoFeatureShadows = 2;     // clouds.castShadows
inline constexpr uint32_t kCloudAutoFeatureNoise = 4;       // clouds.noise.enabled

// `settings` with `quality`'s steps, light_steps, resolution_scale and temporal.enabled (Custom: unchanged).
POSTFX_API CloudSettings applyCloudQuality(const CloudSettings& settings, CloudQuality quality);

// Checks every setting against its documented range; InvalidArgument naming the first bad field with its
// C++ path ("FrameInfo.clouds.topHeight: 1000 must be greater than bottomHeight (1500)"). Checked whether or
// not `enabled` is set.
POSTFX_API Status validateCloudSettings(const CloudSettings& settings);

// The clouds' generated noise textures (3D, R8_UNORM, repeat-tileable), for Context::imageView and
// Context::recordImageReadback: held while clouds with noise run.
inline constexpr ResourceName kCloudsBaseNoise{"clouds.base_noise"};
inline constexpr ResourceName kCloudsDetailNoise{"clouds.detail_noise"};
// The shadow map (2D, R32_SFLOAT: transmittance toward the sun), held while clouds cast shadows; sample it
// with linear filtering and clamp-to-edge addressing at cloudShadowTransform's uv.
inline constexpr ResourceName kCloudsShadowMap{"clouds.shadow_map"};

// Where a world position reads the shadow map of the frame `frame` recorded: uv = (dot(u.xyz, P) + u.w,
// dot(v.xyz, P) + v.w) for world position P in `world`, the host's world frame (ContextCreateInfo::world:
// `frame` is in it, and so is P [host units]); outside [0, 1]² there is no cloud shadow (transmittance
// 1). The map holds the transmittance from the shape's bottom along the sun's direction: exact for points
// below the clouds, too dark for points inside them. A host lighting its surfaces before Context::record
// reads the map held from the previous frame with that frame's FrameInfo (one frame late: the clouds move
// by one frame of wind). With the sun at or below the horizon every point maps outside.
struct CloudShadowTransform {
    DVec4 u{0.0, 0.0, 0.0, -1.0};
    DVec4 v{0.0, 0.0, 0.0, -1.0};
};
struct FrameInfo;
POSTFX_API CloudShadowTransform cloudShadowTransform(const FrameInfo& frame, const WorldFrame& world = {});

}  // namespace postfx
