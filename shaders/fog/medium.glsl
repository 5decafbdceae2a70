// The fog's medium and light at a camera-relative position (docs/effects/fog.md, "Model").
// Expects `fog` (FogUniforms), `shadowMap` (sampler2D) and `noiseTexture` (sampler3D) declared.
#ifndef POSTFX_FOG_MEDIUM_GLSL
#define POSTFX_FOG_MEDIUM_GLSL

bool fogFlag(uint flag) { return (fog.flags.x & flag) != 0u; }

// h(y) = exp(-height_falloff · (y - base_height)), exponent clamped so far below the base it stays finite.
float heightTerm(float heightAboveBase) {
    return exp(min(-fog.medium.y * heightAboveBase, 80.0));
}

// noise(x) = clamp(n(u) - threshold, 0, 1) · multiplier, u = camera's noise coordinate + x · 0.01 · tiling.
float noiseTerm(vec3 x) {
    if (!fogFlag(kFogFlagNoise)) return 1.0;
    float n = textureLod(noiseTexture, fog.noise.xyz + x * fog.noise.w, 0.0).r;
    return clamp(n - fog.noiseRemap.x, 0.0, 1.0) * fog.noiseRemap.y;
}

// σt(x) = density · h(y) · noise(x) [1/m]
float extinction(vec3 x) {
    return fog.medium.x * heightTerm(fog.heights.x + x.y) * noiseTerm(x);
}

// Shadow-map visibility: mean of kernel² texel comparisons around the sample (1 outside the map).
float shadowVisibility(vec3 x) {
    if (!fogFlag(kFogFlagShadowMap)) return 1.0;
    vec4 clip = fog.viewToShadow * vec4(x, 1.0);
    vec3 s = clip.xyz / clip.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || s.z < 0.0 || s.z > 1.0) return 1.0;
    ivec2 size = textureSize(shadowMap, 0);
    ivec2 center = min(ivec2(uv * vec2(size)), size - 1);
    int r = int(fog.shadow.y);
    bool reversed = fogFlag(kFogFlagShadowReversedZ);
    float lit = 0.0;
    for (int b = -r; b <= r; ++b) {
        for (int a = -r; a <= r; ++a) {
            float stored = texelFetch(shadowMap, clamp(center + ivec2(a, b), ivec2(0), size - 1), 0).r;
            bool isLit = reversed ? s.z + fog.shadow.x >= stored : s.z - fog.shadow.x <= stored;
            lit += isLit ? 1.0 : 0.0;
        }
    }
    float taps = float(2 * r + 1);
    return lit / (taps * taps);
}

// Self-shadowing: transmittance of the height fog from height y (above base) to the sun, closed form
// τ = density · h(y) / (height_falloff · toSun.y); no way out (k·toSun.y <= 0) means none reaches x.
float sunTransmittance(float heightAboveBase) {
    if (!fogFlag(kFogFlagSelfShadow)) return 1.0;
    float a = fog.medium.y * fog.toSun.y;
    if (a <= 0.0) return 0.0;
    return exp(-fog.medium.x * heightTerm(heightAboveBase) / a);
}

#endif
