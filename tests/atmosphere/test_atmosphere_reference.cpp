// The double-precision atmosphere reference (atmosphere_reference.h) against closed forms: vertical optical
// depths of the exponential and tent media, the single-scattering sky at zenith, and the properties of Ψ.
#include "atmosphere/atmosphere_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace {

using namespace postfx::atmosphere;

constexpr double kPi = std::numbers::pi;

// Earth's radii, no medium.
Model emptyModel() {
    Model m;
    m.rayleighScattering = glm::dvec3(0.0);
    m.mieScattering = m.mieAbsorption = 0.0;
    m.ozoneAbsorption = glm::dvec3(0.0);
    return m;
}

Model rayleighOnly(double scale = 1.0) {
    Model m = emptyModel();
    m.rayleighScattering = Model().rayleighScattering * scale;
    return m;
}

const glm::dvec3 kUp(0.0, 1.0, 0.0);

// τ of an exponential medium from the ground to the top, straight up:
// ∫_0^Z β e^{-h/H} dh = β·H·(1 - e^{-Z/H}), Z = top - ground.
glm::dvec3 verticalExponentialDepth(const glm::dvec3& beta, double H, double Z) {
    return beta * H * (1.0 - std::exp(-Z / H));
}

TEST(AtmosphereReference, RayleighZenithTransmittanceMatchesClosedForm) {
    const Model m = rayleighOnly();
    const double Z = m.topRadius - m.groundRadius;
    const glm::dvec3 tau = verticalExponentialDepth(m.rayleighScattering, m.rayleighScaleHeight, Z);
    const glm::dvec3 origin(0.0, m.groundRadius, 0.0);
    // 2000 midpoint steps of 50 m: the midpoint rule's relative error on e^{-h/H} is (Δ/H)²/24 = 1.6e-6.
    const glm::dvec3 T = transmittanceToEdge(m, origin, kUp, 2000);
    for (int c = 0; c < 3; ++c) {
        const double expected = std::exp(-tau[c]);
        std::printf("[ measured ] Rayleigh zenith T[%d] = %.9f, closed form %.9f (rel. err %.2g)\n", c, T[c],
                    expected, std::abs(T[c] - expected) / expected);
        EXPECT_NEAR(T[c], expected, 1e-6 * expected);  // stated tolerance: 1e-6 relative
    }
    // The LUT's 40 steps (2.5 km): the midpoint rule's (Δ/H)²/24 = 0.4 % of τ, i.e. ≈ 0.1 % of T in blue.
    const glm::dvec3 T40 = transmittanceToEdge(m, origin, kUp, 40);
    const double rel = std::abs(T40.z - std::exp(-tau.z)) / std::exp(-tau.z);
    std::printf("[ measured ] Rayleigh zenith T (blue) with 40 steps: rel. err %.3g\n", rel);
    EXPECT_LT(rel, 2e-3);
}

// ∫ of the unit tent max(0, 1 - |h - c|/w) over (-∞, h]: w·A(u), u = (h - c)/w.
double tentPrimitive(double h, double c, double w) {
    const double u = (h - c) / w;
    if (u <= -1.0) return 0.0;
    if (u <= 0.0) return w * 0.5 * (u + 1.0) * (u + 1.0);
    if (u <= 1.0) return w * (1.0 - 0.5 * (1.0 - u) * (1.0 - u));
    return w;
}

