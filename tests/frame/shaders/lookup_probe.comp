#version 450
// The host's side of the volumetrics lookup, as a forward pass calls it: for each world position of
// `points`, postfxVolumetrics(p) from <postfx/volumetrics.glsl> at binding numbers a host chose.
#extension GL_GOOGLE_include_directive : require

#define POSTFX_LOOKUP_SET 0
#define POSTFX_LOOKUP_BINDING_UNIFORMS 3
#define POSTFX_LOOKUP_BINDING_SCATTERING 5
#define POSTFX_LOOKUP_BINDING_TRANSMITTANCE 7
#include "postfx/volumetrics.glsl"

layout(local_size_x = 64) in;

layout(binding = 0, std430) readonly buffer Points {
    vec4 points[];  // xyz: world position [m]
};
layout(binding = 1, std430) writeonly buffer Results {
    vec4 results[];  // per point: (L, 0), (T, 0)
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(points.length())) return;
    PostfxVolumetrics v = postfxVolumetrics(points[i].xyz);
    results[2u * i] = vec4(v.radiance, 0.0);
    results[2u * i + 1u] = vec4(v.transmittance, 0.0);
}
