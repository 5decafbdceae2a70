// The froxel fog on the demo's committed scenes through the demo host: the GPU (the scene's own grid,
// one jittered frame) against the CPU reference with its shadow map and noise (froxel_default.json: sun,
// shadows, noise, height fog) and with coloured point and spot lights and fog volumes
// (froxel_lights.json), and the lights scene against its golden image (tolerance in golden.h).
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <cstdio>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class FroxelFogScenes : public GpuTest {
protected:
    demo::Scene load(const std::string& name) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + name, scene, error)) << error;
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer(uint32_t w, uint32_t h) {
        demo::RenderOptions o;
        o.width = w;
        o.height = h;
        o.shadowMapSize = 1024;
        std::string error;
        auto r = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(r) << error;
        return r;
    }
    // GPU against the reference (1024 steps): relative RMSE printed and below `maxRmse`.
    void expectNearReference(const char* name, double maxRmse) {
        const demo::Scene scene = load(name);
        ASSERT_TRUE(scene.froxelFog.enabled);
        auto r = renderer(48, 27);
        ASSERT_TRUE(r);
        demo::ImageF gpu, reference;
        std::string error;
        ASSERT_TRUE(r->render(scene, gpu, error)) << error;
        ASSERT_TRUE(r->renderReference(scene, reference, error, 1024)) << error;
        const ImageStats stats = compareImages(gpu.rgba, reference.rgba, gpu.width, gpu.height, 0.05, 1.0);
        std::printf("[ froxel_fog ] %s: GPU vs reference %s\n", name, stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, maxRmse) << name;
    }
};

TEST_F(FroxelFogScenes, ShadowedNoiseSceneMatchesReference) {
    expectNearReference("froxel_default.json", 0.03);
}

TEST_F(FroxelFogScenes, LightsSceneMatchesReference) {
    expectNearReference("froxel_lights.json", 0.05);
}

TEST_F(FroxelFogScenes, LightsSceneMatchesGolden) {
    const demo::Scene scene = load("froxel_lights.json");
    auto r = renderer(160, 90);
    ASSERT_TRUE(r);
    demo::ImageF image;
    std::string error;
    ASSERT_TRUE(r->render(scene, image, error)) << error;
    expectMatchesGolden(image, "froxel_fog", "froxel_lights_scene");
}

}  // namespace
}  // namespace test
