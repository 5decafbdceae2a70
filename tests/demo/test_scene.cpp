// Scene files (demo/scene): parsing, validation, defaults, the embedded default scene, robustness.
#include "scene/json_text.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

using demo::ObjectType;
using demo::Scene;
using json = nlohmann::json;

const std::string kScenesDir = POSTFX_DEMO_SCENES_DIR;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in.good()) << path;
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Parsed {
    bool ok = false;
    std::string error;
    Scene scene;
};

Parsed parse(const std::string& text) {
    Parsed p;
    p.ok = demo::parseScene(text, p.scene, p.error);
    return p;
}
Parsed parse(const json& j) {
    return parse(j.dump());
}

// A small valid scene with every optional key left out.
json base() {
    return json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 2, 0], "illuminance": [1000, 2000, 3000], "shadows": true},
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]},
        {"type": "box", "center": [1, 1, 1], "half_size": [1, 2, 3], "albedo": [1, 0, 0.25]},
        {"type": "sphere", "center": [-1, 1, 2], "radius": 0.75, "albedo": [0, 1, 0]}
      ]
    })");
}

// base() with the value at a JSON pointer replaced (or added).
json with(const std::string& pointer, const json& value) {
    json j = base();
    j[json::json_pointer(pointer)] = value;
    return j;
}

// base() with the value at a JSON pointer removed.
json without(const std::string& pointer) {
    json j = base();
    const json::json_pointer ptr(pointer);
    j[ptr.parent_pointer()].erase(ptr.back());
    return j;
}

// base() as text with the value at a JSON pointer replaced by raw JSON text (e.g. 1e999).
std::string withRaw(const std::string& pointer, const std::string& raw) {
    const std::string marker = "\"@@RAW@@\"";
    std::string text = with(pointer, "@@RAW@@").dump(2);
    text.replace(text.find(marker), marker.size(), raw);
    return text;
}

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(demo::sceneToJson(a), demo::sceneToJson(b));
}

void expectVec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_FLOAT_EQ(v.x, x);
    EXPECT_FLOAT_EQ(v.y, y);
    EXPECT_FLOAT_EQ(v.z, z);
}
void expectVec3(const glm::vec3& v, const json& expected) {
    expectVec3(v, expected[0].get<float>(), expected[1].get<float>(), expected[2].get<float>());
}

bool isOneLine(const std::string& s) {
    return !s.empty() && s.find('\n') == std::string::npos && s.find('\r') == std::string::npos &&
           demo::json_text::oneLine(s) == s;
}

// ---- valid scenes ------------------------------------------------------------------------------

TEST(DemoSceneParse, MinimalSceneGetsDefaults) {
    const Parsed p = parse(base());
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_TRUE(p.error.empty());
    const Scene& s = p.scene;
    expectVec3(s.camera.position, 0, 2, 10);
    expectVec3(s.camera.lookAt, 0, 1, 0);
    expectVec3(s.camera.up, 0, 1, 0);
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 60.0f);
    EXPECT_FLOAT_EQ(s.camera.nearPlane, 0.1f);
    EXPECT_FLOAT_EQ(s.camera.farPlane, 1000.0f);
    EXPECT_FLOAT_EQ(s.camera.ev100, 15.0f);
    expectVec3(s.sun.direction, 0, 1, 0);  // normalised
    expectVec3(s.sun.illuminance, 1000, 2000, 3000);
    EXPECT_TRUE(s.sun.shadows);
    expectVec3(s.ambient, 0, 0, 0);
    expectVec3(s.sky, 0, 0, 0);
    EXPECT_FALSE(s.fog.enabled);  // no effects.fog
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].type, ObjectType::Plane);
    EXPECT_EQ(s.objects[1].type, ObjectType::Box);
    EXPECT_EQ(s.objects[2].type, ObjectType::Sphere);
}

TEST(DemoSceneParse, OptionalKeysAreRead) {
    json j = base();
    j["camera"]["up"] = {0, 0, -1};
    j["camera"]["ev100"] = 9.5;
    j["ambient"] = {1, 2, 3};
    j["sky"] = {4, 5, 6};
    j["effects"] = {{"fog", {{"density", 0.03}}}};
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    expectVec3(p.scene.camera.up, 0, 0, -1);
    EXPECT_FLOAT_EQ(p.scene.camera.ev100, 9.5f);
    expectVec3(p.scene.ambient, 1, 2, 3);
    expectVec3(p.scene.sky, 4, 5, 6);
    EXPECT_TRUE(p.scene.fog.enabled);  // effects.fog: tests/fog/test_fog_scene.cpp
    EXPECT_FLOAT_EQ(p.scene.fog.density, 0.03f);
}

TEST(DemoSceneParse, IntegersAndFloatsAreNumbers) {
    json j = base();
    j["camera"]["near"] = 1;  // integer
    j["camera"]["far"] = 2.5e3;
    j["camera"]["fov_y_deg"] = 45u;  // unsigned
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_FLOAT_EQ(p.scene.camera.nearPlane, 1.0f);
    EXPECT_FLOAT_EQ(p.scene.camera.farPlane, 2500.0f);
    EXPECT_FLOAT_EQ(p.scene.camera.fovYDeg, 45.0f);
}

