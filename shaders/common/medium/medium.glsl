// The fog's medium and light at a camera-relative position (docs/effects/fog.md, "Model").
// Expects `fog` (FogUniforms), `shadowMap` (sampler2D) and `noiseTexture` (sampler3D) declared.
#ifndef POSTFX_FOG_MEDIUM_GLSL
#define POSTFX_FOG_MEDIUM_GLSL

#include "common/integrate.glsl"
#include "common/medium/flags.glsl"

// h(y) = exp(-height_falloff · (y - base_height)), from its exponent, clamped so that far below the base
// it stays finite.
float heightTermOfExponent(float exponent) {
    return exp(min(exponent, kMaxHeightExponent));
}

float heightTerm(float heightAboveBase) {
    return heightTermOfExponent(-fog.medium.y * heightAboveBase);
}

// noise = clamp(n(u) - threshold, 0, 1) · multiplier at noise coordinate u.
float noiseTermAt(vec3 u) {
    if (!fogFlag(kFogFlagNoise)) return 1.0;
    float n = textureLod(noiseTexture, u, 0.0).r;
    return clamp(n - fog.noiseRemap.x, 0.0, 1.0) * fog.noiseRemap.y;
}

// noise(x), u = camera's noise coordinate + x · 0.01 · tiling.
float noiseTerm(vec3 x) {
    return noiseTermAt(fog.noise.xyz + x * fog.noise.w);
}

// σt = density · h · noise [1/m]. density · noise first (at most 1e6 · 1e3): density · h alone may
// overflow to +Inf (density > 6e3 where h reaches e^80), and +Inf · a noise of 0 would be NaN; +Inf · h is
// +Inf, an opaque step (T = 0), never NaN.
float extinctionOf(float noise, float height) {
    return fog.medium.x * noise * height;
}

float extinction(vec3 x) {
    return extinctionOf(noiseTerm(x), heightTerm(fog.heights.x + x.y));
}

// One PCF tap of the shadow test: whether texel depth `stored` leaves a sample at shadow depth `z` lit.
// Inside the map's depth range [0, 1] the depth comparison with the bias decides. Beyond the far plane
// the map cannot tell where along the texel's column its caster is, only that it is nearer the sun than
// the sample: shadowed wherever the texel holds one (is not the cleared far value), lit where it does not.
// Before the near plane (handled by the caller) nothing is between the sample and the sun: lit.
bool shadowTapLit(float z, float stored, bool reversed) {
    if (reversed) return z < 0.0 ? stored <= 0.0 : z + fog.shadow.x >= stored;
    return z > 1.0 ? stored >= 1.0 : z - fog.shadow.x <= stored;
}

// Shadow-map visibility: mean of kernel² texel tests around the sample (1 outside the map's uv or before
// its near plane).
float shadowVisibilityOfClip(vec4 clip) {
    if (!fogFlag(kFogFlagShadowMap)) return 1.0;
    vec3 s = fogFlag(kFogFlagShadowOrthographic) ? clip.xyz : clip.xyz / clip.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    bool reversed = fogFlag(kFogFlagShadowReversedZ);
    bool beforeNear = reversed ? !(s.z <= 1.0) : !(s.z >= 0.0);  // NaN (clip.w = 0) too, like the reference
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || beforeNear) return 1.0;
    ivec2 size = textureSize(shadowMap, 0);
    ivec2 center = min(ivec2(uv * vec2(size)), size - 1);
    int r = fogShadowRadius();
    // One tap (shadow kernel 1, every preset's): no loop and no clamp (center is inside the map already):
    // 6-9% of the march on the H100.
    if (r == 0) return shadowTapLit(s.z, texelFetch(shadowMap, center, 0).r, reversed) ? 1.0 : 0.0;
    float lit = 0.0;
    for (int b = -r; b <= r; ++b) {
        for (int a = -r; a <= r; ++a) {
            float stored = texelFetch(shadowMap, clamp(center + ivec2(a, b), ivec2(0), size - 1), 0).r;
            lit += shadowTapLit(s.z, stored, reversed) ? 1.0 : 0.0;
        }
    }
    float taps = float(2 * r + 1);
    return lit / (taps * taps);
}

// ... at camera-relative x.
float shadowVisibility(vec3 x) {
    return shadowVisibilityOfClip(fog.viewToShadow * vec4(x, 1.0));
}

