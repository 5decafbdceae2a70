// The clouds' header shared by their C++ (postfx/src/clouds) and their GLSL (shaders/clouds): uniform
// struct, binding numbers, workgroup sizes and the model's constants (docs/effects/clouds.md).
#ifndef POSTFX_CLOUDS_SHARED_H
#define POSTFX_CLOUDS_SHARED_H

#include "common/shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

PFX_CONST(uint, kCloudGroupSize, 8);  // march workgroup: 8×8 pixels

PFX_CONST(uint, kCloudBindingUniforms, 0);     // uniform buffer: CloudUniforms
PFX_CONST(uint, kCloudBindingColorIn, 1);      // storage image: host color (read)
PFX_CONST(uint, kCloudBindingColorOut, 2);     // storage image: output
PFX_CONST(uint, kCloudBindingDepth, 3);        // sampler2D: host depth (texelFetch)
PFX_CONST(uint, kCloudBindingBaseNoise, 4);    // sampler3D (repeat): base shape, Perlin–Worley
PFX_CONST(uint, kCloudBindingDetailNoise, 5);  // sampler3D (repeat): detail, Worley fBm
// The atmosphere's uniforms and LUTs (shaders/atmosphere/atmosphere_shared.h), read by the march with
// kCloudConstantAtmosphere.
PFX_CONST(uint, kCloudBindingAtmosphere, 6);        // uniform buffer: AtmosphereUniforms
PFX_CONST(uint, kCloudBindingTransmittanceLut, 7);  // sampler2D: the sun's transmittance (r, μ)
PFX_CONST(uint, kCloudBindingApScattering, 8);      // sampler3D: aerial perspective's in-scattering
PFX_CONST(uint, kCloudBindingApTransmittance, 9);   // sampler2DArray: aerial perspective's T
PFX_CONST(uint, kCloudBindingMultiScattering, 18);  // sampler2D: the atmosphere's Ψ (μs, r)
// Steps of the aerial perspective's march beyond the aerial-perspective LUT's depth (clouds farther than
// atmosphere.aerial_perspective_distance; docs/effects/clouds.md, "Composite").
PFX_CONST(uint, kCloudFarAerialPerspectiveSteps, 8u);
// Reduced resolution and temporal accumulation (docs/effects/clouds.md, "Resolution and temporal").
PFX_CONST(uint, kCloudBindingScatter, 10);  // storage image: the march's (L, T) at its extent
PFX_CONST(uint, kCloudBindingDistance,
          11);  // storage image r32ui: this frame's distances (packCloudDistances)
PFX_CONST(uint, kCloudBindingHistoryIn, 12);    // storage image rgba32f: accumulated (L, T), last frame
PFX_CONST(uint, kCloudBindingHistoryOut, 13);   // storage image rgba32f: accumulated (L, T), this frame
PFX_CONST(uint, kCloudBindingDistanceIn, 14);   // storage image r32ui: last frame's distances
PFX_CONST(uint, kCloudBindingTemporal, 15);     // uniform buffer: TemporalUniforms (common/shared.h)
PFX_CONST(uint, kCloudBindingShadowOut, 16);    // storage image r32f: the shadow map (clouds.shadow)
PFX_CONST(uint, kCloudBindingCoverageMap, 17);  // sampler2D (repeat): the host's coverage map

// Specialization constants of the march (march.comp), bools fixed when its pipeline is created
// (postfx/src/clouds/clouds_effect.cpp): one shader for every frame, the compiler dropping what a frame
// does not take.
PFX_CONST(uint, kCloudConstantAtmosphere, 0u);  // constant_id: the atmosphere's light and aerial perspective
PFX_CONST(uint, kCloudConstantScatter, 1u);     // constant_id: (L', T) into the march's image, not composited
PFX_CONST(uint, kCloudConstantTemporal, 2u);    // constant_id: with scatter, also the texel's distances

// Flags in CloudUniforms.flags.x
PFX_CONST(uint, kCloudFlagNoise, 1u);   // sample the noise textures (off: the field is 1)
PFX_CONST(uint, kCloudFlagCurved, 2u);  // the layer follows the planet (atmosphere on)
PFX_CONST(uint, kCloudFlagBox, 4u);     // CloudShape::Box
PFX_CONST(uint, kCloudFlagDepthReversedZ, 8u);
PFX_CONST(uint, kCloudFlagJitter, 16u);
PFX_CONST(uint, kCloudFlagCoverageMap, 32u);  // read the host's coverage map
// The upsample reads the temporal history, whose alpha is the optical depth τ (temporal.comp), not T.
PFX_CONST(uint, kCloudFlagOpticalDepthHistory, 64u);
// The depth binding holds postfx.view_distance's surface distances, not the host's depth.
PFX_CONST(uint, kCloudFlagViewDistance, 128u);
// Multiple scattering by the δ-Eddington slab (CloudScatteringModel::Slab), not Wrenninge's octaves.
PFX_CONST(uint, kCloudFlagSlabScattering, 256u);

