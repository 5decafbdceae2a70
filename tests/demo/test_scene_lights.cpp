// Scene files: the top-level `lights` array (demo/scene/lights_json.cpp, docs/scene-format.md#lights).
#include "scene/json_text.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <postfx/inputs.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

using json = nlohmann::json;

json sceneWith(const json& lights) {
    json j = json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [0, 0, 0], "shadows": false},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]}]
    })");
    j["lights"] = lights;
    return j;
}

json point() {
    return {{"type", "point"}, {"position", {1, 2, 3}}, {"intensity", {10, 20, 30}}, {"radius", 0.1}};
}
json spot() {
    return {{"type", "spot"}, {"position", {0, 4, 0}}, {"direction", {0, -2, 0}}, {"intensity", {100, 0, 5}},
            {"radius", 0.2},  {"range", 30},           {"inner_angle_deg", 20},   {"outer_angle_deg", 30}};
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

TEST(DemoSceneLights, AbsentMeansNone) {
    json j = sceneWith(json::array());
    j.erase("lights");
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_TRUE(p.scene.lights.empty());
}

TEST(DemoSceneLights, PointAndSpotAreRead) {
    json minimal = {{"type", "point"}, {"position", {0, 0, 0}}, {"intensity", {1, 1, 1}}};
    const Parsed p = parse(sceneWith({point(), spot(), minimal}));
    ASSERT_TRUE(p.ok) << p.error;
    ASSERT_EQ(p.scene.lights.size(), 3u);
    const demo::Light& a = p.scene.lights[0];
    EXPECT_EQ(a.kind, demo::LightKind::Point);
    EXPECT_EQ(a.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(a.intensity, glm::vec3(10, 20, 30));
    EXPECT_FLOAT_EQ(a.radius, 0.1f);
    EXPECT_FLOAT_EQ(a.range, 100.0f);  // default, as postfx::LocalLight
    const demo::Light& b = p.scene.lights[1];
    EXPECT_EQ(b.kind, demo::LightKind::Spot);
    EXPECT_EQ(b.direction, glm::vec3(0, -1, 0));  // normalised
    EXPECT_FLOAT_EQ(b.range, 30.0f);
    EXPECT_FLOAT_EQ(b.innerAngleDeg, 20.0f);
    EXPECT_FLOAT_EQ(b.outerAngleDeg, 30.0f);
    EXPECT_FLOAT_EQ(p.scene.lights[2].radius, 0.05f);  // default, as postfx::LocalLight

    const postfx::LocalLight l = demo::toLocalLight(b);
    EXPECT_EQ(l.type, postfx::LightType::Spot);
    EXPECT_NEAR(l.outerConeAngle, 30.0 * M_PI / 180.0, 1e-6);
    EXPECT_NEAR(l.innerConeAngle, 20.0 * M_PI / 180.0, 1e-6);
    EXPECT_FLOAT_EQ(l.sourceRadius, 0.2f);
}

TEST(DemoSceneLights, RoundTrip) {
    json s = spot();
    s["inner_angle_deg"] = 0.1;
    s["position"] = {1e7, -1e7, 0.3};
    const Parsed p = parse(sceneWith({point(), s, spot()}));
    ASSERT_TRUE(p.ok) << p.error;
    const json written = demo::sceneToJson(p.scene);
    ASSERT_TRUE(written.contains("lights"));
    const Parsed again = parse(written);
    ASSERT_TRUE(again.ok) << again.error;
    EXPECT_EQ(demo::sceneToJson(again.scene), written);
    ASSERT_EQ(again.scene.lights.size(), 3u);
    EXPECT_EQ(again.scene.lights[1].position, p.scene.lights[1].position);
    EXPECT_EQ(again.scene.lights[1].innerAngleDeg, p.scene.lights[1].innerAngleDeg);
}

// `shadows` and `shadow_resolution`: off and 512 by default, read on both types, written back exactly.
TEST(DemoSceneLights, ShadowKeysRoundTrip) {
    json shadowedSpot = spot();
    shadowedSpot["shadows"] = true;
    shadowedSpot["shadow_resolution"] = 16;
    json shadowedPoint = point();
    shadowedPoint["shadows"] = true;
    shadowedPoint["shadow_resolution"] = 4096.0;  // a whole number written as a decimal
    const Parsed p = parse(sceneWith({point(), shadowedSpot, shadowedPoint}));
    ASSERT_TRUE(p.ok) << p.error;
    ASSERT_EQ(p.scene.lights.size(), 3u);
    EXPECT_FALSE(p.scene.lights[0].shadows);
    EXPECT_EQ(p.scene.lights[0].shadowResolution, 512u);
    EXPECT_TRUE(p.scene.lights[1].shadows);
    EXPECT_EQ(p.scene.lights[1].shadowResolution, 16u);
    EXPECT_TRUE(p.scene.lights[2].shadows);
    EXPECT_EQ(p.scene.lights[2].shadowResolution, 4096u);

    const json written = demo::sceneToJson(p.scene);
    EXPECT_EQ(written["lights"][0]["shadows"], false);
    EXPECT_EQ(written["lights"][0]["shadow_resolution"], 512);
    EXPECT_EQ(written["lights"][1]["shadows"], true);
    EXPECT_EQ(written["lights"][1]["shadow_resolution"], 16);
    const Parsed again = parse(written);
    ASSERT_TRUE(again.ok) << again.error;
    EXPECT_EQ(demo::sceneToJson(again.scene), written);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(again.scene.lights[i].shadows, p.scene.lights[i].shadows) << i;
        EXPECT_EQ(again.scene.lights[i].shadowResolution, p.scene.lights[i].shadowResolution) << i;
    }
}

TEST(DemoSceneLights, LimitIsKMaxLocalLights) {
    EXPECT_TRUE(parse(sceneWith(json::array())).ok);
    json many = json::array();
    for (uint32_t i = 0; i < postfx::kMaxLocalLights; ++i)
        many.push_back(point());
    const Parsed full = parse(sceneWith(many));
    EXPECT_TRUE(full.ok) << full.error;
    many.push_back(point());
    const Parsed over = parse(sceneWith(many));
    ASSERT_FALSE(over.ok);
    EXPECT_EQ(over.error, "lights: 257 lights are more than the limit of 256");
}

// Every light that loads is accepted by postfx as FrameInfo::lights (the boundary values included).
TEST(DemoSceneLights, BoundaryValuesAreAcceptedByPostfx) {
    json a = spot();
    a["position"] = {-1e7, 1e7, 1e7};
    a["intensity"] = {0, 1e9, 0};
    a["range"] = 1e9;
    a["radius"] = 1e9;
    a["outer_angle_deg"] = 89.9;
    a["inner_angle_deg"] = 89.9;
    json b = spot();
    b["outer_angle_deg"] = 0;
    b["inner_angle_deg"] = 0;
    b["range"] = 1e-30;
    b["radius"] = 1e-30;
    const Parsed p = parse(sceneWith({a, b}));
    ASSERT_TRUE(p.ok) << p.error;
    for (const demo::Light& l : p.scene.lights) {
        const postfx::LocalLight pl = demo::toLocalLight(l);
        EXPECT_TRUE(std::isfinite(pl.outerConeAngle) && pl.outerConeAngle < 1.5707963f);
        EXPECT_LE(pl.innerConeAngle, pl.outerConeAngle);
        EXPECT_GT(pl.sourceRadius, 0.0f);
        EXPECT_LE(pl.sourceRadius, pl.range);
    }
}

struct Rejection {
    const char* name;
    json light;
    std::string error;  // the message starts with it
};

std::vector<Rejection> rejections() {
    const auto edit = [](json l, const char* key, const json& v) {
        l[key] = v;
        return l;
    };
    const auto drop = [](json l, const char* key) {
        l.erase(key);
        return l;
    };
    return {
        {"NotAnObject", json(3), "lights[1]: expected an object"},
        {"TypeMissing", drop(point(), "type"), "lights[1].type: missing"},
        {"TypeUnknown", edit(point(), "type", "area"), "lights[1].type: unknown light type \"area\""},
        {"TypeNotString", edit(point(), "type", 1), "lights[1].type: expected a string (point or spot)"},
        {"UnknownKey", edit(point(), "color", {1, 1, 1}), "lights[1].color: unknown key for a point light"},
        {"DirectionOnPoint", edit(point(), "direction", {0, -1, 0}),
         "lights[1].direction: unknown key for a point light"},
        {"AngleOnPoint", edit(point(), "outer_angle_deg", 10),
         "lights[1].outer_angle_deg: unknown key for a point light"},
        {"PositionMissing", drop(point(), "position"), "lights[1].position: missing"},
        {"PositionTooFar", edit(point(), "position", {0, 2e7, 0}),
         "lights[1].position[1]: expected a number in [-1e7, 1e7]"},
        {"PositionNotArray", edit(point(), "position", 1),
         "lights[1].position: expected an array of 3 numbers"},
        {"IntensityMissing", drop(point(), "intensity"), "lights[1].intensity: missing"},
        {"IntensityNegative", edit(point(), "intensity", {1, -1, 1}),
         "lights[1].intensity[1]: expected a number in [0, 1e9]"},
        {"IntensityTooBright", edit(point(), "intensity", {2e9, 1, 1}),
         "lights[1].intensity[0]: expected a number in [0, 1e9]"},
        {"RadiusZero", edit(point(), "radius", 0), "lights[1].radius: expected a number in (0, range]"},
        {"RadiusOverRange", edit(edit(point(), "range", 1), "radius", 2),
         "lights[1].radius: expected a number in (0, range]"},
        {"DefaultRadiusOverRange", edit(drop(point(), "radius"), "range", 0.01),
         "lights[1].radius: the default"},
        {"RangeZero", edit(point(), "range", 0), "lights[1].range: expected a number in (0, 1e9]"},
        {"RangeHuge", edit(point(), "range", 1e30), "lights[1].range: expected a number in (0, 1e9]"},
        {"RangeString", edit(point(), "range", "far"), "lights[1].range: expected a number"},
        {"SpotDirectionMissing", drop(spot(), "direction"), "lights[1].direction: missing"},
        {"SpotDirectionZero", edit(spot(), "direction", {0, 0, 0}),
         "lights[1].direction: expected a non-zero vector"},
        {"OuterNegative", edit(spot(), "outer_angle_deg", -1),
         "lights[1].outer_angle_deg: expected a number in [0, 89.9]"},
        {"OuterNinety", edit(spot(), "outer_angle_deg", 90),
         "lights[1].outer_angle_deg: expected a number in [0, 89.9]"},
        {"InnerOverOuter", edit(spot(), "inner_angle_deg", 31),
         "lights[1].inner_angle_deg: expected a number in [0, outer_angle_deg]"},
        {"InnerNegative", edit(spot(), "inner_angle_deg", -0.5),
         "lights[1].inner_angle_deg: expected a number in [0, outer_angle_deg]"},
        {"SpotUnknownKey", edit(spot(), "angle", 3), "lights[1].angle: unknown key for a spot light"},
        {"ShadowsNotBool", edit(point(), "shadows", 1), "lights[1].shadows: expected true or false"},
        {"ShadowResolutionSmall", edit(spot(), "shadow_resolution", 8),
         "lights[1].shadow_resolution: expected an integer in [16, 4096], got 8"},
        {"ShadowResolutionLarge", edit(point(), "shadow_resolution", 4097),
         "lights[1].shadow_resolution: expected an integer in [16, 4096], got 4097"},
        {"ShadowResolutionFraction", edit(point(), "shadow_resolution", 512.5),
         "lights[1].shadow_resolution: expected an integer"},
    };
}

TEST(DemoSceneLights, ErrorsNameTheKeyPath) {
    for (const Rejection& r : rejections()) {
        SCOPED_TRACE(r.name);
        const Parsed p = parse(sceneWith({point(), r.light}));
        ASSERT_FALSE(p.ok);
        EXPECT_EQ(demo::json_text::oneLine(p.error), p.error);
        EXPECT_EQ(p.error.rfind(r.error, 0), 0u)
            << "error: " << p.error << "\nexpected to start with: " << r.error;
    }
    const Parsed notArray = parse(sceneWith(json::object()));
    ASSERT_FALSE(notArray.ok);
    EXPECT_EQ(notArray.error.rfind("lights: expected an array of lights", 0), 0u) << notArray.error;
}

}  // namespace
