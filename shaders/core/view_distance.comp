#version 450
// postfx.view_distance: each pixel's surface distance [m] along its view ray, from the host's depth, once
// per frame for every effect that reads it, when two or more do (docs/architecture.md, "Shared inputs").
// +∞ where there is no geometry, NaN for a NaN depth (each effect handles those as it did the depth).
#extension GL_GOOGLE_include_directive : require

#include "common/shared.h"

layout(local_size_x = kViewDistanceGroupSize, local_size_y = kViewDistanceGroupSize) in;

layout(binding = kViewDistanceBindingDepth) uniform sampler2D depthTexture;
layout(binding = kViewDistanceBindingOut, r32f) uniform writeonly image2D distanceOut;
layout(push_constant) uniform Push {
    ViewDistancePush pc;
};

#include "common/view_distance.glsl"

// Each invocation does kViewDistanceRows pixels, kViewDistanceGroupSize rows apart, every load first:
// more loads in flight per invocation. On the H100 (postfx-bench --frame, Medium) one, two and four pixels
// an invocation took 0.025, 0.016 and 0.012 ms at 1920×1080, 0.084, 0.045 and 0.028 ms at 3840×2160 (66 MB
// moved: 2.4 TB/s, near the memory's bandwidth).
void main() {
    uvec2 extent = uvec2(pc.params.yz);
    uvec2 base = uvec2(gl_WorkGroupID.x * kViewDistanceGroupSize,
                       gl_WorkGroupID.y * (kViewDistanceGroupSize * kViewDistanceRows)) +
                 gl_LocalInvocationID.xy;
    float depths[kViewDistanceRows];
    for (uint k = 0u; k < kViewDistanceRows; ++k) {
        uvec2 pixel = min(base + uvec2(0u, k * kViewDistanceGroupSize), extent - 1u);
        depths[k] = texelFetch(depthTexture, ivec2(pixel), 0).r;
    }
    for (uint k = 0u; k < kViewDistanceRows; ++k) {
        uvec2 pixel = base + uvec2(0u, k * kViewDistanceGroupSize);
        if (any(greaterThanEqual(pixel, extent))) continue;
        vec2 ndc = (vec2(pixel) + 0.5) / vec2(extent) * 2.0 - 1.0;
        float distance = unprojectedDistance(pc.clipToView, ndc, depths[k], pc.params.x);
        imageStore(distanceOut, ivec2(pixel), vec4(distance));
    }
}
