// Scene files: objects' `opacity` and `forward`, the `particles` emitters and `volumetrics_lookup`
// (demo/scene/transparency_json.cpp, docs/scene-format.md#particles), and the particles' placement.
#include "scene/particles.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

using json = nlohmann::json;

json baseScene() {
    return json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [0, 0, 0], "shadows": false},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]},
                  {"type": "box", "center": [0, 1, 0], "half_size": [1, 1, 0.05], "albedo": [0.5, 0.5, 0.5]},
                  {"type": "sphere", "center": [2, 1, 0], "radius": 1, "albedo": [0.5, 0.5, 0.5]}]
    })");
}

json emitter() {
    return {{"center", {1, 2, 3}}, {"half_size", {0.5, 1, 0.5}}, {"count", 20},
            {"quad_size", 0.4},    {"albedo", {0.6, 0.6, 0.7}},  {"opacity", 0.2},
            {"seed", 9},           {"rise_speed", 0.5},          {"enabled", false}};
}

struct Parsed {
    bool ok = false;
    std::string error;
    demo::Scene scene;
};
Parsed parse(const json& j) {
    Parsed p;
    p.ok = demo::parseScene(j.dump(), p.scene, p.error);
    return p;
}

// The error of `j`, which must not load.
std::string errorOf(const json& j) {
    const Parsed p = parse(j);
    EXPECT_FALSE(p.ok);
    return p.error;
}

TEST(DemoSceneTransparency, DefaultsAreOpaqueWithoutParticles) {
    const Parsed p = parse(baseScene());
    ASSERT_TRUE(p.ok) << p.error;
    for (const demo::Object& o : p.scene.objects) {
        EXPECT_EQ(o.opacity, 1.0f);
        EXPECT_FALSE(o.forward);
        EXPECT_FALSE(demo::drawnForward(o));
        EXPECT_TRUE(demo::castsShadows(o));
    }
    EXPECT_TRUE(p.scene.particles.empty());
    EXPECT_FALSE(demo::hasForwardDraws(p.scene));
    const postfx::VolumetricsLookupSettings defaults;
    EXPECT_EQ(p.scene.volumetricsLookup.extent.x, defaults.extent.x);
    EXPECT_EQ(p.scene.volumetricsLookup.extent.z, defaults.extent.z);
    EXPECT_EQ(p.scene.volumetricsLookup.nearDistance, defaults.nearDistance);
    EXPECT_EQ(p.scene.volumetricsLookup.maxDistance, defaults.maxDistance);
}

TEST(DemoSceneTransparency, OpacityAndForwardAreRead) {
    json j = baseScene();
    j["objects"][0]["opacity"] = 0.25;
    j["objects"][1]["forward"] = true;
    j["objects"][2]["opacity"] = 0;
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.scene.objects[0].opacity, 0.25f);
    EXPECT_TRUE(demo::drawnForward(p.scene.objects[0]));
    EXPECT_FALSE(demo::castsShadows(p.scene.objects[0]));
    EXPECT_TRUE(p.scene.objects[1].forward);
    EXPECT_TRUE(demo::drawnForward(p.scene.objects[1]));
    EXPECT_TRUE(demo::castsShadows(p.scene.objects[1]));  // opacity 1, forced forward
    EXPECT_EQ(p.scene.objects[2].opacity, 0.0f);
    EXPECT_TRUE(demo::hasForwardDraws(p.scene));
}

TEST(DemoSceneTransparency, ParticlesAndLookupAreRead) {
    json j = baseScene();
    json minimal = {{"center", {0, 0, 0}},
                    {"half_size", {1, 1, 1}},
                    {"count", 5},
                    {"quad_size", 1},
                    {"albedo", {1, 1, 1}}};
    j["particles"] = {emitter(), minimal};
    j["volumetrics_lookup"] = {{"extent", {80, 45, 32}}, {"near_distance", 0.5}, {"max_distance", 500}};
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    ASSERT_EQ(p.scene.particles.size(), 2u);
    const demo::ParticleEmitter& e = p.scene.particles[0];
    EXPECT_EQ(e.center, glm::vec3(1, 2, 3));
    EXPECT_EQ(e.halfSize, glm::vec3(0.5f, 1, 0.5f));
    EXPECT_EQ(e.count, 20u);
    EXPECT_FLOAT_EQ(e.quadSize, 0.4f);
    EXPECT_EQ(e.albedo, glm::vec3(0.6f, 0.6f, 0.7f));
    EXPECT_FLOAT_EQ(e.opacity, 0.2f);
    EXPECT_EQ(e.seed, 9u);
    EXPECT_FLOAT_EQ(e.riseSpeed, 0.5f);
    EXPECT_FALSE(e.enabled);
    const demo::ParticleEmitter& m = p.scene.particles[1];  // defaults
    EXPECT_FLOAT_EQ(m.opacity, 0.3f);
    EXPECT_EQ(m.seed, 1u);
    EXPECT_EQ(m.riseSpeed, 0.0f);
    EXPECT_TRUE(m.enabled);
    EXPECT_TRUE(demo::hasForwardDraws(p.scene));  // the second emitter is on
    EXPECT_EQ(p.scene.volumetricsLookup.extent.x, 80u);
    EXPECT_EQ(p.scene.volumetricsLookup.extent.y, 45u);
    EXPECT_EQ(p.scene.volumetricsLookup.extent.z, 32u);
    EXPECT_FLOAT_EQ(p.scene.volumetricsLookup.nearDistance, 0.5f);
    EXPECT_FLOAT_EQ(p.scene.volumetricsLookup.maxDistance, 500.0f);

    // Only disabled or empty emitters: nothing to draw forward.
    j["particles"] = {emitter()};
    j["particles"][0]["enabled"] = true;
    j["particles"][0]["count"] = 0;
    const Parsed empty = parse(j);
    ASSERT_TRUE(empty.ok) << empty.error;
    EXPECT_FALSE(demo::hasForwardDraws(empty.scene));
}

