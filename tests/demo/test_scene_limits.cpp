// The scene loader's limits (docs/scene-format.md, "Limits"): a file that loads renders (the fuzz oracle,
// tests/demo/fuzz/scene_oracle.h, on the committed scenes, the largest allowed scene and the fuzzer's
// regression inputs), the oracle itself catches what the limits keep out, and the object count is capped.
#include "fuzz/scene_oracle.h"
#include "host/camera_math.h"
#include "host/scene_mesh.h"
#include "scene/json_text.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

const std::string kSourceDir = POSTFX_SOURCE_DIR;

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

json sceneWithObjects(std::size_t count, const json& object) {
    json j = json::parse(R"({
      "camera": {"position": [0, 20, 60], "look_at": [0, 0, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0.3, 1, 0.2], "illuminance": [100000, 100000, 100000], "shadows": true},
      "objects": []
    })");
    for (std::size_t i = 0; i < count; ++i)
        j["objects"].push_back(object);
    return j;
}

json sphere() {
    return json::parse(R"({"type": "sphere", "center": [0, 1, 0], "radius": 1, "albedo": [0.5, 0.5, 0.5]})");
}

demo::Scene loaded(const std::string& text) {
    demo::Scene scene;
    std::string error;
    EXPECT_TRUE(demo::parseScene(text, scene, error)) << error;
    return scene;
}

TEST(DemoSceneLimits, ObjectCountIsCapped) {
    demo::Scene scene;
    std::string error;
    EXPECT_TRUE(demo::parseScene(sceneWithObjects(demo::limits::kMaxObjects, sphere()).dump(), scene, error))
        << error;
    EXPECT_EQ(scene.objects.size(), demo::limits::kMaxObjects);
    EXPECT_FALSE(
        demo::parseScene(sceneWithObjects(demo::limits::kMaxObjects + 1, sphere()).dump(), scene, error));
    EXPECT_EQ(error, "objects: 4097 objects are more than the limit of 4096");
}

TEST(DemoSceneLimits, LargestSceneCannotWrapIndices) {
    // kMaxObjects spheres, the object with the most vertices and indices (one sphere's mesh, times the limit:
    // building the whole mesh takes seconds in a sanitizer build).
    const demo::SceneMesh one = demo::buildSceneMesh(loaded(sceneWithObjects(1, sphere()).dump()), false);
    const uint64_t indices = uint64_t(one.indices.size()) * demo::limits::kMaxObjects;
    const uint64_t vertices = uint64_t(one.vertices.size()) * demo::limits::kMaxObjects;
    EXPECT_LT(indices, uint64_t(std::numeric_limits<uint32_t>::max()) / 16);
    EXPECT_LT(vertices, uint64_t(std::numeric_limits<uint32_t>::max()) / 16);
}

TEST(DemoSceneLimits, CommittedScenesRender) {
    int count = 0;
    for (const char* dir : {"/demo/scenes", "/tests/fog/stability/scenes"}) {
        for (const fs::directory_entry& e : fs::directory_iterator(kSourceDir + dir)) {
            if (e.path().extension() != ".json") continue;
            SCOPED_TRACE(e.path().string());
            EXPECT_EQ(demo::fuzz::renderProblem(loaded(readFile(e.path()))), "");
            ++count;
        }
    }
    EXPECT_GT(count, 10);
}

TEST(DemoSceneLimits, BoundaryScenesRender) {
    // Every limit at once, at the edge that strains the renderer's numbers most.
    const demo::Scene scene = loaded(R"({
      "camera": {"position": [1e7, -1e7, 1e7], "look_at": [-1e7, 1e7, -1e7], "up": [1e-6, 0, 0],
                 "fov_y_deg": 179, "near": 1e-6, "far": 1e9, "ev100": -30},
      "sun": {"direction": [0, 1, 0], "illuminance": [1e7, 1e7, 1e7], "shadows": true},
      "ambient": [1e7, 1e7, 1e7], "sky": [1e7, 1e7, 1e7],
      "objects": [
        {"type": "box", "center": [1e7, 1e7, 1e7], "half_size": [1e7, 1e7, 1e7], "albedo": [1, 1, 1]},
        {"type": "sphere", "center": [-1e7, -1e7, -1e7], "radius": 1e7, "albedo": [1, 1, 1]},
        {"type": "plane", "point": [1e7, 1e7, -1e7], "normal": [1, 1e-30, 0], "albedo": [1, 1, 1]}
      ],
      "effects": {"fog": {"max_distance": 1e7, "base_height": 3e38, "quality": "auto"}}
    })");
    EXPECT_EQ(demo::fuzz::renderProblem(scene), "");
    demo::Scene tight = scene;
    tight.camera.fovYDeg = 0.01f;
    tight.camera.nearPlane = 1e6f;
    tight.camera.farPlane = std::nextafter(1e6f, 2e6f);
    tight.camera.ev100 = 30.0f;
    EXPECT_EQ(demo::fuzz::renderProblem(tight), "");
}