TEST(DemoSceneParse, DirectionsAreNormalised) {
    json j = with("/sun/direction", {3, 0, 4});
    j["objects"][0]["normal"] = {0, 1e-30, 0};  // tiny but non-zero
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    expectVec3(p.scene.sun.direction, 0.6f, 0.0f, 0.8f);
    expectVec3(p.scene.objects[0].normal, 0, 1, 0);
}

TEST(DemoSceneParse, EmptyObjectListIsValid) {
    const Parsed p = parse(with("/objects", json::array()));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_TRUE(p.scene.objects.empty());
}

TEST(DemoSceneParse, BoundaryValuesAreAccepted) {
    json j = base();
    j["objects"][0]["albedo"] = {0, 1, 0};
    j["sun"]["illuminance"] = {0, 0, 0};
    j["ambient"] = {0, 0, 0};
    j["camera"]["fov_y_deg"] = 179;
    j["camera"]["ev100"] = -30;
    j["camera"]["near"] = 1e-6;
    j["camera"]["far"] = 1e9;
    j["camera"]["position"] = {1e7, -1e7, 1e7};
    j["camera"]["up"] = {0, 1e-6, 0};
    j["sun"]["illuminance"] = {1e7, 0, 0};
    j["sky"] = {1e7, 1e7, 1e7};
    j["objects"][1]["half_size"] = {1e7, 1e-30, 1};
    j["objects"][2]["center"] = {-1e7, 1e7, -1e7};
    j["objects"][2]["radius"] = 1e7;
    EXPECT_TRUE(parse(j).ok) << parse(j).error;
}

TEST(DemoSceneParse, FailureLeavesSceneUnchanged) {
    Scene scene = demo::defaultScene();
    std::string error;
    EXPECT_FALSE(demo::parseScene(with("/objects/2/radius", -1).dump(), scene, error));
    expectSameScene(scene, demo::defaultScene());
}

// ---- round trips of each object type -----------------------------------------------------------

class DemoObjectRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(DemoObjectRoundTrip, ParseSerialiseParse) {
    json j = base();
    j["objects"] = json::array({json::parse(GetParam())});
    const Parsed first = parse(j);
    ASSERT_TRUE(first.ok) << first.error;
    ASSERT_EQ(first.scene.objects.size(), 1u);
    const demo::Object& o = first.scene.objects[0];
    const json& in = j["objects"][0];
    switch (o.type) {
        case ObjectType::Plane:
            EXPECT_EQ(in["type"], "plane");
            expectVec3(o.position, in["point"]);
            expectVec3(o.normal, 0.0f, 0.6f, 0.8f);
            break;
        case ObjectType::Box:
            EXPECT_EQ(in["type"], "box");
            expectVec3(o.position, in["center"]);
            expectVec3(o.halfSize, in["half_size"]);
            break;
        case ObjectType::Sphere:
            EXPECT_EQ(in["type"], "sphere");
            expectVec3(o.position, in["center"]);
            EXPECT_FLOAT_EQ(o.radius, in["radius"].get<float>());
            break;
    }
    expectVec3(o.albedo, in["albedo"]);

    // Serialised, every key is written; reading it back gives the same scene and the same text.
    const json out = demo::sceneToJson(first.scene);
    EXPECT_EQ(out["objects"][0]["type"], in["type"]);
    EXPECT_EQ(out["objects"][0].size(), in.size() + 2);  // and the defaults of opacity and forward
    EXPECT_EQ(out["objects"][0]["opacity"], 1.0);
    EXPECT_EQ(out["objects"][0]["forward"], false);
    const Parsed second = parse(out.dump(2));
    ASSERT_TRUE(second.ok) << second.error;
    expectSameScene(first.scene, second.scene);
    EXPECT_EQ(demo::sceneToJson(second.scene), out);
}

INSTANTIATE_TEST_SUITE_P(
    Objects, DemoObjectRoundTrip,
    ::testing::Values(
        R"({"type": "plane", "point": [1.5, -2, 0.1], "normal": [0, 3, 4], "albedo": [0.1, 0.2, 0.3]})",
        R"({"type": "box", "center": [-3, 0.5, 7.25], "half_size": [0.4, 4, 0.4], "albedo": [0.7, 0.2, 0.15]})",
        R"({"type": "sphere", "center": [0.3, 1e-3, -1e4], "radius": 0.1, "albedo": [1, 1, 1]})"),
    [](const ::testing::TestParamInfo<const char*>& info) {
        return json::parse(info.param)["type"].get<std::string>();  // plane, box, sphere
    });

TEST(DemoSceneToJson, FloatsAreWrittenShort) {
    const Parsed p = parse(base());
    ASSERT_TRUE(p.ok) << p.error;
    const std::string text = demo::sceneToJson(p.scene).dump();
    EXPECT_NE(text.find("\"near\":0.1,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"radius\":0.75"), std::string::npos) << text;
}

