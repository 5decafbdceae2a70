// Deferred sun + ambient lighting into the HDR radiance image, per RGB channel:
//   L = albedo/π · E · max(0, n·l) · visibility + albedo · ambient;  no geometry: L = sky.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(local_size_x = kLightingGroupSize, local_size_y = kLightingGroupSize) in;

layout(set = 0, binding = kBindingFrame, std140) uniform FrameBlock {
    FrameUniforms frame;
};
layout(set = 0, binding = kBindingAlbedo) uniform sampler2D gAlbedo;
layout(set = 0, binding = kBindingNormal) uniform sampler2D gNormal;
layout(set = 0, binding = kBindingDepth) uniform sampler2D gDepth;
layout(set = 0, binding = kBindingShadowMap) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = kBindingHdr, rgba16f) uniform writeonly image2D hdr;

#include "shadow.glsl"

const float kPi = 3.14159265358979;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), frame.extent.xy))) return;

    float depth = texelFetch(gDepth, pixel, 0).r;
    vec3 radiance = frame.sky.rgb;
    if (depth != frame.depthParams.x) {
        // Pixel centre -> NDC (Vulkan: y down, matching image rows) -> camera-relative world.
        vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.extent.xy) * 2.0 - 1.0;
        vec4 h = frame.invViewProj * vec4(ndc, depth, 1.0);
        vec3 world = h.xyz / h.w + frame.cameraPosition.xyz;

        vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
        vec3 n = normalize(texelFetch(gNormal, pixel, 0).xyz);
        float nDotL = max(dot(n, frame.toSun.xyz), 0.0);
        float visibility = 1.0;
        if (frame.toSun.w > 0.5 && nDotL > 0.0) visibility = sunVisibility(world, n, nDotL);
        radiance =
            albedo / kPi * frame.sunIlluminance.rgb * (nDotL * visibility) + albedo * frame.ambient.rgb;
    }
    imageStore(hdr, pixel, vec4(min(radiance, vec3(kHalfMax)), 1.0));
}
