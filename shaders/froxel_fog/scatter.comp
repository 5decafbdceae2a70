#version 450
// Pass 1 of the froxel fog (docs/effects/froxel-fog.md, "Passes"): one invocation per froxel evaluates
// the medium and its light at the froxel's sample (jittered per frame) and stores
// (albedo · light · storage scale, σt), light = sun · phase · visibility + ambient + Σ local lights.
// Variants: LOCAL_LIGHTS loops over every light; LIGHT_LISTS over those its cluster's list holds
// (light_lists.comp); without either the frame has no local light.
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#ifdef LIGHT_LISTS
#define LOCAL_LIGHTS
#endif

#include "froxel_fog/bindings.glsl"
layout(binding = kFroxelBindingScatter, rgba16f) uniform writeonly image3D scatterVolume;

#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "fog/medium.glsl"
#include "froxel_fog/grid.glsl"
#include "froxel_fog/lights.glsl"

#ifdef LOCAL_LIGHTS
// Σ over the lights the froxel's cluster lists (LIGHT_LISTS), or over all of them.
vec3 localLightsScatter(uvec3 froxelId, vec3 x, vec3 dir) {
    vec3 sum = vec3(0.0);
#ifdef LIGHT_LISTS
    uint words = froxel.counts.z;
    uvec3 cluster = froxelId / uvec3(kFroxelClusterSize, kFroxelClusterSize, kFroxelClusterSlices);
    for (uint w = 0u; w < words; ++w) {
        uint bits = imageLoad(lightLists, ivec3(cluster.xy, cluster.z * words + w)).r;
        while (bits != 0u) {
            int i = findLSB(bits);
            bits &= bits - 1u;
            sum += localLightScatter(w * 32u + uint(i), x, dir);
        }
    }
#else
    for (uint i = 0u; i < froxel.grid.w; ++i)
        sum += localLightScatter(i, x, dir);
#endif
    return sum;
}
#endif

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (any(greaterThanEqual(id, froxel.grid.xyz))) return;
    vec3 offset = froxel.jitter.xyz;
    vec3 dir = gridRayDirection((vec2(id.xy) + offset.xy) / vec2(froxel.grid.xy));
    float start = sliceStart(id.z), end = sliceStart(id.z + 1u);
    vec3 x = dir * mix(start, end, offset.z);

    // σt: the shared medium plus the volumes (+Inf stays +Inf: an opaque froxel, stored as the half max).
    float sigmaT = extinction(x) + volumesExtinction(x);
    vec3 light = vec3(0.0);
    if (sigmaT > 0.0) {
        light = fog.ambient.rgb;
        vec3 sun = fog.sunIlluminance.rgb;
        if (any(greaterThan(sun, vec3(0.0))))
            light += sun * henyeyGreensteinDirections(dir, fog.toSun.xyz, fog.medium.z) *
                     shadowVisibility(x) * sunTransmittance(fog.heights.x + x.y);
#ifdef LOCAL_LIGHTS
        light += localLightsScatter(id, x, dir);
#endif
    }
    vec3 stored = min(fog.albedo.rgb * light * froxel.jitter.w, vec3(kFroxelHalfMax));
    imageStore(scatterVolume, ivec3(id), vec4(stored, min(sigmaT, kFroxelHalfMax)));
}