// ---- the built-in default scene and the committed scene files ---------------------------------

TEST(DemoDefaultScene, EmbeddedTextEqualsTheCommittedFile) {
    EXPECT_EQ(demo::defaultSceneJson(), readFile(kScenesDir + "/default.json"));
}

TEST(DemoDefaultScene, ParsesAndEqualsDefaultScene) {
    const Parsed p = parse(demo::defaultSceneJson());
    ASSERT_TRUE(p.ok) << p.error;
    expectSameScene(p.scene, demo::defaultScene());

    Scene loaded;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/default.json", loaded, error)) << error;
    expectSameScene(loaded, demo::defaultScene());
}

// The built-in scene shows the fog: height fog shaped by noise, lit by a low sun seen through a colonnade
// (pillars under a beam) whose shadow map cuts the light into shafts, at a quality preset.
TEST(DemoDefaultScene, MatchesItsDescription) {
    const Scene s = demo::defaultScene();
    const float elevationDeg = glm::degrees(std::asin(s.sun.direction.y));
    EXPECT_GE(elevationDeg, 8.0f);
    EXPECT_LE(elevationDeg, 16.0f);
    EXPECT_TRUE(s.sun.shadows);
    EXPECT_GE(s.camera.position.y, 2.5f);
    EXPECT_LE(s.camera.position.y, 4.0f);
    // Looking into the light (forward scattering shows the shafts): the sun within 30° of the view's azimuth.
    const glm::vec3 view = s.camera.lookAt - s.camera.position;
    const glm::vec2 viewAzimuth = glm::normalize(glm::vec2(view.x, view.z)),
                    sunAzimuth = glm::normalize(glm::vec2(s.sun.direction.x, s.sun.direction.z));
    EXPECT_GE(glm::dot(viewAzimuth, sunAzimuth), std::cos(glm::radians(30.0f)));
    int planes = 0, pillars = 0, beams = 0, boxes = 0, spheres = 0;
    for (const demo::Object& o : s.objects) {
        if (o.type == ObjectType::Plane) ++planes;
        if (o.type == ObjectType::Sphere) ++spheres;
        if (o.type == ObjectType::Box) {
            if (o.halfSize.y >= 4.0f * o.halfSize.x)
                ++pillars;
            else if (o.halfSize.x >= 4.0f * o.halfSize.y)
                ++beams;
            else
                ++boxes;
        }
        if (o.type != ObjectType::Plane) {
            const float distance = glm::length(o.position - s.camera.position);
            EXPECT_GE(distance, 5.0f);
            EXPECT_LE(distance, 40.0f);
        }
    }
    EXPECT_EQ(planes, 1);
    EXPECT_GE(pillars, 5);
    EXPECT_GE(beams, 1);
    EXPECT_GE(boxes, 2);
    EXPECT_GE(spheres, 1);

    EXPECT_TRUE(s.fog.enabled);
    EXPECT_TRUE(postfx::validateFogSettings(s.fog).ok());
    EXPECT_GT(s.fog.density, 0.0f);
    EXPECT_GT(s.fog.heightFalloff, 0.0f);  // height fog
    EXPECT_GT(s.fog.anisotropy, 0.0f);     // forward scattering
    EXPECT_TRUE(s.fog.noise.enabled);
    // A fixed preset: not Custom, and not Auto (which measures the GPU, so its image is not reproducible).
    EXPECT_NE(s.fog.quality, postfx::FogQuality::Custom);
    EXPECT_NE(s.fog.quality, postfx::FogQuality::Auto);
}

// The host renderer's scene without effects (tests that need no fog use it): shadows on, fog off.
TEST(DemoSceneFiles, PlainHasNoEffects) {
    Scene s;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/plain.json", s, error)) << error;
    EXPECT_TRUE(s.sun.shadows);
    EXPECT_GE(s.objects.size(), 2u);
    EXPECT_FALSE(s.fog.enabled);  // no effects.fog
}

TEST(DemoSceneFiles, LitPlane) {
    Scene s;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/lit_plane.json", s, error)) << error;
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].type, ObjectType::Plane);
    expectVec3(s.objects[0].albedo, 0.5f, 0.5f, 0.5f);
    expectVec3(s.objects[0].normal, 0, 1, 0);
    const glm::vec3 l = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    expectVec3(s.sun.direction, l.x, l.y, l.z);
    expectVec3(s.sun.illuminance, 10000, 10000, 10000);
    EXPECT_FALSE(s.sun.shadows);
    expectVec3(s.ambient, 100, 100, 100);
    expectVec3(s.sky, 0, 0, 0);
    expectVec3(s.camera.position, 0, 5, 5);
    expectVec3(s.camera.lookAt, 0, 0, 0);
}

