// The demo's sky scenes through the demo host (the atmosphere's LUTs, sky, sun disk and aerial
// perspective, the surfaces lit through the atmosphere with the sky's ambient) against golden images in
// tests/atmosphere/golden/ (tolerance in golden.h): demo/scenes/sky_noon.json, sky_sunset.json (the sun
// 2° above the horizon) and sky_space.json (the camera 100 km up), 160×90 as the other scenes' goldens.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <string>

namespace test {
namespace {

class AtmosphereScenes : public GpuTest {
protected:
    void expectSceneMatchesGolden(const std::string& name) {
        demo::Scene scene;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(std::string(POSTFX_SOURCE_DIR) + "/demo/scenes/" + name + ".json",
                                        scene, error))
            << error;
        ASSERT_TRUE(scene.atmosphere.enabled) << name;
        demo::RenderOptions o;
        o.width = 160;
        o.height = 90;
        o.shadowMapSize = 512;
        auto renderer = demo::Renderer::create(*host, o, error);
        ASSERT_TRUE(renderer) << error;
        demo::ImageF image;
        ASSERT_TRUE(renderer->render(scene, image, error)) << error;
        expectMatchesGolden(image, "atmosphere", name);
    }
};

TEST_F(AtmosphereScenes, NoonSceneMatchesGolden) {
    expectSceneMatchesGolden("sky_noon");
}

TEST_F(AtmosphereScenes, SunsetSceneMatchesGolden) {
    expectSceneMatchesGolden("sky_sunset");
}

TEST_F(AtmosphereScenes, SpaceSceneMatchesGolden) {
    expectSceneMatchesGolden("sky_space");
}

}  // namespace
}  // namespace test
