// The showcase (demo/scenes/showcase.json: the atmosphere's sky, a cumulus layer, froxel fog with the sun's
// shadow shafts through a colonnade and four local lights, the camera flying), every effect in one frame
// through the demo host at 96×54, frame 1 (the surfaces read the clouds' shadow map one frame late):
//   - against its golden image (tests/frame/golden/showcase.exr; tolerance in golden.h);
//   - against the demo's combined CPU reference of the same frame (Renderer::renderReference: the
//     atmosphere's reference (a), then renderClouds, then renderFroxelFog, composited in postfx's order
//     over the GPU's lit surfaces): per channel the mean relative difference over 8×6-pixel blocks and the
//     bias, bounded (tests/common/scene_reference.h).
#include "golden.h"
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
constexpr uint32_t kAtmosphereReferenceSteps = 256;

class FrameShowcase : public GpuTest {
protected:
    demo::Scene load() {
        demo::Scene scene = loadDemoScene("showcase");
        EXPECT_TRUE(scene.atmosphere.enabled && scene.clouds.enabled && scene.froxelFog.enabled);
        EXPECT_FALSE(scene.lights.empty());
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer() { return sceneRenderer(*host, kWidth, kHeight); }
};

}  // namespace

TEST_F(FrameShowcase, MatchesGolden) {
    auto r = renderer();
    ASSERT_TRUE(r);
    demo::ImageF image;
    std::string error;
    ASSERT_TRUE(r->render(load(), image, error)) << error;
    expectMatchesGolden(image, "frame", "showcase");
}

// Measured (lavapipe, R G B): 8×6 blocks 0.5% 0.5% 0.3%, bias -0.20% -0.13% -0.03% (per pixel 1.5% 1.4%
// 0.9%; the references' fog and surfaces under the clouds' shadow map). Bounds: blocks within 3% per
// channel, bias within 2%.
TEST_F(FrameShowcase, MatchesTheCombinedReference) {
    const demo::Scene scene = load();
    auto r = renderer();
    ASSERT_TRUE(r);
    demo::ImageF gpu, reference;
    std::string error;
    ASSERT_TRUE(r->render(scene, gpu, error)) << error;
    const auto start = std::chrono::steady_clock::now();
    ASSERT_TRUE(r->renderReference(scene, reference, error, kAtmosphereReferenceSteps)) << error;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(gpu.rgba.size(), reference.rgba.size());
    const ReferenceDifference d = referenceDifference(gpu, reference);
    std::printf(
        "[ frame ] showcase: GPU vs the combined reference, mean relative difference %s; reference "
        "%.1f s\n",
        describe(d).c_str(), seconds);
    ASSERT_TRUE(d.finite);
    for (size_t c = 0; c < 3; ++c) {
        ASSERT_GT(d.referenceSum[c], 0.0);
        EXPECT_LT(d.blocks[c], 0.03) << "channel " << c;
        EXPECT_LT(std::abs(d.bias[c]), 0.02) << "channel " << c;
    }
}

}  // namespace test
