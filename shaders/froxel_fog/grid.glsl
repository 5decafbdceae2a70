// The froxel grid (docs/effects/froxel-fog.md, "Grid"): slice boundaries along each view ray and the
// direction of a froxel's ray. Expects `fog` and `froxel` (bindings.glsl).
#ifndef POSTFX_FROXEL_GRID_GLSL
#define POSTFX_FROXEL_GRID_GLSL

// Distance along the ray of the slice boundary at z01 ∈ [0, 1] [m] (postfx::froxelSliceDepth):
// Power: near + (far - near)·z01^k; Log: near·(far/near)^z01.
float sliceDepth(float z01) {
    float near = froxel.slices.x, far = froxel.slices.y;
    if ((froxel.counts.y & kFroxelFlagLogSlices) != 0u) return near * exp(z01 * froxel.slices.w);
    return near + (far - near) * pow(z01, froxel.slices.z);
}

// Its inverse for a distance t, clamped to [near, far] (postfx::froxelSliceCoordinate).
float sliceCoordinate(float t) {
    float near = froxel.slices.x, far = froxel.slices.y;
    float d = clamp(t, near, far);
    if ((froxel.counts.y & kFroxelFlagLogSlices) != 0u) return log(d / near) / froxel.slices.w;
    return pow((d - near) / (far - near), 1.0 / froxel.slices.z);
}

// Where slice `k` starts along every ray [m]: the first slice starts at the camera (it also holds the
// space before the near plane), slice k > 0 at sliceDepth(k / slices); k = slices is the far end.
float sliceStart(uint k) {
    return k == 0u ? 0.0 : sliceDepth(float(k) / float(froxel.grid.z));
}

// Unit camera-relative direction of the ray through `uv` ∈ [0, 1]² of the image (Vulkan NDC y down,
// as the fog's pixel rays: uv = (pixel + 0.5) / extent).
vec3 gridRayDirection(vec2 uv) {
    vec4 p = fog.clipToView * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
    return normalize(p.xyz / p.w);
}

#endif
