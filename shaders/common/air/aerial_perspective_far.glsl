// The aerial perspective of a point at any distance (docs/effects/clouds.md, "Composite"): the
// aerial-perspective LUT up to its depth (aerial_perspective_lookup.glsl), then the atmosphere's march
// (march.glsl) from the LUT's last slice end to the point, composed front to back (L = L_lut + T_lut·L_far,
// T = T_lut·T_far). The LUT alone stops at its depth (32 km by default): a cloud 100 km away would get 32 km
// of haze. Expects aerial_perspective_lookup.glsl and march.glsl with ATMOSPHERE_MS.
#ifndef POSTFX_ATMOSPHERE_AERIAL_PERSPECTIVE_FAR_GLSL
#define POSTFX_ATMOSPHERE_AERIAL_PERSPECTIVE_FAR_GLSL

// (L per unit illuminance, T) of camera-relative x; `steps` uniform steps beyond the LUT.
void aerialPerspectiveAnyDistance(vec3 x, uint steps, out vec3 luminance, out vec3 transmittance) {
    aerialPerspective(x, luminance, transmittance);
    vec3 xb = x + atmo.apOffset.xyz;  // in the frame of the camera the LUT was built for
    float distance = length(xb);
    vec3 dir = xb / max(distance, 1e-30);
    float entry = 0.0;
    if (atmo.apOffset.w != 0.0) entry = max(raySphere(atmo.apCamera.xyz, dir, atmo.radii.y).x, 0.0);
    float lutEnd = entry + atmo.apCamera.w;  // apCamera.w: the LUT's depth [m]
    if (!(distance > lutEnd)) return;
    AtmosphereMarch far =
        atmosphereMarch(atmo.apCamera.xyz, dir, lutEnd, distance, steps, false, atmo.toSun.xyz);
    luminance += transmittance * far.luminance;
    transmittance *= far.transmittance;
}

#endif
