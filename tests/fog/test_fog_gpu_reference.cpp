// The GPU fog against the double-precision CPU reference on the demo's fog scenes, depth conventions
// agreeing with fog, and the default fog scene against its golden image.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <ostream>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

struct ReferenceCase {
    const char* scene;
    double maxRelativeRmse;   // GPU with the scene's own settings (one frame, jittered) vs reference
    double maxConvergedRmse;  // GPU at 512 steps without jitter vs reference: the same model
};

void PrintTo(const ReferenceCase& c, std::ostream* os) {
    *os << c.scene << " (relative RMSE below " << c.maxRelativeRmse << ", converged below "
        << c.maxConvergedRmse << ")";
}

class FogSceneTest : public GpuTest {
protected:
    demo::Scene load(const std::string& name) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + name, scene, error)) << error;
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer(demo::RenderOptions options) {
        std::string error;
        auto r = demo::Renderer::create(*host, options, error);
        EXPECT_TRUE(r) << error;
        return r;
    }
    static demo::RenderOptions small() {
        demo::RenderOptions o;
        o.width = 64;
        o.height = 36;
        o.shadowMapSize = 1024;
        return o;
    }
};

class FogReferenceTest : public FogSceneTest, public ::testing::WithParamInterface<ReferenceCase> {};

TEST_P(FogReferenceTest, GpuMatchesReference) {
    const ReferenceCase& c = GetParam();
    const demo::Scene scene = load(c.scene);
    ASSERT_TRUE(scene.fog.enabled);
    auto r = renderer(small());
    ASSERT_TRUE(r);
    demo::ImageF gpu, reference, unfogged;
    std::string error;
    ASSERT_TRUE(r->render(scene, gpu, error)) << error;
    ASSERT_TRUE(r->renderReference(scene, reference, error, 4096)) << error;
    demo::Scene clear = scene;
    clear.fog.enabled = false;
    ASSERT_TRUE(r->render(clear, unfogged, error)) << error;

    demo::Scene fine = scene;
    fine.fog.steps = 512;
    fine.fog.jitter = false;
    demo::ImageF converged;
    ASSERT_TRUE(r->render(fine, converged, error)) << error;

    const ImageStats stats = compareImages(gpu.rgba, reference.rgba, gpu.width, gpu.height, 0.05, 1.0);
    const ImageStats model = compareImages(converged.rgba, reference.rgba, gpu.width, gpu.height, 0.05, 1.0);
    const ImageStats fogEffect =
        compareImages(unfogged.rgba, reference.rgba, gpu.width, gpu.height, 0.05, 1.0);
    std::printf("[ fog ] %s: GPU (%u steps) vs reference %s\n", c.scene, scene.fog.steps,
                stats.summary().c_str());
    std::printf("[ fog ] %s: GPU (512 steps, no jitter) vs reference %s\n", c.scene, model.summary().c_str());
    std::printf("[ fog ] %s: un-fogged vs reference: relative RMSE %.3g%%\n", c.scene,
                fogEffect.relativeRmse * 100);
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_LT(stats.relativeRmse, c.maxRelativeRmse) << stats.summary();
    EXPECT_LT(model.relativeRmse, c.maxConvergedRmse) << model.summary();
    // The comparison means something: the fog changes the image far more than the GPU's error.
    EXPECT_GT(fogEffect.relativeRmse, 5.0 * stats.relativeRmse);
}

// Thresholds: measured on lavapipe at 64x36 (docs/effects/fog.md, "Accuracy") with about 2x margin.
// The converged floor (~0.04%) is the half-float output; shadow-map edges converge more slowly.
INSTANTIATE_TEST_SUITE_P(Scenes, FogReferenceTest,
                         ::testing::Values(ReferenceCase{"fog_homogeneous.json", 0.001, 0.001},
                                           ReferenceCase{"fog_height.json", 0.05, 0.001},
                                           ReferenceCase{"fog_noise.json", 0.04, 0.002},
                                           ReferenceCase{"fog_shadowed.json", 0.06, 0.005}),
                         [](const auto& info) {
                             std::string name = info.param.scene;
                             name = name.substr(4, name.find('.') - 4);  // fog_height.json -> height
                             return name;
                         });

// Resolution scale: the reduced march and its depth-aware upsample against the CPU reference doing the
// same (tight: the same model), and against the full-resolution reference (what the scale costs).
struct ScaleCase {
    const char* scene;
    float scale;
    double maxUpsampledRmse;  // GPU at `scale` vs the full-resolution reference, 512 steps, no jitter
    double maxFractionOff;    // ... of pixels off by more than 5% there
};

