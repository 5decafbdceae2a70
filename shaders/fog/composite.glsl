// The fog over the host's color (docs/stability.md, "Host color"): out = color · T + L in the color
// image's format. Expects kColorMax (bindings.glsl): the format's largest finite value.
// - ±Inf (and anything beyond ±kColorMax) in the host's color counts as ±kColorMax, and the result is
//   clamped to [-kColorMax, kColorMax]: never Inf, and no Inf · 0 = NaN where the fog is opaque.
// - A NaN channel of the host's color stays NaN in that pixel's channel (postfx does not hide the
//   host's NaN); it reaches no other pixel, since no pass reads another pixel's color.
// - Negative values are composited like any other.
#ifndef POSTFX_FOG_COMPOSITE_GLSL
#define POSTFX_FOG_COMPOSITE_GLSL

vec3 compositeFog(vec3 color, float transmittance, vec3 inScattered) {
    vec3 bounded = clamp(color, vec3(-kColorMax), vec3(kColorMax));
    vec3 result = clamp(bounded * transmittance + inScattered, vec3(-kColorMax), vec3(kColorMax));
    return mix(result, color, isnan(color));
}

#endif
