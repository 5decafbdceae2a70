// The aerial perspective of a point in front of the camera, from the atmosphere's aerial-perspective LUTs
// (docs/effects/atmosphere.md, "Composite"): for the atmosphere's apply pass and for the effects that
// composite in front of the sky (the clouds). Expects `atmo` (AtmosphereUniforms), model.glsl, and the
// samplers `apScattering` (3D) and `apTransmittance` (2D array).
#ifndef POSTFX_ATMOSPHERE_AERIAL_PERSPECTIVE_LOOKUP_GLSL
#define POSTFX_ATMOSPHERE_AERIAL_PERSPECTIVE_LOOKUP_GLSL

// Aerial perspective of a surface at camera-relative x: (L per unit illuminance, T). The LUT's frustum is
// the camera's it was built for, apOffset from this one: x is looked up where that camera sees it.
void aerialPerspective(vec3 x, out vec3 luminance, out vec3 transmittance) {
    vec3 xb = x + atmo.apOffset.xyz;
    float distance = length(xb);
    vec3 dir = xb / max(distance, 1e-30);
    vec4 clip = atmo.apViewToClip * vec4(xb, 1.0);
    vec2 uv = clip.w > 0.0 ? clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0) : vec2(0.5);
    // From space the LUT's slices start where each ray enters the atmosphere; inside it, at the camera.
    float entry = 0.0;
    if (atmo.apOffset.w != 0.0) entry = max(raySphere(atmo.apCamera.xyz, dir, atmo.radii.y).x, 0.0);
    float w = clamp((distance - entry) * atmo.applyAp.x, 0.0, 1.0);  // [0, 1] over the LUT's depth
    // L: filtered between the slices' ends (texel k holds the end of slice k); within the first slice it
    // runs from 0 at the entry.
    float z = max(w - atmo.applyAp.z, atmo.applyAp.z);
    vec3 L = textureLod(apScattering, vec3(uv, z), 0.0).rgb;
    luminance = L * (clamp(w * atmo.applyAp.y, 0.0, 1.0) * atmo.applyScale.y);
    // T: the last slice end at or before the surface (layer k - 1; T = 1 at the entry), extended over the
    // rest of the way, Δ, by Beer–Lambert with the extinction at its midpoint: T_k · exp(-σt(mid)·Δ). One
    // bilinear fetch where filtering across slices took two, and exponential within a slice, not linear.
    float ends = w * atmo.applyAp.y;
    float k = floor(ends);
    vec3 T = textureLod(apTransmittance, vec3(uv, max(k - 1.0, 0.0)), 0.0).rgb;
    if (k < 1.0) T = vec3(1.0);
    float rest = (ends - k) * atmo.applyAp.w;
    vec3 mid = atmo.apCamera.xyz + dir * (entry + (k + 0.5 * (ends - k)) * atmo.applyAp.w);
    float r = length(mid);
    if (r < atmo.radii.y) T *= exp(-atmosphereMedium(r - atmo.radii.x).extinction * rest);
    transmittance = T;
}

#endif
