#version 450
// Light lists (docs/effects/froxel-fog.md#light-lists): for each cluster of kFroxelClusterSize²
// froxels × kFroxelClusterSlices slices, one bit per light whose sphere of influence (its range) may
// touch the cluster. One invocation writes one 32-light word of one cluster: texel (cx, cy, cz·words + w).
// The test is conservative: the sphere against the radial shell [start, end] of the cluster's slices and
// against the four planes through the camera bounding the cluster's tile.
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#include "froxel_fog/bindings.glsl"
#include "froxel_fog/grid.glsl"

// Unit normal of the plane through the camera holding directions a and b, facing `inward`.
vec3 sidePlane(vec3 a, vec3 b, vec3 inward) {
    vec3 n = normalize(cross(a, b));
    return dot(n, inward) < 0.0 ? -n : n;
}

void main() {
    uint words = froxel.counts.z;
    uvec3 clusters =
        (froxel.grid.xyz + uvec3(kFroxelClusterSize, kFroxelClusterSize, kFroxelClusterSlices) - 1u) /
        uvec3(kFroxelClusterSize, kFroxelClusterSize, kFroxelClusterSlices);
    uvec3 id = gl_GlobalInvocationID;
    uvec3 cluster = uvec3(id.xy, id.z / words);
    uint word = id.z % words;
    if (any(greaterThanEqual(cluster, clusters))) return;

    vec2 grid = vec2(froxel.grid.xy);
    vec2 uv0 = vec2(cluster.xy * kFroxelClusterSize) / grid;
    vec2 uv1 = vec2(min((cluster.xy + 1u) * kFroxelClusterSize, froxel.grid.xy)) / grid;
    vec3 c00 = gridRayDirection(uv0), c11 = gridRayDirection(uv1);
    vec3 c10 = gridRayDirection(vec2(uv1.x, uv0.y)), c01 = gridRayDirection(vec2(uv0.x, uv1.y));
    vec3 inward = c00 + c11 + c10 + c01;
    vec3 planes[4] = vec3[4](sidePlane(c00, c10, inward), sidePlane(c10, c11, inward),
                             sidePlane(c11, c01, inward), sidePlane(c01, c00, inward));
    float start = sliceStart(cluster.z * kFroxelClusterSlices);
    float end = sliceStart(min((cluster.z + 1u) * kFroxelClusterSlices, froxel.grid.z));

    uint bits = 0u;
    uint first = word * 32u, count = min(froxel.grid.w - min(first, froxel.grid.w), 32u);
    for (uint i = 0u; i < count; ++i) {
        vec4 light = local.lights[first + i].positionRange;
        float distance = length(light.xyz), range = light.w;
        bool touches = distance + range >= start && distance - range <= end;
        for (int p = 0; p < 4; ++p)
            touches = touches && dot(planes[p], light.xyz) >= -range;
        if (touches) bits |= 1u << i;
    }
    imageStore(lightLists, ivec3(id), uvec4(bits));
}
