// Where a point of this frame's grid was in the previous frame's (docs/effects/froxel-fog.md#temporal).
// Expects `froxel` (bindings.glsl) and TemporalUniforms `temporal` (common/shared.h).
#ifndef POSTFX_FROXEL_REPROJECT_GLSL
#define POSTFX_FROXEL_REPROJECT_GLSL

// Where the previous frame's grid held camera-relative `x`, as texture coordinates of its volume
// (x, y: the previous view's uv; z: the slice coordinate of the distance from the previous camera with
// the previous near plane; far and the distribution are unchanged, or the history was reset). False off
// the previous frustum (beside or behind the view, beyond max distance).
bool previousGridCoordinate(vec3 x, out vec3 uvw) {
    uvw = vec3(0.0);
    vec4 clip = temporal.previousClip * vec4(x, 1.0);
    if (!(clip.w > 0.0)) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    float t = length(x + temporal.cameraDelta.xyz);
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0))) || t > froxel.slices.y)
        return false;
    float near = temporal.previous.x, far = froxel.slices.y;
    float d = clamp(t, near, far);
    float z = (froxel.counts.y & kFroxelFlagLogSlices) != 0u
                  ? log(d / near) / log(far / near)
                  : pow((d - near) / (far - near), 1.0 / froxel.slices.z);
    uvw = vec3(uv, z);
    return true;
}

#endif
