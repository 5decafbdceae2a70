// Scene files: motion (demo/scene/motion.cpp, docs/scene-format.md#motion) -- camera.velocity and
// camera.yaw_rate, lights[i].velocity and intensity_change, frame_time, camera_cut_frame: defaults, every
// key read, round trips, errors naming their key path, and the scene at frame n (sceneAtFrame).
#include "fuzz/scene_oracle.h"
#include "host/camera_math.h"
#include "scene/json_text.h"
#include "scene/motion.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
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

// A still scene: a camera at (1, 2, 3) looking 10 m down -z, a box, one point light.
json base() {
    return json::parse(R"({
      "camera": {"position": [1, 2, 3], "look_at": [1, 2, -7], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [1000, 1000, 1000], "shadows": true},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]},
                  {"type": "box", "center": [0, 1, -5], "half_size": [1, 1, 1], "albedo": [0.5, 0.5, 0.5]}],
      "lights": [{"type": "point", "position": [0, 3, -2], "intensity": [10, 20, 30]}]
    })");
}

// base() with every motion key.
json moving() {
    json j = base();
    j["camera"]["velocity"] = {2, 0, -1};
    j["camera"]["yaw_rate"] = 90;
    j["lights"][0]["velocity"] = {1, 0.5, 0};
    j["lights"][0]["intensity_change"] = {{"frame", 10}, {"intensity", {0, 0, 0}}};
    j["frame_time"] = 0.02;
    j["camera_cut_frame"] = 5;
    return j;
}

Scene load(const json& j) {
    const Parsed p = parse(j);
    EXPECT_TRUE(p.ok) << p.error;
    return p.scene;
}

void expectNear(const glm::vec3& a, const glm::dvec3& b, double tolerance, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], tolerance) << what << "[" << c << "]";
}

glm::dvec3 viewDirection(const demo::Camera& c) {
    return glm::normalize(glm::dvec3(c.lookAt) - glm::dvec3(c.position));
}

// ---- keys ---------------------------------------------------------------------------------------

TEST(DemoSceneMotion, AbsentMeansStill) {
    const Scene s = load(base());
    EXPECT_EQ(s.camera.velocity, glm::vec3(0.0f));
    EXPECT_EQ(s.camera.yawRateDeg, 0.0f);
    EXPECT_EQ(s.lights[0].velocity, glm::vec3(0.0f));
    EXPECT_FALSE(s.lights[0].intensityChange.has_value());
    EXPECT_EQ(s.frameTime, 1.0 / 60.0);  // exactly: the time of frame n is n / 60 s, as before motion
    EXPECT_FALSE(s.cameraCutFrame.has_value());
    EXPECT_FALSE(demo::hasMotion(s));
    // Every frame is frame 0.
    for (uint64_t n : {1ull, 1000ull, 4294967295ull})
        EXPECT_EQ(demo::sceneToJson(demo::sceneAtFrame(s, n)), demo::sceneToJson(s)) << "frame " << n;
}

TEST(DemoSceneMotion, EveryKeyIsRead) {
    const Scene s = load(moving());
    EXPECT_EQ(s.camera.velocity, glm::vec3(2, 0, -1));
    EXPECT_EQ(s.camera.yawRateDeg, 90.0f);
    EXPECT_EQ(s.lights[0].velocity, glm::vec3(1, 0.5f, 0));
    ASSERT_TRUE(s.lights[0].intensityChange.has_value());
    EXPECT_EQ(s.lights[0].intensityChange->frame, 10u);
    EXPECT_EQ(s.lights[0].intensityChange->intensity, glm::vec3(0.0f));
    EXPECT_EQ(s.frameTime, 0.02);  // kept in double, as written
    ASSERT_TRUE(s.cameraCutFrame.has_value());
    EXPECT_EQ(*s.cameraCutFrame, 5u);
    EXPECT_TRUE(demo::hasMotion(s));
}

