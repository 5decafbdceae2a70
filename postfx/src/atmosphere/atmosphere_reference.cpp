// The atmosphere's reference integrals (atmosphere_reference.h; docs/effects/atmosphere.md, "Reference").
#include "atmosphere/atmosphere_reference.h"

#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_shared.h"
#include "common/parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <span>
#include <thread>
#include <vector>

namespace postfx::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;
static_assert(float(kMaxPsi) == gpu::kAtmosphereMaxPsi, "the reference's bound is the GPU's");

double altitudeOf(const Model& m, const glm::dvec3& p) {
    return glm::length(p) - m.groundRadius;
}

}  // namespace

glm::dvec3 stepIntegral(const glm::dvec3& extinction, double delta) {
    glm::dvec3 r;
    for (int c = 0; c < 3; ++c)
        r[c] = extinction[c] > 0.0 ? -std::expm1(-extinction[c] * delta) / extinction[c] : delta;
    return r;
}

glm::dvec3 expNeg(const glm::dvec3& tau) {
    return {std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z)};
}

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

namespace {

// Ψ at radius r for each sun cosine of `muS` into `out` (multipleScatteringPsi's integral), every sample's
// sun transmittance from `sunT(position, toSun)`. Each direction is marched once; its samples serve every
// sun. The stratified pattern is symmetric about the sun's vertical plane (azimuth φ_i and φ_{n-1-i} =
// 2π - φ_i give the same terms): half of it is marched, each column counted twice.
// Ψ = L2 / (1 - f_ms) (eq. 9, Σ_k f_ms^k), per channel, from `leaves` = 1 - f_ms computed as what does not
// scatter again: the mean over directions of T at the ray's end plus ∫ T·σa dt (a march telescopes: Σ T·(1 -
// e^{-σtΔ}) = 1 - T_end, so this is exactly 1 minus the marched f_ms, without its cancellation as f_ms -> 1
// in thick media that barely absorb). Bounded by kMaxPsi (atmosphere_reference.h): where the series diverges
// (nothing leaves within double's range) or exceeds what energy conservation allows. 0 where no light
// arrives (L2 = 0).
glm::dvec3 seriesPsi(const glm::dvec3& l2, const glm::dvec3& leaves) {
    glm::dvec3 psi;
    for (int c = 0; c < 3; ++c)
        psi[c] = l2[c] <= 0.0 ? 0.0 : l2[c] >= kMaxPsi * leaves[c] ? kMaxPsi : l2[c] / leaves[c];
    return psi;
}

template <class SunT>
void psiForSuns(const Model& m, double r, std::span<const double> muS, const PsiOptions& o, const SunT& sunT,
                std::span<glm::dvec3> out) {
    const glm::dvec3 x(0.0, r, 0.0);
    const size_t suns = muS.size();
    std::vector<glm::dvec3> toSun(suns), l2(suns, glm::dvec3(0.0));
    for (size_t k = 0; k < suns; ++k) {
        const double c = std::clamp(muS[k], -1.0, 1.0);
        toSun[k] = glm::dvec3(std::sqrt(1.0 - c * c), c, 0.0);
    }
    const auto n = uint32_t(std::lround(std::sqrt(double(o.directions))));
    std::vector<glm::dvec3> points(o.steps), weights(o.steps);
    glm::dvec3 leaves(0.0);  // Σ (1 - the direction's f_ms term): see seriesPsi
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t mirror = n - 1 - i;
        if (mirror < i) break;
        const double columnWeight = mirror == i ? 1.0 : 2.0;
        for (uint32_t j = 0; j < n; ++j) {
            // Stratified uniform directions: azimuth 2π·a, cos(polar) = 1 - 2b (Hillaire's 8×8 pattern).
            const double a = (i + 0.5) / n, b = (j + 0.5) / n;
            const double phi = 2.0 * kPi * a, cosPolar = 1.0 - 2.0 * b;
            const double sinPolar = std::sqrt(std::max(0.0, 1.0 - cosPolar * cosPolar));
            const glm::dvec3 dir(std::cos(phi) * sinPolar, cosPolar, std::sin(phi) * sinPolar);

            const AtmosphereSegment seg = atmosphereSegment(m, x, dir);
            // A ray that misses the atmosphere leaves at once; one that starts on the ground ends there at
            // once: its ground bounce still counts.
            if (seg.tEnd <= seg.tBegin && !seg.hitsGround) {
                leaves += columnWeight;
                continue;
            }
            const double dt = std::max(0.0, seg.tEnd - seg.tBegin) / o.steps;
            glm::dvec3 T(1.0), absorbed(0.0);
            for (uint32_t s = 0; s < o.steps; ++s) {
                const glm::dvec3 p = x + (seg.tBegin + (s + 0.5) * dt) * dir;
                const Medium md = mediumAt(m, altitudeOf(m, p));
                const glm::dvec3 w = T * stepIntegral(md.extinction, dt);  // ∫ T dt over the step
                points[s] = p;
                weights[s] = w * md.scattering * columnWeight;
                absorbed += w * (md.extinction - md.scattering);
                T *= expNeg(md.extinction * dt);
            }
            leaves += (T + absorbed) * columnWeight;
            const glm::dvec3 ground = seg.hitsGround ? x + seg.tEnd * dir : glm::dvec3(0.0);
            const glm::dvec3 normal = seg.hitsGround ? glm::normalize(ground) : glm::dvec3(0.0);
            for (size_t k = 0; k < suns; ++k) {
                glm::dvec3 L(0.0);
                for (uint32_t s = 0; s < o.steps; ++s)
                    if (weights[s] != glm::dvec3(0.0)) L += weights[s] * sunT(points[s], toSun[k]);
                L *= kIsotropicPhase;
                if (seg.hitsGround) {
                    const double nDotL = std::max(0.0, glm::dot(normal, toSun[k]));
                    if (nDotL > 0.0)
                        L += columnWeight * T * sunT(ground, toSun[k]) * nDotL * m.groundAlbedo / kPi;
                }
                l2[k] += L;
            }
        }
    }
    const double count = double(n) * n;
    for (size_t k = 0; k < suns; ++k)
        out[k] = seriesPsi(l2[k] / count, leaves / count);
}

