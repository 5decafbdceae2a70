// Phase functions. Normalised over the sphere: ∫ p dω = 1 [1/sr].
#ifndef POSTFX_PHASE_GLSL
#define POSTFX_PHASE_GLSL

const float kInvFourPi = 0.07957747154594767;

// Henyey–Greenstein (1941): p(cosθ) = (1 - g²) / (4π (1 + g² - 2g·cosθ)^{3/2}).
// cosθ = dot(viewDir, toLight) with viewDir pointing from the eye into the scene, so g > 0 is brightest
// looking toward the light. g must be inside (-1, 1) (callers clamp to ±0.999).
float henyeyGreenstein(float cosTheta, float g) {
    float g2 = g * g;
    float denom = 1.0 + g2 - 2.0 * g * cosTheta;
    return kInvFourPi * (1.0 - g2) / (denom * sqrt(denom));
}

#endif
