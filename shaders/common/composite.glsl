// An effect over the host's color (docs/stability.md, "Host color"): out = color · T + L in the color
// image's format, for every effect's composite. Expects kColorMax: the format's largest finite value.
// - ±Inf (and anything beyond ±kColorMax) in the host's color counts as ±kColorMax, and the result is
//   clamped to [-kColorMax, kColorMax]: never Inf, and no Inf · 0 = NaN where the effect is opaque.
// - A NaN channel of the host's color stays NaN in that pixel's channel (postfx does not hide the
//   host's NaN); it reaches no other pixel, since no pass reads another pixel's color.
// - Negative values are composited like any other.
#ifndef POSTFX_COMMON_COMPOSITE_GLSL
#define POSTFX_COMMON_COMPOSITE_GLSL

vec3 compositeOver(vec3 color, vec3 transmittance, vec3 luminance) {
    vec3 bounded = clamp(color, vec3(-kColorMax), vec3(kColorMax));
    vec3 result = clamp(bounded * transmittance + luminance, vec3(-kColorMax), vec3(kColorMax));
    return mix(result, color, isnan(color));
}
vec3 compositeOver(vec3 color, float transmittance, vec3 luminance) {
    return compositeOver(color, vec3(transmittance), luminance);
}

#endif
