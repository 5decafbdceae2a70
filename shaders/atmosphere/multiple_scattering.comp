#version 450
// Pass 2 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the multiple-scattering LUT, Hillaire
// 2020 section 5.5. Texel (μs, r) holds Ψ = L2 / (1 - f_ms) per unit sun illuminance (eq. 10): over n×n
// stratified directions from radius r, each marched `msLut.w` steps to the top or the ground,
//   L2   = mean of ∫ T·σs·Tsun·p_u dt + T·Tsun·max(0, n·s)·albedo/π   (eq. 5–6, p_u = 1/4π),
//   f_ms = mean of ∫ T·σs·p_u dt · 4π                                     (eq. 7–8),
// one workgroup per texel, its invocations sharing the directions, summed in shared memory.
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereMsGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering, rgba16f) uniform writeonly image3D multiScatteringOut;

#include "common/integrate.glsl"
#include "common/air/model.glsl"
#include "common/air/march.glsl"

shared vec3 sharedL2[kAtmosphereMsGroupSize];
shared vec3 sharedFms[kAtmosphereMsGroupSize];

void main() {
    uvec2 texel = gl_WorkGroupID.xy;
    uint lane = gl_LocalInvocationID.x;
    // Texel centre -> (μs, r) (the inverse of multipleScatteringUv).
    vec2 x = vec2(texelToUnit((float(texel.x) + 0.5) / float(atmo.msLut.x), atmo.msLut.x),
                  texelToUnit((float(texel.y) + 0.5) / float(atmo.msLut.y), atmo.msLut.y));
    float muS = clamp(2.0 * x.x - 1.0, -1.0, 1.0);
    float r = atmo.radii.x + clamp(x.y, 0.0, 1.0) * (atmo.radii.y - atmo.radii.x);
    vec3 origin = vec3(0.0, r, 0.0);
    vec3 toSun = vec3(sqrt(max(0.0, 1.0 - muS * muS)), muS, 0.0);

    uint n = atmo.msLut.z, steps = atmo.msLut.w;
    vec3 l2 = vec3(0.0), fms = vec3(0.0);
    for (uint k = lane; k < n * n; k += kAtmosphereMsGroupSize) {
        // Stratified uniform directions: azimuth 2π·a, cos(polar) = 1 - 2b.
        float a = (float(k / n) + 0.5) / float(n), b = (float(k % n) + 0.5) / float(n);
        float phi = 2.0 * kAtmospherePi * a, cosPolar = 1.0 - 2.0 * b;
        float sinPolar = sqrt(max(0.0, 1.0 - cosPolar * cosPolar));
        vec3 dir = vec3(cos(phi) * sinPolar, cosPolar, sin(phi) * sinPolar);
        vec3 seg = atmosphereSegment(origin, dir);
        if (!(seg.y > seg.x) && seg.z == 0.0) continue;
        float dt = max(0.0, seg.y - seg.x) / float(steps);
        vec3 T = vec3(1.0);
        for (uint s = 0u; s < steps; ++s) {
            vec3 p = origin + (seg.x + (float(s) + 0.5) * dt) * dir;
            AtmosphereMedium m = atmosphereMedium(length(p) - atmo.radii.x);
            vec3 w = T * atmosphereStepIntegral(m.extinction, dt) * m.scattering;  // ∫ T·σs dt
            l2 += w * sunTransmittanceAt(p, toSun) * (1.0 / (4.0 * kAtmospherePi));
            fms += w;
            T *= exp(-m.extinction * dt);
        }
        if (seg.z != 0.0) {
            vec3 p = origin + seg.y * dir;
            float nDotL = max(0.0, dot(normalize(p), toSun));
            l2 += T * sunTransmittanceAt(p, toSun) * nDotL * atmo.albedo.rgb / kAtmospherePi;
        }
    }
    sharedL2[lane] = l2;
    sharedFms[lane] = fms;
    barrier();
    for (uint stride = kAtmosphereMsGroupSize / 2u; stride > 0u; stride /= 2u) {
        if (lane < stride) {
            sharedL2[lane] += sharedL2[lane + stride];
            sharedFms[lane] += sharedFms[lane + stride];
        }
        barrier();
    }
    if (lane == 0u) {
        float count = float(n * n);
        vec3 meanL2 = sharedL2[0] / count, meanFms = sharedFms[0] / count;
        // Σ_k f_ms^k = 1 / (1 - f_ms) (eq. 9); f_ms < 1 in any medium that absorbs or lets light escape.
        vec3 psi = meanL2 / max(vec3(1.0) - meanFms, vec3(1e-6));
        imageStore(multiScatteringOut, ivec3(texel, 0), vec4(min(psi * atmo.skyView.w, vec3(65504.0)), 1.0));
    }
}
