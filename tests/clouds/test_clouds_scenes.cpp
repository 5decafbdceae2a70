// The demo's cloud scenes through the demo host (the clouds over the atmosphere's sky, lit through it, the
// ground lit under the clouds' shadow map): demo/scenes/clouds_noon.json, clouds_sunset.json (the sun 2°
// above the horizon) and clouds_above.json (the camera 6 km up, above the layer), at 96×54, two frames (the
// surfaces read the clouds' shadow map one frame late: frame 1 shows the ground shadowed).
//   - against golden images in tests/clouds/golden/ (tolerance in golden.h: relative RMSE below 1%, at most
//     0.5% of pixels off by more than 2%; golden-failures/ gets the actual and a diff image);
//   - against the demo's CPU reference of the same frame (Renderer::renderReference: the atmosphere's
//     reference (a) and postfx::reference::renderClouds in double, 1024 view and 256 light samples): the
//     mean relative difference per channel, Σ|gpu - ref| / Σ ref, per pixel (printed) and over 8×6-pixel
//     blocks (bounded), and the bias Σ(gpu - ref) / Σ ref (bounded);
//   - against the path-traced truth of the same frame (the reference with the clouds path-traced, every
//     scattering order): the mean luminance over the pixels the clouds change (where the GPU's frame differs
//     from its frame without clouds by more than 1 %), within 15 % of the truth's.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"
#include "scene_reference.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;
// The atmosphere reference's samples per view ray (the clouds' reference takes its own 1024).
constexpr uint32_t kAtmosphereReferenceSteps = 256;
// The largest |Σ(gpu - ref)| / Σ ref per channel (measured: at most 3.0%, clouds_sunset's red).
constexpr double kMaxBias = 0.05;

class CloudsScenes : public GpuTest {
protected:
    demo::Scene load(const std::string& name) {
        demo::Scene scene = loadDemoScene(name);
        EXPECT_TRUE(scene.atmosphere.enabled) << name;
        EXPECT_TRUE(scene.clouds.enabled) << name;
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer() { return sceneRenderer(*host, kWidth, kHeight); }

    void expectSceneMatchesGolden(const std::string& name) {
        const demo::Scene scene = load(name);
        auto r = renderer();
        ASSERT_TRUE(r);
        demo::ImageF image;
        std::string error;
        ASSERT_TRUE(r->render(scene, image, error)) << error;
        expectMatchesGolden(image, "clouds", name);
    }

    // The GPU's frame 1 and the reference of the same frame (its surfaces lit by the GPU with the shadow
    // map the GPU's frame 1 wrote): per channel the blocks' mean relative difference below
    // `maxBlockDifference` and the bias below kMaxBias.
    void expectNearReference(const std::string& name, double maxBlockDifference) {
        const demo::Scene scene = load(name);
        auto r = renderer();
        ASSERT_TRUE(r);
        demo::ImageF gpu, reference;
        std::string error;
        ASSERT_TRUE(r->render(scene, gpu, error)) << error;
        const auto start = std::chrono::steady_clock::now();
        ASSERT_TRUE(r->renderReference(scene, reference, error, kAtmosphereReferenceSteps)) << error;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ASSERT_EQ(gpu.rgba.size(), reference.rgba.size());
        // Blocks of 8×6 pixels: what the eye sees, the jitter's one-frame noise averaged out.
        const ReferenceDifference d = referenceDifference(gpu, reference);
        std::printf("[ clouds ] %s: GPU vs reference, mean relative difference %s; reference %.1f s\n",
                    name.c_str(), describe(d).c_str(), seconds);
        ASSERT_TRUE(d.finite) << name;
        for (size_t c = 0; c < 3; ++c) {
            ASSERT_GT(d.referenceSum[c], 0.0);
            EXPECT_LT(d.blocks[c], maxBlockDifference) << name << " channel " << c;
            EXPECT_LT(std::abs(d.bias[c]), kMaxBias) << name << " channel " << c;
        }
    }
};

// The GPU's mean luminance over the clouds' pixels against the path-traced truth's (docs/effects/clouds.md,
// "Against the path tracer"), at 48×27 with 64 paths a pixel (the mean's own standard error is printed).
class CloudsScenesTruth : public CloudsScenes {
protected:
    static constexpr uint32_t kTruthWidth = 48, kTruthHeight = 27;

