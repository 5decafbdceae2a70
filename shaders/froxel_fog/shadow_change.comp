#version 450
// The froxel fog's shadow-change pass (docs/effects/froxel-fog.md, "Local light shadows", temporal),
// before the scatter pass when local lights have shadows and temporal accumulation is on. A moving caster
// changes a shadowed light's light without any light changing, so the lights' rejected spheres do not
// see it. One invocation per block of 2×2×2 froxels evaluates the shadowed lights' light at the block's
// centre (the corner the block's froxels share; no jitter): Σ luminance(E_i)·V_i, pre-exposed and
// storage-scaled as the scatter volume, written to shadowedLight for the next frame. Where it differs from
// the previous frame's value there (the previous block nearest the point's previous grid coordinate) by
// more than kFroxelShadowChangeReject of the larger, shadowChange holds 1: the scatter
// pass drops the history of every froxel whose centre one of its eight enclosing block centres changed
// at. One evaluation per 8 froxels, each block's lights in one invocation: the scatter pass's warps do
// not pay for it. Variants: LIGHT_LISTS loops over the shadowed lights of the block's cluster's list, else
// over every shadowed light; a group's blocks share one cluster (kFroxelBlockGroupSize), so its warps
// loop over the same lights.
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelBlockGroupSize, local_size_y = kFroxelBlockGroupSize,
       local_size_z = kFroxelBlockGroupSize) in;

#ifdef LIGHT_LISTS
#define LOCAL_LIGHTS
#endif

#include "froxel_fog/bindings.glsl"
#include "common/phase.glsl"
#include "froxel_fog/grid.glsl"
#include "froxel_fog/lights.glsl"

layout(binding = kFroxelBindingShadowAtlas) uniform sampler2D shadowAtlas;
layout(binding = kFroxelBindingShadowFaces, std430) readonly buffer ShadowFaces {
    FroxelShadowFace faces[];
}
shadowFaces;
#include "froxel_fog/local_shadows.glsl"

layout(binding = kFroxelBindingTemporal, std140) uniform Temporal {
    TemporalUniforms temporal;
};
#include "froxel_fog/reproject.glsl"

// Per block: this frame's value (written), the previous frame's (read), and whether it changed.
layout(binding = kFroxelBindingShadowedLight, r32f) uniform writeonly image3D shadowedLight;
layout(binding = kFroxelBindingShadowedHistory) uniform sampler3D shadowedHistory;
layout(binding = kFroxelBindingShadowChange, rgba8) uniform writeonly image3D shadowChange;

// Shadowed light i's luminance(E)·V at camera-relative x (0 beyond its range).
float shadowedLightAt(uint i, vec3 x) {
    FroxelLight l = local.lights[i];
    float d2;
    vec3 toLight;
    float falloff = localLightFalloff(l, x, d2, toLight);
    if (!(falloff > 0.0)) return 0.0;
    float r = l.intensityRadius.w;
    float e = dot(l.intensityRadius.rgb, vec3(0.2126, 0.7152, 0.0722)) * falloff / max(d2 + r * r, 1e-30);
    return min(e * froxel.jitter.w * localShadowVisibility(l, x), kMaxLightTerm);
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uvec3 blocks = (froxel.grid.xyz + 1u) / 2u;
    if (any(greaterThanEqual(id, blocks))) return;
    // The block's centre: froxel coordinate 2·id + 1 on each axis (the grid's far edge for the last block
    // of an odd count, which holds one froxel).
    vec3 corner = vec3(2u * id + 1u) / vec3(froxel.grid.xyz);
    vec3 x = gridRayDirection(corner.xy) * sliceDepth(corner.z);

    // The shadowed lights (froxel.shadowed), of the block's cluster's list with LIGHT_LISTS.
    float value = 0.0;
#ifdef LIGHT_LISTS
    uint words = froxel.counts.z;
    uvec3 cluster = (2u * id) / uvec3(kFroxelClusterSize, kFroxelClusterSize, kFroxelClusterSlices);
#else
    uint words = (froxel.grid.w + 31u) / 32u;
#endif
    for (uint w = 0u; w < words; ++w) {
        uint bits = froxel.shadowed[w / 4u][w % 4u];
#ifdef LIGHT_LISTS
        bits &= imageLoad(lightLists, ivec3(cluster.xy, cluster.z * words + w)).r;
#endif
        while (bits != 0u) {
            int i = findLSB(bits);
            bits &= bits - 1u;
            value += shadowedLightAt(w * 32u + uint(i), x);
        }
    }

    bool changed = false;
    vec3 uvw;
    if (temporal.state.x != 0u && (froxel.counts.y & kFroxelFlagShadowedHistory) != 0u &&
        previousGridCoordinate(x, uvw)) {
        // The nearest previous block: a still view reads its own, so the test is exact there (an
        // interpolated value would mix in a neighbour's by the reprojection's rounding, and a block at 0
        // beside a lit one would be rejected every frame).
        ivec3 nearest = clamp(ivec3(floor(uvw * vec3(blocks))), ivec3(0), ivec3(blocks) - 1);
        float previous = texelFetch(shadowedHistory, nearest, 0).r * temporal.previous.y;
        changed = abs(value - previous) > kFroxelShadowChangeReject * max(value, previous);
    }
    imageStore(shadowedLight, ivec3(id), vec4(value));
    imageStore(shadowChange, ivec3(id), vec4(changed ? 1.0 : 0.0));
}
