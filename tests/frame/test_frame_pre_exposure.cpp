// Pre-exposure (docs/integration.md, "Pre-exposure"): with FrameInfo::preExposure p and the
// host's color stored × p, every effect writes its radiance × p: the frame equals p × the frame in physical
// units (the atmosphere, the clouds and either fog together, p a power of two and not, RGBA32F so that
// nothing clips), and a temporal history accumulated at one pre-exposure carries on at another (rescaled,
// not reset: the frame after the change equals a sequence at the new pre-exposure throughout).
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 24, kHeight = 16;

class FramePreExposureTest : public ReversedZContextTest {
protected:
    postfx::FrameInfo frame(bool froxel) const {
        postfx::FrameInfo f;
        f.camera =
            lookCamera({0.0, 1.7, 0.0}, {0.3, 0.3, -1.0}, {0.0, 1.0, 0.0}, 70.0f, float(kWidth) / kHeight);
        f.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.25f, -0.9f));
        f.sun.illuminance = {1e5f, 1e5f, 1e5f};
        f.ambient = {300.0f, 400.0f, 600.0f};
        f.atmosphere.enabled = true;
        f.clouds.enabled = true;
        f.clouds.bottomHeight = 300.0f;
        f.clouds.topHeight = 600.0f;
        f.clouds.coverage = 0.6f;
        f.clouds.density = 0.004f;
        f.clouds.noise.baseSize = 32;
        f.clouds.noise.detailSize = 16;
        f.clouds.shadowMap.size = 64;
        postfx::FogMedium& m =
            froxel ? static_cast<postfx::FogMedium&>(f.froxelFog) : static_cast<postfx::FogMedium&>(f.fog);
        m.density = 0.002f;
        m.heightFalloff = 0.01f;
        m.anisotropy = 0.8f;
        m.maxDistance = 400.0f;
        m.noise.enabled = false;
        (froxel ? f.froxelFog.enabled : f.fog.enabled) = true;
        if (!froxel) f.fog.temporal.enabled = true;
        if (froxel) f.froxelFog.grid = {16, 8, 32};
        return f;
    }

    // Surfaces from 2 m to 2 km, one column in five with no geometry; color × `preExposure`.
    FogHarnessImages images(const postfx::FrameInfo& f, float preExposure) const {
        return surfaceImages(
            f.camera, kWidth, kHeight,
            [](uint32_t i, uint32_t j) {
                return i % 5 == 4 ? std::numeric_limits<double>::infinity()
                                  : 2.0 * std::pow(1e3, double((i * 3 + j * 5) % 11) / 10.0);
            },
            [preExposure](uint32_t i, uint32_t j, int c) {
                return (100.0f + 40.0f * float((i * 7 + j * 3 + c) % 11)) * (c < 3 ? preExposure : 1.0f);
            });
    }

    std::unique_ptr<postfx::Context> newContext() {
        std::unique_ptr<postfx::Context> c;
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        EXPECT_TRUE(createContext(c, info).ok());
        return c;
    }

    // Frames 0..frames-1 of `f` in `c` (still camera), frame k at pre-exposure exposures[k]; the last one's
    // output divided by its pre-exposure.
    std::vector<float> run(postfx::Context& c, postfx::FrameInfo f, const std::vector<float>& exposures) {
        FogHarness harness(*host, gpu);
        std::vector<float> out;
        for (size_t k = 0; k < exposures.size(); ++k) {
            f.frameIndex = k;
            f.cameraCut = k == 0;
            f.preExposure = exposures[k];
            const postfx::Status s = harness.run(c, images(f, exposures[k]), f, out);
            EXPECT_TRUE(s.ok()) << s.message;
        }
        for (size_t i = 0; i < out.size(); ++i)
            if (i % 4 != 3) out[i] /= exposures.back();
        return out;
    }
};

// Largest |a - b| / max(|b|, 1e-3 · the image's mean) over RGB.
double worstRelative(const std::vector<float>& a, const std::vector<float>& b) {
    double mean = 0.0;
    for (float v : b)
        mean += std::abs(v);
    mean /= double(std::max<size_t>(b.size(), 1));
    double worst = a.size() == b.size() ? 0.0 : 1e30;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (i % 4 == 3) continue;
        if (!std::isfinite(a[i])) return 1e30;
        worst =
            std::max(worst, std::abs(double(a[i]) - b[i]) / std::max(std::abs(double(b[i])), 1e-3 * mean));
    }
    return worst;
}

}  // namespace

TEST_F(FramePreExposureTest, EveryEffectWritesItsRadiancePreExposed) {
    for (bool froxel : {false, true}) {
        const postfx::FrameInfo f = frame(froxel);
        const std::vector<float> physical = run(*newContext(), f, {1.0f});
        for (float p : {0.25f, 1.3e-5f, 7.0f}) {
            const std::vector<float> exposed = run(*newContext(), f, {p});
            const double worst = worstRelative(exposed, physical);
            std::printf(
                "[ frame ] %s, pre-exposure %g: worst relative difference from the physical frame %.3g\n",
                froxel ? "froxel fog" : "ray-marched fog", double(p), worst);
            // Float rounding of p·x and x/p; the froxel fog's volumes are RGBA16F (its storage scale a
            // power of two): p·x there rounds to half's 2^-11 apart from x. A power of two rounds nothing.
            const double tolerance = p == 0.25f ? 0.0 : froxel ? 1e-3 : 2e-5;
            EXPECT_LE(worst, tolerance) << "pre-exposure " << p;
        }
    }
}

TEST_F(FramePreExposureTest, HistoriesAreRescaledWhenThePreExposureChanges) {
    // The clouds' and the ray-marched fog's histories, then the froxel fog's volume history.
    for (bool froxel : {false, true}) {
        const postfx::FrameInfo f = frame(froxel);
        const std::vector<float> changed = run(*newContext(), f, {1.0f, 1.0f, 1.0f, 1.0f, 0.125f, 0.125f});
        const std::vector<float> throughout = run(*newContext(), f, std::vector<float>(6, 0.125f));
        const std::vector<float> reset = run(*newContext(), f, {0.125f});  // what a reset would show
        const double worst = worstRelative(changed, throughout), fromReset = worstRelative(changed, reset);
        std::printf(
            "[ frame ] %s: pre-exposure 1 then 1/8 against 1/8 throughout: worst relative difference "
            "%.3g (from a reset frame: %.3g)\n",
            froxel ? "froxel fog" : "ray-marched fog", worst, fromReset);
        EXPECT_LT(worst, 2e-5);
        EXPECT_GT(fromReset, 1e-3);  // the history matters in this sequence
    }
}