double clamp01(double x) {
    return std::clamp(x, 0.0, 1.0);
}

// Bilinear lookup of a w×h grid of nodes at unit coordinates (x, y) in [0, 1].
glm::dvec3 bilinear(const std::vector<glm::dvec3>& v, uint32_t w, uint32_t h, double x, double y) {
    const double fx = clamp01(x) * (w - 1), fy = clamp01(y) * (h - 1);
    const uint32_t x0 = std::min(uint32_t(fx), w - 2), y0 = std::min(uint32_t(fy), h - 2);
    const double ax = fx - x0, ay = fy - y0;
    const glm::dvec3* row0 = &v[size_t(y0) * w + x0];
    const glm::dvec3* row1 = row0 + w;
    return (1.0 - ay) * ((1.0 - ax) * row0[0] + ax * row0[1]) + ay * ((1.0 - ax) * row1[0] + ax * row1[1]);
}

}  // namespace

glm::dvec3 multipleScatteringPsi(const Model& m, double r, double muS, const PsiOptions& o) {
    glm::dvec3 out(0.0);
    psiForSuns(
        m, r, std::span<const double>(&muS, 1), o,
        [&](const glm::dvec3& p, const glm::dvec3& s) {
            return sunTransmittance(m, p, s, o.transmittanceSteps);
        },
        std::span<glm::dvec3>(&out, 1));
    return out;
}

TransmittanceTable::TransmittanceTable(const Model& m, const TransmittanceTableOptions& o)
    : model_(m), size_(glm::max(o.size, glm::uvec2(2))) {
    tau_.resize(size_t(size_.x) * size_.y);
    const uint32_t steps = std::max(1u, o.steps);
    common::parallelFor(size_.y, o.threads, [&](uint32_t j) {
        for (uint32_t i = 0; i < size_.x; ++i) {
            const RadiusCosine rc =
                transmittanceParamsFromUnit(m, {double(i) / (size_.x - 1), double(j) / (size_.y - 1)});
            // Along the ray to the top, the ground ignored (the horizon's node is tangent to it).
            const double d = distanceToTop(m, rc.r, rc.mu), dt = d / steps;
            glm::dvec3 tau(0.0);
            for (uint32_t s = 0; s < steps; ++s) {
                const double t = (s + 0.5) * dt;
                const double rt = std::sqrt(std::max(0.0, rc.r * rc.r + t * t + 2.0 * rc.r * rc.mu * t));
                tau += mediumAt(m, rt - m.groundRadius).extinction * dt;
            }
            tau_[size_t(j) * size_.x + i] = tau;
        }
    });
}

glm::dvec3 TransmittanceTable::toTop(double r, double mu) const {
    const glm::dvec2 unit = transmittanceUnitFromParams(model_, r, mu);
    return expNeg(bilinear(tau_, size_.x, size_.y, unit.x, unit.y));
}

glm::dvec3 TransmittanceTable::sun(const glm::dvec3& position, const glm::dvec3& toSun) const {
    glm::dvec3 p = position;
    double r = glm::length(p);
    if (r > model_.topRadius) {
        const SphereHit top = raySphere(p, toSun, model_.topRadius);
        if (!top.hit || top.tFar <= 0.0) return glm::dvec3(1.0);
        p += std::max(0.0, top.tNear) * toSun;
        r = model_.topRadius;
    }
    r = std::max(r, model_.groundRadius);
    const double len = glm::length(p);
    const double mu = len > 0.0 ? std::clamp(glm::dot(p, toSun) / len, -1.0, 1.0) : toSun.y;
    if (rayIntersectsGround(model_, r, mu)) return glm::dvec3(0.0);
    return toTop(r, mu);
}

