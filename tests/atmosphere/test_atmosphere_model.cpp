// The atmosphere model's pieces (atmosphere_model.h): ray–sphere intersections for a camera inside, outside,
// tangent and far in space; the phase functions' normalisation and direction; the LUT parameterisations'
// round trips (uv → parameters → uv) over grids that include the edges and the horizon.
#include "atmosphere/atmosphere_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

using namespace postfx::atmosphere;

constexpr double kPi = std::numbers::pi;
constexpr double kR = 6360e3;

// ---- ray–sphere -------------------------------------------------------------------------------------

TEST(AtmosphereModel, RaySphereFromInside) {
    const SphereHit h = raySphere({0.0, 100.0, 0.0}, {1.0, 0.0, 0.0}, kR);
    ASSERT_TRUE(h.hit);
    const double half = std::sqrt(kR * kR - 100.0 * 100.0);
    EXPECT_NEAR(h.tNear, -half, 1e-6);
    EXPECT_NEAR(h.tFar, half, 1e-6);
}

TEST(AtmosphereModel, RaySphereFromOutsideLookingAtThePlanet) {
    const SphereHit h = raySphere({0.0, 2.0 * kR, 0.0}, {0.0, -1.0, 0.0}, kR);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.tNear, kR, 1e-6);
    EXPECT_NEAR(h.tFar, 3.0 * kR, 1e-6);
    // From far in space (1e9 m): still exact to a micrometre relative to the distance.
    const SphereHit far = raySphere({0.0, 1e9, 0.0}, {0.0, -1.0, 0.0}, kR);
    ASSERT_TRUE(far.hit);
    EXPECT_NEAR(far.tNear, 1e9 - kR, 1e-6);
    EXPECT_NEAR(far.tFar, 1e9 + kR, 1e-6);
}

TEST(AtmosphereModel, RaySphereFromOutsideLookingAwayHasNoHitAhead) {
    const Model m;
    // Up, away from the planet: the line meets the spheres behind the origin only.
    const glm::dvec3 o(0.0, 2.0 * kR, 0.0), up(0.0, 1.0, 0.0);
    const SphereHit h = raySphere(o, up, kR);
    ASSERT_TRUE(h.hit);
    EXPECT_LT(h.tFar, 0.0);
    const AtmosphereSegment seg = atmosphereSegment(m, o, up);
    EXPECT_LE(seg.tEnd, seg.tBegin);
    // Sideways from 2R: the line passes at 2R from the centre.
    EXPECT_FALSE(raySphere(o, {1.0, 0.0, 0.0}, kR).hit);
    EXPECT_FALSE(raySphere(o, {1.0, 0.0, 0.0}, m.topRadius).hit);
}

TEST(AtmosphereModel, RaySphereTangentAndNearTangent) {
    const glm::dvec3 dir(1.0, 0.0, 0.0);
    const SphereHit t = raySphere({-1e7, kR, 0.0}, dir, kR);
    ASSERT_TRUE(t.hit);
    EXPECT_DOUBLE_EQ(t.tNear, 1e7);
    EXPECT_DOUBLE_EQ(t.tFar, 1e7);
    // 1 mm above the tangent: miss; 1 mm below: a chord of 2·√(2R·1mm - 1mm²).
    EXPECT_FALSE(raySphere({-1e7, kR + 1e-3, 0.0}, dir, kR).hit);
    const double y = kR - 1e-3, depth = kR - y;  // the offset double can hold at 6.36e6 m
    const SphereHit in = raySphere({-1e7, y, 0.0}, dir, kR);
    ASSERT_TRUE(in.hit);
    const double chord = 2.0 * std::sqrt(2.0 * kR * depth - depth * depth);
    EXPECT_NEAR(in.tFar - in.tNear, chord, 1e-9 * chord);
    std::printf("[ measured ] near-tangent chord %.9f m, closed form %.9f m\n", in.tFar - in.tNear, chord);
    // Tangent from a point on the sphere itself.
    const SphereHit on = raySphere({0.0, kR, 0.0}, dir, kR);
    ASSERT_TRUE(on.hit);
    EXPECT_EQ(on.tNear, 0.0);
    EXPECT_EQ(on.tFar, 0.0);
}

TEST(AtmosphereModel, AtmosphereSegmentEndsOnTheGround) {
    const Model m;
    // 1 km up, looking down: 1 km to the ground.
    const AtmosphereSegment down = atmosphereSegment(m, {0.0, kR + 1000.0, 0.0}, {0.0, -1.0, 0.0});
    EXPECT_TRUE(down.hitsGround);
    EXPECT_NEAR(down.tEnd - down.tBegin, 1000.0, 1e-6);
    // From space (1e7 m above), looking down: enters at the top, ends at the ground.
    const AtmosphereSegment space = atmosphereSegment(m, {0.0, kR + 1e7, 0.0}, {0.0, -1.0, 0.0});
    EXPECT_TRUE(space.hitsGround);
    EXPECT_NEAR(space.tBegin, kR + 1e7 - m.topRadius, 1e-6);
    EXPECT_NEAR(space.tEnd, 1e7, 1e-6);
    // Horizontal from the ground: grazes the ground (not blocked), leaves at the top.
    const AtmosphereSegment flat = atmosphereSegment(m, {0.0, kR, 0.0}, {1.0, 0.0, 0.0});
    EXPECT_FALSE(flat.hitsGround);
    EXPECT_NEAR(flat.tEnd, std::sqrt(m.topRadius * m.topRadius - kR * kR), 1e-6);
    // A camera below the ground is clamped onto it.
    EXPECT_NEAR(glm::length(clampAboveGround(m, {0.0, kR - 50.0, 0.0})), kR, 1e-9);
    EXPECT_TRUE(rayIntersectsGround(m, kR + 1000.0, -0.1));
    EXPECT_FALSE(rayIntersectsGround(m, kR + 1000.0, -0.01));  // horizon at μ = -0.0177
}

