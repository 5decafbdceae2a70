#version 450
// Pass 2 of the froxel fog (docs/effects/froxel-fog.md, "Passes"): one invocation per column of the
// grid walks its slices front to back. Slice k holds σt and albedo·light constant over [start, end];
// each adds T·albedo·light·(1 - e^{-σt·Δ}) and multiplies T by e^{-σt·Δ} (Hillaire 2015's
// energy-conserving step with S = σs·light, exact as σt -> 0: common/integrate.glsl), and the slice's
// texel stores (L, T) at its far end. The slices are radial (distances along each ray), so Δ is the
// same in every column.
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#include "froxel_fog/bindings.glsl"
layout(binding = kFroxelBindingScatter, rgba16f) uniform readonly image3D scatterVolume;
layout(binding = kFroxelBindingIntegrated, rgba16f) uniform writeonly image3D integratedVolume;

#include "common/integrate.glsl"
#include "froxel_fog/grid.glsl"

void main() {
    uvec2 column = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(column, froxel.grid.xy))) return;
    vec3 inScattered = vec3(0.0);
    float transmittance = 1.0;
    float start = 0.0;
    for (uint k = 0u; k < froxel.grid.z; ++k) {
        float end = sliceStart(k + 1u);
        vec4 s = imageLoad(scatterVolume, ivec3(column, k));
        float opticalDepth = s.a * (end - start);
        inScattered += integrateStep(transmittance, s.rgb, opticalDepth);
        transmittance *= exp(-opticalDepth);
        imageStore(integratedVolume, ivec3(column, k),
                   vec4(min(inScattered, vec3(kFroxelHalfMax)), transmittance));
        start = end;
    }
}
