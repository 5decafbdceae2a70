// Deferred sun + ambient + local-light lighting into the HDR radiance image, per RGB channel:
//   L = albedo/π · (E · T_atm · max(0, n·l) · visibility + Σ_lights I · falloff · spot · max(0, n·l_i))
//       + albedo · ambient;  no geometry: L = sky.
// T_atm: the sun's transmittance through postfx's atmosphere at the point, exp(-τ) with τ interpolated
// linearly in altitude between two altitudes the host evaluated exactly (host/atmosphere_lighting.h: an
// approximation, docs/effects/atmosphere.md "The demo"); 1 without the atmosphere (τ = 0).
// visibility: the shadow map's times the clouds' transmittance toward the sun from postfx's cloud shadow
// map of the previous frame (postfx::cloudShadowTransform; docs/effects/clouds.md, "Shadows").
// Local lights: falloff and spot factor are demo_shared.h's (localLightFalloff, spotFactor); a light with
// shadows is multiplied by its visibility from the local shadow atlas (local_shadow.glsl).
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
layout(set = 0, binding = kBindingCloudShadow) uniform sampler2D cloudShadowMap;
layout(set = 0, binding = kBindingLights, std140) uniform LightsBlock {
    LightsUniforms lightList;
};
layout(set = 0, binding = kBindingLocalShadowAtlas) uniform sampler2D localShadowAtlas;
layout(set = 0, binding = kBindingLocalShadowFaces, std430) readonly buffer LocalShadowFacesBlock {
    LocalShadowFaces shadowFaces;
};

#include "local_shadow.glsl"
#include "shadow.glsl"

#include "surface_light.glsl"

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
        vec3 relative = h.xyz / h.w;  // camera-relative, as the lights' positions
        vec3 world = relative + frame.cameraPosition.xyz;

        vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
        vec3 n = normalize(texelFetch(gNormal, pixel, 0).xyz);
        vec3 irradiance =
            surfaceIrradiance(relative, world, n, false, frame.cloudShadowU, frame.cloudShadowV);
        radiance = albedo / kPi * irradiance + albedo * frame.ambient.rgb;
    }
    imageStore(hdr, pixel, vec4(min(radiance, vec3(kHalfMax)), 1.0));
}