TEST(DemoSceneMotion, EachKindOfMotionCounts) {
    for (const char* pointer : {"/camera/velocity", "/camera/yaw_rate", "/lights/0/velocity"}) {
        json j = base();
        j[json::json_pointer(pointer)] =
            std::string(pointer).ends_with("yaw_rate") ? json(-1) : json({0, 0, 1});
        EXPECT_TRUE(demo::hasMotion(load(j))) << pointer;
    }
    json change = base();
    change["lights"][0]["intensity_change"] = {{"frame", 0}, {"intensity", {10, 20, 30}}};
    EXPECT_TRUE(demo::hasMotion(load(change)));
    json cut = base();
    cut["camera_cut_frame"] = 3;
    EXPECT_FALSE(demo::hasMotion(load(cut)));  // a cut moves nothing
}

TEST(DemoSceneMotion, RoundTrip) {
    for (const json& j : {base(), moving()}) {
        const Scene s = load(j);
        const json written = demo::sceneToJson(s);
        EXPECT_TRUE(written["camera"].contains("velocity"));
        EXPECT_TRUE(written["camera"].contains("yaw_rate"));
        EXPECT_TRUE(written["lights"][0].contains("velocity"));
        EXPECT_TRUE(written.contains("frame_time"));
        EXPECT_EQ(written["lights"][0].contains("intensity_change"), s.lights[0].intensityChange.has_value());
        EXPECT_EQ(written.contains("camera_cut_frame"), s.cameraCutFrame.has_value());
        const Scene again = load(written);
        EXPECT_EQ(demo::sceneToJson(again), written);
        EXPECT_EQ(again.frameTime, s.frameTime);  // the default 1/60 too, to the last bit
        EXPECT_EQ(again.camera.velocity, s.camera.velocity);
        EXPECT_EQ(again.camera.yawRateDeg, s.camera.yawRateDeg);
    }
}

TEST(DemoSceneMotion, BoundsAreAccepted) {
    json j = base();
    j["camera"]["velocity"] = {1e4, -1e4, 0};
    j["camera"]["yaw_rate"] = -36000;
    j["lights"][0]["velocity"] = {-1e4, 0, 1e4};
    j["lights"][0]["intensity_change"] = {{"frame", 4294967295.0}, {"intensity", {0, 1e9, 0}}};
    j["frame_time"] = 1;
    j["camera_cut_frame"] = 0;
    EXPECT_TRUE(parse(j).ok) << parse(j).error;
    j["frame_time"] = 1e-30;  // any time > 0
    EXPECT_TRUE(parse(j).ok) << parse(j).error;
}

struct Rejection {
    const char* name;
    std::string pointer;  // a JSON pointer into base()
    json value;
    std::string error;  // the message starts with it
};

