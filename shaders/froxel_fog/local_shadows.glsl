// Local lights' shadows from the host's atlas (postfx::LocalShadow, docs/effects/froxel-fog.md, "Local
// light shadows"): the GPU side of the reference's localShadowVisibility. Expects `froxel`, `shadowAtlas`
// (sampler2D, texelFetch) and `shadowFaces` (FroxelShadowFace[]) declared.
#ifndef POSTFX_FROXEL_LOCAL_SHADOWS_GLSL
#define POSTFX_FROXEL_LOCAL_SHADOWS_GLSL

// One tap, as the sun's (common/medium/medium.glsl shadowTapLit): inside [0, 1] the comparison with the
// bias; beyond the far plane shadowed wherever the texel holds a caster (not the cleared far value).
bool localShadowTapLit(float z, float stored, bool reversed, float bias) {
    if (reversed) return z < 0.0 ? stored <= 0.0 : z + bias >= stored;
    return z > 1.0 ? stored >= 1.0 : z - bias <= stored;
}

// Whether face i (of the faces buffer) holds camera-relative x (w > 0, |x|, |y| <= w), and its clip x, y, w.
bool localShadowFaceHolds(uint i, vec4 h, out vec4 c) {
    c = vec4(dot(shadowFaces.faces[i].clipRows[0], h), dot(shadowFaces.faces[i].clipRows[1], h), 0.0,
             dot(shadowFaces.faces[i].clipRows[3], h));
    return c.w > 0.0 && abs(c.x) <= c.w && abs(c.y) <= c.w;
}

// V at camera-relative x in face i that holds it (clip x, y, w in c): one texel tap, or with
// kFroxelFlagShadowFilter the 2×2 texels around it weighted bilinearly (indices clamped to the face's
// region); 1 before the near plane.
float localShadowFaceVisibility(FroxelLight l, uint i, vec4 h, vec4 c) {
    bool reversed = l.shadow.z != 0u;
    float bias = l.cosInnerBias.y;
    FroxelShadowFace face = shadowFaces.faces[i];
    float z = dot(face.clipRows[2], h) / c.w;
    if (reversed ? !(z <= 1.0) : !(z >= 0.0)) return 1.0;  // before the near plane
    vec2 uv = c.xy / c.w * 0.5 + 0.5;
    ivec2 origin = ivec2(face.region.xy), size = ivec2(face.region.zw);
    if ((froxel.counts.y & kFroxelFlagShadowFilter) == 0u) {
        ivec2 t = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
        return localShadowTapLit(z, texelFetch(shadowAtlas, origin + t, 0).r, reversed, bias) ? 1.0 : 0.0;
    }
    vec2 p = uv * vec2(size) - 0.5;
    ivec2 p0 = ivec2(floor(p));
    vec2 w = p - vec2(p0);
    float lit = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 t = clamp(p0 + o, ivec2(0), size - 1);
        float weight = (o.x == 1 ? w.x : 1.0 - w.x) * (o.y == 1 ? w.y : 1.0 - w.y);
        if (localShadowTapLit(z, texelFetch(shadowAtlas, origin + t, 0).r, reversed, bias)) lit += weight;
    }
    return lit;
}

// V(x) of light l at camera-relative x: in the first of its faces that holds x; 1 when none does.
float localShadowVisibility(FroxelLight l, vec3 x) {
    vec4 h = vec4(x, 1.0), c;
    for (uint f = 0u; f < l.shadow.y; ++f) {
        if (!localShadowFaceHolds(l.shadow.x + f, h, c)) continue;
        return localShadowFaceVisibility(l, l.shadow.x + f, h, c);
    }
    return 1.0;
}

#endif
