// The atmosphere's public CPU evaluations (postfx/atmosphere.h): the sun's transmittance at a point and the
// sky's irradiance on a surface facing the zenith, from the double-precision model and reference
// (atmosphere_model.h, atmosphere_reference.h) without the GPU's LUTs. docs/effects/atmosphere.md, "CPU
// evaluations", states their quadratures and measured cost.
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_reference.h"
#include "core/world_frame.h"

#include <postfx/atmosphere.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace postfx {
namespace {

using atmosphere::Model;
using glm::dvec3;

constexpr double kPi = std::numbers::pi;

// atmosphereSunTransmittance's midpoint steps to the top boundary: (Δ/H)²/24 of τ, Δ ≤ 400 m over Earth's
// 100 km shell and its 8 km Rayleigh height: ≈ 1e-4 of τ.
constexpr uint32_t kSunTransmittanceSteps = 256;

// atmosphereSkyIrradiance's quadrature: kRings × kAzimuths directions over the upper hemisphere (weighted
// by their cosine), each marched with kViewSteps midpoint steps to the atmosphere's edge or the ground, each
// step's sun transmittance with kSampleSunSteps steps.
constexpr uint32_t kRings = 16, kAzimuths = 32;
constexpr uint32_t kViewSteps = 24;
constexpr uint32_t kSampleSunSteps = 24;

// Ψ (multipleScatteringPsi) on a kPsiMuS × kPsiR table over the sun's cosine μs in [-1, 1] (uniform) and
// the radius in [ground, top] (nodes at √((r - ground)/(top - ground)) uniform: crowded near the ground,
// where the air is), nodes at both ends, read bilinearly: integrateViewRay's Ψ at every sample (64
// directions × 20 steps each) would cost ~10⁴ times this function's budget. Coarser than the GPU's
// 32×32 LUT of 64 directions: Ψ is smooth in both and a small part of the sky at day.
constexpr uint32_t kPsiMuS = 32, kPsiR = 12;
constexpr atmosphere::PsiOptions kPsiOptions{16, 12, 16};

struct PsiTable {
    Model model;  // what it was built for
    double groundRadius = 0.0, topRadius = 0.0;
    std::vector<dvec3> values;  // [iR · kPsiMuS + iMuS]

    dvec3 at(double r, double muS) const {
        const double x = std::clamp((muS + 1.0) * 0.5, 0.0, 1.0) * (kPsiMuS - 1);
        const double y = std::clamp((r - groundRadius) / (topRadius - groundRadius), 0.0, 1.0) * (kPsiR - 1);
        const auto x0 = std::min(uint32_t(x), kPsiMuS - 2), y0 = std::min(uint32_t(y), kPsiR - 2);
        const double fx = x - x0, fy = y - y0;
        const auto v = [&](uint32_t i, uint32_t j) { return values[j * kPsiMuS + i]; };
        return glm::mix(glm::mix(v(x0, y0), v(x0 + 1, y0), fx),
                        glm::mix(v(x0, y0 + 1), v(x0 + 1, y0 + 1), fx), fy);
    }
};

PsiTable buildPsiTable(const Model& m) {
    PsiTable t;
    t.model = m;
    t.groundRadius = m.groundRadius;
    t.topRadius = m.topRadius;
    t.values.resize(std::size_t(kPsiMuS) * kPsiR);
    for (uint32_t j = 0; j < kPsiR; ++j) {
        const double y = double(j) / (kPsiR - 1);
        const double r = m.groundRadius + (m.topRadius - m.groundRadius) * y * y;
        for (uint32_t i = 0; i < kPsiMuS; ++i) {
            const double muS = -1.0 + 2.0 * i / (kPsiMuS - 1);
            t.values[j * kPsiMuS + i] = atmosphere::multipleScatteringPsi(m, r, muS, kPsiOptions);
        }
    }
    return t;
}

// The table for `m`, built on its first use and kept while the model stays the same (a few recent models;
// thread-safe): a host that moves the sun every frame pays only the quadrature below
// (docs/effects/atmosphere.md, "CPU evaluations").
std::shared_ptr<const PsiTable> psiTable(const Model& m) {
    static atmosphere::TableCache<PsiTable> cache;
    return cache.get([&](const PsiTable& t) { return t.model == m; },
                     [&] { return std::make_shared<const PsiTable>(buildPsiTable(m)); });
}

// Luminance per unit sun illuminance reaching `origin` along `dir` (integrateViewRay's march with the orders
// from `orders` or Ψ from `psi`, or neither when both are null), the lit ground included where the ray ends
// on it.
dvec3 viewRayLuminance(const Model& m, const PsiTable* psi, const atmosphere::OrdersTable* orders,
                       const dvec3& origin, const dvec3& dir, const dvec3& toSun) {
    const atmosphere::AtmosphereSegment seg = atmosphere::atmosphereSegment(m, origin, dir);
    if (seg.tEnd <= seg.tBegin && !seg.hitsGround) return dvec3(0.0);
    const double cosViewSun = glm::dot(dir, toSun);
    const double phaseR = atmosphere::rayleighPhase(cosViewSun);
    const double phaseM = atmosphere::cornetteShanksPhase(cosViewSun, m.mieAnisotropy);
    // Steps growing quadratically from the segment's start, t_k = tBegin + length·(k/N)²: an upward ray from
    // the ground crosses the dense bottom (Mie's 1.2 km scale height) in small steps and the thin top in
    // long ones. Uniform steps of 100 km / 24 lose 3 % of Mie's in-scattering to the midpoint rule.
    const double length = std::max(0.0, seg.tEnd - seg.tBegin);
    dvec3 T(1.0), L(0.0);
    for (uint32_t s = 0; s < kViewSteps; ++s) {
        const double a = double(s) / kViewSteps, b = double(s + 1) / kViewSteps;
        const double t0 = seg.tBegin + length * a * a, t1 = seg.tBegin + length * b * b;
        const double dt = t1 - t0;
        const dvec3 p = origin + (0.5 * (t0 + t1)) * dir;
        const double r = glm::length(p);
        const atmosphere::Medium md = atmosphere::mediumAt(m, r - m.groundRadius);
        const dvec3 tSun = atmosphere::sunTransmittance(m, p, toSun, kSampleSunSteps);
        dvec3 S = tSun * (md.rayleighScattering * phaseR + md.mieScattering * phaseM);
        if (orders) S += orders->source(p, dir, toSun);
        if (psi) S += md.scattering * psi->at(r, glm::dot(p / r, toSun));
        L += T * S * atmosphere::stepIntegral(md.extinction, dt);
        const dvec3 tau = md.extinction * dt;
        T *= dvec3(std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z));
    }
    if (seg.hitsGround) {
        const dvec3 p = origin + seg.tEnd * dir;
        const double muG = glm::dot(glm::normalize(p), toSun);
        dvec3 E = orders ? orders->groundIrradiance(muG) : dvec3(0.0);
        if (muG > 0.0) E += atmosphere::sunTransmittance(m, p, toSun, kSampleSunSteps) * muG;
        L += T * E * m.groundAlbedo / kPi;
    }
    return L;
}