std::vector<Rejection> rejections() {
    return {
        {"CameraVelocityTooFast",
         "/camera/velocity",
         {2e4, 0, 0},
         "camera.velocity[0]: expected a number in [-1e4, 1e4], got 20000.0"},
        {"CameraVelocityNotArray", "/camera/velocity", 1, "camera.velocity: expected an array of 3 numbers"},
        {"CameraVelocityShort",
         "/camera/velocity",
         {1, 2},
         "camera.velocity: expected an array of 3 numbers"},
        {"YawRateTooFast", "/camera/yaw_rate", 36001,
         "camera.yaw_rate: expected a number in [-36000, 36000]"},
        {"YawRateString", "/camera/yaw_rate", "fast", "camera.yaw_rate: expected a number, got the string"},
        {"CameraUnknownKey", "/camera/speed", 1,
         "camera.speed: unknown key (expected position, look_at, up, fov_y_deg, near, far, ev100, velocity "
         "or "
         "yaw_rate)"},
        {"FrameTimeZero", "/frame_time", 0, "frame_time: expected a number in (0, 1], got 0"},
        {"FrameTimeNegative", "/frame_time", -0.01, "frame_time: expected a number in (0, 1]"},
        {"FrameTimeTooLong", "/frame_time", 1.5, "frame_time: expected a number in (0, 1]"},
        {"FrameTimeBool", "/frame_time", true, "frame_time: expected a number"},
        {"CutNegative", "/camera_cut_frame", -1, "camera_cut_frame: expected an integer in [0, 4294967295]"},
        {"CutFraction", "/camera_cut_frame", 2.5, "camera_cut_frame: expected an integer"},
        {"CutTooLate", "/camera_cut_frame", 4294967296.0, "camera_cut_frame: expected an integer in"},
        {"TopUnknownKey", "/frametime", 0.01,
         "frametime: unknown key (expected camera, sun, ambient, sky, "
         "objects, lights, effects, frame_time, camera_cut_frame, budget_ms, particles or "
         "volumetrics_lookup)"},
        {"LightVelocityTooFast",
         "/lights/0/velocity",
         {0, 0, -1e5},
         "lights[0].velocity[2]: expected a number in [-1e4, 1e4]"},
        {"LightVelocityNotArray", "/lights/0/velocity", "up", "lights[0].velocity: expected an array of 3"},
        {"ChangeNotObject", "/lights/0/intensity_change", 3,
         "lights[0].intensity_change: expected an object"},
        {"ChangeFrameMissing",
         "/lights/0/intensity_change",
         {{"intensity", {0, 0, 0}}},
         "lights[0].intensity_change.frame: missing"},
        {"ChangeIntensityMissing",
         "/lights/0/intensity_change",
         {{"frame", 3}},
         "lights[0].intensity_change.intensity: missing"},
        {"ChangeFrameNegative",
         "/lights/0/intensity_change",
         {{"frame", -3}, {"intensity", {0, 0, 0}}},
         "lights[0].intensity_change.frame: expected an integer in [0, 4294967295]"},
        {"ChangeIntensityNegative",
         "/lights/0/intensity_change",
         {{"frame", 3}, {"intensity", {0, -1, 0}}},
         "lights[0].intensity_change.intensity[1]: expected a number in [0, 1e9]"},
        {"ChangeIntensityTooBright",
         "/lights/0/intensity_change",
         {{"frame", 3}, {"intensity", {2e9, 0, 0}}},
         "lights[0].intensity_change.intensity[0]: expected a number in [0, 1e9]"},
        {"ChangeUnknownKey",
         "/lights/0/intensity_change",
         {{"frame", 3}, {"intensity", {0, 0, 0}}, {"color", {1, 1, 1}}},
         "lights[0].intensity_change.color: unknown key (expected frame or intensity)"},
        {"LightUnknownKey", "/lights/0/speed", 1,
         "lights[0].speed: unknown key for a point light (expected type, position, intensity, radius, range, "
         "velocity, intensity_change, shadows or shadow_resolution)"},
    };
}

TEST(DemoSceneMotion, ErrorsNameTheKeyPath) {
    for (const Rejection& r : rejections()) {
        SCOPED_TRACE(r.name);
        json j = base();
        j[json::json_pointer(r.pointer)] = r.value;
        const Parsed p = parse(j);
        ASSERT_FALSE(p.ok);
        EXPECT_EQ(demo::json_text::oneLine(p.error), p.error);
        EXPECT_EQ(p.error.rfind(r.error, 0), 0u)
            << "error: " << p.error << "\nexpected to start with: " << r.error;
    }
}

// ---- the scene at frame n -------------------------------------------------------------------------

TEST(DemoSceneMotion, TimeOfFrameIsFrameTimesFrameTime) {
    const Scene still = load(base());
    for (uint64_t n : {0ull, 1ull, 7ull, 123456ull})
        EXPECT_EQ(demo::frameTimeSeconds(still, n), double(n) * (1.0 / 60.0)) << n;  // as before motion
    const Scene s = load(moving());
    EXPECT_DOUBLE_EQ(demo::frameTimeSeconds(s, 50), 1.0);
}