// The model's constants (docs/effects/clouds.md, "Density" and "Light").
PFX_CONST(float, kCloudDetailTilingRatio, 8.0f);  // the detail texture repeats tiling / this [m]
// A sample inside the march's segment may compute a height fraction a rounding error outside [0, 1]; up
// to this much outside it counts as on the boundary.
PFX_CONST(float, kCloudHeightSlack, 1e-4f);
PFX_CONST(float, kCloudBottomRamp, 0.1f);  // the profile rises from 0 over this height fraction
// Top falloff of the height profile, as a fraction of the layer: stratus (cloud type 0) to cumulus (1).
PFX_CONST(float, kCloudTopFalloffStratus, 0.9f);
PFX_CONST(float, kCloudTopFalloffCumulus, 0.3f);
// Ambient light: the uniform radiance FrameInfo::ambient reaches a sample through the cloud above and
// below it taken as slabs of the sample's own extinction, with Elsasser's diffusivity factor for diffuse
// light through a slab: T ≈ exp(-1.66·τ).
PFX_CONST(float, kCloudDiffusivity, 1.66f);
// The slab model (docs/effects/clouds.md, "Multiple scattering"): the sun's cosine to the slab's normal is
// taken as at least this (a sun on the horizon lights the slab's top at grazing incidence), and kμ0 within
// this of 1 is moved off the particular solution's pole.
PFX_CONST(float, kCloudSlabMinCosine, 0.01f);
PFX_CONST(float, kCloudSlabPoleGap, 1e-3f);
PFX_CONST(float, kCloudTransmittanceCutoff, 1e-3f);  // the march stops below this transmittance
PFX_CONST(uint, kCloudShadowSteps, 32u);             // samples of each shadow-map texel's ray toward the sun
// The upsample blends the march's texels whose ray ends within this fraction of the pixel's own surface
// distance (else the nearest in distance); the temporal pass takes history whose reprojection distance is
// within this fraction of the expected one. Clouds' mean distance moves with the jitter by up to a step.
PFX_CONST(float, kCloudUpsampleDistanceTolerance, 0.1f);
PFX_CONST(float, kCloudTemporalDistanceTolerance, 0.15f);
PFX_CONST(float, kCloudTemporalClipGamma, 1.0f);  // the history box: mean ± γ·σ of the 3×3 neighbourhood
// The temporal history holds τ = -ln T; T below this counts as this (τ ≤ 69).
PFX_CONST(float, kCloudMinHistoryTransmittance, 1e-30f);

struct CloudUniforms {
    mat4 clipToView;   // Vulkan clip -> camera-relative world (this frame's camera)
    mat4 boxFromView;  // Box: camera-relative world -> the box's frame (its centre at the origin)
    // xyz: the camera relative to the layer's origin: the planet's centre (curved) or (0, y, 0) (flat) [m]
    vec4 origin;
    vec4 layer;        // x: bottom, y: top altitude [m], z: ground radius [m] (curved), w: 1 / thickness
    vec4 boxHalf;      // Box: xyz half extents [m]
    vec4 noiseBase;    // xyz: offset added to camera-relative x (camera - wind·t, modulo the period), w:
                       // 1/period
    vec4 noiseDetail;  // the same for the detail texture
    // Coverage map: xy: offset added to camera-relative (x, z) ((camera - wind·t - origin) modulo the
    // size), z: 1 / size [1/m] (u), w: ±1 / size (v; negative when v runs along -z)
    vec4 coverageMap;
    vec4 shape;         // x: coverage, y: 1 / top falloff, z: detail strength, w: σt where the field is 1
    vec4 phase;         // x: g forward, y: g back, z: lobe mix, w: albedo
    vec4 multiScatter;  // x: attenuation a, y: contribution b, z: eccentricity c, w: octaves
    // The slab model's δ-scaled medium (lighting.glsl, cloudSlabDiffuse): x: albedo ω', y: asymmetry g',
    // z: the optical depth's scale 1 - ω·f, w: the phase's first moment g (f: its second moment)
    vec4 slab;
    vec4 sun;        // rgb: illuminance [lux] (outside the atmosphere with it on), w: light distance [m]
    vec4 toSun;      // xyz: unit toward the sun
    vec4 ambient;    // rgb: uniform incident radiance
    vec4 march;      // x: max distance [m], y: no-geometry depth
    vec4 shadow;     // shadow map: xyz its centre on the shape's bottom plane (camera-relative), w extent [m]
    uvec4 counts;    // x: steps, y: light steps, z: octaves, w: shadow map size [texels]
    vec4 windDelta;  // xyz: how far the wind moved the clouds since the previous recorded frame [m]
    uvec4 extent;    // xy: color extent [px], z: frame index, w: 0
    uvec4 marchExtent;  // xy: the march's extent [px] (the color's at resolution scale 1)
    // Sparse update (temporal.comp): x: this frame's block k (1: the march updates every texel), yz: the
    // texel it updates in each k×k block (texel = block·k + yz); w: invocations per ray (1, 2 or 4, a
    // divisor of kCloudGroupSize), each marching a segment of its steps (march.comp)
    uvec4 sparse;
    uvec4 flags;  // x: kCloudFlag* bits
};

#ifdef __cplusplus
static_assert(sizeof(CloudUniforms) == 2 * 64 + 21 * 16, "CloudUniforms must match std140");
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_CLOUDS_SHARED_H
