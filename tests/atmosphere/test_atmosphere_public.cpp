// The public CPU evaluations (postfx/atmosphere.h): atmosphereSunTransmittance against the pure-Rayleigh
// zenith closed form and the planet's shadow; atmosphereSkyIrradiance against an optically thin
// pure-Rayleigh sky's closed form, against a finer quadrature of the reference's integrateViewRay, at night,
// and its cost.
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_reference.h"

#include <postfx/atmosphere.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace {

using postfx::AtmosphereSettings;
using postfx::DVec3;
using postfx::Vec3;

constexpr double kPi = std::numbers::pi;

AtmosphereSettings rayleighOnly() {
    AtmosphereSettings s;
    s.mieScattering = s.mieAbsorption = 0.0f;
    s.ozoneAbsorption = Vec3(0.0f);
    return s;
}

// toSun at `elevationDeg` above the horizon (azimuth toward +x).
Vec3 sunAt(double elevationDeg) {
    const double e = elevationDeg * kPi / 180.0;
    return Vec3(float(std::cos(e)), float(std::sin(e)), 0.0f);
}

bool finiteNonNegative(const Vec3& v) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(v[c]) || v[c] < 0.0f) return false;
    return true;
}

TEST(AtmospherePublic, SunTransmittanceAtZenithMatchesPureRayleighClosedForm) {
    const AtmosphereSettings s = rayleighOnly();
    const double H = s.rayleighScaleHeight, Z = double(s.topRadius) - double(s.groundRadius);
    const Vec3 T = postfx::atmosphereSunTransmittance(s, DVec3(0.0), Vec3(0.0f, 1.0f, 0.0f));
    for (int c = 0; c < 3; ++c) {
        // exp(-β·H·(1 - e^{-Z/H})): the vertical optical depth of an exponential medium.
        const double expected = std::exp(-double(s.rayleighScattering[c]) * H * (1.0 - std::exp(-Z / H)));
        std::printf("[ measured ] zenith T[%d] = %.7f, closed form %.7f\n", c, T[c], expected);
        // 256 midpoint steps of 390 m: (Δ/H)²/24 = 1e-4 of τ (0.27 in blue), 3e-5 of T.
        EXPECT_NEAR(T[c], expected, 5e-5 * expected);
    }
    // A direction not normalised gives the same; a position below the ground is clamped onto it.
    const Vec3 T2 = postfx::atmosphereSunTransmittance(s, DVec3(5.0, -100.0, 3.0), Vec3(0.0f, 7.0f, 0.0f));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(T2[c], T[c], 1e-6f);
}

TEST(AtmospherePublic, SunTransmittanceIsZeroBelowTheHorizonAndFallsTowardIt) {
    const AtmosphereSettings s;  // Earth
    const Vec3 below = postfx::atmosphereSunTransmittance(s, DVec3(0.0), sunAt(-1.0));
    EXPECT_EQ(below, Vec3(0.0f));
    EXPECT_EQ(postfx::atmosphereSunTransmittance(s, DVec3(0.0), sunAt(-90.0)), Vec3(0.0f));
    // Zero direction: no sun.
    EXPECT_EQ(postfx::atmosphereSunTransmittance(s, DVec3(0.0), Vec3(0.0f)), Vec3(0.0f));
    const Vec3 noon = postfx::atmosphereSunTransmittance(s, DVec3(0.0), sunAt(90.0));
    const Vec3 low = postfx::atmosphereSunTransmittance(s, DVec3(0.0), sunAt(5.0));
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(noon[c], low[c]);
        EXPECT_GT(low[c], 0.0f);
        EXPECT_LT(noon[c], 1.0f);
    }
    EXPECT_LT(low.z, low.x);  // blue goes first: a red sun low in the sky
    // From 100 km up the sun 1° below the local horizon is still seen (the horizon dips by ~10°), and
    // outside the atmosphere nothing absorbs.
    const Vec3 high = postfx::atmosphereSunTransmittance(s, DVec3(0.0, 100e3, 0.0), sunAt(-1.0));
    EXPECT_GT(high.x, 0.0f);
    const Vec3 space = postfx::atmosphereSunTransmittance(s, DVec3(0.0, 200e3, 0.0), sunAt(45.0));
    EXPECT_EQ(space, Vec3(1.0f));
}

