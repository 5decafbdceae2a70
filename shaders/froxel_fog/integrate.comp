#version 450
// Pass 2 of the froxel fog (docs/effects/froxel-fog.md, "Passes"): one invocation per column of the
// grid walks its slices front to back. Slice k holds σt and albedo·light constant over [start, end];
// each adds T·albedo·light·(1 - e^{-σt·Δ}) and multiplies T by e^{-σt·Δ} (Hillaire 2015's
// energy-conserving step with S = σs·light, exact as σt -> 0: common/integrate.glsl), and the slice's
// texel stores (L, T) at its far end. The slices are radial (distances along each ray), so Δ is the
// same in every column.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#include "froxel_fog/bindings.glsl"
#ifdef SCATTER_RGBA32F  // the temporal history (scatter.comp's TEMPORAL variants)
layout(binding = kFroxelBindingScatter, rgba32f) uniform readonly image3D scatterVolume;
#else
layout(binding = kFroxelBindingScatter, rgba16f) uniform readonly image3D scatterVolume;
#endif
layout(binding = kFroxelBindingIntegrated, rgba16f) uniform writeonly image3D integratedVolume;

#include "common/integrate.glsl"
#include "froxel_fog/grid.glsl"

// Slices read ahead of their use: a column's loads do not depend on one another, but a loop that loads
// a slice and then uses it waits for each load in turn, and with one invocation per column (14 400 at
// 160×90) too few warps run to hide that: the pass was latency bound (docs/effects/froxel-fog.md,
// "Benchmark"). Loading kBatch slices before integrating them keeps kBatch loads in flight; the
// arithmetic and its order are unchanged.
const uint kBatch = 8u;

void main() {
    uvec2 column = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(column, froxel.grid.xy))) return;
    uint slices = froxel.grid.z;
    vec3 inScattered = vec3(0.0);
    float transmittance = 1.0;
    float start = 0.0;
    for (uint first = 0u; first < slices; first += kBatch) {
        vec4 batch[kBatch];
        [[unroll]] for (uint j = 0u; j < kBatch; ++j) {
            batch[j] = imageLoad(scatterVolume, ivec3(column, min(first + j, slices - 1u)));
        }
        [[unroll]] for (uint j = 0u; j < kBatch; ++j) {
            uint k = first + j;
            if (k >= slices) break;
            float end = sliceStart(k + 1u);
            vec4 s = batch[j];
            float opticalDepth = s.a * (end - start);
            inScattered += integrateStep(transmittance, s.rgb, opticalDepth);
            transmittance *= exp(-opticalDepth);
            imageStore(integratedVolume, ivec3(column, k),
                       vec4(min(inScattered, vec3(kFroxelHalfMax)), transmittance));
            start = end;
        }
    }
}