TEST(DemoSceneFiles, LoadErrorsNameTheFile) {
    Scene s;
    std::string error;
    const std::string missing = kScenesDir + "/no_such_scene.json";
    EXPECT_FALSE(demo::loadSceneFile(missing, s, error));
    EXPECT_EQ(error, missing + ": no such file");

    EXPECT_FALSE(demo::loadSceneFile(kScenesDir, s, error));
    EXPECT_EQ(error, kScenesDir + ": not a regular file");

    const std::string bad = ::testing::TempDir() + "/postfx_bad_scene.json";
    std::ofstream(bad) << with("/camera/near", 0).dump(2);
    EXPECT_FALSE(demo::loadSceneFile(bad, s, error));
    EXPECT_EQ(error.rfind(bad + ": camera.near: expected a number in [1e-6, 1e6], got 0", 0), 0u) << error;
    std::filesystem::remove(bad);
}

// ---- rejections: every error is one line that starts with the key path --------------------------

struct Rejection {
    std::string name;
    std::string text;
    std::string path;      // the error starts with "<path>"
    std::string fragment;  // ... and contains this ("" for no check)
};

void PrintTo(const Rejection& r, std::ostream* os) {
    *os << r.name;
}

std::vector<Rejection> rejections() {
    std::vector<Rejection> r;
    const auto add = [&](std::string name, const json& j, std::string path, std::string fragment = "") {
        r.push_back({std::move(name), j.dump(2), std::move(path), std::move(fragment)});
    };
    const auto addText = [&](std::string name, std::string text, std::string path,
                             std::string fragment = "") {
        r.push_back({std::move(name), std::move(text), std::move(path), std::move(fragment)});
    };

    // JSON syntax
    addText("SyntaxMissingValue", R"({"camera": })", "(line 1, column 12) syntax error: ");
    addText("SyntaxTrailingComma", "{\n  \"objects\": [1,]\n}", "(line 2, column 17) syntax error: ");
    addText("SyntaxTrailingGarbage", base().dump() + " x", "(line 1, column ", "syntax error");
    addText("SyntaxBadLiteral", "{\n  \"sun\": {\"shadows\": tru}}",
            "(line 2, column 25) syntax error: ", "invalid literal");
    addText("SyntaxBadNumber", "{\"camera\": {\"near\": 1.5e}}",
            "(line 1, column 25) syntax error: ", "invalid number");
    addText("SyntaxEmpty", "", "(line 1, column 1) syntax error: ", "unexpected end of input");
    addText("SyntaxUnterminatedString", "{\"camera", "(line 1, column ", "syntax error");
    addText("SyntaxNaNLiteral", withRaw("/camera/near", "NaN"), "(line ", "syntax error");
    addText("SyntaxComment", "// comment\n" + base().dump(), "(line 1, column 1) syntax error: ");
    addText("SyntaxInvalidUtf8", withRaw("/camera/near", "\"\xff\""), "camera: (line ", "syntax error");

    // top level
    addText("RootArray", "[]", "(root): expected a JSON object, got an empty array");
    addText("RootNumber", "42", "(root): expected a JSON object, got 42");
    addText("RootNull", "null", "(root): expected a JSON object, got null");
    add("UnknownTopLevelKey", with("/fog", json::object()), "fog: unknown key",
        "(expected camera, sun, ambient, sky, objects, lights, effects, frame_time, camera_cut_frame, "
        "budget_ms, particles or volumetrics_lookup)");
    add("UnknownTopLevelKeyNotIdentifier", with("/my key\n", 1), R"(["my key\n"]: unknown key)");

    // missing keys
    for (const char* key : {"camera", "sun", "objects"}) {
        add(std::string("Missing_") + key, without(std::string("/") + key), std::string(key) + ": missing");
    }
    for (const char* key : {"position", "look_at", "fov_y_deg", "near", "far"}) {
        add(std::string("MissingCamera_") + key, without(std::string("/camera/") + key),
            std::string("camera.") + key + ": missing");
    }
    for (const char* key : {"direction", "illuminance", "shadows"}) {
        add(std::string("MissingSun_") + key, without(std::string("/sun/") + key),
            std::string("sun.") + key + ": missing");
    }
    add("MissingType", without("/objects/1/type"), "objects[1].type: missing");
    add("MissingPlanePoint", without("/objects/0/point"), "objects[0].point: missing");
    add("MissingPlaneNormal", without("/objects/0/normal"), "objects[0].normal: missing");
    add("MissingPlaneAlbedo", without("/objects/0/albedo"), "objects[0].albedo: missing");
    add("MissingBoxCenter", without("/objects/1/center"), "objects[1].center: missing");
    add("MissingBoxHalfSize", without("/objects/1/half_size"), "objects[1].half_size: missing");
    add("MissingSphereRadius", without("/objects/2/radius"), "objects[2].radius: missing");
    add("MissingSphereCenter", without("/objects/2/center"), "objects[2].center: missing");

    // mistyped keys
    add("CameraNotObject", with("/camera", "x"), "camera: expected an object, got the string \"x\"");
    add("SunNotObject", with("/sun", json::array()), "sun: expected an object");
    add("FovString", with("/camera/fov_y_deg", "60"),
        "camera.fov_y_deg: expected a number, got the string \"60\"");
    add("NearBool", with("/camera/near", true), "camera.near: expected a number, got true");
    add("FarNull", with("/camera/far", nullptr), "camera.far: expected a number, got null");
    add("Ev100Array", with("/camera/ev100", {15}), "camera.ev100: expected a number, got [15]");
    add("PositionTwoNumbers", with("/camera/position", {0, 1}),
        "camera.position: expected an array of 3 numbers");
    add("PositionFourNumbers", with("/camera/position", {0, 1, 2, 3}),
        "camera.position: expected an array of 3");
    add("PositionString", with("/camera/position", "0,1,2"),
        "camera.position: expected an array of 3 numbers");
    add("PositionElementString", with("/camera/position/1", "1"), "camera.position[1]: expected a number");
    add("UpObject", with("/camera/up", json::object()), "camera.up: expected an array of 3 numbers");
    add("IlluminanceTwoNumbers", with("/sun/illuminance", {1, 2}),
        "sun.illuminance: expected an array of 3 numbers, got [1,2]");
    add("ShadowsNumber", with("/sun/shadows", 1), "sun.shadows: expected true or false, got 1");
    add("ShadowsString", with("/sun/shadows", "true"), "sun.shadows: expected true or false");
    add("AmbientString", with("/ambient", "x"), "ambient: expected an array of 3 numbers");
    add("SkyObject", with("/sky", json::object()), "sky: expected an array of 3 numbers");
    add("ObjectsNotArray", with("/objects", json::object()), "objects: expected an array");
    add("ObjectEntryNumber", with("/objects/1", 5), "objects[1]: expected an object, got 5");
    add("TypeNumber", with("/objects/0/type", 5), "objects[0].type: expected a string");
    add("RadiusString", with("/objects/2/radius", "1"), "objects[2].radius: expected a number");
    add("HalfSizeNumber", with("/objects/1/half_size", 1),
        "objects[1].half_size: expected an array of 3 numbers");
    add("AlbedoTwoNumbers", with("/objects/2/albedo", {0.5, 0.5}),
        "objects[2].albedo: expected an array of 3");
    add("EffectsArray", with("/effects", json::array()), "effects: expected an object, got an empty array");
    add("EffectsString", with("/effects", "fog"), "effects: expected an object");

    // non-finite and out-of-range numbers
    addText("NearOverflow", withRaw("/camera/near", "1e999"),
            "camera.near: expected a finite number, got 1e999");
    addText("DirectionOverflow", withRaw("/sun/direction/0", "-1e999"),
            "sun.direction[0]: expected a finite number, got -1e999");
    addText("RadiusOverflow", withRaw("/objects/2/radius", "1e400"),
            "objects[2].radius: expected a finite number");
    addText("EffectsOverflow", withRaw("/effects", R"({"fog": {"density": 1e999}})"),
            "effects.fog.density: expected a finite number");
    addText("RootOverflow", "1e999", "(root): expected a finite number");
    add("FarBeyondFloat", with("/camera/far", 1e300), "camera.far: expected a number of magnitude <= 3.4e38");

    // sizes, albedo, illuminance
    add("RadiusNegative", with("/objects/2/radius", -1),
        "objects[2].radius: expected a number in (0, 1e7], got -1");
    add("RadiusZero", with("/objects/2/radius", 0),
        "objects[2].radius: expected a number in (0, 1e7], got 0");
    add("RadiusUnderflowsToZero", with("/objects/2/radius", 1e-50),
        "objects[2].radius: expected a number in (0, 1e7]");
    add("HalfSizeNegative", with("/objects/1/half_size", {-1, 1, 1}),
        "objects[1].half_size[0]: expected a number in (0, 1e7], got -1");
    add("HalfSizeZero", with("/objects/1/half_size/2", 0.0),
        "objects[1].half_size[2]: expected a number in (0, 1e7]");
    add("AlbedoAboveOne", with("/objects/0/albedo/0", 1.5),
        "objects[0].albedo[0]: expected a number in [0, 1], got 1.5");
    add("AlbedoNegative", with("/objects/1/albedo/1", -0.1),
        "objects[1].albedo[1]: expected a number in [0, 1]");
    add("IlluminanceNegative", with("/sun/illuminance/0", -1),
        "sun.illuminance[0]: expected a number in [0, 1e7], got -1");
    add("AmbientNegative", with("/ambient", {0, -1, 0}), "ambient[1]: expected a number in [0, 1e7]");
    add("SkyNegative", with("/sky", {0, 0, -5}), "sky[2]: expected a number in [0, 1e7], got -5");

    // camera
    add("FovZero", with("/camera/fov_y_deg", 0), "camera.fov_y_deg: expected a number in [0.01, 179], got 0");
    add("Fov180", with("/camera/fov_y_deg", 180),
        "camera.fov_y_deg: expected a number in [0.01, 179], got 180");
    add("FovNegative", with("/camera/fov_y_deg", -5), "camera.fov_y_deg: expected a number in [0.01, 179]");
    add("Fov200", with("/camera/fov_y_deg", 200), "camera.fov_y_deg: expected a number in [0.01, 179]");
    add("NearZero", with("/camera/near", 0), "camera.near: expected a number in [1e-6, 1e6], got 0");
    add("NearNegative", with("/camera/near", -1), "camera.near: expected a number in [1e-6, 1e6], got -1");
    add("FarEqualsNear", with("/camera/far", 0.1),
        "camera.far: expected a number in (near, 1e9], near being 0.1, got 0.1");
    add("FarBelowNear", with("/camera/far", 0.01),
        "camera.far: expected a number in (near, 1e9], near being 0.1");
    add("LookAtEqualsPosition", with("/camera/look_at", {0, 2, 10}),
        "camera.look_at: must be at least 1 mm away");
    add("UpParallel", with("/camera/up", {0, -1, -10}),
        "camera.up: must not be parallel to the view direction");
    add("UpAntiParallel", with("/camera/up", {0, 2, 20}), "camera.up: must not be parallel");
    add("UpZero", with("/camera/up", {0, 0, 0}),
        "camera.up: expected a vector of length >= 1e-6, got [0,0,0]");
    {
        json j = base();
        j["camera"]["position"] = {0, 10, 0};
        j["camera"]["look_at"] = {0, 0, 0};
        add("DefaultUpParallel", j, "camera.up: must not be parallel", "up defaults to [0, 1, 0]");
    }

    // limits that keep what the renderer derives finite and postfx's checks passing (docs/scene-format.md,
    // "Limits"); each was a scene that loaded and then failed at record time or rendered black
    add("IlluminanceAbovePostfxBound", with("/sun/illuminance", {2e7, 0, 0}),
        "sun.illuminance[0]: expected a number in [0, 1e7], got 20000000");
    add("AmbientAbovePostfxBound", with("/ambient", {0, 0, 1.5e7}),
        "ambient[2]: expected a number in [0, 1e7]");
    add("SkyAboveBound", with("/sky", {3e38, 0, 0}), "sky[0]: expected a number in [0, 1e7]");
    add("BoxHalfSizeBreaksShadowFit", with("/objects/1/half_size", {1.8e19, 1, 1}),
        "objects[1].half_size[0]: expected a number in (0, 1e7]");
    add("SphereRadiusBreaksShadowFit", with("/objects/2/radius", 3e38),
        "objects[2].radius: expected a number in (0, 1e7], got 3");
    add("BoxCenterFar", with("/objects/1/center/1", -2e7),
        "objects[1].center[1]: expected a number in [-1e7, 1e7]");
    add("PlanePointFar", with("/objects/0/point/2", 1e8),
        "objects[0].point[2]: expected a number in [-1e7, 1e7]");
    add("CameraPositionFar", with("/camera/position/0", 3e38),
        "camera.position[0]: expected a number in [-1e7, 1e7]");
    add("LookAtFar", with("/camera/look_at/2", -3e38), "camera.look_at[2]: expected a number in [-1e7, 1e7]");
    add("UpTooShort", with("/camera/up", {0, 1e-45, 0}), "camera.up: expected a vector of length >= 1e-6");
    add("UpTooLong", with("/camera/up", {0, 3e38, 0}), "camera.up[1]: expected a number in [-1e7, 1e7]");
    {
        json j = base();
        j["camera"]["near"] = 1e-38;
        j["camera"]["far"] = 3.4e38;
        add("NearTinyFarHuge", j, "camera.near: expected a number in [1e-6, 1e6], got 1e-38");
    }
    add("FarHuge", with("/camera/far", 3.4e38), "camera.far: expected a number in (near, 1e9]");
    add("NearHuge", with("/camera/near", 1e7), "camera.near: expected a number in [1e-6, 1e6]");
    add("FovTiny", with("/camera/fov_y_deg", 1e-30), "camera.fov_y_deg: expected a number in [0.01, 179]");
    add("Ev100OverflowsExposure", with("/camera/ev100", -3e38),
        "camera.ev100: expected a number in [-30, 30]");
    add("Ev100UnderflowsExposure", with("/camera/ev100", 200),
        "camera.ev100: expected a number in [-30, 30], got 200");

    // directions
    add("SunDirectionZero", with("/sun/direction", {0, 0, 0}), "sun.direction: expected a non-zero vector");
    add("PlaneNormalZero", with("/objects/0/normal", {0, 0, 0}),
        "objects[0].normal: expected a non-zero vector");

    // object types and unknown keys
    add("UnknownType", with("/objects/0/type", "cone"),
        R"(objects[0].type: unknown object type "cone" (expected plane, box or sphere))");
    add("TypeIsCaseSensitive", with("/objects/2/type", "Sphere"),
        R"(objects[2].type: unknown object type "Sphere")");
    add("UnknownCameraKey", with("/camera/fov", 60), "camera.fov: unknown key",
        "(expected position, look_at, up, fov_y_deg, near, far, ev100, velocity or yaw_rate)");
    add("UnknownSunKey", with("/sun/color", {1, 1, 1}), "sun.color: unknown key");
    add("SphereWithHalfSize", with("/objects/2/half_size", {1, 1, 1}),
        "objects[2].half_size: unknown key for a sphere");
    add("PlaneWithCenter", with("/objects/0/center", {1, 1, 1}),
        "objects[0].center: unknown key for a plane");
    add("BoxWithRadius", with("/objects/1/radius", 1), "objects[1].radius: unknown key for a box");
    add("UnknownKeyWithNewline", with("/camera/near\nx", 1), R"(camera["near\nx"]: unknown key)");

    // duplicate keys and nesting
    addText("DuplicateTopLevelKey", R"({"camera": {}, "camera": {}})", "camera: duplicate key");
    {
        std::string text = base().dump();
        text.replace(text.find("\"near\""), 6, "\"near\":0.2,\"near\"");
        addText("DuplicateCameraKey", text, "camera.near: duplicate key");
    }
    addText("DeepNesting",
            withRaw("/effects", "{\"a\":" + std::string(100, '[') + std::string(100, ']') + "}"),
            "effects.a[0][0]", "nested deeper than 64 levels");
    return r;
}

