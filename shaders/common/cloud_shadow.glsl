// The clouds' shadow (docs/effects/clouds.md, "Shadows"): the transmittance of the cloud layer toward the
// sun, read by every consumer of sunlight below the clouds (both fogs; hosts through
// postfx::cloudShadowTransform). The map holds, per texel, the transmittance along the sun's direction
// from a point on the layer's bottom; a point below it reads the texel where its ray toward the sun
// crosses the bottom: uv = (dot(u.xyz, x) + u.w, dot(v.xyz, x) + v.w) for camera-relative x, an oblique
// projection folded into two rows. Outside the map, 1 (no shadow); the sun at or below the horizon gives
// rows that put every point outside.
#ifndef POSTFX_COMMON_CLOUD_SHADOW_GLSL
#define POSTFX_COMMON_CLOUD_SHADOW_GLSL

float cloudShadow(sampler2D map, vec4 u, vec4 v, vec3 x) {
    vec2 uv = vec2(dot(u.xyz, x) + u.w, dot(v.xyz, x) + v.w);
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return 1.0;
    return textureLod(map, uv, 0.0).r;
}

#endif
