// One consistent composite: with every medium purely absorbing (the atmosphere's Mie and ozone
// absorption without any scattering, clouds and fog of albedo 0), what postfx leaves in the color image is
// the host's color times each effect's transmittance, and the frame with every effect on is the product
// of the frames with one effect each (the clouds and the fog under an atmosphere of no medium, so that
// the layer is the same curved one): the sky, the clouds, the aerial perspective and either fog composite
// in one record(), in order, and none attenuates what another already attenuated.
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 32, kHeight = 18;
constexpr double kSurfaceDistance = 5300.0;  // every pixel sees a surface this far away [m]: between two
                                             // of the aerial perspective's 1 km slice ends (at one, either
                                             // side of it is an approximation 3e-4 apart)

class FrameCompositeTest : public ReversedZContextTest {
protected:
    // Looking 40° up (rays from 10° to 70° above the horizon): every ray crosses the cloud layer
    // (300–600 m) before its surface 5 km away.
    postfx::FrameInfo frame() const {
        postfx::FrameInfo f;
        f.cameraCut = true;
        const double up = 40.0 * 3.14159265358979 / 180.0;
        f.camera = lookCamera({0.0, 1.5, 0.0}, {0.0, std::sin(up), -std::cos(up)}, {0.0, 1.0, 0.0}, 60.0f,
                              float(kWidth) / kHeight);
        f.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.6f, -0.7f));
        f.sun.illuminance = {1e5f, 1e5f, 1e5f};
        f.ambient = {500.0f, 600.0f, 800.0f};
        // Absorption only: no Rayleigh or Mie scattering (no sky light, no multiple scattering).
        f.atmosphere.rayleighScattering = {0.0f, 0.0f, 0.0f};
        f.atmosphere.mieScattering = 0.0f;
        f.atmosphere.mieAbsorption = 2e-5f;
        f.atmosphere.sunAngularRadiusDeg = 0.0f;
        f.clouds.bottomHeight = 300.0f;
        f.clouds.topHeight = 600.0f;
        f.clouds.coverage = 0.6f;
        f.clouds.density = 0.004f;
        f.clouds.albedo = 0.0f;
        f.clouds.castShadows = false;
        f.fog.density = 0.0004f;
        f.fog.heightFalloff = 0.002f;
        f.fog.albedo = {0.0f, 0.0f, 0.0f};
        f.fog.maxDistance = 2000.0f;
        f.fog.noise.enabled = false;
        f.froxelFog.density = 0.0004f;
        f.froxelFog.heightFalloff = 0.002f;
        f.froxelFog.albedo = {0.0f, 0.0f, 0.0f};
        f.froxelFog.maxDistance = 2000.0f;
        f.froxelFog.noise.enabled = false;
        return f;
    }

    FogHarnessImages images(const postfx::FrameInfo& f) const {
        return surfaceImages(
            f.camera, kWidth, kHeight, [](uint32_t, uint32_t) { return kSurfaceDistance; },
            [](uint32_t i, uint32_t j, int c) { return 100.0f + 10.0f * float((i * 7 + j * 3 + c) % 11); });
    }

    // `f` rendered alone in a new context: the output over the input color, per channel (RGB).
    std::vector<double> transmittance(const postfx::FrameInfo& f, const FogHarnessImages& im) {
        std::unique_ptr<postfx::Context> c;
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        EXPECT_TRUE(createContext(c, info).ok());
        FogHarness harness(*host, gpu);
        std::vector<float> out;
        const postfx::Status s = harness.run(*c, im, f, out);
        EXPECT_TRUE(s.ok()) << s.message;
        std::vector<double> t(size_t(kWidth) * kHeight * 3, 1.0);
        if (out.size() != im.color.size()) return t;
        for (size_t p = 0; p < size_t(kWidth) * kHeight; ++p)
            for (int c = 0; c < 3; ++c)
                t[p * 3 + c] = double(out[p * 4 + c]) / double(im.color[p * 4 + c]);
        return t;
    }

    void expectProductOfTransmittances(bool froxel) {
        const postfx::FrameInfo base = frame();
        const FogHarnessImages im = images(base);
        postfx::FrameInfo sky = base, clouds = base, fog = base, all = base;
        sky.atmosphere.enabled = true;
        smallScatteringOrders(sky.atmosphere);
        // The clouds and the fog each alone, under an atmosphere of no medium at all: with the atmosphere
        // on, the cloud layer follows the planet's curvature (its own transmittance is the curved layer's).
        for (postfx::FrameInfo* f : {&clouds, &fog}) {
            f->atmosphere.enabled = true;
            smallScatteringOrders(f->atmosphere);
            f->atmosphere.mieAbsorption = 0.0f;
            f->atmosphere.ozoneAbsorption = {0.0f, 0.0f, 0.0f};
        }
        clouds.clouds.enabled = true;
        (froxel ? fog.froxelFog.enabled : fog.fog.enabled) = true;
        all.atmosphere.enabled = all.clouds.enabled = true;
        (froxel ? all.froxelFog.enabled : all.fog.enabled) = true;
        const std::vector<double> tSky = transmittance(sky, im), tClouds = transmittance(clouds, im),
                                  tFog = transmittance(fog, im), tAll = transmittance(all, im);
        double worst = 0.0, minSky = 1.0, minClouds = 1.0, minFog = 1.0, minAll = 1.0;
        for (size_t k = 0; k < tAll.size(); ++k) {
            const double product = tSky[k] * tClouds[k] * tFog[k];
            worst = std::max(worst, std::abs(tAll[k] - product) / std::max(product, 1e-6));
            minSky = std::min(minSky, tSky[k]);
            minClouds = std::min(minClouds, tClouds[k]);
            minFog = std::min(minFog, tFog[k]);
            minAll = std::min(minAll, tAll[k]);
        }
        std::printf(
            "[ frame ] %s: lowest transmittance sky %.4g, clouds %.4g, fog %.4g, all %.4g; worst "
            "|T_all - product| / product %.3g\n",
            froxel ? "froxel fog" : "ray-marched fog", minSky, minClouds, minFog, minAll, worst);
        // Each effect attenuates (the test would pass trivially with one of them off).
        EXPECT_LT(minSky, 0.95);
        EXPECT_LT(minClouds, 0.5);
        EXPECT_LT(minFog, 0.95);
        EXPECT_LT(worst, 1e-5);  // float rounding of a few products: ~2e-7 measured
    }
};

}  // namespace

TEST_F(FrameCompositeTest, AbsorbingMediaMultiplyWithTheRayMarchedFog) {
    expectProductOfTransmittances(false);
}

TEST_F(FrameCompositeTest, AbsorbingMediaMultiplyWithTheFroxelFog) {
    expectProductOfTransmittances(true);
}
