#version 450
// Baseline "seed-as-written" of the accuracy–cost benchmark (bench/baseline.h): the ray march postfx
// started from, as its author wrote it, over postfx's medium.
//
// Where it came from: a Unity URP post-process fog shader, described in a Korean tutorial article. A
// full-screen pass marches each pixel's ray from the camera to the depth buffer's surface (clipped to a
// maximum distance) in steps of a fixed length, the start offset by interleaved gradient noise of the
// pixel and the frame; each step with density adds main light × shadow × Henyey–Greenstein phase ×
// density × step, and multiplies the transmittance by exp(-density · step); the pixel becomes
// lerp(scene colour, fog colour, 1 - T). This file is our own code for that algorithm.
//
// One invocation per pixel; the bindings and FogUniforms are those of shaders/fog/raymarch.comp, and σt,
// the shadow-map visibility and the fog's sun transmittance come from shaders/common/medium/medium.glsl, so
// only the integration, the phase function and the composite differ from postfx:
//   D = min(surface distance, max distance); t = IGN(pixel, frame) · Δ   (Δ = push.stepLength [m])
//   while (t < D) {                          // cost grows with D: no step cap (a safety cap of
//       σ = σt(t·d)                          // kMaxIterations only, so a far or tiny-step ray ends)
//       if (σ > 0) { L += E · pSeed(d·toSun, g) · σ · V(t·d) · Δ;  T *= exp(-σ·Δ); }
//       t += Δ;
//   }
//   out = mix(color, L + albedo · ambient, 1 - T)
// The seed's errors are kept on purpose (docs/effects/fog.md lists them): its phase function's numerator
// is 1 - cos²θ instead of 1 - g²; the in-scattered light is neither attenuated by the transmittance in
// front of it nor multiplied by the albedo; it is added to a constant fog colour (the seed's _Color:
// here albedo · ambient, the radiance a fully opaque fog lit by the ambient alone would have) and the
// sum is blended in by 1 - T, which scales the light a second time; the step count grows with the
// distance. The seed has no ambient in-scattering and no fog self-shadowing (V is the shadow map only).
// With jitter off (fog.jitter) the offset is 0.5 instead of IGN, as in postfx.
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
#include "common/medium/medium.glsl"
#include "common/medium/ray.glsl"

const uint kMaxIterations = 100000u;  // safety cap only; the seed has none
const float kPi = 3.14159265358979;

// The seed's henyey_greenstein(angle, scattering), exactly as it computes it:
//   (1 - cos²θ) / (4π (1 + g² - 2g·cosθ)^1.5)
// (the real Henyey–Greenstein has 1 - g² in the numerator). 0 at cosθ = ±1 for every g.
float seedPhase(float cosTheta, float g) {
    return (1.0 - cosTheta * cosTheta) / (4.0 * kPi * pow(1.0 + g * g - (2.0 * g) * cosTheta, 1.5));
}

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
    float t = offset * stepLength;  // the seed's noise offset: one step

    vec3 sunPhase = fog.sunIlluminance.rgb * seedPhase(dot(dir, fog.toSun.xyz), fog.medium.z);
    float transmittance = 1.0;
    vec3 light = vec3(0.0);
    for (uint i = 0u; t < distLimit && i < kMaxIterations; ++i) {
        vec3 x = dir * t;
        float sigma = extinction(x);
        if (sigma > 0.0) {
            light += sunPhase * sigma * shadowVisibility(x) * stepLength;
            transmittance *= exp(-sigma * stepLength);
        }
        t += stepLength;
    }

    vec3 fogColor = light + fog.albedo.rgb * fog.ambient.rgb;
    vec3 result = mix(color.rgb, fogColor, 1.0 - clamp(transmittance, 0.0, 1.0));
    imageStore(colorOut, ivec2(pixel), vec4(min(result, vec3(kColorMax)), color.a));
}