class DemoSceneRejects : public ::testing::TestWithParam<Rejection> {};

TEST_P(DemoSceneRejects, WithOneLineNamingTheKeyPath) {
    const Rejection& c = GetParam();
    const Parsed p = parse(c.text);
    ASSERT_FALSE(p.ok) << c.text;
    EXPECT_TRUE(isOneLine(p.error)) << p.error;
    EXPECT_EQ(p.error.rfind(c.path, 0), 0u)
        << "error: " << p.error << "\nexpected it to start with: " << c.path;
    EXPECT_NE(p.error.find(c.fragment), std::string::npos)
        << "error: " << p.error << "\nexpected: " << c.fragment;
}

INSTANTIATE_TEST_SUITE_P(Cases, DemoSceneRejects, ::testing::ValuesIn(rejections()),
                         [](const ::testing::TestParamInfo<Rejection>& info) { return info.param.name; });

TEST(DemoSceneParse, SyntaxErrorPositionIsLineAndColumn) {
    // The error is at the '0' of "0.2", after a two-byte character on the same line.
    const std::string text = "{\n  \"camera\": {\n    \"é\" 0.2\n  }\n}\n";
    const Parsed p = parse(text);
    ASSERT_FALSE(p.ok);
    EXPECT_EQ(p.error.rfind("(line 3, column 9) syntax error: ", 0), 0u) << p.error;
    EXPECT_NE(p.error.find("expected ':'"), std::string::npos) << p.error;
}

