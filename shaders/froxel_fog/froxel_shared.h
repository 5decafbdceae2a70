// The froxel fog's header shared by its C++ (postfx/src/froxel_fog) and its GLSL (shaders/froxel_fog):
// uniform structs, binding numbers, workgroup sizes, flags (docs/effects/froxel-fog.md). The medium's
// uniforms are the shared medium's FogUniforms (common/medium_shared.h): the froxel fog's kernels bind
// them as `fog` and include shaders/common/medium/medium.glsl.
#ifndef POSTFX_FROXEL_SHARED_H
#define POSTFX_FROXEL_SHARED_H

#include "common/medium_shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

PFX_CONST(uint, kFroxelGroupSize, 8);  // scatter, integrate, apply: 8×8 invocations
// Shadow change (shadow_change.comp): 4×4×4 invocations, one per block of 2×2×2 froxels, so that a group's
// blocks lie in one cluster of the light lists and its warps loop over one list.
PFX_CONST(uint, kFroxelBlockGroupSize, 4);

// Light lists: one bit per light (1 = its sphere of influence touches the cluster) for each cluster of
// kFroxelClusterSize² froxels × kFroxelClusterSlices slices, in words of 32 lights.
PFX_CONST(uint, kFroxelClusterSize, 8);
PFX_CONST(uint, kFroxelClusterSlices, 16);
PFX_CONST(uint, kFroxelMaxLightWords, 8);  // kMaxLocalLights / 32

PFX_CONST(uint, kFroxelBindingColorIn, 0);     // storage image: host color (read)
PFX_CONST(uint, kFroxelBindingColorOut, 1);    // storage image: output (host color itself when in place)
PFX_CONST(uint, kFroxelBindingDepth, 2);       // sampler2D: host depth (texelFetch)
PFX_CONST(uint, kFroxelBindingShadowMap, 3);   // sampler2D: host shadow map (texelFetch)
PFX_CONST(uint, kFroxelBindingNoise, 4);       // sampler3D: noise, trilinear, repeat
PFX_CONST(uint, kFroxelBindingUniforms, 5);    // uniform buffer: FogUniforms, FroxelUniforms
PFX_CONST(uint, kFroxelBindingLights, 6);      // uniform buffer: FroxelLights
PFX_CONST(uint, kFroxelBindingLightLists, 7);  // storage image r32ui: cluster light bits
PFX_CONST(uint, kFroxelBindingScatter, 8);     // storage image rgba16f: per froxel (albedo·light, σt)
PFX_CONST(uint, kFroxelBindingIntegrated,
          9);  // storage image / sampler3D rgba16f: (L, T) to each slice's end
// Temporal accumulation (docs/effects/froxel-fog.md#temporal): the previous frame's accumulated scatter
// volume (RGBA32F, fetched texel by texel; the scatter pass writes the other of two) and TemporalUniforms.
PFX_CONST(uint, kFroxelBindingHistory, 10);   // sampler3D rgba32f: previous accumulated scatter volume
PFX_CONST(uint, kFroxelBindingTemporal, 11);  // uniform buffer: TemporalUniforms
// sampler2D: the atmosphere's transmittance LUT (common/medium/atmosphere_light.glsl), with the atmosphere on
PFX_CONST(uint, kFroxelBindingAtmosphere, kMediumBindingAtmosphere);
// sampler2D: the clouds' shadow map (common/medium/atmosphere_light.glsl), with clouds casting shadows
PFX_CONST(uint, kFroxelBindingCloudShadow, kMediumBindingCloudShadow);
// Local lights' shadows (froxel-fog.md#local-light-shadows): the host's atlas, its faces, and (temporal)
// the shadowed lights' light at each block's centre in this and the previous frame, and where it changed.
PFX_CONST(uint, kFroxelBindingShadowAtlas, 14);  // sampler2D: host local shadow atlas (texelFetch)
PFX_CONST(uint, kFroxelBindingShadowFaces, 15);  // storage buffer: FroxelShadowFace[]
// Per block of 2×2×2 froxels (shadow_change.comp).
PFX_CONST(uint, kFroxelBindingShadowedLight, 16);    // storage image r32f: written this frame
PFX_CONST(uint, kFroxelBindingShadowedHistory, 17);  // sampler3D r32f: the previous frame's
PFX_CONST(uint, kFroxelBindingShadowChange, 18);     // storage image / sampler3D rgba8: 1 where it changed