TEST(DemoSceneTransparency, RoundTrip) {
    json j = baseScene();
    j["objects"][1]["opacity"] = 0.3;
    j["objects"][2]["forward"] = true;
    j["particles"] = {emitter()};
    j["volumetrics_lookup"] = {{"extent", {64, 32, 16}}, {"near_distance", 2}, {"max_distance", 3000}};
    const Parsed first = parse(j);
    ASSERT_TRUE(first.ok) << first.error;
    const json out = demo::sceneToJson(first.scene);
    const Parsed second = parse(out);
    ASSERT_TRUE(second.ok) << second.error;
    EXPECT_EQ(demo::sceneToJson(second.scene), out);
    EXPECT_EQ(second.scene.objects[1].opacity, first.scene.objects[1].opacity);
    EXPECT_TRUE(second.scene.objects[2].forward);
    ASSERT_EQ(second.scene.particles.size(), 1u);
    EXPECT_EQ(second.scene.particles[0].seed, 9u);
    EXPECT_EQ(second.scene.volumetricsLookup.extent.y, 32u);
}

TEST(DemoSceneTransparency, BadValuesNameTheKey) {
    struct Case {
        const char* what;
        json scene;
        const char* error;
    };
    std::vector<Case> cases;
    const auto withObject = [](const char* key, const json& value) {
        json j = baseScene();
        j["objects"][1][key] = value;
        return j;
    };
    const auto withEmitter = [](const char* key, const json& value) {
        json j = baseScene();
        j["particles"] = {emitter()};
        if (value.is_null())
            j["particles"][0].erase(key);
        else
            j["particles"][0][key] = value;
        return j;
    };
    const auto withLookup = [](const json& lookup) {
        json j = baseScene();
        j["volumetrics_lookup"] = lookup;
        return j;
    };
    cases.push_back({"opacity above 1", withObject("opacity", 1.5),
                     "objects[1].opacity: expected a number in [0, 1], got 1.5"});
    cases.push_back({"opacity negative", withObject("opacity", -0.1), "objects[1].opacity: "});
    cases.push_back({"opacity a string", withObject("opacity", "half"), "objects[1].opacity: "});
    cases.push_back({"forward a number", withObject("forward", 1), "objects[1].forward: "});
    cases.push_back({"particles not an array",
                     [] {
                         json j = baseScene();
                         j["particles"] = json::object();
                         return j;
                     }(),
                     "particles: expected an array of particle emitters"});
    cases.push_back({"too many emitters",
                     [] {
                         json j = baseScene();
                         j["particles"] = json::array();
                         for (int i = 0; i < 17; ++i)
                             j["particles"].push_back(emitter());
                         return j;
                     }(),
                     "particles: 17 particle emitters are more than the limit of 16"});
    cases.push_back(
        {"unknown emitter key", withEmitter("colour", {1, 1, 1}), "particles[0].colour: unknown key"});
    cases.push_back({"missing center", withEmitter("center", nullptr), "particles[0].center: "});
    cases.push_back({"center too far", withEmitter("center", {0, 2e7, 0}), "particles[0].center[1]: "});
    cases.push_back({"half size zero", withEmitter("half_size", {1, 0, 1}),
                     "particles[0].half_size[1]: expected a number in (0, 1e4], got 0"});
    cases.push_back({"missing count", withEmitter("count", nullptr), "particles[0].count: "});
    cases.push_back({"count too large", withEmitter("count", 5000),
                     "particles[0].count: expected an integer in [0, 4096], got 5000"});
    cases.push_back({"count fractional", withEmitter("count", 2.5), "particles[0].count: "});
    cases.push_back({"quad size zero", withEmitter("quad_size", 0), "particles[0].quad_size: "});
    cases.push_back({"quad size too large", withEmitter("quad_size", 2e4), "particles[0].quad_size: "});
    cases.push_back({"albedo above 1", withEmitter("albedo", {1, 2, 1}), "particles[0].albedo[1]: "});
    cases.push_back({"opacity above 1", withEmitter("opacity", 2), "particles[0].opacity: "});
    cases.push_back({"seed negative", withEmitter("seed", -1), "particles[0].seed: "});
    cases.push_back({"rise speed too fast", withEmitter("rise_speed", 2e4), "particles[0].rise_speed: "});
    cases.push_back({"enabled a string", withEmitter("enabled", "yes"), "particles[0].enabled: "});
    cases.push_back({"lookup not an object", withLookup(json::array()), "volumetrics_lookup: "});
    cases.push_back(
        {"lookup unknown key", withLookup({{"enabled", true}}), "volumetrics_lookup.enabled: unknown key"});
    cases.push_back(
        {"lookup extent zero", withLookup({{"extent", {0, 90, 64}}}), "volumetrics_lookup.extent: "});
    cases.push_back(
        {"lookup extent one slice", withLookup({{"extent", {160, 90, 1}}}), "volumetrics_lookup.extent: "});
    cases.push_back(
        {"lookup extent too wide", withLookup({{"extent", {2048, 90, 64}}}), "volumetrics_lookup.extent: "});
    cases.push_back(
        {"lookup extent too deep", withLookup({{"extent", {160, 90, 513}}}), "volumetrics_lookup.extent: "});
    cases.push_back(
        {"lookup extent two numbers", withLookup({{"extent", {160, 90}}}), "volumetrics_lookup.extent"});
    cases.push_back({"near too small", withLookup({{"near_distance", 0.001}}),
                     "volumetrics_lookup.near_distance: expected a number in [0.01, 1e5], got 0.001"});
    cases.push_back({"max below near", withLookup({{"near_distance", 10}, {"max_distance", 5}}),
                     "volumetrics_lookup.max_distance: expected a number in (near_distance, 1e7], got 5"});
    cases.push_back({"max equal to near", withLookup({{"near_distance", 10}, {"max_distance", 10}}),
                     "volumetrics_lookup.max_distance: "});
    cases.push_back(
        {"max too far", withLookup({{"max_distance", 2e7}}), "volumetrics_lookup.max_distance: "});
    cases.push_back({"default max below near", withLookup({{"near_distance", 1e5}}),
                     "volumetrics_lookup.max_distance: the default 10000 is not above near_distance"});
    for (const Case& c : cases) {
        const std::string error = errorOf(c.scene);
        EXPECT_EQ(error.rfind(c.error, 0), 0u) << c.what << ": " << error;
    }
}

