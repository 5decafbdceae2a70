#version 450
// Baseline "seed-fixed-riemann" of the accuracy–cost benchmark (bench/baseline.h): the seed's ray march
// (the Unity URP fog shader postfx started from; seed_as_written.comp says where it came from) with its
// formula errors fixed but still a plain Riemann sum with a fixed step length. One invocation per pixel;
// the bindings and FogUniforms are those of shaders/fog/raymarch.comp, and σt, the shadow-map visibility
// V and the fog's sun transmittance Tsun come from shaders/common/medium/medium.glsl, so the medium and its
// light are postfx's:
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

#include "fog/fog_shared.h"

layout(local_size_x = kFogGroupSize, local_size_y = kFogGroupSize) in;

#include "fog/bindings.glsl"
// clang-format off
layout(push_constant) uniform Push {
    float stepLength;  // Δ [m], > 0
} push;
// clang-format on

#include "common/ign.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/ray.glsl"

const uint kMaxIterations = 100000u;  // safety cap only

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, fog.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));

    FogRay ray = fogRay(pixel);
    vec3 dir = ray.dir;
    float surfaceDistance = ray.surfaceDistance;

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
