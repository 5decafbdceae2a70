// The atmosphere's march along a view ray (docs/effects/atmosphere.md, "Passes"): single scattering with
// the exact phase functions and the sun's transmittance from the transmittance LUT, plus the orders >= 2
// from the multiple-scattering LUT (the orders' J≥2, or Hillaire's σs·Ψ, eq. 11), each step integrated in
// closed form (energy-conserving:
// T·S·(1 - e^{-σt·Δ})/σt). Expects `atmo`, model.glsl, common/integrate.glsl and the samplers
// `transmittanceLut` and (ATMOSPHERE_MS) `multiScatteringLut`. Luminance per unit sun illuminance.
#ifndef POSTFX_ATMOSPHERE_MARCH_GLSL
#define POSTFX_ATMOSPHERE_MARCH_GLSL

// The transmittance LUT's T from planet-centred p toward unit `toSun`: 0 where the planet hides it.
vec3 sunTransmittanceAt(vec3 p, vec3 toSun) {
    float r = length(p);
    float mu = dot(p, toSun) / r;
    if (atmosphereHitsGround(r, mu)) return vec3(0.0);
    if (r >= atmo.radii.y) return vec3(1.0);
    return textureLod(transmittanceLut, transmittanceUv(r, mu), 0.0).rgb;
}

// ∫ over a step of length dt of e^{-σt·s} ds, per channel, without cancellation for thin media.
vec3 atmosphereStepIntegral(vec3 extinction, float dt) {
    return dt * vec3(oneMinusExpOverX(extinction.r * dt), oneMinusExpOverX(extinction.g * dt),
                     oneMinusExpOverX(extinction.b * dt));
}

#ifdef ATMOSPHERE_MS
#include "common/air/orders_lookup.glsl"

// Orders >= 2 in-scattered at p (radius r) into view direction d, per unit length and illuminance: the
// scattering-orders LUT's J≥2, Hillaire's σs·Ψ, or none (AtmosphereUniforms flags).
vec3 multipleScatteringSource(vec3 p, float r, vec3 d, vec3 toSun, AtmosphereMedium m) {
    if ((atmo.flags.x & kAtmosphereFlagScatteringOrders) != 0u)
        return ordersSource(multiScatteringLut, p, r, d, toSun, m);
    if ((atmo.flags.x & kAtmosphereFlagMultipleScattering) == 0u) return vec3(0.0);
    vec2 uv = multipleScatteringUv(dot(p, toSun) / r, r);
    return m.scattering * textureLod(multiScatteringLut, vec3(uv, 0.5), 0.0).rgb / atmo.skyView.w;
}

// The ground's irradiance from the sky per unit sun illuminance (the orders' E≥2; 0 otherwise) at a
// ground point whose zenith makes cosine muS with the sun.
vec3 skyGroundIrradiance(float muS) {
    if ((atmo.flags.x & kAtmosphereFlagScatteringOrders) == 0u) return vec3(0.0);
    return ordersGroundIrradiance(multiScatteringLut, muS);
}
#endif

struct AtmosphereMarch {
    vec3 luminance;      // per unit illuminance [cd/m² per lux]
    vec3 transmittance;  // of the marched segment
};

// Marches [tBegin, tEnd] of ray o + t·d with `steps` steps, each sampled at its middle. quadratic: the
// step boundaries at tBegin + (tEnd - tBegin)·(i/steps)², short near the origin where a view ray from
// the ground meets the densest air (as Hillaire's sky-view LUT); else uniform.
// Steps [first, last) of the `steps`: a part of the march, for passes that split a ray among invocations
// (combined front to back: L = L0 + T0·L1, T = T0·T1).
AtmosphereMarch atmosphereMarchPart(vec3 o, vec3 d, float tBegin, float tEnd, uint steps, uint first,
                                    uint last, bool quadratic, vec3 toSun) {
    AtmosphereMarch result = AtmosphereMarch(vec3(0.0), vec3(1.0));
    if (!(tEnd > tBegin) || steps == 0u || first >= last) return result;
    float cosViewSun = dot(d, toSun);
    float phaseR = rayleighPhase(cosViewSun);
    float phaseM = cornetteShanksPhase(cosViewSun, atmo.mie.w);
    float span = tEnd - tBegin;
    float x0 = float(first) / float(steps);
    float previous = quadratic ? x0 * x0 : x0;
    for (uint i = first; i < last; ++i) {
        float x = float(i + 1u) / float(steps);
        float next = quadratic ? x * x : x;
        float dt = (next - previous) * span;
        vec3 p = o + (tBegin + 0.5 * (previous + next) * span) * d;
        previous = next;
        float r = length(p);
        AtmosphereMedium m = atmosphereMedium(r - atmo.radii.x);
        vec3 S = sunTransmittanceAt(p, toSun) * (m.rayleighScattering * phaseR + m.mieScattering * phaseM);
#ifdef ATMOSPHERE_MS
        S += multipleScatteringSource(p, r, d, toSun, m);
#endif
        result.luminance += result.transmittance * S * atmosphereStepIntegral(m.extinction, dt);
        result.transmittance *= exp(-m.extinction * dt);
    }
    return result;
}

AtmosphereMarch atmosphereMarch(vec3 o, vec3 d, float tBegin, float tEnd, uint steps, bool quadratic,
                                vec3 toSun) {
    return atmosphereMarchPart(o, d, tBegin, tEnd, steps, 0u, steps, quadratic, toSun);
}

#endif