// A byte that is not UTF-8 in a string: the object it is in, then the position.
TEST(DemoSceneParse, InvalidUtf8NamesTheObjectItIsIn) {
    const std::string text =
        "{\"camera\": {\"position\": [0, 2, 10]},\n \"effects\": {\"fog\": {\"x\": \"a\xff\"}}}";
    const Parsed p = parse(text);
    ASSERT_FALSE(p.ok);
    EXPECT_EQ(p.error.rfind("effects.fog: (line 2, column ", 0), 0u) << p.error;
    EXPECT_NE(p.error.find("UTF-8"), std::string::npos) << p.error;
}

TEST(DemoSceneParse, VeryDeepNestingDoesNotCrash) {
    const std::size_t depth = 1000000;
    const Parsed arrays = parse(std::string(depth, '[') + std::string(depth, ']'));
    EXPECT_FALSE(arrays.ok);
    EXPECT_EQ(arrays.error.rfind("[0][0]", 0), 0u) << arrays.error.substr(0, 100);
    std::string objects;
    for (std::size_t i = 0; i < depth; ++i)
        objects += "{\"a\":";
    const Parsed unclosed = parse(objects);
    EXPECT_FALSE(unclosed.ok);
    EXPECT_EQ(unclosed.error.rfind("a.a.a.a", 0), 0u) << unclosed.error.substr(0, 100);
}

