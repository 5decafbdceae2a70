// Fog under the clouds' shadow (tests/frame/scenes/fog_under_clouds.json: the ray-marched fog of
// demo/scenes/fog_default.json with its generated noise, 128³ as the clouds' base noise, so that both
// effects share one image; a cloud layer of coverage 0.5 at 1500–3000 m casting its shadow over the whole
// view; the sun 21° up), through the demo host at 96×54, frame 1 (the surfaces read the clouds' shadow map
// one frame late), against the demo's combined CPU reference of the same frame (Renderer::renderReference:
// its fog reads the clouds' shadow map read back from the GPU, its surfaces are lit under it) within the
// whole frame's bounds (FrameShowcase's: per channel the mean relative difference over 8×6-pixel blocks
// within 3%, the bias within 2%; tests/common/scene_reference.h):
//   - the ray-marched fog sharing its noise with the clouds, without the clouds' shadow: the reference reads
//     the shared noise by the fog's name;
//   - the ray-marched fog (noise 64³: not shared) and the froxel fog (the same medium) under the shadow;
//   - the scene as it is: shared noise and the shadow.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"
#include "scene_reference.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;
constexpr uint32_t kReferenceSteps = 1024;  // the fogs' midpoint steps per pixel

class FrameCloudShadow : public GpuTest {
protected:
    static demo::Scene load() {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(
            std::string(POSTFX_SOURCE_DIR) + "/tests/frame/scenes/fog_under_clouds.json", scene, error))
            << error;
        EXPECT_TRUE(scene.fog.enabled && scene.fog.noise.enabled && scene.clouds.enabled &&
                    scene.clouds.castShadows);
        return scene;
    }
    // The froxel fog over the scene's medium instead of the ray-marched fog.
    static demo::Scene froxel(demo::Scene scene) {
        static_cast<postfx::FogMedium&>(scene.froxelFog) = scene.fog;
        scene.froxelFog.enabled = true;
        scene.froxelFog.grid = {48, 27, 64};
        scene.fog.enabled = false;
        return scene;
    }

    // GPU frame 1 against the reference: blocks within 3% and bias within 2% per channel.
    void expectNearReference(const demo::Scene& scene, const char* what) {
        auto r = sceneRenderer(*host, kWidth, kHeight);
        ASSERT_TRUE(r);
        demo::ImageF gpu, reference;
        std::string error;
        ASSERT_TRUE(r->render(scene, gpu, error)) << error;
        const auto start = std::chrono::steady_clock::now();
        ASSERT_TRUE(r->renderReference(scene, reference, error, kReferenceSteps)) << error;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ASSERT_EQ(gpu.rgba.size(), reference.rgba.size());
        const ReferenceDifference d = referenceDifference(gpu, reference);
        std::printf(
            "[ frame ] %s: GPU vs the combined reference, mean relative difference %s; reference %.1f s\n",
            what, describe(d).c_str(), seconds);
        ASSERT_TRUE(d.finite);
        for (size_t c = 0; c < 3; ++c) {
            ASSERT_GT(d.referenceSum[c], 0.0);
            EXPECT_LT(d.blocks[c], 0.03) << what << " channel " << c;
            EXPECT_LT(std::abs(d.bias[c]), 0.02) << what << " channel " << c;
        }
    }
};

}  // namespace

TEST_F(FrameCloudShadow, FogSharingTheCloudsNoiseMatchesTheReference) {
    demo::Scene scene = load();
    scene.clouds.castShadows = false;
    expectNearReference(scene, "fog sharing the clouds' noise, no cloud shadow");
}

TEST_F(FrameCloudShadow, FogUnderTheShadowMatchesTheReference) {
    demo::Scene scene = load();
    scene.fog.noise.textureSize = 64;
    expectNearReference(scene, "fog under the cloud shadow");
}

TEST_F(FrameCloudShadow, FroxelFogUnderTheShadowMatchesTheReference) {
    demo::Scene scene = load();
    scene.fog.noise.textureSize = 64;
    expectNearReference(froxel(scene), "froxel fog under the cloud shadow");
}

TEST_F(FrameCloudShadow, SceneMatchesTheReference) {
    expectNearReference(load(), "fog sharing the clouds' noise under their shadow");
}

}  // namespace test
