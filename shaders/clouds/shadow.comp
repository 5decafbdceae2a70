#version 450
// The clouds' shadow map (docs/effects/clouds.md, "Shadows"): one invocation per texel. Texel (i, j) is
// the point of the layer's bottom (y = bottom height, camera-relative) at the map's centre plus
// ((i, j) + 0.5) / size - 0.5 times its extent along x and z; it stores the transmittance toward the sun
// through the shape from there, exp(-Σ σt·Δs) over kCloudShadowSteps midpoint samples of the ray's part
// in the shape (whatever its length). The sun at or below the horizon: 1.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"

layout(local_size_x = kCloudGroupSize, local_size_y = kCloudGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
layout(binding = kCloudBindingBaseNoise) uniform sampler3D baseNoise;
layout(binding = kCloudBindingDetailNoise) uniform sampler3D detailNoise;
layout(binding = kCloudBindingCoverageMap) uniform sampler2D coverageMap;
layout(binding = kCloudBindingShadowOut, r32f) uniform restrict writeonly image2D shadowOut;

#include "clouds/density.glsl"

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    uint size = cl.counts.w;
    if (any(greaterThanEqual(texel, uvec2(size)))) return;
    vec3 toSun = cl.toSun.xyz;
    float T = 1.0;
    if (toSun.y > 0.0) {
        vec2 f = (vec2(texel) + 0.5) / float(size) - 0.5;
        vec3 x = cl.shadow.xyz + vec3(f.x, 0.0, f.y) * cl.shadow.w;
        vec2 seg = cloudSegment(x, toSun, cl.march.x);
        if (seg.y > seg.x) {
            float ds = (seg.y - seg.x) / float(kCloudShadowSteps);
            float tau = 0.0;
            for (uint k = 0u; k < kCloudShadowSteps; ++k)
                tau += cloudExtinction(x + toSun * (seg.x + (float(k) + 0.5) * ds));
            T = exp(-tau * ds);
        }
    }
    imageStore(shadowOut, ivec2(texel), vec4(T));
}