// ---- phase functions ------------------------------------------------------------------------------------

// ∫ p dω over the sphere = 2π ∫_{-1}^{1} p(μ) dμ, Simpson with many intervals (the peaked g = 0.95 needs
// them).
double phaseIntegral(double (*phase)(double, double), double g) {
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double mu = -1.0 + 2.0 * i / n;
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * phase(mu, g);
    }
    return 2.0 * kPi * sum * (2.0 / n) / 3.0;
}

TEST(AtmosphereModel, PhaseFunctionsIntegrateToOne) {
    EXPECT_NEAR(phaseIntegral([](double mu, double) { return rayleighPhase(mu); }, 0.0), 1.0, 1e-9);
    for (double g : {-0.5, 0.0, 0.5, 0.8, 0.95}) {
        const double integral = phaseIntegral(cornetteShanksPhase, g);
        std::printf("[ measured ] Cornette-Shanks g=%.2f: integral %.12f\n", g, integral);
        EXPECT_NEAR(integral, 1.0, 1e-6) << "g = " << g;
    }
}

TEST(AtmosphereModel, CornetteShanksIsRayleighAtZeroAndForwardForPositiveG) {
    for (double mu : {-1.0, -0.3, 0.0, 0.7, 1.0})
        EXPECT_NEAR(cornetteShanksPhase(mu, 0.0), rayleighPhase(mu), 1e-15);
    // g > 0: brightest looking at the sun (cosViewSun = 1).
    EXPECT_GT(cornetteShanksPhase(1.0, 0.8), cornetteShanksPhase(0.0, 0.8));
    EXPECT_GT(cornetteShanksPhase(0.0, 0.8), cornetteShanksPhase(-1.0, 0.8));
    EXPECT_NEAR(rayleighPhase(1.0), 3.0 / (8.0 * kPi), 1e-15);
}

// ---- LUT parameterisations --------------------------------------------------------------------------

std::vector<double> unitGrid() {
    std::vector<double> g = {0.0, 1e-6, 1e-3, 0.5 - 1e-6, 0.5, 0.5 + 1e-6, 1.0 - 1e-3, 1.0 - 1e-6, 1.0};
    for (int i = 1; i < 16; ++i)
        g.push_back(i / 16.0 + 0.013);
    return g;
}

TEST(AtmosphereModel, TransmittanceUvRoundTrip) {
    const Model m;
    const glm::uvec2 size(256, 64);
    double worst = 0.0;
    for (double xm : unitGrid())
        for (double xr : unitGrid()) {
            const glm::dvec2 uv(postfx::atmosphere::unitToTexelUv(xm, size.x), unitToTexelUv(xr, size.y));
            const RadiusCosine p = transmittanceParamsFromUv(m, uv, size);
            ASSERT_GE(p.r, m.groundRadius - 1e-6);
            ASSERT_LE(p.r, m.topRadius + 1e-6);
            const glm::dvec2 back = transmittanceUvFromParams(m, p.r, p.mu, size);
            worst = std::max({worst, std::abs(back.x - uv.x), std::abs(back.y - uv.y)});
        }
    std::printf("[ measured ] transmittance uv round trip: worst |Δuv| %.3g\n", worst);
    EXPECT_LT(worst, 1e-9);
    // x_μ = 0 is the zenith, 1 the horizon (μ = -ρ/r); x_r = 0 the ground, 1 the top; the edges are texel
    // centres.
    const RadiusCosine zenithTop = transmittanceParamsFromUnit(m, {0.0, 1.0});
    EXPECT_NEAR(zenithTop.r, m.topRadius, 1e-6);
    EXPECT_EQ(zenithTop.mu, 1.0);
    const double r = kR + 5000.0;
    const double horizonMu = -std::sqrt(r * r - kR * kR) / r;
    EXPECT_NEAR(transmittanceUnitFromParams(m, r, horizonMu).x, 1.0, 1e-9);
    EXPECT_NEAR(transmittanceUnitFromParams(m, r, 1.0).x, 0.0, 1e-12);
    EXPECT_NEAR(transmittanceUvFromParams(m, kR, 1.0, size).x, 0.5 / 256.0, 1e-15);
    EXPECT_NEAR(transmittanceUvFromParams(m, m.topRadius, 1.0, size).y, 1.0 - 0.5 / 64.0, 1e-12);
}

