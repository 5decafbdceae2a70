#version 450
// Pass 2 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the multiple-scattering LUT, Hillaire
// 2020 section 5.5. Texel (μs, r) holds Ψ = L2 / (1 - f_ms) per unit sun illuminance (eq. 10): over n×n
// stratified directions from radius r, each marched `msLut.w` steps to the top or the ground,
//   L2   = mean of ∫ T·σs·Tsun·p_u dt + T·Tsun·max(0, n·s)·albedo/π   (eq. 5–6, p_u = 1/4π),
//   f_ms = mean of ∫ T·σs·p_u dt · 4π                                     (eq. 7–8),
// 1 - f_ms summed as what does not scatter again (T at the ray's end plus ∫ T·σa dt: the march telescopes
// to 1 - T_end, so no cancellation as f_ms -> 1), Ψ bounded by kAtmosphereMaxPsi (atmosphere_shared.h),
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
shared vec3 sharedLeaves[kAtmosphereMsGroupSize];

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
    vec3 l2 = vec3(0.0), leaves = vec3(0.0);  // leaves: Σ (1 - the direction's f_ms)
    for (uint k = lane; k < n * n; k += kAtmosphereMsGroupSize) {
        // Stratified uniform directions: azimuth 2π·a, cos(polar) = 1 - 2b.
        float a = (float(k / n) + 0.5) / float(n), b = (float(k % n) + 0.5) / float(n);
        float phi = 2.0 * kAtmospherePi * a, cosPolar = 1.0 - 2.0 * b;
        float sinPolar = sqrt(max(0.0, 1.0 - cosPolar * cosPolar));
        vec3 dir = vec3(cos(phi) * sinPolar, cosPolar, sin(phi) * sinPolar);
        vec3 seg = atmosphereSegment(origin, dir);
        if (!(seg.y > seg.x) && seg.z == 0.0) {
            leaves += vec3(1.0);  // misses the atmosphere
            continue;
        }
        float dt = max(0.0, seg.y - seg.x) / float(steps);
        vec3 T = vec3(1.0), absorbed = vec3(0.0);
        for (uint s = 0u; s < steps; ++s) {
            vec3 p = origin + (seg.x + (float(s) + 0.5) * dt) * dir;
            AtmosphereMedium m = atmosphereMedium(length(p) - atmo.radii.x);
            vec3 t = T * atmosphereStepIntegral(m.extinction, dt);  // ∫ T dt
            l2 += t * m.scattering * sunTransmittanceAt(p, toSun) * (1.0 / (4.0 * kAtmospherePi));
            absorbed += t * (m.extinction - m.scattering);
            T *= exp(-m.extinction * dt);
        }
        leaves += T + absorbed;
        if (seg.z != 0.0) {
            vec3 p = origin + seg.y * dir;
            float nDotL = max(0.0, dot(normalize(p), toSun));
            l2 += T * sunTransmittanceAt(p, toSun) * nDotL * atmo.albedo.rgb / kAtmospherePi;
        }
    }
    sharedL2[lane] = l2;
    sharedLeaves[lane] = leaves;
    barrier();
    for (uint stride = kAtmosphereMsGroupSize / 2u; stride > 0u; stride /= 2u) {
        if (lane < stride) {
            sharedL2[lane] += sharedL2[lane + stride];
            sharedLeaves[lane] += sharedLeaves[lane + stride];
        }
        barrier();
    }
    if (lane == 0u) {
        float count = float(n * n);
        vec3 meanL2 = sharedL2[0] / count, meanLeaves = sharedLeaves[0] / count;
        // Σ_k f_ms^k = 1 / (1 - f_ms) (eq. 9), bounded: kAtmosphereMaxPsi where the series diverges (nothing
        // leaves within float's range), 0 where no light arrives.
        vec3 psi = vec3(0.0);
        for (int c = 0; c < 3; ++c)
            if (meanL2[c] > 0.0)
                psi[c] = meanL2[c] >= kAtmosphereMaxPsi * meanLeaves[c] ? kAtmosphereMaxPsi
                                                                        : meanL2[c] / meanLeaves[c];
        imageStore(multiScatteringOut, ivec3(texel, 0), vec4(min(psi * atmo.skyView.w, vec3(65504.0)), 1.0));
    }
}
