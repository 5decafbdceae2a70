// postfx-bench's in-motion measurement, its pure side (bench/motion.h, bench/motion_report.h): the frames
// measured, the walking and turning camera, the moving, switched-off and dimmed light, the switched-off
// light's metrics, and the report's target and temporal rule on made-up rows.
#include "motion.h"
#include "motion_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using bench::MotionKind;
using bench::MotionOptions;
using bench::MotionResult;

TEST(BenchMotion, MeasuredFramesFollowTheWarmUpEveryStepFrames) {
    MotionOptions o;
    EXPECT_EQ(bench::measuredFrames(o), (std::vector<uint32_t>{32, 36, 40, 44, 48, 52, 56, 60}));
    EXPECT_EQ(bench::sequenceLength(o), 61u);
    o.warmup = 4;
    o.frames = 2;
    o.frameStep = 2;
    EXPECT_EQ(bench::measuredFrames(o), (std::vector<uint32_t>{4, 6}));
    EXPECT_EQ(bench::sequenceLength(o), 7u);
    o.frames = 0;
    EXPECT_TRUE(bench::measuredFrames(o).empty());
    EXPECT_EQ(bench::sequenceLength(o), 4u);
}

demo::Camera camera() {
    demo::Camera c;
    c.position = {0.0f, 3.5f, 20.0f};
    c.lookAt = {0.0f, 0.5f, 0.0f};  // along -z, looking down a little
    return c;
}

TEST(BenchMotion, WalkingWithoutTurningGoesStraightAlongTheHorizontalView) {
    const demo::Camera start = camera();
    const demo::Camera c = bench::walkingCamera(start, 1.4f, 0.0f, 2.0);
    EXPECT_NEAR(c.position.x, 0.0f, 1e-6f);
    EXPECT_NEAR(c.position.y, 3.5f, 1e-6f);   // horizontal: the height is kept
    EXPECT_NEAR(c.position.z, 17.2f, 1e-5f);  // 2 s at 1.4 m/s along -z
    EXPECT_NEAR(glm::length((c.lookAt - c.position) - (start.lookAt - start.position)), 0.0f, 1e-5f);
    EXPECT_EQ(c.up, start.up);
    EXPECT_EQ(bench::walkingCamera(start, 1.4f, 20.0f, 0.0).position, start.position);
}

TEST(BenchMotion, WalkingAndTurningFollowsTheArcAndTurnsLeft) {
    const demo::Camera start = camera();
    const float speed = 1.4f, rate = 20.0f;
    const double t = 1.5;
    const demo::Camera c = bench::walkingCamera(start, speed, rate, t);
    // The view turned by rate · t about +y, to the left (toward -x when looking along -z).
    const glm::vec3 v0 = glm::normalize(start.lookAt - start.position),
                    v = glm::normalize(c.lookAt - c.position);
    EXPECT_NEAR(v.y, v0.y, 1e-6f);
    const double turned = std::atan2(-double(v.x), -double(v.z));  // from -z toward -x
    EXPECT_NEAR(turned, glm::radians(double(rate) * t), 1e-5);
    EXPECT_NEAR(glm::length(c.lookAt - c.position), glm::length(start.lookAt - start.position), 1e-4f);
    // The position is the integral of the turning direction: small steps of the same walk agree.
    glm::dvec3 p(start.position);
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) {
        const double a = glm::radians(double(rate)) * (i + 0.5) * t / steps;
        p += double(speed) * t / steps * glm::dvec3(-std::sin(a), 0.0, -std::cos(a));
    }
    EXPECT_NEAR(glm::length(glm::dvec3(c.position) - p), 0.0, 1e-4);
    // An arc of 30°: the chord is the distance walked times sin(15°) / 15° (in radians).
    const double chord = glm::length(glm::dvec3(c.position) - glm::dvec3(start.position));
    const double half = glm::radians(double(rate) * t) / 2.0;
    EXPECT_NEAR(chord, speed * t * std::sin(half) / half, 1e-5);
}

