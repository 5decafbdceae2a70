// The clouds' light at a sample (docs/effects/clouds.md, "Light"), mirrored in double by
// postfx/src/clouds/clouds_model.cpp: the sun through the atmosphere (kCloudAtmosphere) and through the
// cloud toward it (a short march), scattered by a dual-lobe Henyey–Greenstein phase with Wrenninge's
// octaves, plus the ambient light. Expects `cl`, density.glsl, kCloudAtmosphere, `atmo` and
// transmittanceLut.
#ifndef POSTFX_CLOUDS_LIGHTING_GLSL
#define POSTFX_CLOUDS_LIGHTING_GLSL

#include "common/integrate.glsl"
#include "common/phase.glsl"

// The distance from camera-relative x toward the sun to where the ray leaves the shape, at most the light
// distance [m].
float cloudLightLength(vec3 x) {
    vec2 seg = cloudSegment(x, cl.toSun.xyz, cl.sun.w);
    return seg.y > seg.x ? max(seg.y, 0.0) : 0.0;
}

// Optical depth of the cloud from x toward the sun: lightSteps midpoint samples over cloudLightLength,
// step k spanning [(k/n)², ((k+1)/n)²] of it: short steps near x, where a dense cloud takes the sun's
// light within tens of metres (the self-shadowing that shapes a cloud's lit side), long ones far away,
// where only whether the path is blocked matters. Uniform steps over a 2 km path missed that first
// stretch: on the H100 the benchmark's noon view fell from 3.4% to 2.0% error at 6 light steps
// (docs/effects/clouds.md, "Light").
float cloudSunOpticalDepth(vec3 x) {
    float length = cloudLightLength(x);
    if (length <= 0.0) return 0.0;
    float n = float(cl.counts.y);
    float scale = length / (n * n);
    float tau = 0.0;
    for (uint k = 0u; k < cl.counts.y; ++k) {
        float a = float(k * k), b = float((k + 1u) * (k + 1u));
        tau += cloudExtinction(x + cl.toSun.xyz * (0.5 * (a + b) * scale)) * ((b - a) * scale);
    }
    return tau;
}

// (1 - w)·HG(g_f) + w·HG(g_b) for view direction d (from the eye), the asymmetries scaled by `scale`.
float cloudPhase(vec3 d, float scale) {
    float forward = henyeyGreensteinDirections(d, cl.toSun.xyz, cl.phase.x * scale);
    float back = henyeyGreensteinDirections(d, cl.toSun.xyz, cl.phase.y * scale);
    return mix(forward, back, cl.phase.z);
}

// The atmosphere's transmittance from camera-relative x toward the sun (0 where the planet hides it).
vec3 cloudAtmosphereTransmittance(vec3 x) {
    return sunTransmittanceFromLut(transmittanceLut, atmo.camera.xyz + x, cl.toSun.xyz, atmo.radii.x,
                                   atmo.radii.y, vec2(atmo.transmittanceLut.xy));
}

// The slab's unit normal at camera-relative x: up through a flat layer, the planet's radial direction
// through a curved one, the box's own y.
vec3 cloudSlabNormal(vec3 x) {
    if ((cl.flags.x & kCloudFlagBox) != 0u)
        return vec3(cl.boxFromView[0][1], cl.boxFromView[1][1], cl.boxFromView[2][1]);
    if ((cl.flags.x & kCloudFlagCurved) != 0u) return normalize(cl.origin.xyz + x);
    return vec3(0.0, 1.0, 0.0);
}

