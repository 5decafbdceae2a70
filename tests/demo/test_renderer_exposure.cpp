// The ends of camera.ev100's range (docs/scene-format.md): the demo meters its pre-exposure from what the
// camera sees (host/metering.h), so that the physical EXR of a lit froxel scene and of the sky at ev100
// -30 and +30 equals the same frame at ev100 15 (half precision's 2^-11 on pre-exposed values), and the
// GPU frame and its reference agree at the ends as they do at 15.
#include "gpu_test.h"
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace test {
namespace {

const std::string kScenesDir = POSTFX_DEMO_SCENES_DIR;
constexpr uint32_t kWidth = 32, kHeight = 18;

class DemoRendererExposure : public GpuTest {
protected:
    // The scene at `ev100`: its GPU frame, its reference (when `reference`), the pre-exposure used. One
    // renderer for all (every render() starts anew at frame 0, a camera cut).
    demo::ImageF render(demo::Scene scene, float ev100, bool reference, float* preExposure = nullptr) {
        scene.camera.ev100 = ev100;
        std::string error;
        if (!renderer) {
            demo::RenderOptions o;
            o.width = kWidth;
            o.height = kHeight;
            o.shadowMapSize = 256;
            renderer = demo::Renderer::create(*host, o, error);
        }
        EXPECT_TRUE(renderer) << error;
        demo::ImageF image;
        if (!renderer) return image;
        if (reference)
            EXPECT_TRUE(renderer->renderReference(scene, image, error, 256)) << error;
        else
            EXPECT_TRUE(renderer->render(scene, image, error)) << error;
        if (preExposure) *preExposure = renderer->preExposure();
        return image;
    }

    std::unique_ptr<demo::Renderer> renderer;
};

// Mean over RGB of |a - b| / max(|b|, 1e-3 · b's mean).
double meanRelative(const demo::ImageF& a, const demo::ImageF& b) {
    if (a.rgba.size() != b.rgba.size() || a.rgba.empty()) return 1e30;
    double mean = 0.0;
    for (float v : b.rgba)
        mean += std::abs(v);
    mean /= double(b.rgba.size());
    double sum = 0.0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        if (!std::isfinite(a.rgba[i])) return 1e30;
        sum += std::abs(double(a.rgba[i]) - b.rgba[i]) / std::max(std::abs(double(b.rgba[i])), 1e-3 * mean);
    }
    return sum / double(a.rgba.size() / 4 * 3);
}

}  // namespace

TEST_F(DemoRendererExposure, EndsOfTheRangeKeepThePhysicalImage) {
    for (const char* file : {"sky_noon.json", "froxel_lights.json"}) {
        demo::Scene scene;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/" + file, scene, error)) << error;
        test::smallScatteringOrders(scene.atmosphere);
        float p15 = 0.0f;
        const demo::ImageF gpu15 = render(scene, 15.0f, false, &p15);
        const demo::ImageF ref15 = render(scene, 15.0f, true);
        const double agree15 = meanRelative(gpu15, ref15);
        for (float ev : {-30.0f, 30.0f}) {
            float p = 0.0f;
            const demo::ImageF gpu = render(scene, ev, false, &p);
            const demo::ImageF ref = render(scene, ev, true);
            const double same = meanRelative(gpu, gpu15), agree = meanRelative(gpu, ref);
            std::printf(
                "[ exposure ] %s at ev100 %g: pre-exposure 2^%d (at 15: 2^%d); mean relative difference "
                "from ev100 15 %.3g; GPU against reference %.3g (at 15: %.3g)\n",
                file, double(ev), int(std::lround(std::log2(p))), int(std::lround(std::log2(p15))), same,
                agree, agree15);
            // Each image within half's 2^-11 of the radiance on its pre-exposed values (a power of two
            // moves values, it rounds nothing): 2^-10 apart.
            EXPECT_LE(same, 0x1p-10) << file << " at ev100 " << ev;
            EXPECT_LE(agree, agree15 * 1.05 + 0x1p-11) << file << " at ev100 " << ev;
        }
    }
}

// The window's auto-exposure (RenderOptions::meterInterval): frames recorded one after another as a window
// records them, each metered once its slot comes round, reach the pre-exposure render() meters for frame 0,
// from the camera's exposure at the ends of the range (where it clips everything or shows nothing).
TEST_F(DemoRendererExposure, WindowMeteringReachesWhatRenderMeters) {
    for (const auto& [file, ev] : {std::pair{"sky_noon.json", -30.0f}, std::pair{"sky_noon.json", 30.0f},
                                   std::pair{"froxel_lights.json", -30.0f}}) {
        demo::Scene scene;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/" + file, scene, error)) << error;
        test::smallScatteringOrders(scene.atmosphere);
        {
            float metered = 0.0f;
            render(scene, ev, false, &metered);
            demo::RenderOptions o;
            o.width = kWidth;
            o.height = kHeight;
            o.shadowMapSize = 256;
            o.meterInterval = 1;
            auto window = demo::Renderer::create(*host, o, error);
            ASSERT_TRUE(window) << error;
            demo::Scene frameScene = scene;
            frameScene.camera.ev100 = ev;
            ASSERT_TRUE(window->setScene(frameScene, error)) << error;
            std::vector<float> chosen;
            for (uint64_t f = 0; f < 10; ++f) {
                bool recorded = false;
                ASSERT_TRUE(host->submitAndWait(
                    [&](VkCommandBuffer cmd) { recorded = window->recordFrame(cmd, frameScene, f, error); },
                    error))
                    << error;
                ASSERT_TRUE(recorded) << error;
                chosen.push_back(window->preExposure());
            }
            std::printf(
                "[ exposure ] window metering, %s at ev100 %g: frame 0 at 2^%d, frame 9 at 2^%d "
                "(render() meters 2^%d)\n",
                file, double(ev), int(std::lround(std::log2(chosen.front()))),
                int(std::lround(std::log2(chosen.back()))), int(std::lround(std::log2(metered))));
            // Each decision waits for its frame (two slots): after a few, it stands.
            EXPECT_EQ(chosen[7], metered) << file << " at ev100 " << ev;
            EXPECT_EQ(chosen.back(), metered) << file << " at ev100 " << ev;
        }
    }
}

}  // namespace test