// Flags in FroxelUniforms.counts.y
PFX_CONST(uint, kFroxelFlagLogSlices, 1u);        // depth distribution Log (else Power)
PFX_CONST(uint, kFroxelFlagTricubic, 2u);         // apply: tricubic B-spline (else trilinear)
PFX_CONST(uint, kFroxelFlagShadowFilter, 4u);     // local shadows: 2×2 bilinear PCF (else one texel)
PFX_CONST(uint, kFroxelFlagShadowedHistory, 8u);  // temporal: the previous shadowed light is valid

// FroxelLight.shadow.x of a light without a shadow.
PFX_CONST(uint, kFroxelNoShadow, 0xffffffffu);
// Temporal: a froxel's history is dropped where its shadowed lights' light at the centre changed by more
// than this fraction of the larger of the two (a caster or a shadowed light moved; froxel-fog.md#temporal).
PFX_CONST(float, kFroxelShadowChangeReject, 0.25f);

// Largest value stored in the rgba16f volumes (the largest finite half): never Inf.
PFX_CONST(float, kFroxelHalfMax, 65504.0f);
// Temporal accumulation: the blur the repeated trilinear resampling of the history may add up to
// [froxel²] (scatter.comp, accumulate; froxel-fog.md#temporal).
PFX_CONST(float, kFroxelTemporalBlurBudget, 0.25f);

struct FroxelUniforms {
    uvec4 grid;    // xyz: froxels along x, y and depth; w: lights this frame
    vec4 jitter;   // xyz: sample position inside each froxel, [0, 1) (Halton or 0.5); w: storage scale
    vec4 slices;   // x: near [m], y: far = max distance [m], z: power exponent k, w: ln(far / near)
    uvec4 counts;  // x: fog volumes, y: kFroxelFlag* bits, z: light-list words per cluster, w: 0
    // Bit i % 32 of word i / 32 (of shadowed[i / 128][i / 32 % 4]): light i has a shadow.
    uvec4 shadowed[2];
    // Fog volume i: volumes[2i] = (camera-relative centre [m], edge falloff [m]); volumes[2i + 1] = box:
    // (half size [m], density [1/m]), sphere: (radius [m], -1, 0, density [1/m]).
    vec4 volumes[2 * 64];
};

// One local light, camera-relative (postfx::LocalLight).
struct FroxelLight {
    vec4 positionRange;      // xyz: position [m], w: range [m]
    vec4 intensityRadius;    // rgb: intensity [cd], w: source radius [m]
    vec4 directionCosOuter;  // xyz: unit cone axis, w: cos(outer angle); -2 for a point light
    vec4 cosInnerBias;       // x: cos(inner angle), y: its shadow's depth bias
    // Its shadow: x first face in the faces buffer (kFroxelNoShadow: none), y face count, z reversed Z
    uvec4 shadow;
};

// One face of a local light's shadow (postfx::LocalShadowFace), camera-relative.
struct FroxelShadowFace {
    // Camera-relative world -> the face's clip space, by rows (clip.x = dot(rows[0], (x, 1)), ...): the
    // face test needs x, y and w only.
    vec4 clipRows[4];
    vec4 region;  // xy: first texel, zw: size [texels] in the atlas
};

struct FroxelLights {
    FroxelLight lights[256];  // kMaxLocalLights
};

#ifdef __cplusplus
static_assert(sizeof(FroxelUniforms) == 6 * 16 + 128 * 16, "FroxelUniforms must match std140");
static_assert(sizeof(FroxelLight) == 80, "FroxelLight must match std140");
static_assert(2 * kFroxelBlockGroupSize == kFroxelClusterSize &&
                  kFroxelClusterSlices % (2 * kFroxelBlockGroupSize) == 0,
              "a shadow-change group's blocks must lie in one cluster");
static_assert(sizeof(FroxelLights) == 256 * 80, "FroxelLights must match std140");
static_assert(sizeof(FroxelShadowFace) == 80, "FroxelShadowFace must match std430");
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_FROXEL_SHARED_H
