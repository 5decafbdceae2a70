// The air's header (the atmosphere's media and LUTs as every effect reads them: docs/effects/atmosphere.md),
// for the C++ that fills it (postfx/src/atmosphere) and the GLSL that reads it (shaders/common/air/, the
// atmosphere's passes and the clouds' march): the uniform struct, its flags and thresholds.
#ifndef POSTFX_COMMON_AIR_SHARED_H
#define POSTFX_COMMON_AIR_SHARED_H

#include "common/shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

// Flags in AtmosphereUniforms.flags.x
PFX_CONST(uint, kAtmosphereFlagMultipleScattering, 1u);  // add σs·Ψ (Hillaire eq. 10)
PFX_CONST(uint, kAtmosphereFlagDepthReversedZ, 2u);
// The apply pass's depth binding holds postfx.view_distance's surface distances, not the host's depth.
PFX_CONST(uint, kAtmosphereFlagViewDistance, 4u);
// Orders >= 2 from the scattering-orders LUT (J = σR·ΨR + σM·ΨM, the ground lit by E≥2) instead of σs·Ψ.
PFX_CONST(uint, kAtmosphereFlagScatteringOrders, 8u);

// The sky-view LUT's mapping above the top (atmosphere.md#high-up-and-in-space): the span D of its sky
// half's zenith angles falls from Z = π - β at the top to αt - β at this fraction of the atmosphere's
// thickness (linear in the altitude), continuously, so the sky has no seam at the top.
PFX_CONST(float, kAtmosphereSpaceViewMinAltitude, 1.1f);

// Rebuild thresholds (docs/effects/atmosphere.md#frame-plan): the sky-view and aerial-perspective LUTs
// built for a camera and sun are reused while the camera moved less than kAtmosphereRebuildDistance,
// turned (or its projection changed) less than kAtmosphereRebuildAngle, and the sun turned less than
// kAtmosphereRebuildAngle.
PFX_CONST(float, kAtmosphereRebuildDistance, 1.0f);  // [m]
PFX_CONST(float, kAtmosphereRebuildAngle, 1e-3f);    // [rad]

struct AtmosphereUniforms {
    mat4 clipToView;    // Vulkan clip -> camera-relative world direction (this frame's camera)
    mat4 apClipToView;  // the same for the camera the AP LUT was built for
    mat4 apViewToClip;  // its inverse: camera-relative world -> that camera's clip
    // x: ground, y: top [m], z: top² - ground²; w: the scattering-orders LUT's storage scale (its Ψ and E
    // are radiance-like: as the luminance LUTs' scale for a thin atmosphere, at most 1 for a thick one, whose
    // light near the ground would otherwise fall below half floats' normal range)
    vec4 radii;
    vec4 rayleigh;  // rgb: scattering at the ground [1/m], w: 1 / scale height [1/m]
    vec4 mie;       // x: scattering, y: absorption at the ground [1/m], z: 1 / scale height, w: g
    vec4 ozone;     // rgb: absorption at the peak [1/m], w: peak altitude [m]
    vec4 albedo;    // rgb: ground albedo, w: ozone half width [m]
    vec4 camera;    // xyz: planet-centred camera (clamped above the ground) [m], w: its radius
    vec4 apCamera;  // xyz: planet-centred camera of the AP LUT [m], w: AP distance [m]
    vec4 apOffset;  // xyz: this camera - the AP LUT's camera [m]
    vec4 toSun;     // xyz: unit toward the sun, w: cos(sun angular radius)
    vec4 sun;       // rgb: illuminance outside the atmosphere [lux], w: 1 / disk solid angle [1/sr]
    // x: radius, y: sun's cos zenith the sky-view LUT was built for; z: no-geometry depth; w: the storage
    // scale of the luminance LUTs (multiple scattering, sky view, aerial perspective): they hold luminance
    // per unit illuminance times this, so that thin and dense atmospheres both stay normal half floats
    vec4 skyView;
    // The sky-view LUT's mapping at skyView.x's radius r (atmosphere_model.h): x: the horizon's angle β
    // from the nadir, y: its zenith angle Z = π - β, z: the sky half's span D of zenith angles (Z inside
    // the atmosphere, falling to αt - β above the top). sunHorizontal.xyz: the sun's direction across the
    // camera's local horizontal plane (unit; w 0 when the sun is at the zenith or nadir: every azimuth is
    // the sun's)
    vec4 skyHorizon;
    vec4 sunHorizontal;
    // The apply pass's per-frame constants, so that a pixel multiplies where it would divide: the pass is
    // bound by the special-function units (docs/effects/atmosphere.md, "Benchmark").
    vec4 applyNdc;       // xy: 2 / extent, zw: 1 / extent - 1: a pixel's centre in NDC = pixel·xy + zw
    vec4 applySkyView;   // x: 1 / D, y: 1 / β (skyHorizon)
    vec4 applySkyTexel;  // the sky-view LUT's unit -> texel-centre uv: xy: 1 - 1 / size, zw: 0.5 / size
    // x: 1 / the camera's radius, y: 1 / the storage scale (skyView.w), z: the largest cos view zenith
    // of a ray that meets the atmosphere (-cos αt above the top, 2 inside)
    vec4 applyScale;
    vec4 applyAp;  // x: 1 / the AP distance, y: the AP's slices, z: 0.5 / slices, w: slice length [m]
    uvec4 transmittanceLut;  // xy: size, z: steps
    uvec4 msLut;             // xy: size, z: directions per side (n of n×n), w: steps
    uvec4 ordersLut;         // nodes of x: cos view zenith, y: cos sun zenith, z: height, w: azimuth
    uvec4 ordersMarch;       // x: directions per side (n of n×n), y: steps per direction
    uvec4 skyViewLut;        // xy: size, z: steps
    uvec4 apLut;             // xyz: size, w: steps per slice
    uvec4 extent;            // xy: color extent [px]
    uvec4 flags;             // x: kAtmosphereFlag* bits
};

#ifdef __cplusplus
static_assert(sizeof(AtmosphereUniforms) == 3 * 64 + 26 * 16, "AtmosphereUniforms must match std140");
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_COMMON_AIR_SHARED_H
