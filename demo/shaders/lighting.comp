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

const float kPi = 3.14159265358979;

// The clouds' transmittance toward the sun at world position p: 1 outside postfx's map.
float cloudShadow(vec3 p) {
    vec2 uv = vec2(dot(frame.cloudShadowU.xyz, p) + frame.cloudShadowU.w,
                   dot(frame.cloudShadowV.xyz, p) + frame.cloudShadowV.w);
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return 1.0;
    return textureLod(cloudShadowMap, uv, 0.0).r;
}

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
        float nDotL = max(dot(n, frame.toSun.xyz), 0.0);
        float visibility = 1.0;
        if (frame.toSun.w > 0.5 && nDotL > 0.0) visibility = sunVisibility(world, n, nDotL);
        if (nDotL > 0.0) visibility *= cloudShadow(world);
        float altitudeSpan = frame.sunOpticalDepthHigh.w - frame.sunOpticalDepthLow.w;
        float a = clamp((world.y - frame.sunOpticalDepthLow.w) / altitudeSpan, 0.0, 1.0);
        vec3 sunTransmittance = exp(-mix(frame.sunOpticalDepthLow.rgb, frame.sunOpticalDepthHigh.rgb, a));
        vec3 irradiance = frame.sunIlluminance.rgb * sunTransmittance * (nDotL * visibility);
        uint lightCount = uint(frame.depthParams.w);
        for (uint i = 0u; i < lightCount; ++i) {
            GpuLight light = lightList.lights[i];
            vec3 toLight = light.positionRadius.xyz - relative;
            float d = length(toLight);
            vec3 l = d > 0.0 ? toLight / d : n;
            float nDotLi = max(dot(n, l), 0.0);
            if (nDotLi <= 0.0) continue;
            float spot =
                spotFactor(dot(light.directionCosOuter.xyz, -l), light.directionCosOuter.w, light.cosInner.x);
            float falloff = localLightFalloff(d, light.positionRadius.w, light.intensityRange.w);
            float contribution = falloff * spot * nDotLi;
            if (light.cosInner.z > 0.5 && contribution > 0.0)
                contribution *= localShadowVisibility(light, relative, n, nDotLi, d);
            irradiance += light.intensityRange.rgb * contribution;
        }
        irradiance = min(irradiance, vec3(1e30));  // finite (I · falloff may overflow): albedo 0 gives 0
        radiance = albedo / kPi * irradiance + albedo * frame.ambient.rgb;
    }
    imageStore(hdr, pixel, vec4(min(radiance, vec3(kHalfMax)), 1.0));
}
