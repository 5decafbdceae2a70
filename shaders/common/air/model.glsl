// The atmosphere model on the GPU (docs/effects/atmosphere.md, "Model" and "Parameterisations"): media,
// ray–sphere intersections, phase functions, the LUTs' parameterisations and lookups. It mirrors
// postfx/src/atmosphere/atmosphere_model.cpp (double), which the tests hold it to. Expects `atmo`
// (AtmosphereUniforms). Positions are planet-centred [m]; r = |position|, μ = cos(angle to the zenith).
#ifndef POSTFX_ATMOSPHERE_MODEL_GLSL
#define POSTFX_ATMOSPHERE_MODEL_GLSL

#include "common/air/transmittance_lut.glsl"
#include "common/ray_sphere.glsl"

const float kAtmospherePi = 3.14159265358979;

struct AtmosphereMedium {
    vec3 rayleighScattering;
    float mieScattering;
    vec3 scattering;  // σs
    vec3 extinction;  // σt
};

// The medium at altitude h above the ground (h < 0 taken as 0) [1/m]: Rayleigh e^{-h/H_R}, Mie
// e^{-h/H_M} (scattering and absorption), ozone's tent max(0, 1 - |h - centre| / half width).
AtmosphereMedium atmosphereMedium(float altitude) {
    float h = max(altitude, 0.0);
    float rayleigh = exp(-h * atmo.rayleigh.w);
    float mie = exp(-h * atmo.mie.z);
    float ozone = max(0.0, 1.0 - abs(h - atmo.ozone.w) / atmo.albedo.w);
    AtmosphereMedium m;
    m.rayleighScattering = atmo.rayleigh.rgb * rayleigh;
    m.mieScattering = atmo.mie.x * mie;
    m.scattering = m.rayleighScattering + m.mieScattering;
    m.extinction = m.scattering + atmo.mie.y * mie + atmo.ozone.rgb * ozone;
    return m;
}

// The part of ray o + t·d (t >= 0) inside the atmosphere and before the ground: x = begin, y = end
// (end <= begin: none), z = 1 when it ends on the ground.
vec3 atmosphereSegment(vec3 o, vec3 d) {
    vec2 top = raySphere(o, d, atmo.radii.y);
    if (top.y <= 0.0) return vec3(0.0);
    vec3 seg = vec3(max(top.x, 0.0), top.y, 0.0);
    vec2 ground = raySphere(o, d, atmo.radii.x);
    if (ground.x < ground.y && ground.x >= 0.0 && ground.x < seg.y) seg.yz = vec2(ground.x, 1.0);
    return seg;
}

// Rayleigh: 3/(16π)(1 + cos²θ). Cornette–Shanks (1992): 3/(8π)(1 - g²)(1 + cos²θ)/((2 + g²)(1 + g² -
// 2g·cosθ)^{3/2}), cosθ = dot(view direction, toSun): g > 0 is brightest toward the sun.
float rayleighPhase(float c) {
    return 3.0 / (16.0 * kAtmospherePi) * (1.0 + c * c);
}
float cornetteShanksPhase(float c, float g) {
    float g2 = g * g;
    float denom = max(1.0 + g2 - 2.0 * g * c, 1e-12);
    return 3.0 / (8.0 * kAtmospherePi) * (1.0 - g2) * (1.0 + c * c) / ((2.0 + g2) * denom * sqrt(denom));
}

// Texel-centre mapping of x in [0, 1] onto n texels (Bruneton 2017): 0 and 1 at the end texels' centres.
float unitToTexel(float x, uint n) {
    return 0.5 / float(n) + x * (1.0 - 1.0 / float(n));
}
float texelToUnit(float u, uint n) {
    return (u - 0.5 / float(n)) / (1.0 - 1.0 / float(n));
}

// A direction at radius r with cosine μ meets the ground.
bool atmosphereHitsGround(float r, float mu) {
    return rayMeetsGround(r, mu, atmo.radii.x);
}

// Distance from radius r <= top along μ to the top boundary: -rμ + √(top² - r²(1 - μ²)).
float atmosphereDistanceToTop(float r, float mu) {
    float t = atmo.radii.y;
    return max(0.0, -r * mu + sqrt(max(0.0, (t - r) * (t + r) + r * r * mu * mu)));
}

// Transmittance LUT (transmittance_lut.glsl).
vec2 transmittanceUv(float r, float mu) {
    return transmittanceLutUv(r, mu, atmo.radii.x, atmo.radii.y, vec2(atmo.transmittanceLut.xy));
}
// The inverse, for the LUT's texels: x = (r, μ).
vec2 transmittanceParams(vec2 uv) {
    float g = atmo.radii.x, t = atmo.radii.y;
    vec2 x = vec2(texelToUnit(uv.x, atmo.transmittanceLut.x), texelToUnit(uv.y, atmo.transmittanceLut.y));
    float H = sqrt(atmo.radii.z);
    float rho = H * x.y;
    float r = sqrt(rho * rho + g * g);
    float dMin = t - r, dMax = rho + H;
    float d = dMin + x.x * (dMax - dMin);
    // Law of cosines in the triangle (centre, point, exit point): top² = r² + d² + 2rdμ.
    float mu = d == 0.0 ? 1.0 : clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
    return vec2(r, mu);
}

// Multiple-scattering LUT (Hillaire's): x = (μs + 1)/2, y = (r - ground)/(top - ground).
vec2 multipleScatteringUv(float muS, float r) {
    float x = clamp(0.5 * muS + 0.5, 0.0, 1.0);
    float y = clamp((r - atmo.radii.x) / (atmo.radii.y - atmo.radii.x), 0.0, 1.0);
    return vec2(unitToTexel(x, atmo.msLut.x), unitToTexel(y, atmo.msLut.y));
}

// The sky-view LUT's mapping (Hillaire's non-linear mapping; atmosphere_model.h, skyViewUnitFromParams)
// at its radius, from the uniforms' skyHorizon (β the horizon's angle from the nadir, Z = π - β, the sky
// half's span D): texel -> x = cos view zenith, y = cos azimuth. Above the horizon θ = Z - D·(1 - 2v)²,
// below it Z + β·(2v - 1)²; cos azimuth from the sun 1 - 2u². The forward form (direction -> texel)
// is the apply pass's (apply.comp, skyViewLuminance), with its per-frame reciprocals.
vec2 skyViewParams(vec2 uv) {
    vec2 x = vec2(texelToUnit(uv.x, atmo.skyViewLut.x), texelToUnit(uv.y, atmo.skyViewLut.y));
    float theta;
    if (x.y < 0.5) {
        float c = 1.0 - 2.0 * x.y;
        theta = atmo.skyHorizon.y - atmo.skyHorizon.z * c * c;
    } else {
        float c = 2.0 * x.y - 1.0;
        theta = atmo.skyHorizon.y + atmo.skyHorizon.x * c * c;
    }
    return vec2(cos(theta), 1.0 - 2.0 * x.x * x.x);
}

#endif