TEST(AtmosphereReference, OzoneVerticalDepthMatchesClippedTentArea) {
    struct Case {
        double centre, halfWidth;
    };
    // The default tent (inside the atmosphere: area = half width), one clipped by the ground, one by the top.
    for (const Case tc : {Case{25e3, 15e3}, Case{5e3, 15e3}, Case{95e3, 15e3}}) {
        Model m = emptyModel();
        m.ozoneAbsorption = Model().ozoneAbsorption;
        m.ozoneCenterHeight = tc.centre;
        m.ozoneHalfWidth = tc.halfWidth;
        const double Z = m.topRadius - m.groundRadius;
        const double area =
            tentPrimitive(Z, tc.centre, tc.halfWidth) - tentPrimitive(0.0, tc.centre, tc.halfWidth);
        const glm::dvec3 tau = opticalDepth(m, {0.0, m.groundRadius, 0.0}, kUp, 4000);
        for (int c = 0; c < 3; ++c) {
            const double expected = m.ozoneAbsorption[c] * area;
            EXPECT_NEAR(tau[c], expected, 1e-6 * expected) << "centre " << tc.centre << " channel " << c;
        }
        std::printf("[ measured ] ozone tent centre %.0f m: area %.4f m, reference %.4f m\n", tc.centre, area,
                    tau.y / m.ozoneAbsorption.y);
    }
}

TEST(AtmosphereReference, SunBehindThePlanetIsBlack) {
    const Model m;
    const glm::dvec3 p(0.0, m.groundRadius + 100.0, 0.0);
    EXPECT_EQ(sunTransmittance(m, p, {0.0, -1.0, 0.0}, 40), glm::dvec3(0.0));
    // Seen from orbit the sun behind the planet is hidden; beside it, the path misses the atmosphere.
    const glm::dvec3 orbit(0.0, m.groundRadius + 1e7, 0.0);
    EXPECT_EQ(sunTransmittance(m, orbit, {0.0, -1.0, 0.0}, 40), glm::dvec3(0.0));
    EXPECT_EQ(sunTransmittance(m, orbit, {1.0, 0.0, 0.0}, 40), glm::dvec3(1.0));
}

// Single scattering, pure Rayleigh, camera on the ground looking at the zenith, sun at the zenith.
// Derivation: a sample at altitude h scatters E·T_sun(h)·σs(h)·p(θ) per unit length toward the camera,
// attenuated by T(0, h). Both paths are vertical, so T_sun(h)·T(0, h) = e^{-τ(h, Z)}·e^{-τ(0, h)} = e^{-τ}
// with τ = β·H·(1 - e^{-Z/H}) the whole column's depth, the same at every h. The camera looks toward the
// sun: θ = 0, p_R(0) = 3/(16π)·2 = 3/(8π). Hence
//   L = E·p_R(0)·e^{-τ}·∫_0^Z β e^{-h/H} dh = E·(3/(8π))·τ·e^{-τ},
// exactly (σs = σt for Rayleigh). Optically thin (β·H tiny): L ≈ E·(3/(8π))·β·H·(1 - e^{-Z/H}).
TEST(AtmosphereReference, ThinRayleighZenithSkyMatchesSingleScattering) {
    for (double scale : {1e-6, 1.0}) {
        const Model m = rayleighOnly(scale);
        const double Z = m.topRadius - m.groundRadius;
        const glm::dvec3 tau = verticalExponentialDepth(m.rayleighScattering, m.rayleighScaleHeight, Z);
        Sun sun;
        sun.toSun = kUp;
        sun.illuminance = glm::dvec3(120000.0);
        ViewRayOptions o;
        o.steps = 1000;
        o.transmittanceSteps = 1000;
        o.multipleScattering = false;
        const ViewRayResult res = integrateViewRay(m, {0.0, m.groundRadius, 0.0}, kUp, sun, o);
        for (int c = 0; c < 3; ++c) {
            const double expected = sun.illuminance[c] * 3.0 / (8.0 * kPi) * tau[c] * std::exp(-tau[c]);
            const double rel = std::abs(res.luminance[c] - expected) / expected;
            std::printf(
                "[ measured ] Rayleigh x%g zenith L[%d] = %.6g cd/m2, closed form %.6g (rel. err %.2g)\n",
                scale, c, res.luminance[c], expected, rel);
            EXPECT_LT(rel, 1e-5);  // the midpoint rule's (Δ/H)²/24 = 6.5e-6
            // 1000 steps of 100 m: (Δ/H)²/24 = 6.5e-6 of τ.
            EXPECT_NEAR(res.transmittance[c], std::exp(-tau[c]), 1e-5 * std::exp(-tau[c]));
        }
    }
}

