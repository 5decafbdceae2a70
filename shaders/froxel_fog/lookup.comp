#version 450
// froxel_fog.lookup (docs/integration.md, "Transparent surfaces"): the froxel fog's (L, T) from the camera to
// the end of every slice of the volumetrics lookup, as the apply pass reads them for a pixel's surface at
// that distance (the integrated volume, then the analytic tail beyond max distance), composited over the
// lookup (common/lookup.glsl).
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"
#include "common/lookup_shared.h"

layout(local_size_x = kLookupGroupSize, local_size_y = kLookupGroupSize, local_size_z = kLookupGroupSize) in;

#include "froxel_fog/bindings.glsl"
layout(binding = kFroxelBindingIntegrated) uniform sampler3D integratedVolume;

#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/atmosphere_light.glsl"
#include "froxel_fog/grid.glsl"
#include "froxel_fog/integrated.glsl"
#include "common/lookup.glsl"

void main() {
    uvec3 cell = gl_GlobalInvocationID;
    if (any(greaterThanEqual(cell, lookupExtent()))) return;
    vec2 uv = lookupUv(cell.xy);
    vec3 dir = lookupRayDirection(uv);
    float t = lookupSliceEnd(cell.z);
    vec4 volume = integratedAt(uv, min(t, froxel.slices.y));
    vec3 inScattered = volume.rgb / froxel.jitter.w;
    float transmittance = volume.a;
    vec3 sunPhase = fog.sunIlluminance.rgb * henyeyGreensteinDirections(dir, fog.toSun.xyz, fog.medium.z);
    addAnalyticTail(dir, t, sunPhase * atmosphereSunTransmittance(dir * fog.medium.w), inScattered,
                    transmittance);
    lookupComposite(ivec3(cell), inScattered, vec3(transmittance));
}