// The δ-Eddington diffuse light (Joseph, Wiscombe and Weinman 1976) per unit sun illuminance at δ-scaled
// optical depth tt below the sunlit face of a slab with tb more beyond, the sun at cosine mu0 to its
// normal, the scaled direct beam `beam` here and `farBeam` at the far face: (U, F), the fluence and the
// net flux away from the sunlit face. U'' = k²U - 3ω'(1 + g' - ω'g')·beam (Eddington's closure) with no
// diffuse light entering either face (Marshak: U ± 2F = 0), solved as U = a·u1 + b·u2 + A·beam with
// u1 = sinh(k·tb)/sinh(k·τ0), u2 = sinh(k·tt)/sinh(k·τ0) written with decaying exponentials only, so that
// thick slabs do not overflow and ω' -> 1 (k -> 0) tends to the linear conservative solution.
vec2 cloudSlabDiffuse(float tt, float tb, float mu0, float beam, float farBeam) {
    float w = cl.slab.x, g = cl.slab.y;
    float k = max(sqrt(max(3.0 * (1.0 - w) * (1.0 - w * g), 0.0)), 1e-6);
    float tau0 = max(tt + tb, 1e-6);
    float pole = 1.0 - k * k * mu0 * mu0;  // the particular solution's denominator
    if (abs(pole) < kCloudSlabPoleGap) pole = pole < 0.0 ? -kCloudSlabPoleGap : kCloudSlabPoleGap;
    float A = -3.0 * w * (1.0 + g * (1.0 - w)) * mu0 * mu0 / pole;
    float D = 3.0 * (1.0 - w * g), B = 3.0 * w * g * mu0;
    float q0 = oneMinusExp(2.0 * k * tau0);
    float et = exp(-k * tt), eb = exp(-k * tb);
    float u1 = et * oneMinusExp(2.0 * k * tb) / q0, u2 = eb * oneMinusExp(2.0 * k * tt) / q0;
    float u1d = -k * et * (1.0 + eb * eb) / q0, u2d = k * eb * (1.0 + et * et) / q0;
    // Marshak's conditions: [p -q; -q p]·(a, b) = (r1, r2), p - q = 1 + 2k·tanh(kτ0/2)/D.
    float e0 = et * eb;
    float c = k * (1.0 + e0 * e0) / q0, sn = 2.0 * k * e0 / q0;
    float p = 1.0 + 2.0 * c / D, q = 2.0 * sn / D;
    float pMinusQ = 1.0 + 2.0 * k * oneMinusExp(k * tau0) / ((1.0 + e0) * D);
    // a = (p·r1 + q·r2)/((p - q)(p + q)) with p, q ~ 1/τ0 in a thin slab: written so that nothing of that
    // size cancels.
    float top = B + A / mu0;
    float r1 = -A - 2.0 * top / D, r2 = farBeam * (-A + 2.0 * top / D);
    float sum = -A * (1.0 + farBeam) - 2.0 * top / D * (1.0 - farBeam);  // r1 + r2
    float both = p / (p + q) * sum / pMinusQ;
    float a = both - r2 / (p + q), b = both - r1 / (p + q);
    float U = a * u1 + b * u2 + A * beam;
    // U' = a·u1' + b·u2' - A/μ0·beam with u1' ≈ -u2' ~ 1/τ0: summed as both·(u1' + u2'), u1' + u2' =
    // k(e^{-k·tb} - e^{-k·tt})/(1 + e^{-kτ0}), so that the thin slab's large derivatives do not cancel.
    float slope = both * k * (eb - et) / (1.0 + e0) - (r2 * u1d + r1 * u2d) / (p + q) - A / mu0 * beam;
    float F = (B * beam - slope) / D;
    return vec2(max(U, 0.0), F);
}

// The slab model's sun term per unit illuminance toward the eye (docs/effects/clouds.md, "Multiple
// scattering"): single scattering p·e^{-τ}, the light scattered into the phase's forward peak, carried
// with the direct beam by the δ-scaling (f = the phase's second moment) and seen through the phase
// convolved with itself (HG(g)∗HG(g) = HG(g²)): p(g·g)·(e^{-(1 - ωf)τ} - e^{-τ}), and the diffuse light
// of the local slab: (U + 3g·F·(d·n))/4π (the source function of the Eddington field, Toon et al. 1989).
// The slab: its sunlit face where the sun's optical depth τ puts it (τ·μ0 above x), the far face the
// sample's own extinction times its height fraction's distance to it.
float cloudSlabSunTerm(vec3 n, vec3 d, float sigma, float h, float tau, float thickness) {
    float cosSun = dot(n, cl.toSun.xyz);
    float hc = clamp(h, 0.0, 1.0);
    float beyond = sigma * thickness * (cosSun >= 0.0 ? hc : 1.0 - hc);  // to the far face
    if (cosSun < 0.0) n = -n;                                            // toward the sunlit face
    float mu0 = max(abs(cosSun), kCloudSlabMinCosine);
    float scale = cl.slab.z;
    float direct = exp(-tau), beam = exp(-scale * tau);
    float tt = scale * tau * mu0, tb = scale * beyond;
    vec2 UF = cloudSlabDiffuse(tt, tb, mu0, beam, beam * exp(-tb / mu0));
    float diffuse = max(UF.x + 3.0 * cl.slab.w * UF.y * dot(d, n), 0.0) * kInvFourPi;
    return cloudPhase(d, 1.0) * direct + cloudPhase(d, cl.slab.w) * (beam - direct) + diffuse;
}