// toSun normalised in double; false for a zero or non-finite vector.
bool unitDirection(const Vec3& v, dvec3& out) {
    const dvec3 d(v.x, v.y, v.z);
    const double len = glm::length(d);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    out = d / len;
    return true;
}

Vec3 toFloat(const dvec3& v) {
    return Vec3(float(v.x), float(v.y), float(v.z));
}

}  // namespace

Vec3 atmosphereSunTransmittance(const AtmosphereSettings& settings, const DVec3& worldPosition,
                                const Vec3& toSun, const WorldFrame& world) {
    const core::WorldTransform frame(world);
    dvec3 s;
    if (!unitDirection(frame.direction(glm::vec3(toSun)), s)) return Vec3(0.0f);
    const Model m = atmosphere::modelFrom(settings);
    const dvec3 x =
        atmosphere::clampAboveGround(m, atmosphere::planetCentred(m, frame.position(dvec3(worldPosition))));
    return toFloat(atmosphere::sunTransmittance(m, x, s, kSunTransmittanceSteps));
}

Vec3 atmosphereSkyIrradiance(const AtmosphereSettings& settings, const DVec3& worldPosition,
                             const Vec3& toSun, const Vec3& sunIlluminance, const WorldFrame& world) {
    const core::WorldTransform frame(world);
    dvec3 s;
    if (!unitDirection(frame.direction(glm::vec3(toSun)), s)) return Vec3(0.0f);
    const Model m = atmosphere::modelFrom(settings);
    const dvec3 x =
        atmosphere::clampAboveGround(m, atmosphere::planetCentred(m, frame.position(dvec3(worldPosition))));
    const std::shared_ptr<const PsiTable> psi =
        settings.multipleScattering == AtmosphereMultipleScattering::Hillaire ? psiTable(m) : nullptr;
    const std::shared_ptr<const atmosphere::OrdersTable> orders =
        settings.multipleScattering == AtmosphereMultipleScattering::Orders
            ? atmosphere::sharedOrdersTable(m, atmosphere::coarseOrdersOptions())
            : nullptr;

    // The local frame: n the zenith at x, (t, b) across it.
    const dvec3 n = glm::normalize(x);
    const dvec3 t = glm::normalize(std::abs(n.y) < 0.9 ? glm::cross(n, dvec3(0.0, 1.0, 0.0))
                                                       : glm::cross(n, dvec3(1.0, 0.0, 0.0)));
    const dvec3 b = glm::cross(n, t);
    // Rings uniform in cos θ (equal solid angle), each direction weighted by its cos θ: E = ∫ L cos θ dω ≈
    // Σ L·cos θ·ΔΩ with ΔΩ = 2π / (rings · azimuths). L·cos θ stays bounded toward the horizon, where L
    // grows as 1/cos θ in a thin medium (sampling sin²θ uniformly instead leaves that peak to a midpoint rule
    // and loses 7 % of a thin sky's irradiance).
    dvec3 sum(0.0);
    for (uint32_t i = 0; i < kRings; ++i) {
        const double cosTheta = (i + 0.5) / kRings;
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        for (uint32_t j = 0; j < kAzimuths; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / kAzimuths;
            const dvec3 dir = cosTheta * n + sinTheta * (std::cos(phi) * t + std::sin(phi) * b);
            sum += cosTheta * viewRayLuminance(m, psi.get(), orders.get(), x, dir, s);
        }
    }
    const dvec3 irradiance = sum * (2.0 * kPi / (double(kRings) * kAzimuths));
    return toFloat(irradiance * dvec3(sunIlluminance.x, sunIlluminance.y, sunIlluminance.z));
}

}  // namespace postfx
