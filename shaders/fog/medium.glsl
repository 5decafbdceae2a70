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

// 1 when a stored shadow-map depth lets the sun reach shadow-space depth z (bias toward lit), else 0.
float shadowLit(float stored, float z) {
    bool lit = fogFlag(kFogFlagShadowReversedZ) ? z + fog.shadow.x >= stored : z - fog.shadow.x <= stored;
    return lit ? 1.0 : 0.0;
}

// Shadow-map visibility: mean of the kernel² texel comparisons around the sample (1 outside the map).
// The texels are read 2×2 at a time with textureGather: a gather at the corner shared by texels
// (i, j) .. (i+1, j+1) returns exactly those four (clamp-to-edge clamps indices as the reference does),
// so a 3×3 kernel costs 4 fetches instead of 9 and compares the same texels.
float shadowVisibility(vec3 x) {
    if (!fogFlag(kFogFlagShadowMap)) return 1.0;
    vec4 clip = fog.viewToShadow * vec4(x, 1.0);
    vec3 s = clip.xyz / clip.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || s.z < 0.0 || s.z > 1.0) return 1.0;
    ivec2 size = textureSize(shadowMap, 0);
    ivec2 center = min(ivec2(uv * vec2(size)), size - 1);
    int r = int(fog.shadow.y);
    if (r == 0) return shadowLit(texelFetch(shadowMap, center, 0).r, s.z);
    int n = 2 * r + 1;
    vec2 texelSize = 1.0 / vec2(size);
    float lit = 0.0;
    for (int by = 0; by < n; by += 2) {
        for (int bx = 0; bx < n; bx += 2) {
            ivec2 corner = center - r + ivec2(bx, by);  // top-left texel of this 2×2 block
            // Gather order: (i, j+1), (i+1, j+1), (i+1, j), (i, j).
            vec4 d = textureGather(shadowMap, vec2(corner + 1) * texelSize, 0);
            float right = bx + 1 < n ? 1.0 : 0.0;  // the block's second column is inside the kernel
            float below = by + 1 < n ? 1.0 : 0.0;  // its second row is inside the kernel
            lit += shadowLit(d.w, s.z) + right * shadowLit(d.z, s.z) + below * shadowLit(d.x, s.z) +
                   right * below * shadowLit(d.y, s.z);
        }
    }
    return lit / float(n * n);
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
