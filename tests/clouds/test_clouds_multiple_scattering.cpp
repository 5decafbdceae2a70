// The slab model of multiple scattering (docs/effects/clouds.md, "Multiple scattering") in double: energy
// conservation of a homogeneous layer, the δ-scaling's medium, and the limits it must reach.
#include "clouds/clouds_model.h"
#include "clouds_frames.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace cl = postfx::clouds;

constexpr double kPi = 3.14159265358979323846;

// A homogeneous flat layer 1000–1500 m of optical depth `tau`, albedo 1, one HG lobe of asymmetry g, lit
// by the sun alone (illuminance 1) at `sunElevationDeg`, seen from a camera at `cameraY`.
postfx::FrameInfo slabFrame(double tau, double g, double sunElevationDeg, double cameraY) {
    postfx::FrameInfo f;
    f.clouds = test::homogeneousLayer();
    f.clouds.bottomHeight = 1000.0f;
    f.clouds.topHeight = 1500.0f;
    f.clouds.density = float(tau / 500.0);
    f.clouds.albedo = 1.0f;
    f.clouds.anisotropyForward = float(g);
    f.clouds.lobeMix = 0.0f;
    f.clouds.lightDistance = 1e6f;
    f.clouds.maxDistance = 1e7f;
    const double e = sunElevationDeg * kPi / 180.0;
    f.sun.toSun = {float(std::cos(e)), float(std::sin(e)), 0.0f};
    f.sun.illuminance = postfx::Vec3(1.0f);
    f.camera.position = {0.0, cameraY, 0.0};
    return f;
}

// The flux through a horizontal plane carried by the model's radiance arriving at the camera from the
// hemisphere `upward` (looking up: the light going down) [lx per unit sun illuminance]: ∫ L·|μ| dω by a
// midpoint rule in (μ², φ), on which the cosine-weighted measure is uniform.
double hemisphereFlux(const postfx::FrameInfo& frame, bool upward) {
    const cl::Model m = cl::modelFrom(frame, {}, {});
    constexpr int kRings = 48, kSectors = 24;
    double sum = 0.0;
    for (int i = 0; i < kRings; ++i)
        for (int j = 0; j < kSectors; ++j) {
            const double mu = std::sqrt((i + 0.5) / kRings), phi = 2.0 * kPi * (j + 0.5) / kSectors;
            const double s = std::sqrt(1.0 - mu * mu);
            const glm::dvec3 d(s * std::cos(phi), upward ? mu : -mu, s * std::sin(phi));
            sum += cl::march(m, d, 1e7, 512, 0.5, 64).luminance.x;
        }
    return kPi * sum / (kRings * kSectors);  // ∫ L·μ dω = π · the cosine-weighted mean
}

// δ-scaling (Joseph, Wiscombe and Weinman 1976) of one lobe: f = g², and of the dual lobe: its moments.
TEST(CloudsMultipleScattering, SlabMediumIsTheDeltaScaledPhase) {
    postfx::CloudSettings s;
    s.albedo = 0.9f;
    s.anisotropyForward = 0.6f;
    s.lobeMix = 0.0f;
    cl::SlabMedium m = cl::slabMedium(s);
    EXPECT_NEAR(m.g, 0.6, 1e-7);
    EXPECT_NEAR(m.f, 0.36, 1e-7);
    EXPECT_NEAR(m.depthScale, 1.0 - 0.9 * 0.36, 1e-7);
    EXPECT_NEAR(m.albedo, 0.9 * 0.64 / (1.0 - 0.9 * 0.36), 1e-7);
    EXPECT_NEAR(m.asymmetry, 0.24 / 0.64, 1e-7);
    s.anisotropyBack = -0.3f;
    s.lobeMix = 0.25f;
    m = cl::slabMedium(s);
    EXPECT_NEAR(m.g, 0.75 * 0.6 - 0.25 * 0.3, 1e-7);
    EXPECT_NEAR(m.f, 0.75 * 0.36 + 0.25 * 0.09, 1e-7);
}

// Conservative scattering: the diffuse fluence and flux are finite and positive as ω' -> 1 and in slabs
// from 1e-6 to 1e4 optical depths thick; F is constant through the slab (no absorption: dF/dτ = beam).
TEST(CloudsMultipleScattering, ConservativeSlabIsFiniteAndConservesFlux) {
    cl::SlabMedium medium;
    medium.albedo = 1.0;
    medium.asymmetry = 0.5;
    for (double tau0 : {1e-6, 1e-2, 1.0, 50.0, 1e4}) {
        for (double mu0 : {0.01, 0.3, 1.0}) {
            const auto net = [&](double tt) {  // the net flux downward: diffuse + direct beam
                const double beam = std::exp(-tt / mu0);
                const glm::dvec2 uf =
                    cl::slabDiffuse(medium, tt, tau0 - tt, mu0, beam, std::exp(-tau0 / mu0));
                EXPECT_TRUE(std::isfinite(uf.x) && std::isfinite(uf.y)) << tau0 << " " << mu0;
                EXPECT_GE(uf.x, 0.0) << tau0 << " " << mu0;
                return uf.y + mu0 * beam;
            };
            const double top = net(0.0), middle = net(0.5 * tau0), bottom = net(tau0);
            EXPECT_NEAR(middle, top, 1e-3 * mu0) << tau0 << " " << mu0;
            EXPECT_NEAR(bottom, top, 1e-3 * mu0) << tau0 << " " << mu0;
        }
    }
}

// Albedo 1, the sun alone: the model's reflected plus transmitted flux (the diffuse light integrated
// over each hemisphere, and the direct beam) is the incident E·μ0 within 10 %. (The octaves model keeps
// a fifth of it in this layer: it has no light in most directions.)
TEST(CloudsMultipleScattering, SlabModelConservesEnergy) {
    for (double tau : {0.5, 5.0, 50.0}) {
        for (double sunDeg : {90.0, 45.0}) {
            const double mu0 = std::sin(sunDeg * kPi / 180.0);
            const double reflected = hemisphereFlux(slabFrame(tau, 0.6, sunDeg, 1600.0), false);
            const double transmitted = hemisphereFlux(slabFrame(tau, 0.6, sunDeg, 900.0), true);
            const double direct = mu0 * std::exp(-tau / mu0);
            const double total = (reflected + transmitted + direct) / mu0;
            std::printf("[ clouds ] τ %g, sun %g°: R %.4f, T %.4f (direct %.4f), R + T = %.4f of E·μ0\n", tau,
                        sunDeg, reflected / mu0, (transmitted + direct) / mu0, direct / mu0, total);
            EXPECT_NEAR(total, 1.0, 0.10) << tau << " " << sunDeg;
        }
    }
}

}  // namespace
