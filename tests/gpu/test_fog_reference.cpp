// The GPU fog against the double-precision CPU reference on the demo's fog scenes, depth conventions
// agreeing with fog, and the default fog scene against its golden image.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

struct ReferenceCase {
    const char* scene;
    double maxRelativeRmse;   // GPU with the scene's own settings (one frame, jittered) vs reference
    double maxConvergedRmse;  // GPU at 512 steps without jitter vs reference: the same model
};

class FogReferenceTest : public GpuTest, public ::testing::WithParamInterface<ReferenceCase> {
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

class FogImageTest : public FogReferenceTest {};

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
    expectMatchesGolden(image, "fog_default");
}

}  // namespace
}  // namespace test