// The slab model's ambient term per unit ambient radiance toward the eye (docs/effects/clouds.md, "Multiple
// scattering"): the δ-Eddington slab lit on both faces by the uniform radiance A, with nothing else:
// U'' = k²U, F = -U'/D, πA entering each face (U/4 ± F/2 = πA), symmetric: U = πA(e^{-k·tt} +
// e^{-k·tb})/((1 + e^{-kτ0})/4 + k(1 - e^{-kτ0})/(2D)), which is 4πA throughout at albedo 1 (a
// conservative cloud under a uniform sky is as bright as it). tt and tb: the scaled optical depths to the
// top and bottom from the sample's extinction.
float cloudSlabAmbient(vec3 n, vec3 d, float sigma, float h, float thickness) {
    float w = cl.slab.x, g = cl.slab.y;
    float k = max(sqrt(max(3.0 * (1.0 - w) * (1.0 - w * g), 0.0)), 1e-6);
    float D = 3.0 * (1.0 - w * g);
    float hc = clamp(h, 0.0, 1.0);
    float tt = cl.slab.z * sigma * (1.0 - hc) * thickness, tb = cl.slab.z * sigma * hc * thickness;
    float et = exp(-k * tt), eb = exp(-k * tb), e0 = et * eb;
    float den = 0.25 * (1.0 + e0) + k / (2.0 * D) * oneMinusExp(k * (tt + tb));
    // U/4π and F/4π per unit A; F away from the top.
    float u = 0.25 * (et + eb) / den, f = -0.25 * k * (eb - et) / (D * den);
    return max(u + 3.0 * cl.slab.w * f * dot(d, n), 0.0);
}

// The radiance a unit of scattering coefficient sends toward the eye from x, σt = `sigma` there, height
// fraction h: E·T_atm·(the slab's sun term, or Wrenninge's Σ_i b^i·p(c^i·g)·e^{-a^i·τ_sun}) +
// A·(e^{-1.66·σ·up} + e^{-1.66·σ·down})/2.
vec3 cloudInScattered(vec3 x, vec3 d, float sigma, float h) {
    float tau = cloudSunOpticalDepth(x);
    bool slab = (cl.flags.x & kCloudFlagSlabScattering) != 0u;
    float thickness = (cl.flags.x & kCloudFlagBox) != 0u ? 2.0 * cl.boxHalf.y : 1.0 / cl.layer.w;
    vec3 n = slab ? cloudSlabNormal(x) : vec3(0.0);
    float sunTerm = 0.0;
    if (slab) {
        sunTerm = cloudSlabSunTerm(n, d, sigma, h, tau, thickness);
    } else {
        float a = 1.0, b = 1.0, c = 1.0;
        for (uint i = 0u; i < cl.counts.z; ++i) {
            sunTerm += b * cloudPhase(d, c) * exp(-a * tau);
            a *= cl.multiScatter.x;
            b *= cl.multiScatter.y;
            c *= cl.multiScatter.z;
        }
    }
    vec3 sun = cl.sun.rgb;
    if (kCloudAtmosphere) sun *= cloudAtmosphereTransmittance(x);
    float ambient;
    if (slab) {
        ambient = cloudSlabAmbient(n, d, sigma, h, thickness);
    } else {
        float hc = clamp(h, 0.0, 1.0);
        ambient = 0.5 * (exp(-kCloudDiffusivity * sigma * (1.0 - hc) * thickness) +
                         exp(-kCloudDiffusivity * sigma * hc * thickness));
    }
    return sun * sunTerm + cl.ambient.rgb * ambient;
}

#endif