// Ψ at the ground for an empty atmosphere, the sun at the zenith: f_ms = 0 and L2 is the ground alone. Half
// of the stratified directions point down and end at once on the ground lit at n·s = 1:
// L2 = (1/2)·albedo/π, so Ψ = albedo/(2π).
TEST(AtmosphereReference, PsiOfAnEmptyAtmosphereIsTheGroundBounce) {
    Model m = emptyModel();
    m.groundAlbedo = {0.3, 0.5, 0.0};
    const glm::dvec3 psi = multipleScatteringPsi(m, m.groundRadius, 1.0);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(psi[c], m.groundAlbedo[c] / (2.0 * kPi), 1e-15);
    // No scattering, black ground: nothing at all, whatever the absorption.
    Model absorbing = emptyModel();
    absorbing.groundAlbedo = glm::dvec3(0.0);
    absorbing.mieAbsorption = 4.4e-6;
    absorbing.ozoneAbsorption = Model().ozoneAbsorption;
    EXPECT_EQ(multipleScatteringPsi(absorbing, absorbing.groundRadius + 1000.0, 0.5), glm::dvec3(0.0));
}

TEST(AtmosphereReference, PsiIsPositiveFiniteAndGrowsWithGroundAlbedo) {
    const Model earth;
    for (double h : {0.0, 1000.0, 30e3, 100e3})
        for (double muS : {-1.0, -0.2, 0.0, 0.3, 1.0}) {
            const glm::dvec3 psi = multipleScatteringPsi(earth, earth.groundRadius + h, muS);
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(std::isfinite(psi[c]));
                EXPECT_GE(psi[c], 0.0);
                if (muS >= 0.0) {
                    EXPECT_GT(psi[c], 0.0) << "h " << h << " muS " << muS;
                }
            }
        }
    const double r = earth.groundRadius + 1000.0;
    glm::dvec3 previous(-1.0);
    for (double albedo : {0.0, 0.3, 0.9}) {
        Model m = earth;
        m.groundAlbedo = glm::dvec3(albedo);
        const glm::dvec3 psi = multipleScatteringPsi(m, r, 0.5);
        std::printf("[ measured ] Psi(1 km, muS 0.5, albedo %.1f) = (%.4g, %.4g, %.4g) 1/sr\n", albedo, psi.x,
                    psi.y, psi.z);
        for (int c = 0; c < 3; ++c)
            EXPECT_GT(psi[c], previous[c]);
        previous = psi;
    }
}

TEST(AtmosphereReference, EarthSkyIsFiniteEverywhere) {
    // Camera below the ground (clamped), on it, at 1e7 m; looking up, down, at the horizon; sun up, at the
    // horizon and below it: finite, non-negative luminance, transmittance in [0, 1].
    const Model m;
    ViewRayOptions o;
    o.steps = 32;
    o.transmittanceSteps = 32;
    o.psi.steps = 8;
    o.psi.transmittanceSteps = 8;
    o.ground = true;
    for (double h : {-100.0, 0.0, 1000.0, 1e7})
        for (const glm::dvec3 dir :
             {kUp, -kUp, glm::dvec3(1.0, 0.0, 0.0), glm::normalize(glm::dvec3(1.0, -0.1, 0.0))})
            for (double muS : {1.0, 0.0, -0.2}) {
                Sun sun;
                sun.toSun = {std::sqrt(1.0 - muS * muS), muS, 0.0};
                sun.illuminance = glm::dvec3(120000.0);
                const glm::dvec3 origin = clampAboveGround(m, {0.0, m.groundRadius + h, 0.0});
                const ViewRayResult res = integrateViewRay(m, origin, dir, sun, o);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_TRUE(std::isfinite(res.luminance[c]));
                    EXPECT_GE(res.luminance[c], 0.0);
                    EXPECT_GE(res.transmittance[c], 0.0);
                    EXPECT_LE(res.transmittance[c], 1.0);
                }
            }
}

}  // namespace
