// The atmosphere's reference integrals (atmosphere_reference.h; docs/effects/atmosphere.md, "Reference").
#include "atmosphere/atmosphere_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace postfx::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;

double altitudeOf(const Model& m, const glm::dvec3& p) {
    return glm::length(p) - m.groundRadius;
}

// ∫ over a step of length Δ of e^{-σt·s} ds = (1 - e^{-σtΔ})/σt per channel; Δ where σt = 0.
glm::dvec3 stepIntegral(const glm::dvec3& extinction, double delta) {
    glm::dvec3 r;
    for (int c = 0; c < 3; ++c)
        r[c] = extinction[c] > 0.0 ? -std::expm1(-extinction[c] * delta) / extinction[c] : delta;
    return r;
}

glm::dvec3 expNeg(const glm::dvec3& tau) {
    return {std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z)};
}

}  // namespace

glm::dvec3 opticalDepth(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir, uint32_t steps) {
    const AtmosphereSegment seg = atmosphereSegment(m, origin, dir);
    glm::dvec3 tau(0.0);
    if (seg.tEnd <= seg.tBegin || steps == 0) return tau;
    const double dt = (seg.tEnd - seg.tBegin) / steps;
    for (uint32_t i = 0; i < steps; ++i) {
        const glm::dvec3 p = origin + (seg.tBegin + (i + 0.5) * dt) * dir;
        tau += mediumAt(m, altitudeOf(m, p)).extinction * dt;
    }
    return tau;
}

glm::dvec3 transmittanceToEdge(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir,
                               uint32_t steps) {
    return expNeg(opticalDepth(m, origin, dir, steps));
}

glm::dvec3 sunTransmittance(const Model& m, const glm::dvec3& position, const glm::dvec3& toSun,
                            uint32_t steps) {
    if (atmosphereSegment(m, position, toSun).hitsGround) return glm::dvec3(0.0);
    return transmittanceToEdge(m, position, toSun, steps);
}

glm::dvec3 multipleScatteringPsi(const Model& m, double r, double muS, const PsiOptions& o) {
    const glm::dvec3 x(0.0, r, 0.0);
    muS = std::clamp(muS, -1.0, 1.0);
    const glm::dvec3 toSun(std::sqrt(1.0 - muS * muS), muS, 0.0);
    const auto n = uint32_t(std::lround(std::sqrt(double(o.directions))));
    glm::dvec3 l2(0.0), fms(0.0);
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = 0; j < n; ++j) {
            // Stratified uniform directions: azimuth 2π·a, cos(polar) = 1 - 2b (Hillaire's 8×8 pattern).
            const double a = (i + 0.5) / n, b = (j + 0.5) / n;
            const double phi = 2.0 * kPi * a, cosPolar = 1.0 - 2.0 * b;
            const double sinPolar = std::sqrt(std::max(0.0, 1.0 - cosPolar * cosPolar));
            const glm::dvec3 dir(std::cos(phi) * sinPolar, cosPolar, std::sin(phi) * sinPolar);

            const AtmosphereSegment seg = atmosphereSegment(m, x, dir);
            // A ray that starts on the ground ends there at once: its ground bounce still counts.
            if (seg.tEnd <= seg.tBegin && !seg.hitsGround) continue;
            const double dt = std::max(0.0, seg.tEnd - seg.tBegin) / o.steps;
            glm::dvec3 T(1.0), L(0.0), F(0.0);
            for (uint32_t s = 0; s < o.steps; ++s) {
                const glm::dvec3 p = x + (seg.tBegin + (s + 0.5) * dt) * dir;
                const Medium md = mediumAt(m, altitudeOf(m, p));
                const glm::dvec3 w = T * stepIntegral(md.extinction, dt);  // ∫ T dt over the step
                L +=
                    w * md.scattering * sunTransmittance(m, p, toSun, o.transmittanceSteps) * kIsotropicPhase;
                F += w * md.scattering;
                T *= expNeg(md.extinction * dt);
            }
            if (seg.hitsGround) {
                const glm::dvec3 p = x + seg.tEnd * dir;
                const glm::dvec3 normal = glm::normalize(p);
                const double nDotL = std::max(0.0, glm::dot(normal, toSun));
                L += T * sunTransmittance(m, p, toSun, o.transmittanceSteps) * nDotL * m.groundAlbedo / kPi;
            }
            l2 += L;
            fms += F;
        }
    }
    const double count = double(n) * n;
    l2 /= count;
    fms /= count;
    return l2 / (glm::dvec3(1.0) - fms);  // Σ_k f_ms^k = 1/(1 - f_ms), f_ms < 1 (eq. 9)
}

ViewRayResult integrateViewRay(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir,
                               const Sun& sun, const ViewRayOptions& o) {
    ViewRayResult res;
    const AtmosphereSegment seg = atmosphereSegment(m, origin, dir);
    const double tEnd = std::min(seg.tEnd, o.maxDistance);
    if ((tEnd <= seg.tBegin && !seg.hitsGround) || o.steps == 0) return res;
    const double cosViewSun = glm::dot(dir, sun.toSun);
    const double phaseR = rayleighPhase(cosViewSun);
    const double phaseM = cornetteShanksPhase(cosViewSun, m.mieAnisotropy);
    const double dt = std::max(0.0, tEnd - seg.tBegin) / o.steps;
    glm::dvec3 T(1.0), L(0.0);
    for (uint32_t s = 0; s < o.steps; ++s) {
        const glm::dvec3 p = origin + (seg.tBegin + (s + 0.5) * dt) * dir;
        const double r = glm::length(p);
        const Medium md = mediumAt(m, r - m.groundRadius);
        const glm::dvec3 tSun = sunTransmittance(m, p, sun.toSun, o.transmittanceSteps);
        // In-scattered radiance per unit length at p, per unit illuminance.
        glm::dvec3 S = tSun * (md.rayleighScattering * phaseR + md.mieScattering * phaseM);
        if (o.multipleScattering)
            S += md.scattering * multipleScatteringPsi(m, r, glm::dot(p / r, sun.toSun), o.psi);
        L += T * S * stepIntegral(md.extinction, dt);
        T *= expNeg(md.extinction * dt);
    }
    if (o.ground && seg.hitsGround && seg.tEnd <= o.maxDistance) {
        const glm::dvec3 p = origin + seg.tEnd * dir;
        const double nDotL = std::max(0.0, glm::dot(glm::normalize(p), sun.toSun));
        L += T * sunTransmittance(m, p, sun.toSun, o.transmittanceSteps) * nDotL * m.groundAlbedo / kPi;
    }
    res.luminance = L * sun.illuminance;
    res.transmittance = T;
    return res;
}

}  // namespace postfx::atmosphere
