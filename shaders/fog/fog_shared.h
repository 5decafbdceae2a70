// The ray-marched fog's header shared by its C++ (postfx/src/fog) and its GLSL (shaders/fog): uniform
// binding numbers, workgroup sizes, temporal thresholds. The medium's uniforms and flags (shared with the
// froxel fog) are in common/medium_shared.h.
#ifndef POSTFX_FOG_SHARED_H
#define POSTFX_FOG_SHARED_H

#include "common/medium_shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

PFX_CONST(uint, kFogGroupSize, 8);  // temporal and upsample workgroups: kFogGroupSize² pixels
// The march's workgroup: kFogMarchGroupX × kFogMarchGroupY pixels
PFX_CONST(uint, kFogMarchGroupX, 32);
PFX_CONST(uint, kFogMarchGroupY, 8);
// fog.lookup: the march's steps per slice of the volumetrics lookup (fog/lookup.comp).
PFX_CONST(uint, kFogLookupStepsPerSlice, 2);

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

#ifdef __cplusplus
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_FOG_SHARED_H