// An optically thin pure-Rayleigh atmosphere over a nearly flat ground (a planet of 1e8 m, 1 km scale
// height), no ground albedo: every point is lit by the full sun and nothing attenuates, so the sky at
// direction ω with cos θ = μ from the zenith has L = E·p(ω·s)·∫σ dt = E·p·β·H/μ (flat layers), and
// E_sky = ∫ L μ dω = E·β·H·∫_{upper} p(ω·s) dω = E·β·H/2 for every sun above the horizon: the Rayleigh
// phase is even in ω·s, so each hemisphere holds half of its unit integral. (The top's e^{-Z/(H μ)}, Z/H =
// 20, and the curvature, which shortens rays within μ < √(2H/R) = 0.5 % of the horizon, are below 1e-3.)
TEST(AtmospherePublic, ThinRayleighSkyIrradianceMatchesClosedForm) {
    AtmosphereSettings s = rayleighOnly();
    s.groundRadius = 1e8f;
    s.topRadius = 1e8f + 2e4f;
    s.rayleighScaleHeight = 1000.0f;
    s.rayleighScattering = Vec3(1e-8f, 2e-8f, 4e-8f);
    s.groundAlbedo = Vec3(0.0f);
    const Vec3 sun(1000.0f, 2000.0f, 3000.0f);
    for (const bool ms : {false, true}) {
        s.multipleScattering =
            ms ? postfx::AtmosphereMultipleScattering::Hillaire : postfx::AtmosphereMultipleScattering::Off;
        for (const double elevation : {90.0, 30.0, 5.0}) {
            const Vec3 e = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(elevation), sun);
            for (int c = 0; c < 3; ++c) {
                const double expected = double(sun[c]) * double(s.rayleighScattering[c]) * 1000.0 / 2.0;
                const double rel = std::abs(e[c] - expected) / expected;
                std::printf(
                    "[ measured ] thin Rayleigh, sun %g°, ms %d: E[%d] = %.6g, closed form %.6g "
                    "(rel. err %.2g)\n",
                    elevation, int(ms), c, e[c], expected, rel);
                EXPECT_LT(rel, 1e-2);
            }
        }
    }
}

// atmosphereSkyIrradiance (16×32 directions, 24 growing steps; Hillaire's Ψ from a 32×12 table, or the
// coarse scattering-orders table) against a finer quadrature of the reference's own view ray
// (integrateViewRay: Ψ evaluated at every sample, or the same orders table): Earth, a sunny afternoon.
glm::dvec3 referenceIrradiance(const AtmosphereSettings& s, const Vec3& toSun, bool ms, uint32_t rings,
                               uint32_t azimuths, uint32_t steps) {
    using namespace postfx::atmosphere;
    const Model m = modelFrom(s);
    const glm::dvec3 x(0.0, m.groundRadius, 0.0);
    postfx::atmosphere::Sun sun;
    sun.toSun = glm::normalize(glm::dvec3(toSun.x, toSun.y, toSun.z));
    ViewRayOptions o;
    o.steps = steps;
    o.transmittanceSteps = 48;
    o.multipleScattering = ms;
    o.psi = PsiOptions{16, 12, 16};
    o.ground = true;
    std::shared_ptr<const OrdersTable> orders;
    if (ms && s.multipleScattering == postfx::AtmosphereMultipleScattering::Orders) {
        orders = sharedOrdersTable(m, coarseOrdersOptions());
        o.ordersTable = orders.get();
    }
    glm::dvec3 sum(0.0);
    for (uint32_t i = 0; i < rings; ++i) {
        const double mu = (i + 0.5) / rings, sinTheta = std::sqrt(1.0 - mu * mu);
        for (uint32_t j = 0; j < azimuths; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / azimuths;
            const glm::dvec3 dir(sinTheta * std::cos(phi), mu, sinTheta * std::sin(phi));
            sum += mu * integrateViewRay(m, x, dir, sun, o).luminance;
        }
    }
    return sum * (2.0 * kPi / (double(rings) * azimuths));
}

