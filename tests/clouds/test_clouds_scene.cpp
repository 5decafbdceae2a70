// Scene files' effects.clouds (demo/scene/clouds_json.cpp): every key read and written back exactly, and
// bad values rejected with a message naming the key path.
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using json = nlohmann::json;

json base() {
    return json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [1000, 1000, 1000], "shadows": true},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]}]
    })");
}

TEST(CloudsScene, EveryKeyRoundTrips) {
    json j = base();
    j["effects"]["clouds"] = json::parse(R"({
      "shape": "box", "bottom_height": 800, "top_height": 3000,
      "box": {"center": [10.5, 2000, -3], "half_size": [1000, 400, 2000], "yaw_deg": 30, "pitch_deg": -5},
      "coverage": 0.7, "cloud_type": 0.8, "density": 0.03, "albedo": 0.95,
      "anisotropy_forward": 0.7, "anisotropy_back": -0.2, "lobe_mix": 0.3,
      "multiple_scattering": {"model": "octaves", "octaves": 3, "attenuation": 0.6, "contribution": 0.4,
                              "eccentricity": 0.3},
      "steps": 96, "light_steps": 8, "light_distance": 5000, "max_distance": 80000, "wind": [5, 0, 2],
      "jitter": false, "quality": "custom", "resolution_scale": 0.25,
      "temporal": {"enabled": false, "blend_weight": 0.2}, "cast_shadows": false,
      "shadow_map": {"size": 1024, "extent": 30000},
      "noise": {"base_size": 64, "detail_size": 16, "seed": 9, "tiling": 9000, "detail_strength": 0.5}
    })");
    demo::Scene scene;
    std::string error;
    ASSERT_TRUE(demo::parseScene(j.dump(), scene, error)) << error;
    const postfx::CloudSettings& s = scene.clouds;
    EXPECT_TRUE(s.enabled);
    EXPECT_EQ(s.shape, postfx::CloudShape::Box);
    EXPECT_EQ(s.box.center.x, 10.5);
    EXPECT_FLOAT_EQ(s.box.yawDeg, 30.0f);
    EXPECT_EQ(s.multipleScattering.model, postfx::CloudScatteringModel::Octaves);
    EXPECT_EQ(s.multipleScattering.octaves, 3u);
    EXPECT_FLOAT_EQ(s.multipleScattering.contribution, 0.4f);
    EXPECT_EQ(s.steps, 96u);
    EXPECT_FALSE(s.jitter);
    EXPECT_EQ(s.quality, postfx::CloudQuality::Custom);
    EXPECT_FLOAT_EQ(s.resolutionScale, 0.25f);
    EXPECT_FALSE(s.temporal.enabled);
    EXPECT_FLOAT_EQ(s.temporal.blendWeight, 0.2f);
    EXPECT_FALSE(s.castShadows);
    EXPECT_EQ(s.shadowMap.size, 1024u);
    EXPECT_FLOAT_EQ(s.shadowMap.extent, 30000.0f);
    EXPECT_TRUE(s.noise.enabled);
    EXPECT_EQ(s.noise.baseSize, 64u);
    EXPECT_FLOAT_EQ(s.noise.detailStrength, 0.5f);
    const json out = demo::sceneToJson(scene);
    demo::Scene again;
    ASSERT_TRUE(demo::parseScene(out.dump(), again, error)) << error;
    EXPECT_EQ(demo::sceneToJson(again), out);
    EXPECT_EQ(out["effects"]["clouds"]["box"]["center"], json::parse("[10.5, 2000, -3]"));
}

TEST(CloudsScene, BadValuesNameTheirKeyPath) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"top_height": 1000})", "effects.clouds.top_height: 1000 must be greater than bottomHeight"},
        {R"({"shape": "sphere"})", "effects.clouds.shape: expected \"layer\" or \"box\""},
        {R"({"noise": {"base_size": 100}})", "effects.clouds.noise.base_size: 100 is not a power of two"},
        {R"({"multiple_scattering": {"contribution": 0.9}})",
         "effects.clouds.multiple_scattering.contribution"},
        {R"({"multiple_scattering": {"model": "diffusion"}})",
         "effects.clouds.multiple_scattering.model: expected \"slab\" or \"octaves\""},
        {R"({"box": {"yaw": 3}})", "effects.clouds.box.yaw: unknown key"},
        {R"({"coverage": 2})", "effects.clouds.coverage: 2 is outside [0, 1]"},
        {R"({"cast": true})", "effects.clouds.cast: unknown key"},
        {R"({"shadow_map": {"size": 8}})", "effects.clouds.shadow_map.size: 8 is outside [16, 2048]"},
        {R"({"shadow_map": {"extent": -1}})", "effects.clouds.shadow_map.extent"},
        {R"({"resolution_scale": 0.1})", "effects.clouds.resolution_scale: 0.1 is outside [0.25, 1]"},
        {R"({"quality": "epic"})", "effects.clouds.quality: expected"},
        // keys that the chosen shape, model or quality ignores
        {R"({"box": {"center": [0, 2000, 0]}})",
         "effects.clouds.box.center: ignored with shape \"layer\" (used with \"box\")"},
        {R"({"multiple_scattering": {"octaves": 4}})",
         "effects.clouds.multiple_scattering.octaves: ignored with multiple_scattering.model \"slab\" (used "
         "with \"octaves\")"},
        {R"({"quality": "high", "light_steps": 12})",
         "effects.clouds.light_steps: ignored with quality \"high\" (used with \"custom\")"},
    };
    for (const auto& [clouds, message] : cases) {
        json j = base();
        j["effects"]["clouds"] = json::parse(clouds);
        demo::Scene scene;
        std::string error;
        EXPECT_FALSE(demo::parseScene(j.dump(), scene, error)) << clouds;
        EXPECT_EQ(error.rfind(message, 0), 0u) << clouds << " got: " << error;
    }
}

}  // namespace
