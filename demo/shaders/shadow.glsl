// Sun visibility from the shadow map: normal offset + 3x3 bilinear PCF of depth comparisons.
// Expects `frame` (FrameUniforms) and `shadowMap` (sampler2DShadow: nearest, compare LESS_OR_EQUAL,
// border depth 1) declared. Uses gathers, so it needs no linear filtering of depth formats.
#ifndef DEMO_SHADOW_GLSL
#define DEMO_SHADOW_GLSL

// world: surface position [m]; n: unit surface normal; nDotL: cosine to the sun (> 0).
float sunVisibility(vec3 world, vec3 n, float nDotL) {
    // Normal offset: move the lookup off the surface by about one shadow texel, more at grazing
    // angles (sin of the angle to the sun), so the surface does not shadow itself (acne).
    float sinTheta = sqrt(max(1.0 - nDotL * nDotL, 0.0));
    vec3 p = world + n * frame.depthParams.z * (0.5 + 1.5 * sinTheta);
    vec3 s = (frame.shadowViewProj * vec4(p, 1.0)).xyz;  // orthographic: w == 1
    vec2 uv = s.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || s.z < 0.0 || s.z > 1.0) {
        return 1.0;  // outside the shadow map: no known occluder
    }
    // The mean of 9 bilinear comparisons at texel offsets -1, 0, 1 weighs the 4x4 texels around the
    // point by (1-f, 1, 1, f) per axis (f: bilinear fraction), /9. Four gathers of 2x2 texels each.
    float texel = frame.depthParams.y;
    vec2 t = uv / texel - 0.5;
    vec2 base = floor(t);
    vec2 f = t - base;
    vec2 w0[2] = vec2[2](vec2(1.0) - f, vec2(1.0));  // weights of the lower and upper texel of block 0
    vec2 w1[2] = vec2[2](vec2(1.0), f);              // ... of block 1
    float sum = 0.0;
    for (int by = 0; by < 2; ++by) {
        for (int bx = 0; bx < 2; ++bx) {
            // Block corner in texel units: texels (base-1, base) for block 0, (base+1, base+2) for 1.
            vec2 corner = base + vec2(bx, by) * 2.0;
            vec4 lit = textureGather(shadowMap, corner * texel, s.z);
            vec2 lo = vec2(bx == 0 ? w0[0].x : w1[0].x, by == 0 ? w0[0].y : w1[0].y);
            vec2 hi = vec2(bx == 0 ? w0[1].x : w1[1].x, by == 0 ? w0[1].y : w1[1].y);
            // Gather order: x (i0, j1), y (i1, j1), z (i1, j0), w (i0, j0).
            sum += dot(lit, vec4(lo.x * hi.y, hi.x * hi.y, hi.x * lo.y, lo.x * lo.y));
        }
    }
    return sum / 9.0;
}

#endif
