// A march at a reduced resolution and its upsample (the ray-marched fog's and the clouds'): which
// full-resolution pixel a reduced texel marches, and which 2×2 texels around a full-resolution pixel's
// centre an upsample reads, with their bilinear weights. Exact integer arithmetic, so a still view maps
// the same way every frame and a reduced extent equal to the full one maps each pixel onto itself.
#ifndef POSTFX_COMMON_REDUCED_RESOLUTION_GLSL
#define POSTFX_COMMON_REDUCED_RESOLUTION_GLSL

// The full-resolution pixel whose ray texel `texel` of a `reduced`-sized march marches: the one nearest
// the texel's centre, floor((texel + 0.5) · extent / reduced).
uvec2 reducedSourcePixel(uvec2 texel, uvec2 extent, uvec2 reduced) {
    return min((2u * texel + 1u) * extent / (2u * reduced), extent - 1u);
}

// The 2×2 texels of a `size`-sized march around full-resolution pixel `pixel`'s centre, u = (pixel + 0.5)
// · size / extent - 0.5, and their bilinear weights; clamped to the image at its borders. In integers:
// u = num / (2·extent) with num = (2·pixel + 1)·size - extent.
void reducedFootprint(uvec2 pixel, uvec2 extent, uvec2 size, out uvec2 texels[4], out float weights[4]) {
    uvec2 num = (2u * pixel + 1u) * size;
    uvec2 den = 2u * extent;
    bvec2 inside = greaterThanEqual(num, extent);
    uvec2 shifted = num - min(num, extent);
    uvec2 t0 = min(shifted / den, size - 1u);
    vec2 f = mix(vec2(0.0), vec2(shifted - t0 * den) / vec2(den), inside);
    f = min(f, vec2(1.0));
    uvec2 t1 = min(t0 + 1u, size - 1u);
    texels = uvec2[4](t0, uvec2(t1.x, t0.y), uvec2(t0.x, t1.y), t1);
    weights = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
}

#endif