TEST(AtmosphereModel, TransmittanceParamsRoundTrip) {
    const Model m;
    const glm::uvec2 size(256, 64);
    double worstMu = 0.0, worstR = 0.0;
    for (double h : {0.0, 1.0, 1000.0, 25e3, 99999.0, 100e3})
        for (double t : {0.0, 0.01, 0.3, 0.5, 0.9, 0.999, 1.0}) {
            const double r = kR + h;
            const double horizonMu = -std::sqrt(std::max(0.0, r * r - kR * kR)) / r;
            // From the horizon to the zenith; at the top boundary below the horizontal only: every ray with
            // μ >= 0 there leaves at once (d = 0, x_μ = 0: one texel column for all of them, T = 1).
            const double highest = h == 100e3 ? -1e-3 : 1.0;
            const double mu = horizonMu + t * (highest - horizonMu);
            const RadiusCosine p =
                transmittanceParamsFromUv(m, transmittanceUvFromParams(m, r, mu, size), size);
            worstMu = std::max(worstMu, std::abs(p.mu - mu));
            worstR = std::max(worstR, std::abs(p.r - r));
        }
    std::printf("[ measured ] transmittance (r, mu) round trip: worst |Δmu| %.3g, |Δr| %.3g m\n", worstMu,
                worstR);
    EXPECT_LT(worstMu, 1e-7);
    EXPECT_LT(worstR, 1e-4);
    for (double mu : {0.0, 0.1, 0.5, 1.0})
        EXPECT_EQ(transmittanceUnitFromParams(m, m.topRadius, mu).x, 0.0);
}

TEST(AtmosphereModel, MultipleScatteringUvRoundTrip) {
    const Model m;
    const glm::uvec2 size(32, 32);
    double worst = 0.0;
    for (double x : unitGrid())
        for (double y : unitGrid()) {
            const glm::dvec2 uv(unitToTexelUv(x, size.x), unitToTexelUv(y, size.y));
            const SunCosineRadius p = multipleScatteringParamsFromUv(m, uv, size);
            const glm::dvec2 back = multipleScatteringUvFromParams(m, p.muS, p.r, size);
            worst = std::max({worst, std::abs(back.x - uv.x), std::abs(back.y - uv.y)});
        }
    std::printf("[ measured ] multiple-scattering uv round trip: worst |Δuv| %.3g\n", worst);
    EXPECT_LT(worst, 1e-12);
    const SunCosineRadius first = multipleScatteringParamsFromUv(m, {0.5 / 32, 0.5 / 32}, size);
    EXPECT_NEAR(first.muS, -1.0, 1e-15);
    EXPECT_NEAR(first.r, m.groundRadius, 1e-6);
}

TEST(AtmosphereModel, SkyViewUvRoundTrip) {
    const Model m;
    const glm::uvec2 size(192, 108);
    double worst = 0.0;
    for (double h : {0.0, 1.0, 1000.0, 50e3, 100e3, 1e7})
        for (double x : unitGrid())
            for (double y : unitGrid()) {
                const double r = kR + h;
                const glm::dvec2 uv(unitToTexelUv(x, size.x), unitToTexelUv(y, size.y));
                const SkyViewParams p = skyViewParamsFromUv(m, r, uv, size);
                const glm::dvec2 back = skyViewUvFromParams(m, r, p, size);
                worst = std::max({worst, std::abs(back.x - uv.x), std::abs(back.y - uv.y)});
            }
    std::printf("[ measured ] sky-view uv round trip: worst |Δuv| %.3g\n", worst);
    // √ of the angle from the horizon amplifies acos's rounding there: |Δv| ≈ √(1e-16) at v = 0.5.
    EXPECT_LT(worst, 1e-7);
    // v = 0.5 is the horizon, v = 0 the zenith, 1 the nadir; u = 0 toward the sun.
    const double r = kR + 1000.0;
    const double horizonCos = -std::sqrt(r * r - kR * kR) / r;
    EXPECT_NEAR(skyViewUnitFromParams(m, r, {horizonCos, 1.0}).y, 0.5, 1e-7);
    EXPECT_NEAR(skyViewUnitFromParams(m, r, {1.0, 1.0}).y, 0.0, 1e-12);
    EXPECT_NEAR(skyViewUnitFromParams(m, r, {-1.0, -1.0}).y, 1.0, 1e-7);
    EXPECT_NEAR(skyViewUnitFromParams(m, r, {0.3, 1.0}).x, 0.0, 1e-12);
    EXPECT_NEAR(skyViewUnitFromParams(m, r, {0.3, -1.0}).x, 1.0, 1e-12);
    // Non-linear: 0.57° above the horizontal (1.6° above the horizon seen from 1 km) is 7 of 108 rows from
    // the horizon (v ≈ 0.434); a mapping linear in the zenith angle would give it less than one (v ≈ 0.491).
    const double v = skyViewUnitFromParams(m, r, {std::cos(kPi / 2 - 0.01), 1.0}).y;
    EXPECT_NEAR(v, 0.434, 0.002);
}

}  // namespace
