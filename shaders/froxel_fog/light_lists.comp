#version 450
// Light lists (docs/effects/froxel-fog.md#light-lists): for each cluster of kFroxelClusterSize²
// froxels × kFroxelClusterSlices slices, one bit per light whose sphere of influence (its range) may
// touch the cluster. One workgroup of 32 invocations writes one 32-light word of one cluster: texel
// (cx, cy, cz·words + w), invocation i testing light 32w + i. The test is conservative: the sphere against
// the radial shell [start, end] of the cluster's slices and against the four planes through the camera
// bounding the cluster's tile. One light per invocation, not a loop over 32 in each: the pass has few
// clusters (20×12×8·words at 160×90×128), too few invocations to hide a loop's latency.
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = 32) in;

shared uint wordBits;

#include "froxel_fog/bindings.glsl"
#include "froxel_fog/grid.glsl"

// Unit normal of the plane through the camera holding directions a and b, facing `inward`.
vec3 sidePlane(vec3 a, vec3 b, vec3 inward) {
    vec3 n = normalize(cross(a, b));
    return dot(n, inward) < 0.0 ? -n : n;
}

void main() {
    uint words = froxel.counts.z;
    uvec3 id = gl_WorkGroupID;  // one group per cluster word: (cx, cy, cz·words + w)
    uvec3 cluster = uvec3(id.xy, id.z / words);
    uint word = id.z % words;
    uint lane = gl_LocalInvocationID.x;
    if (lane == 0u) wordBits = 0u;
    barrier();

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

    uint i = word * 32u + lane;
    if (i < froxel.grid.w) {
        vec4 light = local.lights[i].positionRange;
        float distance = length(light.xyz), range = light.w;
        bool touches = distance + range >= start && distance - range <= end;
        for (int p = 0; p < 4; ++p)
            touches = touches && dot(planes[p], light.xyz) >= -range;
        if (touches) atomicOr(wordBits, 1u << lane);
    }
    barrier();
    if (lane == 0u) imageStore(lightLists, ivec3(id), uvec4(wordBits));
}
