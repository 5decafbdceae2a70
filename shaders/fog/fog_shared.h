// The ray-marched fog's header shared by its C++ (postfx/src/fog) and its GLSL (shaders/fog): uniform
// structs, binding numbers, workgroup sizes, flags. Includes the common header (PFX_CONST).
#ifndef POSTFX_FOG_SHARED_H
#define POSTFX_FOG_SHARED_H

#include "common/shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

PFX_CONST(uint, kFogGroupSize, 8);  // temporal and upsample workgroups: kFogGroupSize² pixels
// The march's workgroup: kFogMarchGroupX × kFogMarchGroupY pixels
PFX_CONST(uint, kFogMarchGroupX, 32);
PFX_CONST(uint, kFogMarchGroupY, 8);

PFX_CONST(uint, kFogBindingColorIn, 0);    // storage image: host color (read)
PFX_CONST(uint, kFogBindingColorOut, 1);   // storage image: output (host color itself when in place)
PFX_CONST(uint, kFogBindingDepth, 2);      // sampler2D: host depth (texelFetch)
PFX_CONST(uint, kFogBindingShadowMap, 3);  // sampler2D: host shadow map (texelFetch)
PFX_CONST(uint, kFogBindingNoise, 4);      // sampler3D: noise, trilinear, repeat
PFX_CONST(uint, kFogBindingUniforms, 5);   // uniform buffer: FogUniforms
// storage image: the reduced-resolution march (rgb: in-scattered radiance, a: transmittance), postfx's own
PFX_CONST(uint, kFogBindingScatter, 6);
// Temporal accumulation (shaders/fog/temporal.comp, docs/effects/fog.md#temporal): the previous frame's
// accumulated (L, T) and the distance each texel's ray ended at (postfx's own, at the march's size), the
// accumulation this frame writes, this frame's distances (written by the march) and the TemporalUniforms.
PFX_CONST(uint, kFogBindingHistoryIn, 7);   // storage image, color format: previous (L, T)
PFX_CONST(uint, kFogBindingHistoryOut, 8);  // storage image, color format: accumulated (L, T)
PFX_CONST(uint, kFogBindingDistanceIn, 9);  // storage image r32f: previous surface distance [m], ∞: none
PFX_CONST(uint, kFogBindingDistance, 10);   // storage image r32f: this frame's surface distance [m]
PFX_CONST(uint, kFogBindingTemporal, 11);   // uniform buffer: TemporalUniforms
// With the atmosphere on (docs/effects/atmosphere.md): its transmittance LUT, for the sun's light at each
// sample (fog/atmosphere_light.glsl); the froxel fog binds it at the same number.
PFX_CONST(uint, kFogBindingAtmosphere, 12);  // sampler2D rgba16f: the atmosphere's transmittance LUT
// With clouds casting shadows (docs/effects/clouds.md, "Shadows"): their shadow map, for the sun's light
// at each sample; the froxel fog binds it at the same number.
PFX_CONST(uint, kFogBindingCloudShadow, 13);  // sampler2D r32f: transmittance toward the sun
// A history texel is used for a pixel when the distance its ray ended at (min(surface, max distance))
// is within this fraction of the distance from the previous camera to the pixel's point (disocclusion).
PFX_CONST(float, kFogTemporalDistanceTolerance, 0.1f);
// A texel whose history moved on screen by at least this many texels blends the depth-aware 3×3 mean of
// this frame's march instead of its own value; a still one its own (temporal.comp, step 5).
PFX_CONST(float, kFogTemporalFilterMotion, 0.5f);
// ... over the neighbours whose surface is the texel's (kFogTemporalDistanceTolerance) and whose fog is
// within this of its own: transmittance absolute, in-scattered light relative (temporal.comp, similarFog).
PFX_CONST(float, kFogTemporalFilterRange, 0.25f);

// Upsampling of a reduced-resolution march (shaders/fog/upsample.comp): a low-resolution sample
// is used for a pixel when its surface distance is within this fraction of the pixel's [1].
PFX_CONST(float, kFogUpsampleDistanceTolerance, 0.1f);

// The height term's exponent -height_falloff·(y - base_height) is clamped to at most this, so that
// h(y) = e^80 ≈ 5.5e34 stays finite in float far below the base height (fog.md, "Model").
PFX_CONST(float, kMaxHeightExponent, 80.0f);