void PrintTo(const ScaleCase& c, std::ostream* os) {
    *os << c.scene << " at scale " << c.scale << " (relative RMSE below " << c.maxUpsampledRmse
        << ", fraction off below " << c.maxFractionOff << ")";
}

class FogResolutionScaleTest : public FogSceneTest, public ::testing::WithParamInterface<ScaleCase> {};

TEST_P(FogResolutionScaleTest, MatchesReferenceAtTheSameScale) {
    const ScaleCase& c = GetParam();
    demo::Scene scene = load(c.scene);
    scene.fog.steps = 512;
    scene.fog.jitter = false;
    demo::RenderOptions o = small();
    o.width = 96;
    o.height = 54;
    auto r = renderer(o);
    ASSERT_TRUE(r);
    std::string error;
    demo::ImageF full;
    ASSERT_TRUE(r->renderReference(scene, full, error, 1024)) << error;
    scene.fog.resolutionScale = c.scale;
    demo::ImageF gpu, reference;
    ASSERT_TRUE(r->render(scene, gpu, error)) << error;
    ASSERT_TRUE(r->renderReference(scene, reference, error, 1024)) << error;

    const ImageStats same = compareImages(gpu.rgba, reference.rgba, gpu.width, gpu.height, 0.01, 1.0);
    const ImageStats cost = compareImages(gpu.rgba, full.rgba, gpu.width, gpu.height, 0.05, 1.0);
    std::printf("[ fog ] %s at scale %g: GPU vs reference at that scale %s\n", c.scene, c.scale,
                same.summary().c_str());
    std::printf("[ fog ] %s at scale %g: GPU vs full-resolution reference %s\n", c.scene, c.scale,
                cost.summary().c_str());
    EXPECT_EQ(same.nonFinite, 0u);
    // Float against double may pick another texel where a distance sits on the tolerance: a few pixels.
    EXPECT_LT(same.relativeRmse, 0.002) << same.summary();
    EXPECT_LT(same.fractionOff, 0.01) << same.summary();
    EXPECT_LT(cost.relativeRmse, c.maxUpsampledRmse) << cost.summary();
    EXPECT_LT(cost.fractionOff, c.maxFractionOff) << cost.summary();
}

// Thresholds: measured on lavapipe at 96x54 with about 2x margin (edges are many pixels at this size).
INSTANTIATE_TEST_SUITE_P(Scales, FogResolutionScaleTest,
                         ::testing::Values(ScaleCase{"fog_default.json", 0.5f, 0.05, 0.1},
                                           ScaleCase{"fog_shadowed.json", 0.5f, 0.08, 0.25},
                                           ScaleCase{"fog_default.json", 0.25f, 0.1, 0.2},
                                           ScaleCase{"fog_noise.json", 0.7f, 0.05, 0.1}),
                         [](const auto& info) {
                             std::string name = info.param.scene;
                             name = name.substr(4, name.find('.') - 4);
                             return name + "_" + std::to_string(int(info.param.scale * 100));
                         });

class FogImageTest : public FogSceneTest {};

// Standard and reversed Z, finite and infinite far plane: the same fogged image.
TEST_F(FogImageTest, DepthConventionsGiveTheSameImage) {
    const demo::Scene scene = load("fog_default.json");
    demo::RenderOptions reversed = small();
    demo::ImageF a;
    std::string error;
    ASSERT_TRUE(renderer(reversed)->render(scene, a, error)) << error;
    demo::RenderOptions standard = reversed;
    standard.reversedZ = false;
    demo::RenderOptions infinite = reversed;
    infinite.infiniteFar = true;
    for (const demo::RenderOptions& o : {standard, infinite}) {
        demo::ImageF b;
        ASSERT_TRUE(renderer(o)->render(scene, b, error)) << error;
        const ImageStats stats = compareImages(b.rgba, a.rgba, a.width, a.height, 0.02, 1.0);
        EXPECT_LT(stats.relativeRmse, 0.01) << stats.summary();
        EXPECT_LT(stats.fractionOff, 0.01) << stats.summary();
    }
}

TEST_F(FogImageTest, DefaultFogSceneMatchesGolden) {
    demo::RenderOptions o = small();
    o.width = 160;
    o.height = 90;
    demo::ImageF image;
    std::string error;
    ASSERT_TRUE(renderer(o)->render(load("fog_default.json"), image, error)) << error;
    expectMatchesGolden(image, "fog", "fog_default");
}

}  // namespace
}  // namespace test
