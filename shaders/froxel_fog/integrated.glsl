// The integrated volume (L, T) at a distance along a pixel's ray: the apply pass's and the volumetrics
// lookup's. Expects `froxel`, grid.glsl and the sampler `integratedVolume`.
#ifndef POSTFX_FROXEL_INTEGRATED_GLSL
#define POSTFX_FROXEL_INTEGRATED_GLSL

// The volume at normalised coordinate p with the hardware's trilinear filter, or a tricubic B-spline
// from 8 trilinear fetches (Sigg and Hadwiger, "Fast third-order texture filtering", GPU Gems 2 ch. 20:
// each pair of B-spline weights w0·f[i-1] + w1·f[i] is one linear fetch between the two texels).
vec4 sampleIntegrated(vec3 p) {
    if ((froxel.counts.y & kFroxelFlagTricubic) == 0u) return textureLod(integratedVolume, p, 0.0);
    vec3 size = vec3(froxel.grid.xyz);
    vec3 texel = p * size - 0.5;
    vec3 i = floor(texel), f = texel - i;
    vec3 f2 = f * f, f3 = f2 * f;
    vec3 w0 = (1.0 - 3.0 * f + 3.0 * f2 - f3) / 6.0;
    vec3 w1 = (4.0 - 6.0 * f2 + 3.0 * f3) / 6.0;
    vec3 w2 = (1.0 + 3.0 * f + 3.0 * f2 - 3.0 * f3) / 6.0;
    vec3 w3 = f3 / 6.0;
    vec3 g0 = w0 + w1, g1 = w2 + w3;
    vec3 p0 = (i - 0.5 + w1 / g0) / size;  // between texels i - 1 and i (centres at index + 0.5)
    vec3 p1 = (i + 1.5 + w3 / g1) / size;  // between texels i + 1 and i + 2
    vec4 result = vec4(0.0);
    for (int c = 0; c < 8; ++c) {
        bvec3 high = bvec3((c & 1) != 0, (c & 2) != 0, (c & 4) != 0);
        vec3 weight = mix(g0, g1, high);
        result += weight.x * weight.y * weight.z * textureLod(integratedVolume, mix(p0, p1, high), 0.0);
    }
    return result;
}

// (L, T) from the camera to distance t along the ray through uv. Texel k holds them at the end of slice
// k, so a distance in slice k > 0 reads between texels k - 1 and k; within the first slice they run
// linearly from (0, 1) at the camera to texel 0.
vec4 integratedAt(vec2 uv, float t) {
    float slices = float(froxel.grid.z);
    float firstEnd = sliceStart(1u);
    if (t < firstEnd)
        return mix(vec4(0.0, 0.0, 0.0, 1.0), sampleIntegrated(vec3(uv, 0.5 / slices)), t / firstEnd);
    return sampleIntegrated(vec3(uv, (sliceCoordinate(t) * slices - 0.5) / slices));
}

#endif
