// The shared medium's header (FogMedium: the ray-marched and the froxel fog), for its C++
// (postfx/src/common/medium.h) and its GLSL (shaders/common/medium/): the uniform struct both fogs bind
// as `fog`, its flags and specialization constants, the height term's clamp.
#ifndef POSTFX_COMMON_MEDIUM_SHARED_H
#define POSTFX_COMMON_MEDIUM_SHARED_H

#include "common/shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

// With the atmosphere on (docs/effects/atmosphere.md): its transmittance LUT, for the sun's light at each
// sample (common/medium/atmosphere_light.glsl); both fogs bind it at this number.
PFX_CONST(uint, kMediumBindingAtmosphere, 12);  // sampler2D rgba16f: the atmosphere's transmittance LUT
// With clouds casting shadows (docs/effects/clouds.md, "Shadows"): their shadow map, for the sun's light
// at each sample; both fogs bind it at this number.
PFX_CONST(uint, kMediumBindingCloudShadow, 13);  // sampler2D r32f: transmittance toward the sun

// The height term's exponent -height_falloff·(y - base_height) is clamped to at most this, so that
// h(y) = e^80 ≈ 5.5e34 stays finite in float far below the base height (fog.md, "Model").
PFX_CONST(float, kMaxHeightExponent, 80.0f);

// Specialization constants of the fog's march (common/medium/medium.glsl): its flags and its shadow kernel's
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

#endif  // POSTFX_COMMON_MEDIUM_SHARED_H