TEST(DemoSceneParse, NestingUpToTheLimitIsAccepted) {
    // The root object is level 1, effects level 2, so 62 more levels fit: the JSON is read, and the
    // error is the unknown key (no scene key takes nested arrays).
    const Parsed p =
        parse(withRaw("/effects", "{\"a\":" + std::string(62, '[') + std::string(62, ']') + "}"));
    EXPECT_FALSE(p.ok);
    EXPECT_EQ(p.error.rfind("effects.a: unknown key (expected fog, froxel_fog, atmosphere or clouds)", 0), 0u)
        << p.error;
}

// ---- robustness ---------------------------------------------------------------------------------

void expectWellBehaved(const std::string& text) {
    Scene scene;
    std::string error;
    bool ok = false;
    ASSERT_NO_THROW(ok = demo::parseScene(text, scene, error));
    if (ok) {
        EXPECT_TRUE(error.empty());
        // Whatever was accepted serialises and reads back to the same scene.
        const Parsed again = parse(demo::sceneToJson(scene).dump());
        ASSERT_TRUE(again.ok) << again.error;
        expectSameScene(again.scene, scene);
    } else {
        EXPECT_TRUE(isOneLine(error)) << "input:\n" << text << "\nerror: " << error;
    }
}

TEST(DemoSceneFuzz, EveryTruncationOfTheDefaultScene) {
    const std::string text = demo::defaultSceneJson();
    for (std::size_t n = 0; n <= text.size(); ++n) {
        expectWellBehaved(text.substr(0, n));
        if (::testing::Test::HasFailure()) FAIL() << "truncated at " << n;
    }
}