// Specialization constants of the fog's march (fog/medium.glsl): its flags and its shadow kernel's
// radius, fixed when the pipeline is created (postfx/src/fog/fog_effect.cpp), so that the compiler drops
// the branches a frame does not take. A pipeline created without them (the froxel fog's scatter, the
// benchmark's baselines) reads both from FogUniforms.
PFX_CONST(uint, kFogConstantFlags, 0u);               // constant_id: FogUniforms.flags.x
PFX_CONST(uint, kFogConstantShadowRadius, 1u);        // constant_id: FogUniforms.shadow.y
PFX_CONST(uint, kFogFlagsFromUniforms, 0x80000000u);  // the flags constant's default: read the uniforms

// Flags in FogUniforms.flags.x
PFX_CONST(uint, kFogFlagJitter, 1u);
PFX_CONST(uint, kFogFlagNoise, 2u);
PFX_CONST(uint, kFogFlagShadowMap, 4u);
PFX_CONST(uint, kFogFlagShadowReversedZ, 8u);
PFX_CONST(uint, kFogFlagSelfShadow, 16u);
PFX_CONST(uint, kFogFlagAnalyticTail, 32u);
PFX_CONST(uint, kFogFlagDepthReversedZ, 64u);
PFX_CONST(uint, kFogFlagSkipEmptySpace, 128u);
PFX_CONST(uint, kFogFlagAtmosphere, 256u);   // the sun's light through the atmosphere's transmittance LUT
PFX_CONST(uint, kFogFlagCloudShadow, 512u);  // the sun's light through the clouds' shadow map
// The depth binding holds postfx.view_distance's surface distances, not the host's depth (shared by the
// frame's effects; docs/architecture.md, "Shared inputs").
PFX_CONST(uint, kFogFlagViewDistance, 1024u);
// The shadow map's projection is orthographic (viewToShadow's last row is exactly (0, 0, 0, 1), a sun's
// map): clip w is 1 and the march does not divide by it (the same bits, fewer instructions).
PFX_CONST(uint, kFogFlagShadowOrthographic, 2048u);

struct FogUniforms {
    mat4 clipToView;      // Vulkan clip -> camera-relative world (inverse(projection · rotation(view)))
    mat4 viewToShadow;    // camera-relative world -> shadow clip (built in double on the host)
    vec4 toSun;           // xyz: unit direction toward the sun
    vec4 sunIlluminance;  // rgb [lux]
    vec4 ambient;         // rgb: uniform incident radiance
    vec4 albedo;          // rgb: σs/σt
    vec4 medium;          // x: density [1/m], y: height falloff [1/m], z: HG g (clamped), w: max distance [m]
    vec4 heights;         // x: camera y - base height [m], y: the medium's top above base [m] (may be +Inf)
    vec4 noise;           // xyz: noise coordinate of the camera, wrapped to [0,1); w: 0.01·tiling [1/m]
    vec4 noiseRemap;      // x: threshold, y: multiplier
    vec4 shadow;          // x: depth bias, y: kernel radius in texels (kernel = 2r+1)
    vec4 march;           // x: transmittance cutoff, y: depth of "no geometry" (0 or 1)
    uvec4 extent;         // x, y: output size [px], z: steps, w: frame index (mod 2^32)
    uvec4 scatterExtent;  // x, y: size of the march [px]: extent.xy · resolution scale, rounded up
    uvec4 flags;          // x: kFogFlag* bits
    // kFogFlagAtmosphere: x: the planet's ground radius, y: the atmosphere's top radius [m], zw: the
    // transmittance LUT's size [texels]; planetCamera.xyz: the camera's planet-centred position [m].
    vec4 planet;
    vec4 planetCamera;
    // kFogFlagCloudShadow: the clouds' shadow map's uv of camera-relative x: (dot(u.xyz, x) + u.w, ...)
    vec4 cloudShadowU;
    vec4 cloudShadowV;
};

#ifdef __cplusplus
static_assert(sizeof(FogUniforms) == 2 * 64 + 17 * 16, "FogUniforms must match std140");
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_FOG_SHARED_H