// At frame n (t = n · frame_time) the camera is at position + velocity · t, turned yaw_rate · t to the
// right about +y: here 90°/s for 0.5 s (25 frames of 0.02 s) is 45° from -z toward +x.
TEST(DemoSceneMotion, CameraAfterNFrames) {
    const Scene s = load(moving());
    const Scene f = demo::sceneAtFrame(s, 25);
    const double t = 0.5;
    expectNear(f.camera.position, glm::dvec3(1 + 2 * t, 2, 3 - 1 * t), 1e-6, "position");
    const double h = std::sqrt(0.5);
    expectNear(glm::vec3(viewDirection(f.camera)), glm::dvec3(h, 0, -h), 1e-6, "view direction");
    EXPECT_NEAR(glm::length(glm::dvec3(f.camera.lookAt) - glm::dvec3(f.camera.position)), 10.0, 1e-5);
    expectNear(f.camera.up, glm::dvec3(0, 1, 0), 1e-7, "up");
    // Frame 0 is the file's camera; what is not motion stays.
    EXPECT_EQ(demo::sceneToJson(demo::sceneAtFrame(s, 0)), demo::sceneToJson(s));
    EXPECT_EQ(f.camera.fovYDeg, s.camera.fovYDeg);
    EXPECT_EQ(f.camera.velocity, s.camera.velocity);
    EXPECT_EQ(f.objects.size(), s.objects.size());
}

// The sense of yaw_rate: positive turns from -z toward +x (right, clockwise seen from above), as the
// window's fly camera and the sun's azimuth; a whole turn comes back.
TEST(DemoSceneMotion, PositiveYawRateTurnsRight) {
    json j = base();
    j["camera"]["yaw_rate"] = 90;
    j["frame_time"] = 0.25;
    const Scene s = load(j);
    const std::vector<glm::dvec3> expected{{0, 0, -1}, {1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}};
    for (uint64_t n = 0; n <= 16; n += 4) {
        const Scene f = demo::sceneAtFrame(s, n);
        expectNear(glm::vec3(viewDirection(f.camera)), expected[n / 4], 1e-6, "view direction");
        expectNear(f.camera.position, glm::dvec3(1, 2, 3), 0.0, "position");  // turning in place
    }
    j["camera"]["yaw_rate"] = -90;
    expectNear(glm::vec3(viewDirection(demo::sceneAtFrame(load(j), 4).camera)), glm::dvec3(-1, 0, 0), 1e-6,
               "view direction turning left");
}

// A tilted view turns with its up vector: the angle between them, the pitch and up's height are kept.
TEST(DemoSceneMotion, YawKeepsPitchAndUp) {
    json j = base();
    j["camera"]["look_at"] = {4, -1, -1};
    j["camera"]["up"] = {0.2, 1, 0.1};
    j["camera"]["yaw_rate"] = 33;
    const Scene s = load(j);
    const Scene f = demo::sceneAtFrame(s, 77);
    const glm::dvec3 v0 = viewDirection(s.camera), v1 = viewDirection(f.camera);
    const glm::dvec3 u0 = glm::normalize(glm::dvec3(s.camera.up)),
                     u1 = glm::normalize(glm::dvec3(f.camera.up));
    EXPECT_NEAR(v1.y, v0.y, 1e-6);
    EXPECT_NEAR(u1.y, u0.y, 1e-6);
    EXPECT_NEAR(glm::dot(v1, u1), glm::dot(v0, u0), 1e-6);
    const double turned = std::atan2(v1.x, -v1.z) - std::atan2(v0.x, -v0.z);
    EXPECT_NEAR(std::remainder(turned, 2 * M_PI), glm::radians(std::fmod(33.0 * 77.0 / 60.0, 360.0)), 1e-6);
}

