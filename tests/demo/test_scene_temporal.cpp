// Scene files: `effects.fog.temporal` and `effects.froxel_fog.temporal` (postfx::TemporalSettings, read by
// read for both fogs from their settings tables, demo/scene/settings_json.cpp) -- the library's defaults,
// every key read, round trips, errors naming their key path with postfx's ranges.
#include "scene/json_text.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <postfx/temporal.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

using demo::Scene;
using json = nlohmann::json;

struct Parsed {
    bool ok = false;
    std::string error;
    Scene scene;
};
Parsed parse(const json& j) {
    Parsed p;
    p.ok = demo::parseScene(j.dump(), p.scene, p.error);
    return p;
}

// A scene with effects.<fog> = `settings` ("fog" or "froxel_fog").
json withFog(const char* fog, const json& settings) {
    json j = json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [1000, 1000, 1000], "shadows": true},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]}]
    })");
    j["effects"] = {{fog, settings}};
    return j;
}

const postfx::TemporalSettings& temporalOf(const Scene& s, const std::string& fog) {
    return fog == "fog" ? s.fog.temporal : s.froxelFog.temporal;
}

const char* const kFogs[] = {"fog", "froxel_fog"};

// The library's defaults: off for the ray-marched fog, on at 5% for the froxel fog (postfx/fog.h,
// postfx/froxel_fog.h).
postfx::TemporalSettings libraryDefault(const std::string& fog) {
    return fog == "fog" ? postfx::FogSettings{}.temporal : postfx::FroxelFogSettings{}.temporal;
}

TEST(DemoSceneTemporal, AbsentKeysKeepTheLibrarysDefaults) {
    EXPECT_FALSE(postfx::FogSettings{}.temporal.enabled);
    EXPECT_TRUE(postfx::FroxelFogSettings{}.temporal.enabled);
    for (const char* fog : kFogs) {
        SCOPED_TRACE(fog);
        const postfx::TemporalSettings d = libraryDefault(fog);
        // No temporal object, an empty one, and one with only a weight: `enabled` is the library's (the
        // object's presence does not turn it on, unlike `noise`).
        for (const json& temporal : {json(), json::object(), json{{"blend_weight", 0.25}}}) {
            json settings = json::object();
            if (!temporal.is_null()) settings["temporal"] = temporal;
            const Parsed p = parse(withFog(fog, settings));
            ASSERT_TRUE(p.ok) << p.error;
            const postfx::TemporalSettings& t = temporalOf(p.scene, fog);
            EXPECT_EQ(t.enabled, d.enabled);
            EXPECT_EQ(t.blendWeight, temporal.contains("blend_weight") ? 0.25f : d.blendWeight);
        }
    }
    // Without the fog objects at all: the library's settings too.
    const Parsed none = parse(withFog("fog", json::object()));
    ASSERT_TRUE(none.ok) << none.error;
    EXPECT_EQ(none.scene.froxelFog.temporal.enabled, true);
    EXPECT_EQ(none.scene.froxelFog.temporal.blendWeight, 0.05f);
}

TEST(DemoSceneTemporal, EveryKeyIsRead) {
    for (const char* fog : kFogs) {
        SCOPED_TRACE(fog);
        const bool flipped = !libraryDefault(fog).enabled;
        const Parsed p = parse(withFog(fog, {{"temporal", {{"enabled", flipped}, {"blend_weight", 0.375}}}}));
        ASSERT_TRUE(p.ok) << p.error;
        EXPECT_EQ(temporalOf(p.scene, fog).enabled, flipped);
        EXPECT_EQ(temporalOf(p.scene, fog).blendWeight, 0.375f);
    }
}

TEST(DemoSceneTemporal, RoundTrip) {
    for (const char* fog : kFogs) {
        for (const json& temporal : {json::object(), json{{"enabled", true}, {"blend_weight", 1}},
                                     json{{"enabled", false}, {"blend_weight", 0.1}},
                                     json{{"enabled", true}, {"blend_weight", 1e-30}}}) {
            SCOPED_TRACE(std::string(fog) + " " + temporal.dump());
            const Parsed p = parse(withFog(fog, {{"temporal", temporal}}));
            ASSERT_TRUE(p.ok) << p.error;
            const json written = demo::sceneToJson(p.scene);
            // Both fogs' objects are written with both keys.
            for (const char* f : kFogs) {
                const json& t = written["effects"][f]["temporal"];
                EXPECT_TRUE(t.contains("enabled") && t.contains("blend_weight")) << t.dump();
            }
            const Parsed again = parse(written);
            ASSERT_TRUE(again.ok) << again.error;
            EXPECT_EQ(demo::sceneToJson(again.scene), written);
            for (const char* f : kFogs) {
                EXPECT_EQ(temporalOf(again.scene, f).enabled, temporalOf(p.scene, f).enabled);
                EXPECT_EQ(temporalOf(again.scene, f).blendWeight, temporalOf(p.scene, f).blendWeight);
            }
        }
    }
}

TEST(DemoSceneTemporal, ErrorsNameTheKeyPath) {
    struct Case {
        json temporal;
        std::string error;  // after "effects.<fog>.temporal"
    };
    const std::vector<Case> cases{
        {json(3), ": expected an object, got 3"},
        {json::array(), ": expected an object"},
        {{{"enabled", "yes"}}, ".enabled: expected true or false, got the string \"yes\""},
        {{{"blend_weight", "half"}}, ".blend_weight: expected a number, got the string \"half\""},
        {{{"blend_weight", 0}}, ".blend_weight: 0 is outside (0, 1]"},
        {{{"blend_weight", -0.5}}, ".blend_weight: -0.5 is outside (0, 1]"},
        {{{"blend_weight", 1.5}}, ".blend_weight: 1.5 is outside (0, 1]"},
        // The weight is checked while temporal is off too, so that turning it on cannot make a file invalid.
        {{{"enabled", false}, {"blend_weight", 2}}, ".blend_weight: 2 is outside (0, 1]"},
        {{{"weight", 0.5}}, ".weight: unknown key (expected enabled or blend_weight)"},
    };
    for (const char* fog : kFogs) {
        for (const Case& c : cases) {
            SCOPED_TRACE(std::string(fog) + " " + c.temporal.dump());
            json settings = {{"temporal", c.temporal}};
            if (std::string(fog) == "fog") settings["enabled"] = false;  // off: still checked
            const Parsed p = parse(withFog(fog, settings));
            ASSERT_FALSE(p.ok);
            EXPECT_EQ(demo::json_text::oneLine(p.error), p.error);
            const std::string expected = "effects." + std::string(fog) + ".temporal" + c.error;
            EXPECT_EQ(p.error.rfind(expected, 0), 0u) << "error: " << p.error << "\nexpected: " << expected;
        }
    }
}

}  // namespace
