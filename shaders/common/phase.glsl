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

// The same for unit vectors `viewDir` and `toLight`, without cancellation at either peak (docs/stability.md):
// with s = sign(g), 1 + g² - 2g·cosθ = (1 - |g|)² + |g|·|viewDir - s·toLight|², because
// |d ∓ l|² = 2 ∓ 2cosθ. So for |g| -> 1 the peak's (1 - |g|)² ~ 1e-6 is a sum of two non-negative terms,
// not the difference of two numbers near 2 (float would lose ~20% there).
float henyeyGreensteinDirections(vec3 viewDir, vec3 toLight, float g) {
    float absG = abs(g);
    vec3 d = viewDir - (g < 0.0 ? -toLight : toLight);
    float oneMinusG = 1.0 - absG;
    float denom = oneMinusG * oneMinusG + absG * dot(d, d);
    return kInvFourPi * oneMinusG * (1.0 + absG) / (denom * sqrt(denom));  // 1 - g² without cancellation
}

#endif