TEST(DemoSceneMotion, LightMovesAndChangesIntensityAtItsFrame) {
    const Scene s = load(moving());  // velocity (1, 0.5, 0) m/s, off from frame 10, 0.02 s per frame
    for (uint64_t n : {0ull, 9ull, 10ull, 11ull, 500ull}) {
        const demo::Light l = demo::sceneAtFrame(s, n).lights[0];
        const double t = double(n) * 0.02;
        expectNear(l.position, glm::dvec3(0 + t, 3 + 0.5 * t, -2), 1e-5, "position");
        EXPECT_EQ(l.intensity, n < 10 ? glm::vec3(10, 20, 30) : glm::vec3(0.0f)) << "frame " << n;
    }
    // Turned back on: the change is the intensity from its frame on, whatever the file's intensity.
    json j = base();
    j["lights"][0]["intensity"] = {0, 0, 0};
    j["lights"][0]["intensity_change"] = {{"frame", 3}, {"intensity", {5, 6, 7}}};
    const Scene on = load(j);
    EXPECT_EQ(demo::sceneAtFrame(on, 2).lights[0].intensity, glm::vec3(0.0f));
    EXPECT_EQ(demo::sceneAtFrame(on, 3).lights[0].intensity, glm::vec3(5, 6, 7));
}

TEST(DemoSceneMotion, MoveToFrameChangesOnlyCameraAndLights) {
    const Scene s = load(moving());
    Scene state = s;
    state.sky = glm::vec3(7.0f);  // not the scene's: left alone
    demo::moveToFrame(s, 40, state);
    EXPECT_EQ(state.sky, glm::vec3(7.0f));
    const Scene expected = demo::sceneAtFrame(s, 40);
    EXPECT_EQ(state.camera.position, expected.camera.position);
    EXPECT_EQ(state.camera.lookAt, expected.camera.lookAt);
    EXPECT_EQ(state.lights[0].position, expected.lights[0].position);
    EXPECT_EQ(state.lights[0].intensity, expected.lights[0].intensity);
}

TEST(DemoSceneMotion, CameraCutIsItsFrameOnly) {
    const Scene s = load(moving());  // camera_cut_frame 5
    EXPECT_FALSE(demo::isCameraCut(s, 0));
    EXPECT_FALSE(demo::isCameraCut(s, 4));
    EXPECT_TRUE(demo::isCameraCut(s, 5));
    EXPECT_FALSE(demo::isCameraCut(s, 6));
    EXPECT_FALSE(demo::isCameraCut(load(base()), 0));
}

// Positions stop at the coordinate limit, so that every frame of a file that loads renders: a camera
// and a light at the edge of the world, moving out at full speed with the fastest turn, at the last
// frame a 32-bit number names.
TEST(DemoSceneMotion, PositionsStopAtTheLimitAndEveryFrameRenders) {
    json j = base();
    j["camera"]["position"] = {9.99e6, 1, -1e7};
    j["camera"]["look_at"] = {9.99e6, 1, -9999998};  // 2 m along +z
    j["camera"]["velocity"] = {1e4, 0, -1e4};
    j["camera"]["yaw_rate"] = 36000;
    j["lights"][0]["position"] = {-1e7, 0, 0};
    j["lights"][0]["velocity"] = {-1e4, 1e4, 0};
    j["frame_time"] = 1;
    const Scene s = load(j);
    EXPECT_EQ(demo::fuzz::renderProblem(s), "");
    const Scene f = demo::sceneAtFrame(s, 4294967295u);
    expectNear(f.camera.position, glm::dvec3(1e7, 1, -1e7), 0.0, "camera position");
    expectNear(f.lights[0].position, glm::dvec3(-1e7, 1e7, 0), 0.0, "light position");
    // look_at stays distinct from the position in float, and the view matrix finite.
    EXPECT_NE(f.camera.lookAt, f.camera.position);
    const glm::mat4 view = demo::cameraView(f.camera);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_TRUE(std::isfinite(view[c][r]));
}

}  // namespace