    static double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

    void expectNearTruth(const std::string& name, double tolerance) {
        demo::Scene scene = load(name);
        // No cloud shadow on the ground: the pixels the clouds change are then the clouds' own.
        scene.clouds.castShadows = false;
        auto r = sceneRenderer(*host, kTruthWidth, kTruthHeight);
        ASSERT_TRUE(r);
        demo::ImageF gpu, sky, truth;
        std::string error;
        ASSERT_TRUE(r->render(scene, gpu, error)) << error;
        demo::Scene clear = scene;
        clear.clouds.enabled = false;
        auto rClear = sceneRenderer(*host, kTruthWidth, kTruthHeight);
        ASSERT_TRUE(rClear && rClear->render(clear, sky, error)) << error;
        demo::CloudsPathTracing paths;
        paths.samples = 64;
        const auto start = std::chrono::steady_clock::now();
        ASSERT_TRUE(r->renderReference(scene, truth, error, kAtmosphereReferenceSteps, 1, &paths)) << error;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        double sumGpu = 0.0, sumTruth = 0.0, variance = 0.0;
        size_t n = 0;
        for (size_t p = 0; p < size_t(kTruthWidth) * kTruthHeight; ++p) {
            const double yg = luminance(&gpu.rgba[p * 4]), ys = luminance(&sky.rgba[p * 4]);
            if (!(std::abs(yg - ys) > 0.01 * ys)) continue;
            sumGpu += yg;
            sumTruth += luminance(&truth.rgba[p * 4]);
            const double e = luminance(&paths.standardError[p * 4]);
            variance += e * e;
            ++n;
        }
        ASSERT_GT(n, 50u) << name;
        const double bias = sumGpu / sumTruth - 1.0, meanError = std::sqrt(variance) / sumTruth;
        std::printf(
            "[ clouds ] %s: GPU vs path-traced truth over %zu cloud pixels: mean luminance %+.2f%% "
            "(the truth's standard error %.2f%%); truth %.1f s\n",
            name.c_str(), n, 100.0 * bias, 100.0 * meanError, seconds);
        EXPECT_LT(std::abs(bias), tolerance + 3.0 * meanError) << name;
    }
};

TEST_F(CloudsScenesTruth, NoonSceneIsNearThePathTracer) {
    expectNearTruth("clouds_noon", 0.15);
}

TEST_F(CloudsScenesTruth, SunsetSceneIsNearThePathTracer) {
    expectNearTruth("clouds_sunset", 0.15);
}

TEST_F(CloudsScenesTruth, AboveSceneIsNearThePathTracer) {
    expectNearTruth("clouds_above", 0.15);
}

TEST_F(CloudsScenes, NoonSceneMatchesGolden) {
    expectSceneMatchesGolden("clouds_noon");
}

TEST_F(CloudsScenes, SunsetSceneMatchesGolden) {
    expectSceneMatchesGolden("clouds_sunset");
}

TEST_F(CloudsScenes, AboveSceneMatchesGolden) {
    expectSceneMatchesGolden("clouds_above");
}

// Measured (blocks, R G B): noon 2.4 1.6 1.0%, sunset 15.5 8.0 1.8% (the low sun's bright edges in one
// jittered half-resolution frame, two frames into the accumulation), above 4.2 3.0 2.0%.
TEST_F(CloudsScenes, NoonSceneMatchesReference) {
    expectNearReference("clouds_noon", 0.07);
}

TEST_F(CloudsScenes, SunsetSceneMatchesReference) {
    expectNearReference("clouds_sunset", 0.25);
}

TEST_F(CloudsScenes, AboveSceneMatchesReference) {
    expectNearReference("clouds_above", 0.07);
}

}  // namespace
}  // namespace test
