#version 450
// Baseline "seed-fixed-riemann" of the accuracy–cost benchmark (bench/baseline.h): the seed's ray march
// (../shared/seeds/urp-raymarch-fog.md) with its formula errors fixed but still a plain Riemann sum with a
// fixed step length. One invocation per pixel; the bindings and FogUniforms are those of
// shaders/fog/raymarch.comp, and σt, the shadow-map visibility V and the fog's sun transmittance Tsun
// come from shaders/fog/medium.glsl, so the medium and its light are postfx's:
//   D = min(surface distance, max distance); t = IGN(pixel, frame) · Δ   (Δ = push.stepLength [m])
//   while (t < D) {                          // cost grows with D (safety cap kMaxIterations only)
//       δ = min(Δ, D - t)                    // the last step clipped to D
//       σ = σt(t·d)
//       L += T · albedo · σ · (E · pHG(d·toSun, g) · V · Tsun + ambient) · δ
//       T *= exp(-σ·δ)
//       t += Δ;
//   }
//   out = color · T + L
// The sample at t stands for [t, t + δ] (left Riemann sum): first-order in Δ, and the first
// IGN·Δ metres of the ray are not covered (the seed's start offset kept). No analytic tail beyond the
// max distance and no early exit on low transmittance (postfx has both). With jitter off (fog.jitter)
// the offset is 0.5 instead of IGN, as in postfx.
#extension GL_GOOGLE_include_directive : require

#include "common/shared.h"

layout(local_size_x = kFogGroupSize, local_size_y = kFogGroupSize) in;

layout(binding = kFogBindingColorIn, rgba16f) uniform readonly image2D colorIn;
layout(binding = kFogBindingColorOut, rgba16f) uniform writeonly image2D colorOut;
layout(binding = kFogBindingDepth) uniform sampler2D depthTexture;
layout(binding = kFogBindingShadowMap) uniform sampler2D shadowMap;
layout(binding = kFogBindingNoise) uniform sampler3D noiseTexture;
layout(binding = kFogBindingUniforms, std140) uniform Uniforms { FogUniforms fog; };
layout(push_constant) uniform Push {
    float stepLength;  // Δ [m], > 0
} push;

#include "common/ign.glsl"
#include "common/phase.glsl"
#include "fog/medium.glsl"

const float kColorMax = 65504.0;      // largest finite half: never write Inf (as postfx)
const uint kMaxIterations = 100000u;  // safety cap only
const float kInfinity = 1.0 / 0.0;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, fog.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));

    // The ray exactly as postfx builds it: camera-relative surface position; no geometry: infinite.
    float depth = texelFetch(depthTexture, ivec2(pixel), 0).r;
    bool noGeometry = depth == fog.march.y;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(fog.extent.xy) * 2.0 - 1.0;
    vec4 p = fog.clipToView * vec4(ndc, noGeometry ? 0.5 : depth, 1.0);
    vec3 surface = p.xyz / p.w;
    float surfaceDistance = length(surface);
    vec3 dir = surface / surfaceDistance;
    if (noGeometry) surfaceDistance = kInfinity;

    float stepLength = push.stepLength;
    float distLimit = min(surfaceDistance, fog.medium.w);
    float offset = fogFlag(kFogFlagJitter) ? interleavedGradientNoise(pixel, fog.extent.w) : 0.5;
    float t = offset * stepLength;

    vec3 albedo = fog.albedo.rgb;
    vec3 sunPhase = fog.sunIlluminance.rgb * henyeyGreenstein(dot(dir, fog.toSun.xyz), fog.medium.z);
    vec3 ambient = fog.ambient.rgb;
    float transmittance = 1.0;
    vec3 inScattered = vec3(0.0);
    for (uint i = 0u; t < distLimit && i < kMaxIterations; ++i) {
        float dt = min(stepLength, distLimit - t);
        vec3 x = dir * t;
        float sigma = extinction(x);
        if (sigma > 0.0) {
            float visibility = shadowVisibility(x) * sunTransmittance(fog.heights.x + x.y);
            inScattered += transmittance * albedo * sigma * (sunPhase * visibility + ambient) * dt;
            transmittance *= exp(-sigma * dt);
        }
        t += stepLength;
    }

    vec3 result = min(color.rgb * transmittance + inScattered, vec3(kColorMax));
    imageStore(colorOut, ivec2(pixel), vec4(result, color.a));
}