TEST(DemoSceneTransparency, ParticlesAreInTheirBoxAndRise) {
    demo::ParticleEmitter e;
    e.center = {1.0f, 5.0f, -2.0f};
    e.halfSize = {0.5f, 2.0f, 1.0f};
    e.count = 500;
    e.opacity = 0.4f;
    e.riseSpeed = 0.25f;
    const std::vector<demo::Particle> at0 = demo::emitParticles(e, 0.0);
    const std::vector<demo::Particle> at1 = demo::emitParticles(e, 1.0);
    ASSERT_EQ(at0.size(), 500u);
    ASSERT_EQ(at1.size(), 500u);
    size_t rose = 0;
    for (size_t i = 0; i < at0.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(at0[i].center[a], e.center[a] - e.halfSize[a]);
            EXPECT_LE(at0[i].center[a], e.center[a] + e.halfSize[a]);
        }
        EXPECT_GE(at0[i].opacity, 0.0f);
        EXPECT_LE(at0[i].opacity, e.opacity);
        EXPECT_EQ(at1[i].center.x, at0[i].center.x);  // only y moves
        EXPECT_EQ(at1[i].center.z, at0[i].center.z);
        if (std::abs(at1[i].center.y - at0[i].center.y - 0.25f) < 1e-4f) ++rose;
    }
    // All but those that wrapped (a quarter metre of the four-metre box: about 6 %) rose 0.25 m.
    EXPECT_GT(rose, 420u);
    // A particle's place does not depend on the count.
    e.count = 10;
    const std::vector<demo::Particle> few = demo::emitParticles(e, 0.0);
    for (size_t i = 0; i < few.size(); ++i)
        EXPECT_EQ(few[i].center, at0[i].center);
    e.enabled = false;
    EXPECT_TRUE(demo::emitParticles(e, 0.0).empty());
}

}  // namespace
