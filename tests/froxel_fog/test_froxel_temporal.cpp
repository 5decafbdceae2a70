// The froxel fog's temporal accumulation (docs/effects/froxel-fog.md#temporal) on the device: a still
// camera converges toward the reference; history exists only with temporal on.
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <cstdio>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class FroxelTemporalTest : public GpuTest {
protected:
    demo::Scene load(const std::string& name) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + name, scene, error)) << error;
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer(uint32_t frames) {
        demo::RenderOptions o;
        o.width = 48;
        o.height = 27;
        o.shadowMapSize = 1024;
        o.frames = frames;
        o.fixedTimeSeconds = 0.0;
        std::string error;
        auto r = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(r) << error;
        return r;
    }
    double error(demo::Renderer& r, const demo::Scene& scene, const demo::ImageF& reference) {
        demo::ImageF image;
        std::string message;
        EXPECT_TRUE(r.render(scene, image, message)) << message;
        const ImageStats s = compareImages(image.rgba, reference.rgba, image.width, image.height, 0.05, 1.0);
        EXPECT_EQ(s.nonFinite, 0u);
        return s.relativeRmse;
    }
};

TEST_F(FroxelTemporalTest, StillCameraConvergesTowardTheReference) {
    demo::Scene scene = load("froxel_default.json");
    scene.froxelFog.grid = {48, 27, 64};
    scene.froxelFog.tileSizePx = 0;
    auto one = renderer(1);
    auto many = renderer(32);
    ASSERT_TRUE(one && many);
    demo::ImageF reference;
    std::string message;
    ASSERT_TRUE(one->renderReference(scene, reference, message, 1024)) << message;
    scene.froxelFog.temporal.enabled = false;
    const double single = error(*one, scene, reference);
    const double still = error(*many, scene, reference);
    scene.froxelFog.temporal.enabled = true;
    scene.froxelFog.temporal.blendWeight = 0.1f;
    const double accumulated = error(*many, scene, reference);
    std::printf(
        "[ froxel_fog ] temporal, still camera: 1 frame %.3g%%, frame 32 alone %.3g%%, 32 frames "
        "accumulated %.3g%%\n",
        single * 100, still * 100, accumulated * 100);
    // Measured on lavapipe: 1.02% (the mean of 16 frames without temporal: 0.77%; single frames 1.2 to
    // 2.8%). Blending σt linearly instead of the slices' opacity gave 3.2% (froxel-fog.md#temporal).
    EXPECT_LT(accumulated, 1.5e-2);
    EXPECT_LT(accumulated, 0.6 * still);
}

}  // namespace
}  // namespace test
