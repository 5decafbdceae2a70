// Pre-exposure (docs/integration.md, "Pre-exposure"): with FrameInfo::preExposure p and the
// host's color stored × p, every effect writes its radiance × p: the frame equals p × the frame in physical
// units (the atmosphere, the clouds and either fog together, p a power of two and not, RGBA32F so that
// nothing clips), and a temporal history accumulated at one pre-exposure carries on at another (rescaled,
// not reset: the frame after the change equals a sequence at the new pre-exposure throughout), except
// where it clipped: after a 512× drop the clipped history is rejected, not rescaled into a ghost.
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
        smallScatteringOrders(f.atmosphere);
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
    // `colorFormat`: the color image's (RGBA32F: nothing clips); `each`: every frame's output, divided by
    // its pre-exposure; `cut`: a frame besides 0 that is a camera cut.
    std::vector<float> run(postfx::Context& c, postfx::FrameInfo f, const std::vector<float>& exposures,
                           VkFormat colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT,
                           std::vector<std::vector<float>>* each = nullptr, size_t cut = 0) {
        FogHarness harness(*host, gpu);
        std::vector<float> out;
        for (size_t k = 0; k < exposures.size(); ++k) {
            f.frameIndex = k;
            f.cameraCut = k == 0 || k == cut;
            f.preExposure = exposures[k];
            FogHarnessImages im = images(f, exposures[k]);
            im.colorFormat = colorFormat;
            const postfx::Status s = harness.run(c, im, f, out);
            EXPECT_TRUE(s.ok()) << s.message;
            for (size_t i = 0; i < out.size(); ++i)
                if (i % 4 != 3) out[i] /= exposures[k];
            if (each) each->push_back(out);
        }
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

// Mean over RGB of |a - b| / max(|b|, 1e-3 · the image's mean).
double meanRelative(const std::vector<float>& a, const std::vector<float>& b) {
    double mean = 0.0;
    for (float v : b)
        mean += std::abs(v);
    mean /= double(std::max<size_t>(b.size(), 1));
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (i % 4 == 3) continue;
        if (!std::isfinite(a[i])) return 1e30;
        sum += std::abs(double(a[i]) - b[i]) / std::max(std::abs(double(b[i])), 1e-3 * mean);
        ++count;
    }
    return a.size() == b.size() && count > 0 ? sum / double(count) : 1e30;
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

TEST_F(FramePreExposureTest, ClippedHistoryIsNotRescaledIntoAGhost) {
    // At pre-exposure 4096 the fog's in-scattering of a 1,000 lux sun, the clouds and the froxels near a
    // 2e5 cd light clip at RGBA16F's 65,504; at frame 4 the pre-exposure drops 512× to 8, where none
    // does. Rescaled, the clipped history would be 512× too dark and fade over ~30 frames.
    constexpr float kHigh = 4096.0f, kLow = 8.0f;
    constexpr size_t kBefore = 4, kAfter = 3;
    for (bool froxel : {false, true}) {
        postfx::FrameInfo f = frame(froxel);
        f.sun.illuminance = {1e3f, 1e3f, 1e3f};
        f.ambient = {3.0f, 4.0f, 6.0f};
        postfx::LocalLight light;
        light.position = {0.6, 2.3, -2.0};
        light.intensity = {2e5f, 2e5f, 2e5f};
        light.range = 30.0f;
        if (froxel) {
            f.froxelFog.anisotropy = 0.0f;  // its storage scale follows the sun's peak: keep it low
            f.lights = &light;
            f.lightCount = 1;
        }
        std::vector<float> exposures(kBefore, kHigh);
        exposures.resize(kBefore + kAfter, kLow);
        std::vector<std::vector<float>> changed, throughout, cut, high;
        const std::vector<float> low(kBefore + kAfter, kLow);
        run(*newContext(), f, exposures, VK_FORMAT_R16G16B16A16_SFLOAT, &changed);
        run(*newContext(), f, low, VK_FORMAT_R16G16B16A16_SFLOAT, &throughout);
        // What texels that reject their history show: the run at the new exposure, reset at the drop.
        run(*newContext(), f, low, VK_FORMAT_R16G16B16A16_SFLOAT, &cut, kBefore);
        run(*newContext(), f, {kHigh}, VK_FORMAT_R16G16B16A16_SFLOAT, &high);
        // The scene clips at the high pre-exposure (what the history held), not at the low one.
        size_t clipped = 0;
        for (size_t i = 0; i < high[0].size(); ++i)
            clipped += i % 4 != 3 && high[0][i] * kHigh >= 0.5f * 65504.0f;
        EXPECT_GT(clipped, high[0].size() / 8) << (froxel ? "froxel fog" : "ray-marched fog");
        for (size_t k = kBefore; k < kBefore + kAfter; ++k) {
            // The temporal tolerance: what the frame after a reset at the drop differs by (its texels hold
            // that frame alone, as rejected texels do; they then blend on at the history's weight).
            const double difference = meanRelative(changed[k], throughout[k]);
            const double reset = meanRelative(cut[kBefore], throughout[kBefore]);
            std::printf(
                "[ frame ] %s, frame %zu after a 512x drop at frame %zu: mean relative difference from "
                "the run at the new pre-exposure %.3g (reset at the drop: %.3g)\n",
                froxel ? "froxel fog" : "ray-marched fog", k, kBefore, difference, reset);
            EXPECT_LE(difference, std::max(reset, 1e-4)) << "frame " << k;
        }
    }
}