TEST(AtmospherePublic, SkyIrradianceMatchesFinerReferenceQuadrature) {
    const AtmosphereSettings earth;
    const Vec3 toSun = sunAt(25.0);
    // Single scattering: 24×48 directions, 320 uniform steps (310 m: (Δ/H)²/24 = 0.3 % of Mie's).
    {
        AtmosphereSettings s = earth;
        s.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
        const Vec3 e = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), toSun, Vec3(1.0f));
        const glm::dvec3 ref = referenceIrradiance(s, toSun, false, 24, 48, 320);
        for (int c = 0; c < 3; ++c) {
            const double rel = std::abs(e[c] - ref[c]) / ref[c];
            std::printf("[ measured ] single scattering E[%d] = %.6g, reference %.6g (rel. err %.2g)\n", c,
                        e[c], ref[c], rel);
            EXPECT_LT(rel, 0.02);
        }
    }
    // With multiple scattering, each model (the reference: 8×16 directions, 64 steps).
    for (const auto model :
         {postfx::AtmosphereMultipleScattering::Hillaire, postfx::AtmosphereMultipleScattering::Orders}) {
        AtmosphereSettings withModel = earth;
        withModel.multipleScattering = model;
        const Vec3 e = postfx::atmosphereSkyIrradiance(withModel, DVec3(0.0), toSun, Vec3(1.0f));
        const Vec3 single = [&] {
            AtmosphereSettings s = earth;
            s.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
            return postfx::atmosphereSkyIrradiance(s, DVec3(0.0), toSun, Vec3(1.0f));
        }();
        const glm::dvec3 ref = referenceIrradiance(withModel, toSun, true, 8, 16, 64);
        const glm::dvec3 refSingle = referenceIrradiance(earth, toSun, false, 8, 16, 64);
        for (int c = 0; c < 3; ++c) {
            // The multiple-scattering part alone, against the reference's (itself a few % off: 64 uniform
            // steps of 1.6 km against Mie's 1.2 km scale height; Ψ of 16 directions in both).
            const double part = e[c] - single[c], refPart = ref[c] - refSingle[c];
            const double rel = std::abs(part - refPart) / refPart;
            std::printf(
                "[ measured ] %s: multiple-scattering part of E[%d] = %.6g, reference %.6g (rel. err %.2g); "
                "total %.6g\n",
                model == postfx::AtmosphereMultipleScattering::Orders ? "orders" : "hillaire", c, part,
                refPart, rel, e[c]);
            EXPECT_GT(part, 0.0);
            EXPECT_LT(rel, 0.05);
        }
    }
}

TEST(AtmospherePublic, SkyIrradianceIsPositiveByDayAndZeroAtNight) {
    const AtmosphereSettings s;
    const Vec3 sun(100000.0f);
    const Vec3 noon = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(90.0), sun);
    const Vec3 sunset = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(2.0), sun);
    const Vec3 dusk = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(-3.0), sun);
    const Vec3 night = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(-60.0), sun);
    std::printf(
        "[ measured ] sky irradiance at noon (%.5g, %.5g, %.5g), sun at 2° (%.5g, %.5g, %.5g), at -3° "
        "(%.3g, %.3g, %.3g) lux for 1e5 lux\n",
        noon.x, noon.y, noon.z, sunset.x, sunset.y, sunset.z, dusk.x, dusk.y, dusk.z);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(noon[c], 0.0f);
        EXPECT_GT(sunset[c], 0.0f);
        EXPECT_LT(sunset[c], noon[c]);
        EXPECT_LT(dusk[c], sunset[c]);
        EXPECT_LT(noon[c], sun[c]);  // the sky is dimmer than the sun
    }
    EXPECT_GT(noon.z, noon.x);  // a blue sky
    EXPECT_TRUE(finiteNonNegative(dusk));
    for (int c = 0; c < 3; ++c)  // the planet's shadow covers the whole atmosphere
        EXPECT_LT(night[c], 1e-9f * noon[c]);
    // Space far above: nothing above scatters; a zero sun gives nothing.
    EXPECT_TRUE(
        finiteNonNegative(postfx::atmosphereSkyIrradiance(s, DVec3(0.0, 1e7, 0.0), sunAt(45.0), sun)));
    EXPECT_EQ(postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(45.0), Vec3(0.0f)), Vec3(0.0f));
}

TEST(AtmospherePublic, SkyIrradianceCost) {
    AtmosphereSettings s;
    s.mieScattering *= 1.0001f;  // media no earlier test used: the first call builds the Ψ table
    for (const bool ms : {true, false}) {
        s.multipleScattering =
            ms ? postfx::AtmosphereMultipleScattering::Hillaire : postfx::AtmosphereMultipleScattering::Off;
        const auto t0 = std::chrono::steady_clock::now();
        const Vec3 e = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(30.0), Vec3(1.0f));
        const double ms_ =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        std::printf("[ measured ] atmosphereSkyIrradiance with multiple scattering %s: %.1f ms\n",
                    ms ? "on" : "off", ms_);
        EXPECT_GT(e.x, 0.0f);
        if (!ms) continue;
        // The sun moved, the media the same: the kept Ψ table, the same result as a call that builds it.
        const auto t1 = std::chrono::steady_clock::now();
        const Vec3 moved = postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(31.0), Vec3(1.0f));
        std::printf("[ measured ] atmosphereSkyIrradiance with multiple scattering, the sun moved: %.1f ms\n",
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count());
        EXPECT_EQ(postfx::atmosphereSkyIrradiance(s, DVec3(0.0), sunAt(30.0), Vec3(1.0f)), e);
        EXPECT_NE(moved, e);
    }
    const auto t0 = std::chrono::steady_clock::now();
    postfx::atmosphereSunTransmittance(s, DVec3(0.0), sunAt(30.0));
    std::printf("[ measured ] atmosphereSunTransmittance: %.3f ms\n",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace
