// Double-precision CPU references of postfx's effects, for tests, benchmarks and `postfx-render
// --reference`. They evaluate the same model as the GPU passes (docs/effects/*.md) with the same input
// data, so that the difference between the two is integration and precision error only.
//
// They work in postfx's own world frame (y up, right-handed, metres: a default WorldFrame) and take no
// WorldFrame: every position, direction, matrix and size in their inputs is in it, as a context converts
// a host's frame into it (docs/integration.md, "World frame and units"). Their cloudShadowRows come from
// cloudShadowTransform of that frame.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/clouds.h>
#include <postfx/export.h>
#include <postfx/fog.h>
#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>
#include <postfx/result.h>
#include <postfx/types.h>

#include <cstdint>
#include <span>
#include <vector>

namespace postfx::reference {

// Everything the fog reference reads: the host's images as plain arrays, and the frame's inputs.
struct FogInputs {
    uint32_t width = 0, height = 0;
    std::span<const float> color;  // RGBA, width·height·4, row-major, top row first
    std::span<const float> depth;  // width·height depth values as the GPU samples them
    DepthConvention depthConvention;

    CameraInput camera;
    SunInput sun;
    Vec3 ambient{0.0f};
    double timeSeconds = 0.0;
    FogSettings settings;
    // With atmosphere.enabled the sun's illuminance is outside the atmosphere: at each sample it is
    // attenuated by the atmosphere's transmittance toward the sun (atmosphereSunTransmittance, from a fine
    // table in double) at the sample's position clamped above the ground. Validated when enabled.
    AtmosphereSettings atmosphere;

    // Shadow map texels (row-major, top row = v 0), empty for none.
    std::span<const float> shadowDepth;
    uint32_t shadowWidth = 0, shadowHeight = 0;
    DMat4 shadowWorldToClip{1.0};
    bool shadowReversedZ = false;
    float shadowDepthBias = 0.0f;

    // The clouds' shadow map (Context::recordImageReadback of kCloudsShadowMap: the transmittance toward the
    // sun), width·height texels, row-major, row 0 at v = 0; empty for none. Each march sample's sunlight is
    // multiplied by it as the GPU's fogs read it (shaders/common/cloud_shadow.glsl): uv from cloudShadowRows
    // (cloudShadowTransform of the frame that made the map) at the sample's world position, 1 outside
    // [0, 1]², else bilinear between texel centres, clamped to the edge texels. Not in the analytic tail.
    std::span<const float> cloudShadow;
    uint32_t cloudShadowWidth = 0, cloudShadowHeight = 0;
    CloudShadowTransform cloudShadowRows;

    // Noise texels in [0, 1], noiseSize³ of them, x fastest then y then z. Required when
    // settings.noise.enabled.
    std::span<const float> noise;
    uint32_t noiseSize = 0;

    uint32_t stepsPerPixel = 4096;  // midpoint steps of the march (the tail is exact)
    uint32_t threads = 0;           // 0: all hardware threads
};

// Renders the fog over `inputs.color` into `out` (RGBA, same layout). Validates like Context::record.
POSTFX_API Status renderFog(const FogInputs& inputs, std::vector<float>& out);

// Everything the froxel fog reference reads: FogInputs' images and frame inputs, the froxel fog's
// settings and the frame's local lights.
struct FroxelFogInputs {
    uint32_t width = 0, height = 0;
    std::span<const float> color;  // RGBA, width·height·4, row-major, top row first
    std::span<const float> depth;  // width·height depth values as the GPU samples them
    DepthConvention depthConvention;

    CameraInput camera;
    SunInput sun;
    Vec3 ambient{0.0f};
    double timeSeconds = 0.0;
    FroxelFogSettings settings;          // its volumes are read through settings.volumes
    std::span<const LocalLight> lights;  // at most kMaxLocalLights, each checked as FrameInfo's
    AtmosphereSettings atmosphere;       // as FogInputs::atmosphere: the sun attenuated at each sample

    // The local lights' shadow atlas (LocalShadowAtlasInput's image read back: row-major, top row = v 0,
    // depth values as the GPU samples them), empty for none; lights[i].shadow indexes localShadows. Read
    // with the GPU's rules (LocalShadow) and settings.localShadowFilter.
    std::span<const float> localShadowDepth;
    uint32_t localShadowWidth = 0, localShadowHeight = 0;
    std::span<const LocalShadow> localShadows;

    // Shadow map texels (row-major, top row = v 0), empty for none; read as the ray-marched fog reads
    // them with a 1×1 kernel.
    std::span<const float> shadowDepth;
    uint32_t shadowWidth = 0, shadowHeight = 0;
    DMat4 shadowWorldToClip{1.0};
    bool shadowReversedZ = false;
    float shadowDepthBias = 0.0f;

    // The clouds' shadow map (Context::recordImageReadback of kCloudsShadowMap: the transmittance toward the
    // sun), width·height texels, row-major, row 0 at v = 0; empty for none. Each march sample's sunlight is
    // multiplied by it as the GPU's fogs read it (shaders/common/cloud_shadow.glsl): uv from cloudShadowRows
    // (cloudShadowTransform of the frame that made the map) at the sample's world position, 1 outside
    // [0, 1]², else bilinear between texel centres, clamped to the edge texels. Not in the analytic tail.
    std::span<const float> cloudShadow;
    uint32_t cloudShadowWidth = 0, cloudShadowHeight = 0;
    CloudShadowTransform cloudShadowRows;

    // Noise texels in [0, 1], noiseSize³ of them, x fastest then y then z. Required when
    // settings.noise.enabled.
    std::span<const float> noise;
    uint32_t noiseSize = 0;

    uint32_t stepsPerPixel =
        4096;              // midpoint steps along [0, min(surface, max_distance)] (the tail is exact)
    uint32_t threads = 0;  // 0: all hardware threads
};

// Renders the froxel fog's model over `inputs.color` into `out` (RGBA, same layout), evaluated
// continuously along each pixel's ray (no grid: its difference to the GPU includes the grid's
// discretisation), docs/effects/froxel-fog.md. InvalidArgument naming the field for bad settings,
// lights or inputs.
POSTFX_API Status renderFroxelFog(const FroxelFogInputs& inputs, std::vector<float>& out);

// Everything the atmosphere reference (docs/effects/atmosphere.md, "Reference") reads.
struct AtmosphereInputs {
    uint32_t width = 0, height = 0;
    std::span<const float> color;  // RGBA, width·height·4, row-major, top row first
    std::span<const float> depth;  // width·height depth values as the GPU samples them
    DepthConvention depthConvention;

    CameraInput camera;  // position: world [m], y = 0 the ground
    SunInput sun;        // illuminance outside the atmosphere
    AtmosphereSettings settings;

    uint32_t stepsPerPixel = 512;  // midpoint steps along each pixel's ray inside the atmosphere; >= 1
    // Ψ (multiple scattering) from a fine table in double: directions (a perfect square) and steps of each
    // node's integral, and the table's nodes over (μ_s, altitude); see atmosphere_reference.h, PsiTable.
    uint32_t psiDirections = 256, psiSteps = 100;
    uint32_t psiTableMuS = 64, psiTableHeights = 64;
    // The scattering orders (settings.multipleScattering "orders") from the reference's own table in double
    // (atmosphere_orders.h), not the settings' LUT sizes: nodes over cos view zenith, cos sun zenith, height
    // and azimuth; directions (a perfect square) and steps at each node; orders before the tail.
    uint32_t ordersViewNodes = 32, ordersSunNodes = 96, ordersHeightNodes = 24, ordersAzimuthNodes = 16;
    uint32_t ordersDirections = 576, ordersSteps = 64, ordersCount = 8;
    uint32_t threads = 0;  // 0: all hardware threads
};

// Renders the atmosphere's model without LUTs, in double, per pixel (docs/effects/atmosphere.md,
// "Reference"), into `out` (RGBA, color's layout; alpha passes through). Pixels without geometry (depth at
// the far plane): the sky along the view ray to the atmosphere's edge, plus the host color and the sun disk
// through the ray's transmittance; where the ray meets the planet the lit ground instead (it hides the host
// color and the disk). Geometry pixels: color·T + in-scattered light from the camera to the surface. With
// settings.enabled false `out` is the color. InvalidArgument naming the field for bad inputs.
POSTFX_API Status renderAtmosphere(const AtmosphereInputs& inputs, std::vector<float>& out);

// Everything the clouds' reference (docs/effects/clouds.md, "Reference") reads.
struct CloudInputs {
    uint32_t width = 0, height = 0;
    std::span<const float> color;  // RGBA, width·height·4, row-major, top row first
    std::span<const float> depth;  // width·height depth values as the GPU samples them
    DepthConvention depthConvention;

    CameraInput camera;
    SunInput sun;  // outside the atmosphere with it on
    Vec3 ambient{0.0f};
    double timeSeconds = 0.0;
    CloudSettings settings;
    // With atmosphere.enabled the layer follows the planet, the sun reaching each sample is attenuated by
    // the atmosphere's transmittance (a fine table in double), and the clouds are seen through the air in
    // front of them: the atmosphere's in-scattering and transmittance, integrated in double from the camera
    // to the clouds' extinction-weighted mean distance (as reference (a) integrates a surface's).
    AtmosphereSettings atmosphere;

    // The noise textures' texels in [0, 1] (x fastest, then y, then z): baseSize³ and detailSize³ of them,
    // as the GPU generated them (read back) or as the CPU port generates them (empty: generated here from
    // the settings' sizes and seed, quantized to 8 bits as the GPU stores them).
    std::span<const float> baseNoise, detailNoise;
    // Their edges when given and not the settings' base_size / detail_size (a host's own textures): 0 is
    // the settings' size.
    uint32_t baseNoiseSize = 0, detailNoiseSize = 0;
    // The host's coverage map (settings.coverage_map's size and origin place it): width·height values in
    // [0, 1], row-major, v = 0 row first, as the GPU samples its first channel; empty: no map.
    std::span<const float> coverageMap;
    uint32_t coverageMapWidth = 0, coverageMapHeight = 0;

    uint32_t stepsPerPixel = 1024;  // midpoint samples along each view ray's part inside the clouds; >= 1
    uint32_t lightSteps = 256;      // midpoint samples of each sample's march toward the sun; >= 1
    uint32_t threads = 0;           // 0: all hardware threads

    // Path-traced truth (docs/effects/clouds.md, "Path-traced truth"): the clouds' radiance from a Monte
    // Carlo volumetric path tracer through the same density field, phase, sun and ambient (every scattering
    // order, no light_distance cut, no octaves) instead of the model's march; the transmittance and the
    // mean distance of the composite still come from the fine march (stepsPerPixel). Off by default.
    bool pathTraced = false;
    // Paths per pixel [1]; in [2, 16777216] (two at least for a standard error). The error falls as
    // 1/sqrt(pathSamples).
    uint32_t pathSamples = 256;
    // Scattering orders kept [1]; 0: all (default), k in [1, 1000000]: the light of at most k events (1:
    // single scattering, the model's first octave without its ambient approximation).
    uint32_t maxScatteringOrders = 0;
    // Seed of the paths' random numbers; any value. Pixel p's path s draws from (pathSeed, p, s): the image
    // does not depend on `threads`.
    uint64_t pathSeed = 1;
};

// Renders the clouds' model over `inputs.color` into `out` (RGBA, color's layout; alpha passes through),
// in double, per pixel with fine steps and a fine march toward the sun (no jitter, no early exit). With
// settings.enabled false `out` is the color. InvalidArgument naming the field for bad inputs.
POSTFX_API Status renderClouds(const CloudInputs& inputs, std::vector<float>& out);
// As above; with inputs.pathTraced and `standardError` not null, also writes the Monte Carlo standard error
// of each pixel's added radiance (through the air in front of the clouds when the atmosphere is on) to
// *standardError (RGBA, color's layout, alpha 0; 0 where no path was traced). Without pathTraced it is all
// 0 (the march is deterministic).
POSTFX_API Status renderClouds(const CloudInputs& inputs, std::vector<float>& out,
                               std::vector<float>* standardError);

// The local-light terms of the model (docs/effects/froxel-fog.md#local-lights), exposed for tests.
// Illuminance [lx] at world position `x` from `light`, before the phase function:
// I·cone/(d² + r²)·window(d), 0 at d >= range.
POSTFX_API Vec3 localLightIlluminance(const LocalLight& light, const DVec3& x);
// The density factor of `volume` at world position `x` [1]: 0 outside, smoothstep(0, edge_falloff,
// depth inside) inside (1 with edge_falloff 0).
POSTFX_API double fogVolumeWeight(const FogVolume& volume, const DVec3& x);

// The model's pieces, exposed for tests.
POSTFX_API double henyeyGreenstein(double cosTheta, double g);  // [1/sr]; g clamped to [-0.999, 0.999]

}  // namespace postfx::reference