PsiTable::PsiTable(const Model& m, const TransmittanceTable& transmittance, const PsiTableOptions& o)
    : model_(m), options_(o), muSSize_(std::max(2u, o.muSSize)), heightSize_(std::max(2u, o.heightSize)) {
    psi_.resize(size_t(muSSize_) * heightSize_);
    std::vector<double> muS(muSSize_);
    for (uint32_t i = 0; i < muSSize_; ++i) {
        const double u = 2.0 * double(i) / (muSSize_ - 1) - 1.0;
        muS[i] = u * std::abs(u);
    }
    PsiOptions psi = o.psi;
    psi.steps = std::max(1u, psi.steps);
    psi.directions = std::max(1u, psi.directions);
    const auto sunT = [&](const glm::dvec3& p, const glm::dvec3& s) { return transmittance.sun(p, s); };
    common::parallelFor(heightSize_, o.threads, [&](uint32_t j) {
        const double y = double(j) / (heightSize_ - 1);
        const double r = m.groundRadius + y * y * (m.topRadius - m.groundRadius);
        psiForSuns(m, r, muS, psi, sunT, std::span<glm::dvec3>(&psi_[size_t(j) * muSSize_], muSSize_));
    });
}

glm::dvec3 PsiTable::at(double r, double muS) const {
    const double x = 0.5 + 0.5 * std::copysign(std::sqrt(std::min(1.0, std::abs(muS))), muS);
    const double y = std::sqrt(clamp01((r - model_.groundRadius) / (model_.topRadius - model_.groundRadius)));
    return bilinear(psi_, muSSize_, heightSize_, x, y);
}

bool PsiTable::builtWith(const PsiTableOptions& o) const {
    return o.muSSize == options_.muSSize && o.heightSize == options_.heightSize &&
           o.psi.directions == options_.psi.directions && o.psi.steps == options_.psi.steps;
}

std::shared_ptr<const TransmittanceTable> sharedTransmittanceTable(const Model& m) {
    static TableCache<TransmittanceTable> cache;
    return cache.get([&](const TransmittanceTable& t) { return t.model() == m; },
                     [&] { return std::make_shared<const TransmittanceTable>(m); });
}

std::shared_ptr<const PsiTable> sharedPsiTable(const Model& m, const PsiTableOptions& options) {
    static TableCache<PsiTable> cache;
    return cache.get([&](const PsiTable& t) { return t.model() == m && t.builtWith(options); },
                     [&] {
                         const std::shared_ptr<const TransmittanceTable> t = sharedTransmittanceTable(m);
                         return std::make_shared<const PsiTable>(m, *t, options);
                     });
}

ViewRayResult integrateViewRay(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir,
                               const Sun& sun, const ViewRayOptions& o) {
    ViewRayResult res;
    AtmosphereSegment seg = atmosphereSegment(m, origin, dir);
    if (o.throughGround && seg.hitsGround) {
        seg.tEnd = raySphere(origin, dir, m.topRadius).tFar;
        seg.hitsGround = false;
    }
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
        const glm::dvec3 tSun = o.transmittanceTable
                                    ? o.transmittanceTable->sun(p, sun.toSun)
                                    : sunTransmittance(m, p, sun.toSun, o.transmittanceSteps);
        // In-scattered radiance per unit length at p, per unit illuminance.
        glm::dvec3 S = tSun * (md.rayleighScattering * phaseR + md.mieScattering * phaseM);
        if (o.multipleScattering && o.ordersTable) {
            S += o.ordersTable->source(p, dir, sun.toSun);
        } else if (o.multipleScattering) {
            const double muS = glm::dot(p / r, sun.toSun);
            S += md.scattering *
                 (o.psiTable ? o.psiTable->at(r, muS) : multipleScatteringPsi(m, r, muS, o.psi));
        }
        L += T * S * stepIntegral(md.extinction, dt);
        T *= expNeg(md.extinction * dt);
    }
    if (o.ground && seg.hitsGround && seg.tEnd <= o.maxDistance) {
        const glm::dvec3 p = origin + seg.tEnd * dir;
        const double nDotL = std::max(0.0, glm::dot(glm::normalize(p), sun.toSun));
        const glm::dvec3 tSun = o.transmittanceTable
                                    ? o.transmittanceTable->sun(p, sun.toSun)
                                    : sunTransmittance(m, p, sun.toSun, o.transmittanceSteps);
        glm::dvec3 E = tSun * nDotL;
        if (o.multipleScattering && o.ordersTable)
            E += o.ordersTable->groundIrradiance(glm::dot(glm::normalize(p), sun.toSun));
        L += T * E * m.groundAlbedo / kPi;
    }
    res.luminance = L * sun.illuminance;
    res.transmittance = T;
    return res;
}

}  // namespace postfx::atmosphere
