// Empty-space skipping (docs/effects/fog.md, "Empty space") on the valley scene: the skipped march against
// the un-skipped one and against the double-precision reference that skips the same way.
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <cstdio>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class FogEmptySpaceTest : public GpuTest {
protected:
    demo::ImageF render(const demo::Scene& scene, bool reference = false) {
        std::string error;
        demo::RenderOptions options;
        options.width = 64;
        options.height = 36;
        options.shadowMapSize = 256;
        auto renderer = demo::Renderer::create(*host, options, error);
        EXPECT_TRUE(renderer) << error;
        demo::ImageF image;
        if (!renderer) return image;
        if (reference) {
            EXPECT_TRUE(renderer->renderReference(scene, image, error, scene.fog.steps)) << error;
        } else {
            EXPECT_TRUE(renderer->render(scene, image, error)) << error;
        }
        return image;
    }
    demo::Scene valley(uint32_t steps) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/fog_valley.json", scene, error)) << error;
        scene.fog.steps = steps;
        scene.fog.jitter = false;
        scene.fog.transmittanceCutoff = 0.0f;
        return scene;
    }
};

// The skipped march against the un-skipped one, both converged (256 steps): the same image within the
// march's own error; and the skipped march against the double-precision reference that skips the same way
// (same step count, so the same samples).
TEST_F(FogEmptySpaceTest, SkippingLeavesTheValleyImageUnchanged) {
    demo::Scene skipped = valley(256);
    demo::Scene full = skipped;
    full.fog.skipEmptySpace = false;
    const demo::ImageF a = render(skipped), b = render(full);
    const ImageStats d = compareImages(a.rgba, b.rgba, a.width, a.height, 0.01, 1.0);
    std::printf("[ empty space ] skipped vs un-skipped, 256 steps: %s\n", d.summary().c_str());
    EXPECT_LT(d.relativeRmse, 2e-3);

    demo::Scene few = valley(16);
    const demo::ImageF gpu16 = render(few), ref16 = render(few, true);
    const ImageStats r = compareImages(gpu16.rgba, ref16.rgba, gpu16.width, gpu16.height, 0.01, 1.0);
    std::printf("[ empty space ] GPU vs reference, 16 steps: relative RMSE %.3g%%\n", 100.0 * r.relativeRmse);
    EXPECT_LT(r.relativeRmse, 2e-3);
    // At 16 steps the skipped march is much nearer the converged image than the un-skipped one.
    demo::Scene fewFull = few;
    fewFull.fog.skipEmptySpace = false;
    const double skippedError = compareImages(gpu16.rgba, a.rgba, a.width, a.height, 0.01, 1.0).relativeRmse;
    const double fullError =
        compareImages(render(fewFull).rgba, a.rgba, a.width, a.height, 0.01, 1.0).relativeRmse;
    std::printf("[ empty space ] 16 steps against converged: skipped %.3g%%, un-skipped %.3g%%\n",
                100.0 * skippedError, 100.0 * fullError);
    EXPECT_LT(skippedError, fullError);
}

}  // namespace
}  // namespace test
