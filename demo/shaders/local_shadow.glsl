// Local light visibility from the shadow atlas (host/local_shadows.h), by postfx's rule for
// postfx::LocalShadow, so that the surfaces and the froxel fog agree: the first face whose clip square
// holds the point (w > 0, |x| <= w, |y| <= w); in it z = c.z / c.w, lit when z - bias <= stored; beyond the
// far plane (z > 1) shadowed where a caster was drawn (stored < 1); before the near plane lit; no face:
// lit. On the surfaces, as the sun's (shadow.glsl): a normal offset and a 3x3 bilinear PCF.
// Expects `localShadowAtlas` (sampler2D, nearest) and `shadowFaces` (LocalShadowFaces) declared.
#ifndef DEMO_LOCAL_SHADOW_GLSL
#define DEMO_LOCAL_SHADOW_GLSL

// The depth comparison of one texel of `face` (clamped to its region, so the kernel never reads a
// neighbouring face): 1 lit, 0 shadowed.
float localShadowTap(GpuShadowFace face, vec2 texel, float reference) {
    vec2 t = clamp(texel, vec2(0.0), face.region.zw - 1.0) + face.region.xy;
    return reference <= texelFetch(localShadowAtlas, ivec2(t), 0).r ? 1.0 : 0.0;
}

// p: camera-relative surface position [m]; n: unit normal; nDotL: cosine to the light (> 0); d: the
// distance to the light [m].
float localShadowVisibility(GpuLight light, vec3 p, vec3 n, float nDotL, float d) {
    uint first = uint(light.cosInner.y);
    uint count = uint(light.cosInner.z);
    float bias = light.cosInner.w;
    // Normal offset: about one texel at this distance, more at grazing angles (as the sun's).
    float sinTheta = sqrt(max(1.0 - nDotL * nDotL, 0.0));
    float texelWorld = shadowFaces.faces[first].params.x * d;
    vec3 q = p + n * texelWorld * (0.5 + 1.5 * sinTheta);
    for (uint i = first; i < first + count; ++i) {
        GpuShadowFace face = shadowFaces.faces[i];
        vec4 c = face.worldToClip * vec4(q, 1.0);
        if (!(c.w > 0.0 && abs(c.x) <= c.w && abs(c.y) <= c.w)) continue;
        float z = c.z / c.w;
        if (z < 0.0) return 1.0;                     // before the near plane
        float reference = z > 1.0 ? 1.0 : z - bias;  // beyond the far plane: lit only where nothing was drawn
        // The mean of 9 bilinear comparisons at texel offsets -1, 0, 1: the 4x4 texels around the point
        // weighed by (1-f, 1, 1, f) per axis, /9 (shadow.glsl).
        vec2 t = (c.xy / c.w * 0.5 + 0.5) * face.region.zw - 0.5;
        vec2 base = floor(t);
        vec2 f = t - base;
        float wx[4] = float[4](1.0 - f.x, 1.0, 1.0, f.x);
        float wy[4] = float[4](1.0 - f.y, 1.0, 1.0, f.y);
        float sum = 0.0;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                sum += wx[x] * wy[y] * localShadowTap(face, base + vec2(x - 1, y - 1), reference);
        return sum / 9.0;
    }
    return 1.0;  // no face holds the point
}

#endif
