// The atmosphere's header shared by its C++ (postfx/src/atmosphere) and its GLSL (shaders/atmosphere):
// binding numbers, workgroup sizes, the orders pass's push constants (docs/effects/atmosphere.md). The
// uniform struct, flags and thresholds other effects read too are in common/air_shared.h.
#ifndef POSTFX_ATMOSPHERE_SHARED_H
#define POSTFX_ATMOSPHERE_SHARED_H

#include "common/air_shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

PFX_CONST(uint, kAtmosphereGroupSize, 8);  // transmittance and sky-view workgroups: 8×8 invocations
// The apply pass's workgroup (pixels).
PFX_CONST(uint, kAtmosphereApplyGroupX, 8);
PFX_CONST(uint, kAtmosphereApplyGroupY, 8);
PFX_CONST(uint, kAtmosphereApplyRows, 2);  // pixels per invocation, kAtmosphereApplyGroupY rows apart
// The aerial-perspective LUT: one workgroup per (x, y) texel column, its invocations sharing the slices.
PFX_CONST(uint, kAtmosphereApGroupSize, 32);
// The sky-view LUT: each texel's ray split among this many invocations (a z of its workgroup).
PFX_CONST(uint, kAtmosphereSkyViewSplit, 4);
// The multiple-scattering LUT: one workgroup per texel, one invocation per direction (at most 1024).
PFX_CONST(uint, kAtmosphereMsGroupSize, 64);
// Hillaire's Ψ's bound per unit sun illuminance [1/sr]: 2/π. The diffuse radiance in a plane-parallel
// atmosphere over a ground of albedo <= 1 is largest where nothing is absorbed (conservative air over a
// white ground): no net flux, so the diffusion approximation's K = J/3 is the same at every depth as at the
// top, where a sun at cosine μs gives K = E·(μs/6 + μs²/4)/π (its reflected flux E·μs leaving as a
// Lambertian field, and the beam): J <= 1.25·E/π. 2/π leaves margin for the approximation. The series
// L2/(1 - f_ms) exceeds it where it diverges (f_ms -> 1: thick air that barely absorbs, whose light leaves by
// diffusion, not in the single flight f_ms assumes).
PFX_CONST(float, kAtmosphereMaxPsi, 0.63661977f);
// The scattering-orders LUT: one workgroup per (sun, height) node, its invocations sharing the directions.
PFX_CONST(uint, kAtmosphereOrdersGroupSize, 64);
PFX_CONST(uint, kAtmosphereOrdersMaxDirections, 576);  // 24×24: the shared memory of lavapipe

PFX_CONST(uint, kAtmosphereBindingUniforms, 0);       // uniform buffer: AtmosphereUniforms
PFX_CONST(uint, kAtmosphereBindingTransmittance, 1);  // rgba16f 2D: T to the top (r, μ)
// rgba16f 3D: the multiple-scattering LUT, "hillaire": Ψ per unit illuminance at (μs, r, 0); "orders": the
// scattering-orders LUT (orders_lookup.glsl): ΨR, ΨM at (μ + azimuth·μ nodes, μs, height + {0, height
// nodes}) and the ground's E≥2 at (any, μs, 2·height nodes)
PFX_CONST(uint, kAtmosphereBindingMultiScattering, 2);
// rgba16f 2D: sky luminance per unit illuminance, one mapping for every altitude (model.glsl,
// skyViewParams; atmosphere.md#high-up-and-in-space)
PFX_CONST(uint, kAtmosphereBindingSkyView, 3);
PFX_CONST(uint, kAtmosphereBindingApScattering, 4);     // rgba16f 3D: AP in-scattering per unit illuminance
PFX_CONST(uint, kAtmosphereBindingApTransmittance, 5);  // rgba16f 2D array, layer k = slice k: AP T
PFX_CONST(uint, kAtmosphereBindingColorIn, 6);          // storage image: host color (read)
PFX_CONST(uint, kAtmosphereBindingColorOut, 7);         // storage image: output
PFX_CONST(uint, kAtmosphereBindingDepth, 8);            // sampler2D: host depth (texelFetch)
PFX_CONST(uint, kAtmosphereBindingOrdersIn, 9);         // sampler3D: order n of the orders LUT's layout
PFX_CONST(uint, kAtmosphereBindingOrdersOut, 10);       // rgba16f 3D: order n + 1

// The orders pass's push constants: which order it computes (1: from single scattering) and whether it is
// the last (it adds the geometric tail).
struct AtmosphereOrderConstants {
    uint order;
    uint last;
};

#ifdef __cplusplus
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_ATMOSPHERE_SHARED_H