// Self-shadowing: transmittance of the height fog from height y (above base) to the sun, closed form
// τ = density · h(y) / (height_falloff · toSun.y); no way out (k·toSun.y <= 0) means none reaches x.
// `height`: h(y) at the sample.
float sunTransmittanceOfHeightTerm(float height) {
    if (!fogFlag(kFogFlagSelfShadow)) return 1.0;
    float a = fog.medium.y * fog.toSun.y;
    if (a <= 0.0) return 0.0;
    return exp(-fog.medium.x * height / a);
}

float sunTransmittance(float heightAboveBase) {
    return sunTransmittanceOfHeightTerm(heightTerm(heightAboveBase));
}

// Optical depth of the height fog (no noise) along a ray segment that starts at `heightAboveBase0`, climbs
// `dirY` per metre and is `len` long (+Inf: to infinity): density · ∫0^len h(y0 + dirY·s) ds in closed
// form (the reference's tailOpticalDepth). With x = a·len, a = height_falloff · dirY, the integral is
// h_low · len · (1 - e^{-|x|}) / |x| where h_low is h at the segment's lower end, so that no term
// overflows while another underflows (a ray descending from far above: h0 = 0, e^{-x} = ∞ would be 0·∞).
float heightFogOpticalDepth(float heightAboveBase0, float dirY, float len) {
    float density = fog.medium.x;
    if (density <= 0.0 || len <= 0.0) return 0.0;
    float a = fog.medium.y * dirY;
    float exponent0 = min(-fog.medium.y * heightAboveBase0, kMaxHeightExponent);
    // Never leaving the medium (a <= 0 to infinity) means infinite optical depth. Otherwise density · h_low
    // · len · (1 - e^{-|x|})/|x| with x = a·len, where the lower end's exponent is exponent0 - x when
    // descending (x < 0), not clamped along the segment, like the reference (for len = ∞: density · h0 / a).
    // The small factors first and e^E as (e^{E/2})², so that the product under- or overflows only when the
    // optical depth itself is beyond float (an infinite one gives T = 0, which is what it is).
    // A finite segment so long that x overflows (len > 3e37 / |a|) is an infinite one: (1 - e^{-x})/x = 0
    // there would make density · len · 0 = ∞ · 0.
    float x = a * len;
    bool infinite = isinf(len) || isinf(x);
    if (infinite && a <= 0.0) return kInfinity;
    // len · (1 - e^{-|x|})/|x| first: it is at most len and at most 1/|a|, where density · len alone
    // overflows for a long segment whose optical depth is finite.
    float factors = infinite ? density / a : density * (len * oneMinusExpOverX(abs(x)));
    float halfExponent = 0.5 * (infinite ? exponent0 : exponent0 + max(-x, 0.0));
    float opticalDepth = factors * exp(halfExponent) * exp(halfExponent);
    // A factor beyond float whose product is not (density · len > 3e38 on a segment whose h is tiny):
    // the same product as a sum of logarithms, +Inf only when the optical depth is.
    if (isinf(opticalDepth) || isnan(opticalDepth))
        opticalDepth = exp(log(infinite ? density / a : density) +
                           (infinite ? 0.0 : log(len * oneMinusExpOverX(abs(x)))) + 2.0 * halfExponent);
    return opticalDepth;
}

// The analytic tail (docs/effects/fog.md, "Analytic tail"): the height fog without noise or shadow map
// from max distance to the surface (or to infinity) behind (L, T), when the flag is on and the surface is
// beyond max distance. `sunPhase`: the sun's illuminance times the phase toward the camera along `dir`.
void addAnalyticTail(vec3 dir, float surfaceDistance, vec3 sunPhase, inout vec3 inScattered,
                     inout float transmittance) {
    float maxDistance = fog.medium.w;
    if (!fogFlag(kFogFlagAnalyticTail) || !(surfaceDistance > maxDistance)) return;
    float y0 = fog.heights.x + dir.y * maxDistance;
    float opticalDepth = heightFogOpticalDepth(y0, dir.y, surfaceDistance - maxDistance);
    vec3 light = sunPhase * sunTransmittance(y0) + fog.ambient.rgb;
    inScattered += integrateStep(transmittance, fog.albedo.rgb * light, opticalDepth);
    transmittance *= exp(-opticalDepth);
}

#endif