TEST(BenchMotion, CameraMotionSceneIsTheWalkAtTheFramesTime) {
    demo::Scene scene;
    scene.camera = camera();
    MotionOptions o;
    const demo::Scene s = bench::cameraMotionScene(scene, o, 30);
    const demo::Camera expected = bench::walkingCamera(scene.camera, o.cameraSpeed, o.yawRateDeg, 0.5);
    EXPECT_EQ(s.camera.position, expected.position);
    EXPECT_EQ(s.camera.lookAt, expected.lookAt);
    EXPECT_EQ(bench::cameraMotionScene(scene, o, 0).camera.position, scene.camera.position);
}

TEST(BenchMotion, TheLightMovesAcrossTheViewAndSwitchesOff) {
    demo::Scene scene;
    scene.camera = camera();
    scene.lights.resize(2);
    scene.lights[0].position = {-3.0f, 2.2f, 9.0f};
    scene.lights[0].intensity = glm::vec3(900.0f, 480.0f, 180.0f);
    scene.lights[1].position = {5.0f, 2.5f, 4.5f};
    scene.lights[1].intensity = glm::vec3(150.0f);
    EXPECT_NEAR(glm::length(bench::lightMotionDirection(scene.camera) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    MotionOptions o;
    const demo::Scene moved = bench::lightMotionScene(scene, o, 60);  // 1 s at 1.4 m/s along +x
    EXPECT_NEAR(moved.lights[0].position.x, -1.6f, 1e-5f);
    EXPECT_EQ(moved.lights[0].position.y, 2.2f);
    EXPECT_EQ(moved.lights[0].position.z, 9.0f);
    EXPECT_EQ(moved.lights[1].position, scene.lights[1].position);
    EXPECT_EQ(moved.camera.position, scene.camera.position);
    o.light = 5;  // no such light: unchanged
    EXPECT_EQ(bench::lightMotionScene(scene, o, 60).lights[0].position, scene.lights[0].position);

    const demo::Scene off = bench::lightOffScene(scene, 0);
    EXPECT_EQ(off.lights[0].intensity, glm::vec3(0.0f));
    EXPECT_EQ(off.lights[1].intensity, scene.lights[1].intensity);
    const demo::Scene dim = bench::dimmedLightScene(scene, 0);
    EXPECT_GT(dim.lights[0].intensity.x, 0.0f);  // still on for postfx
    EXPECT_EQ(dim.lights[0].intensity, scene.lights[0].intensity * bench::kControlDim);
    EXPECT_EQ(dim.lights[0].position, scene.lights[0].position);
}

// Two pixels: the light adds 10 to the first (of 100) and 0.5 to the second (of 1000: below 1%).
TEST(BenchMotion, TheSwitchedOffLightsRemainingContribution) {
    const std::vector<float> without = {90, 90, 90, 1, 999.5f, 999.5f, 999.5f, 1};
    const std::vector<float> with = {100, 100, 100, 1, 1000, 1000, 1000, 1};
    const std::vector<uint8_t> touched = bench::touchedPixels(with, without, 0.01);
    EXPECT_EQ(touched, (std::vector<uint8_t>{1, 0}));
    EXPECT_DOUBLE_EQ(bench::remainingContribution(with, with, without, touched), 1.0);
    EXPECT_DOUBLE_EQ(bench::remainingContribution(without, with, without, touched), 0.0);
    const std::vector<float> half = {95, 95, 95, 1, 0, 0, 0, 1};  // the untouched pixel does not count
    EXPECT_DOUBLE_EQ(bench::remainingContribution(half, with, without, touched), 0.5);
    // Leftover: against the control, whatever the reference says.
    const std::vector<float> control = {91, 89, 90, 1, 5, 5, 5, 1};
    const std::vector<float> image = {92, 89, 90, 1, 7, 7, 7, 1};
    EXPECT_DOUBLE_EQ(bench::leftoverContribution(image, control, with, without, touched), 1.0 / 30.0);
    EXPECT_DOUBLE_EQ(bench::leftoverContribution(control, control, with, without, touched), 0.0);
    EXPECT_TRUE(
        std::isnan(bench::remainingContribution(with, with, with, bench::touchedPixels(with, with, 0.01))));
}

TEST(BenchMotion, SettledAfterIsTheFirstFrameFromWhichAllStayBelow) {
    EXPECT_EQ(bench::settledAfter({0.0, 0.0}, 0.01), 0u);
    EXPECT_EQ(bench::settledAfter({0.5, 0.02, 0.005, 0.001}, 0.01), 2u);
    EXPECT_EQ(bench::settledAfter({0.005, 0.02, 0.005}, 0.01), 2u);  // back above: later
    EXPECT_EQ(bench::settledAfter({0.5, 0.02}, 0.01), 2u);           // never: the size
    EXPECT_EQ(bench::settledAfter({0.005, NAN}, 0.01), 2u);
    EXPECT_EQ(bench::settledAfter({}, 0.01), 0u);
}

MotionResult motionRow(const std::string& scene, const std::string& preset, bool temporal, double ms,
                       std::vector<double> errors) {
    MotionResult m;
    m.setting.scene = scene;
    m.setting.preset = preset;
    m.temporal = temporal;
    m.blendWeight = temporal ? 0.1f : 0.0f;
    m.kind = MotionKind::Camera;
    m.timing.median = ms;
    if (temporal) m.timing.passMedians = {{"fog.raymarch", ms - 0.05}, {"fog.temporal", 0.05}};
    for (double e : errors) {
        m.frames.push_back(uint32_t(m.frames.size()));
        bench::ErrorStats s;
        s.relativeRmse = e;
        m.errors.push_back(s);
    }
    return m;
}

TEST(BenchMotion, MeanMaxAndTheTemporalPass) {
    const MotionResult m = motionRow("a", "medium", true, 0.5, {0.01, 0.03, 0.02});
    EXPECT_DOUBLE_EQ(m.meanError(), 0.02);
    EXPECT_DOUBLE_EQ(m.maxError(), 0.03);
    EXPECT_DOUBLE_EQ(m.temporalMs(), 0.05);
    EXPECT_TRUE(std::isnan(motionRow("a", "medium", false, 0.5, {}).meanError()));
    EXPECT_TRUE(std::isnan(motionRow("a", "medium", false, 0.5, {0.01}).temporalMs()));
}

TEST(BenchMotion, TheTargetIsMediumInMotionOverTheStillSixteenFrames) {
    bench::RunInfo info;
    info.presetScene = "fog_default";
    std::vector<bench::Result> results;
    std::vector<MotionResult> motion = {motionRow("fog_default", "medium", false, 0.4, {0.03}),
                                        motionRow("fog_default", "medium", true, 0.5, {0.005, 0.007})};
    motion[0].still[2].relativeRmse = 0.004;  // temporal off, the still camera's mean of 16 frames
    motion[1].still[2].relativeRmse = 0.002;  // temporal on: not the target's denominator
    bench::MotionTarget t = bench::motionTarget(info, results, motion);
    ASSERT_TRUE(t.motion && t.still);
    EXPECT_TRUE(t.motion->temporal);
    EXPECT_DOUBLE_EQ(t.ratio, 1.5);
    EXPECT_TRUE(t.met());
    motion[1].errors[1].relativeRmse = 0.0071;
    EXPECT_FALSE(bench::motionTarget(info, results, motion).met());
    motion.erase(motion.begin());  // no temporal-off row: not measured
    EXPECT_FALSE(bench::motionTarget(info, results, motion).still);
}

TEST(BenchMotion, TemporalPaysWhenNoPresetWithoutItIsCheaperAtThatError) {
    bench::RunInfo info;
    info.presetScene = "a";
    // Errors averaged over scenes a and b; times from a.
    std::vector<MotionResult> motion = {
        motionRow("a", "low", false, 0.2, {0.020}),     motionRow("a", "low", true, 0.30, {0.012}),
        motionRow("b", "low", false, 0.1, {0.020}),     motionRow("b", "low", true, 0.15, {0.012}),
        motionRow("a", "medium", false, 0.25, {0.010}), motionRow("a", "medium", true, 0.35, {0.006}),
        motionRow("b", "medium", false, 0.1, {0.010}),  motionRow("b", "medium", true, 0.15, {0.006}),
        motionRow("a", "high", false, 1.0, {0.004}),    motionRow("a", "high", true, 1.1, {0.005}),
        motionRow("b", "high", false, 0.5, {0.004}),    motionRow("b", "high", true, 0.6, {0.005}),
    };
    const std::vector<bench::TemporalPays> pays = bench::temporalPays(info, motion);
    ASSERT_EQ(pays.size(), 3u);
    // low: 2% -> 1.2% for 0.3 ms, but medium without temporal gets 1% in 0.25 ms: does not pay.
    EXPECT_EQ(pays[0].preset, "low");
    EXPECT_DOUBLE_EQ(pays[0].offMs, 0.2);
    EXPECT_DOUBLE_EQ(pays[0].onMs, 0.3);
    EXPECT_DOUBLE_EQ(pays[0].temporalMs, 0.05);
    EXPECT_NEAR(pays[0].offError, 0.020, 1e-12);
    EXPECT_NEAR(pays[0].onError, 0.012, 1e-12);
    EXPECT_EQ(pays[0].cheapestOff, "medium");
    EXPECT_FALSE(pays[0].pays);
    // medium: 1% -> 0.6%; only high gets there without it, in 1 ms > 0.35 ms: pays.
    EXPECT_EQ(pays[1].cheapestOff, "high");
    EXPECT_TRUE(pays[1].pays);
    // high: the error rises with temporal: does not pay.
    EXPECT_FALSE(pays[2].pays);
}

TEST(BenchMotion, WritesMotionCsvAndTheSections) {
    bench::RunInfo info;
    info.device = "made-up";
    info.presetScene = "a";
    info.width = 64;
    info.height = 36;
    bench::MotionInfo mi;
    mi.errorStride = 1;
    mi.referenceSteps = 1024;
    std::vector<MotionResult> motion = {motionRow("a", "medium", false, 0.4, {0.03, 0.02}),
                                        motionRow("a", "medium", true, 0.5, {0.005, 0.007})};
    bench::SwitchOffResult off;
    off.setting.scene = "lights";
    off.temporal = true;
    off.blendWeight = 0.05f;
    off.offFrame = 32;
    off.lastLitRemaining = 1.01;
    off.lastLitLeftover = 0.99;
    off.remaining = {0.03, 0.03, 0.03};
    off.controlRemaining = {0.03, 0.03, 0.03};
    off.neverLitRemaining = {0.02, 0.02, 0.02};
    off.leftover = {0.02, 0.005, 0.0};
    const std::string path = (std::filesystem::temp_directory_path() / "bench_motion_test.csv").string();
    std::string error;
    ASSERT_TRUE(bench::writeMotionCsv(path, info, mi, motion, {off}, error)) << error;
    std::ifstream in(path);
    std::string line, header;
    size_t rows = 0;
    while (std::getline(in, line)) {
        if (line.rfind("#", 0) == 0) continue;
        if (header.empty()) {
            header = line;
            continue;
        }
        ++rows;
    }
    std::string columns;
    for (const std::string& c : bench::motionCsvColumns())
        columns += (columns.empty() ? "" : ",") + c;
    EXPECT_EQ(header, columns);
    // 2 × (still + 2 frames); switched off: F - 1 and 3 frames, the control's and the never-lit 3 each.
    EXPECT_EQ(rows, 2u * 3u + 4u + 3u + 3u);
    std::filesystem::remove(path);

    const std::string fog = bench::motionMarkdown(info, mi, {}, motion);
    EXPECT_NE(fog.find("## In motion"), std::string::npos);
    EXPECT_NE(fog.find("### Where the temporal pass pays"), std::string::npos);
    const std::string froxel = bench::froxelMotionMarkdown(info, mi, {}, {off});
    EXPECT_NE(froxel.find("leftover below 1% from F + 1 on"), std::string::npos) << froxel;
    EXPECT_NE(froxel.find("**PASS**"), std::string::npos);
    off.leftover = {0.02, 0.02, 0.02};
    EXPECT_NE(bench::froxelMotionMarkdown(info, mi, {}, {off}).find("**MISS**"), std::string::npos);
    EXPECT_EQ(bench::motionMarkdown(info, mi, {}, {}), "");
}

}  // namespace
