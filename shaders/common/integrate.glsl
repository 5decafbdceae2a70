// Closed-form integration of a step through a medium of constant extinction (Hillaire 2015,
// "Physically based and unified volumetric rendering in Frostbite", eq. for S_int).
#ifndef POSTFX_INTEGRATE_GLSL
#define POSTFX_INTEGRATE_GLSL

// 1 - exp(-x) for x >= 0 without cancellation: the series x - x²/2 below 1e-4 (relative error < 2e-13).
float oneMinusExp(float x) {
    return x < 1e-4 ? x * (1.0 - 0.5 * x) : 1.0 - exp(-x);
}

// In-scattered radiance of one step of length dt, seen through transmittance T in front of it:
//   T · ∫0^dt S e^{-σt s} ds = T · S · (1 - e^{-σt·dt}) / σt.
// With S = σs · light = albedo · σt · light the σt cancels: T · albedo · light · (1 - e^{-σt·dt}),
// whose limit as σt -> 0 is the exact S·dt.
vec3 integrateStep(float transmittance, vec3 albedoTimesLight, float opticalDepth) {
    return transmittance * albedoTimesLight * oneMinusExp(opticalDepth);
}

#endif