TEST(DemoSceneFuzz, RandomByteMutationsOfTheDefaultScene) {
    const std::string original = demo::defaultSceneJson();
    const std::string interesting = "{}[],:\"\\-+.eE0123456789 \n\tnulltruefalse\x01\x7f\xc3\xa9\xff";
    std::mt19937 rng(20240611u);
    const auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    int accepted = 0;
    for (int iteration = 0; iteration < 4000; ++iteration) {
        std::string text = original;
        const std::size_t mutations = 1 + pick(4);
        for (std::size_t m = 0; m < mutations && !text.empty(); ++m) {
            const std::size_t at = pick(text.size());
            const char c = pick(2) ? interesting[pick(interesting.size())] : char(pick(256));
            switch (pick(3)) {
                case 0:
                    text[at] = c;
                    break;
                case 1:
                    text.insert(text.begin() + std::ptrdiff_t(at), c);
                    break;
                default:
                    text.erase(at, 1 + pick(8));
                    break;
            }
        }
        Scene scene;
        std::string error;
        if (demo::parseScene(text, scene, error)) ++accepted;
        expectWellBehaved(text);
        if (::testing::Test::HasFailure()) FAIL() << "iteration " << iteration;
    }
    // Some mutations (whitespace, digits) keep the scene valid; most must be rejected.
    EXPECT_GT(accepted, 0);
    EXPECT_LT(accepted, 4000);
}

// ---- text helpers -------------------------------------------------------------------------------

TEST(DemoJsonText, PositionOf) {
    using demo::json_text::positionOf;
    const std::string text = "ab\ncé\n\nx";
    EXPECT_EQ(positionOf(text, 0).line, 1u);
    EXPECT_EQ(positionOf(text, 0).column, 1u);
    EXPECT_EQ(positionOf(text, 2).column, 3u);  // the '\n' ends line 1
    EXPECT_EQ(positionOf(text, 3).line, 2u);
    EXPECT_EQ(positionOf(text, 6).column, 3u);  // after "cé": 'é' is one character
    EXPECT_EQ(positionOf(text, 7).line, 3u);
    EXPECT_EQ(positionOf(text, 8).line, 4u);
    EXPECT_EQ(positionOf(text, 100).line, 4u);  // clamped
    EXPECT_EQ(positionOf(text, 100).column, 2u);
}

TEST(DemoJsonText, OneLine) {
    using demo::json_text::oneLine;
    EXPECT_EQ(oneLine("a\nb\r\tc"), "a b  c");
    EXPECT_EQ(oneLine("caf\xc3\xa9"), "caf\xc3\xa9");
    EXPECT_EQ(oneLine("\xff\xc3"), "??");
    EXPECT_EQ(oneLine("\xed\xa0\x80"), "???");    // a UTF-16 surrogate
    EXPECT_EQ(oneLine("a\xe2\x80\xa8z"), "a z");  // U+2028 LINE SEPARATOR
}

TEST(DemoJsonText, FormatFloat) {
    using demo::json_text::formatFloat;
    using demo::json_text::roundTripDouble;
    EXPECT_EQ(formatFloat(0.1f), "0.1");
    EXPECT_EQ(formatFloat(100000.0f), "100000");
    EXPECT_EQ(formatFloat(0.0001f), "0.0001");
    EXPECT_EQ(formatFloat(1e-7f), "0.0000001");
    EXPECT_EQ(formatFloat(1e-9f), "1e-09");
    EXPECT_EQ(formatFloat(3e38f), "3e+38");
    EXPECT_EQ(json(roundTripDouble(0.1f)).dump(), "0.1");
    std::mt19937 rng(7u);
    for (int i = 0; i < 10000; ++i) {
        const uint32_t bits = rng();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isfinite(f)) continue;
        ASSERT_EQ(float(roundTripDouble(f)), f) << formatFloat(f);
    }
}

TEST(DemoJsonText, KeyPaths) {
    using demo::json_text::indexPath;
    using demo::json_text::keyPath;
    EXPECT_EQ(keyPath("", "camera"), "camera");
    EXPECT_EQ(keyPath("camera", "near"), "camera.near");
    EXPECT_EQ(indexPath("objects", 2), "objects[2]");
    EXPECT_EQ(keyPath("effects", "a b"), R"(effects["a b"])");
    EXPECT_EQ(keyPath("effects", "1x"), R"(effects["1x"])");
}

}  // namespace
