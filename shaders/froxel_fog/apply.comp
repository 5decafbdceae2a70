#version 450
// Pass 3 of the froxel fog (docs/effects/froxel-fog.md, "Passes"): each pixel reads the integrated
// volume (L, T) at its surface distance along its ray (max distance for pixels beyond it or with no
// geometry), adds the ray-marched fog's analytic tail beyond max distance, and writes
// out = color · T + L (common/composite.glsl).
// Variants: COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#include "froxel_fog/bindings.glsl"
layout(binding = kFroxelBindingIntegrated) uniform sampler3D integratedVolume;

#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/atmosphere_light.glsl"
#include "common/medium/ray.glsl"
#include "common/composite.glsl"
#include "froxel_fog/grid.glsl"
#include "froxel_fog/integrated.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, fog.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    FogRay ray = fogRay(pixel);
    vec2 uv = (vec2(pixel) + 0.5) / vec2(fog.extent.xy);
    vec4 volume = integratedAt(uv, min(ray.surfaceDistance, froxel.slices.y));
    vec3 inScattered = volume.rgb / froxel.jitter.w;
    float transmittance = volume.a;
    vec3 sunPhase = fog.sunIlluminance.rgb * henyeyGreensteinDirections(ray.dir, fog.toSun.xyz, fog.medium.z);
    addAnalyticTail(ray.dir, ray.surfaceDistance,
                    sunPhase * atmosphereSunTransmittance(ray.dir * fog.medium.w), inScattered,
                    transmittance);
    imageStore(colorOut, ivec2(pixel), vec4(compositeOver(color.rgb, transmittance, inScattered), color.a));
}