// The oracle fails on what the limits keep out (scenes built past the loader), so the fuzzer's silence
// means something.
TEST(DemoSceneLimits, OracleCatchesWhatTheLimitsKeepOut) {
    const demo::Scene good = loaded(sceneWithObjects(1, sphere()).dump());
    ASSERT_EQ(demo::fuzz::renderProblem(good), "");
    auto problem = [&](auto change) {
        demo::Scene s = good;
        change(s);
        return demo::fuzz::renderProblem(s);
    };
    // A shadow fit float cannot hold is not valid: the renderer then draws no shadow map (camera_math).
    for (auto change : {+[](demo::Scene& s) { s.objects[0].radius = 3e38f; },
                        +[](demo::Scene& s) { s.objects[0].position.x = 3e38f; }}) {
        demo::Scene s = good;
        change(s);
        EXPECT_FALSE(demo::fitShadowMap(s, 2048).valid);
        EXPECT_EQ(demo::fuzz::renderProblem(s), "");
    }
    EXPECT_NE(problem([](demo::Scene& s) { s.camera.position.x = 3e38f; }), "");
    EXPECT_NE(problem([](demo::Scene& s) { s.camera.up = {0.0f, 1e-45f, 0.0f}; }), "");
    EXPECT_NE(problem([](demo::Scene& s) {
                  s.camera.nearPlane = 1e-38f;
                  s.camera.farPlane = 3.4e38f;
              }),
              "");
    EXPECT_NE(problem([](demo::Scene& s) { s.camera.ev100 = -3e38f; }), "");
    EXPECT_NE(problem([](demo::Scene& s) { s.camera.ev100 = -60.0f; }), "");
    EXPECT_NE(problem([](demo::Scene& s) { s.sun.illuminance.x = 2e7f; }), "");
    EXPECT_NE(problem([](demo::Scene& s) { s.ambient.y = 2e7f; }), "");
    EXPECT_NE(problem([](demo::Scene& s) {
                  s.fog.enabled = true;
                  s.fog.steps = 0;
              }),
              "");
}

// Inputs the fuzzer found (tests/demo/fuzz/regressions/README.md): NAME.json with NAME.expected holding the
// error line it must give, or "loads" when it must load, render and round-trip through sceneToJson.
TEST(DemoSceneLimits, FuzzRegressions) {
    const fs::path dir = kSourceDir + "/tests/demo/fuzz/regressions";
    int count = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".json") continue;
        SCOPED_TRACE(e.path().string());
        fs::path expectedPath = e.path();
        expectedPath.replace_extension(".expected");
        std::string expected = readFile(expectedPath);
        while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r'))
            expected.pop_back();
        ASSERT_FALSE(expected.empty()) << "missing " << expectedPath;
        demo::Scene scene;
        std::string error;
        const bool ok = demo::parseScene(readFile(e.path()), scene, error);
        if (expected == "loads") {
            EXPECT_TRUE(ok) << error;
            if (ok) {
                EXPECT_EQ(demo::fuzz::renderProblem(scene), "");
                // And it reads back from what sceneToJson writes as the same scene.
                demo::Scene again;
                EXPECT_TRUE(demo::parseScene(demo::sceneToJson(scene).dump(), again, error)) << error;
                EXPECT_EQ(demo::sceneToJson(again), demo::sceneToJson(scene));
            }
        } else {
            EXPECT_FALSE(ok);
            EXPECT_EQ(error, expected);
            EXPECT_EQ(demo::json_text::oneLine(error), error);
        }
        ++count;
    }
    EXPECT_GT(count, 0);
}

}  // namespace
