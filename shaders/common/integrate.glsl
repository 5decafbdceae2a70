// Closed-form integration of a step through a medium of constant extinction (Hillaire 2015,
// "Physically based and unified volumetric rendering in Frostbite", eq. for S_int).
#ifndef POSTFX_INTEGRATE_GLSL
#define POSTFX_INTEGRATE_GLSL

// (1 - e^{-x}) / x for x >= 0, to a few float ulps everywhere (docs/stability.md, "Shader functions").
// Below 0.5 the Taylor series 1 - x/2 + x²/6 - … to x⁷/8! (truncation < x⁸/9! < 1.1e-8): 1 - e^{-x}
// computed directly there cancels (at x = 1e-4 it keeps only ~11 of float's 24 bits). Above, e^{-x} <
// 0.61, so 1 - e^{-x} loses at most 2 bits. x = +Inf gives 0.
float oneMinusExpOverX(float x) {
    if (x < 0.5) {
        // clang-format off
        return 1.0 - x * (1.0 / 2.0 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0 -
               x * (1.0 / 720.0 - x * (1.0 / 5040.0 - x * (1.0 / 40320.0)))))));
        // clang-format on
    }
    return (1.0 - exp(-x)) / x;
}

// 1 - exp(-x) for x >= 0 without cancellation; +Inf gives 1.
float oneMinusExp(float x) {
    return x < 0.5 ? x * oneMinusExpOverX(x) : 1.0 - exp(-x);
}

// In-scattered radiance of one step of length dt, seen through transmittance T in front of it:
//   T · ∫0^dt S e^{-σt s} ds = T · S · (1 - e^{-σt·dt}) / σt.
// With S = σs · light = albedo · σt · light the σt cancels: T · albedo · light · (1 - e^{-σt·dt}),
// whose limit as σt -> 0 is the exact S·dt.
vec3 integrateStep(float transmittance, vec3 albedoTimesLight, float opticalDepth) {
    return transmittance * albedoTimesLight * oneMinusExp(opticalDepth);
}

#endif
