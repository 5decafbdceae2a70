// The temporal history's rules (postfx/src/core/temporal.h, docs/temporal.md) on the host: when the
// history is valid, its blend weight, what resets it, which spheres a changed local light rejects, and
// the reprojection matrix.
#include "core/temporal.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

namespace postfx::core {
namespace {

constexpr uint64_t kKey = 42;

FrameInfo still() {
    FrameInfo f;
    f.camera.position = {10.0, 2.0, -5.0};
    f.camera.projection = glm::perspectiveRH_ZO(1.0f, 16.0f / 9.0f, 0.1f, 500.0f);
    f.sun.toSun = {0.3f, 0.8f, 0.2f};
    f.sun.illuminance = {1e5f, 9e4f, 8e4f};
    f.ambient = {1000.0f, 1200.0f, 1500.0f};
    return f;
}

class CoreTemporalRules : public ::testing::Test {
protected:
    TemporalSettings settings{true, 0.1f};
    TemporalHistory history;
    // decide() for `frame`, then recorded(): what the frame did.
    TemporalFrame step(const FrameInfo& frame, uint64_t key = kKey, bool lights = true) {
        const TemporalFrame t = history.decide(frame, settings, key, lights);
        history.recorded(frame, settings, key, lights);
        return t;
    }
};

TEST_F(CoreTemporalRules, FirstFrameStartsAndLaterFramesBlendWithARunningMeanThenTheWeight) {
    const FrameInfo f = still();
    TemporalFrame t = step(f);
    EXPECT_FALSE(t.historyValid);
    EXPECT_EQ(t.currentWeight, 1.0f);
    for (uint32_t n = 1; n < 20; ++n) {
        t = step(f);
        EXPECT_TRUE(t.historyValid) << t.resetReason;
        EXPECT_EQ(t.framesSinceReset, n);
        EXPECT_FLOAT_EQ(t.currentWeight, std::max(0.1f, 1.0f / float(n + 1)));
        EXPECT_NE(t.readSlot, t.writeSlot);
    }
}

TEST_F(CoreTemporalRules, SlotsAlternateSoEachFrameReadsWhatThePreviousWrote) {
    const FrameInfo f = still();
    uint32_t written = step(f).writeSlot;
    for (int i = 0; i < 4; ++i) {
        const TemporalFrame t = step(f);
        EXPECT_EQ(t.readSlot, written);
        written = t.writeSlot;
    }
}

TEST_F(CoreTemporalRules, CameraCutKeyAndDroppedFramesReset) {
    FrameInfo f = still();
    step(f);
    step(f);
    f.cameraCut = true;
    EXPECT_FALSE(step(f).historyValid);
    f.cameraCut = false;
    EXPECT_TRUE(step(f).historyValid);
    EXPECT_FALSE(step(f, kKey + 1).historyValid);  // extent, settings or medium
    EXPECT_TRUE(step(f, kKey + 1).historyValid);
    history.dropped();  // a frame without the effect: its images were released
    EXPECT_FALSE(step(f, kKey + 1).historyValid);
}

TEST_F(CoreTemporalRules, SunChangesBeyondTheThresholdsReset) {
    FrameInfo f = still();
    step(f);
    // 0.3° of turn per frame: each below kTemporalLightAngle (0.5°), the second beyond it in total.
    const double step03 = 0.3 * 3.14159265358979 / 180.0;
    auto turned = [&](double angle) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(f.sun.toSun));
        const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0, 0, 1));
        FrameInfo g = f;
        g.sun.toSun = Vec3(glm::dvec3(r * glm::dvec4(d, 0.0)));
        return g;
    };
    EXPECT_TRUE(step(turned(step03)).historyValid);
    EXPECT_FALSE(step(turned(2 * step03)).historyValid);  // 0.6° from the state it was reset for
    EXPECT_TRUE(step(turned(2 * step03)).historyValid);

    FrameInfo g = turned(2 * step03);
    g.sun.illuminance = f.sun.illuminance * 1.01f;
    EXPECT_TRUE(step(g).historyValid);
    g.sun.illuminance = f.sun.illuminance * 1.03f;
    EXPECT_FALSE(step(g).historyValid);
    g.ambient = f.ambient * 1.05f;
    EXPECT_FALSE(step(g).historyValid);
}

TEST_F(CoreTemporalRules, ShadowMapMatrixChangeResets) {
    FrameInfo f = still();
    f.shadowMap.image.image = reinterpret_cast<VkImage>(uintptr_t(1));
    f.shadowMap.worldToClip = glm::orthoRH_ZO(-50.0, 50.0, -50.0, 50.0, 0.0, 200.0);
    step(f);
    EXPECT_TRUE(step(f).historyValid);
    f.shadowMap.worldToClip[3][0] += 0.01;
    const TemporalFrame t = step(f);
    EXPECT_FALSE(t.historyValid);
    EXPECT_STREQ(t.resetReason, "shadow map's matrix changed");
    f.shadowMap.image.image = VK_NULL_HANDLE;  // the map went away
    EXPECT_FALSE(step(f).historyValid);
}

TEST_F(CoreTemporalRules, ChangedLocalLightsRejectTheirOldAndNewSpheres) {
    FrameInfo f = still();
    std::vector<LocalLight> lights(3);
    for (size_t i = 0; i < lights.size(); ++i) {
        lights[i].position = {double(i) * 10.0, 1.0, 0.0};
        lights[i].intensity = {100.0f, 100.0f, 100.0f};
        lights[i].range = 10.0f;
    }
    f.lights = lights.data();
    f.lightCount = uint32_t(lights.size());
    step(f);
    EXPECT_TRUE(step(f).rejected.empty());

    lights[1].position.x += 0.005;  // 0.05% of its range: kept
    TemporalFrame t = step(f);
    EXPECT_TRUE(t.historyValid);
    EXPECT_TRUE(t.rejected.empty());
    lights[1].position.x += 0.007;  // 0.12% from the state last rejected for
    t = step(f);
    ASSERT_EQ(t.rejected.size(), 2u);
    const glm::dvec3 camera = f.camera.position;
    EXPECT_NEAR(t.rejected[0].center.x, 10.0 - camera.x, 1e-5);
    EXPECT_NEAR(t.rejected[1].center.x, 10.012 - camera.x, 1e-5);
    EXPECT_EQ(t.rejected[1].radius, 10.0f);
    EXPECT_TRUE(step(f).rejected.empty());

    lights[2].intensity = {0.0f, 0.0f, 0.0f};  // switched off: its old sphere
    t = step(f);
    ASSERT_EQ(t.rejected.size(), 1u);
    EXPECT_NEAR(t.rejected[0].center.x, 20.0 - camera.x, 1e-5);
    f.lightCount = 2;  // removed (it was off): nothing
    EXPECT_TRUE(step(f).rejected.empty());
    f.lightCount = 3;
    lights[2].intensity = {50.0f, 0.0f, 0.0f};  // a new light: its sphere
    EXPECT_EQ(step(f).rejected.size(), 1u);
    lights[0].intensity.x *= 1.05f;  // colour or intensity
    EXPECT_EQ(step(f).rejected.size(), 2u);
    lights[0].type = LightType::Spot;
    step(f);
    lights[0].direction = {0.0f, -1.0f, 0.02f};  // 1.1° turn
    EXPECT_EQ(step(f).rejected.size(), 2u);
    // Without local lights (the ray-marched fog) they are ignored.
    lights[0].position.x += 5.0;
    EXPECT_TRUE(history.decide(f, settings, kKey, false).historyValid);
}

TEST_F(CoreTemporalRules, TooManyChangedLightsResetTheWholeHistory) {
    FrameInfo f = still();
    std::vector<LocalLight> lights(kTemporalMaxRejectedSpheres / 2 + 1);
    for (LocalLight& l : lights)
        l.intensity = {1.0f, 1.0f, 1.0f};
    f.lights = lights.data();
    f.lightCount = uint32_t(lights.size());
    step(f);
    for (LocalLight& l : lights)
        l.position.y += 5.0;
    const TemporalFrame t = step(f);
    EXPECT_FALSE(t.historyValid);
    EXPECT_TRUE(t.rejected.empty());
}

TEST_F(CoreTemporalRules, ReprojectionMapsAPointToWhereThePreviousCameraSawIt) {
    FrameInfo f = still();
    f.camera.view = glm::lookAtRH(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    step(f);
    const FrameInfo before = f;
    f.camera.position.x += 1.5;
    f.camera.view = glm::rotate(glm::mat4(1.0f), 0.2f, glm::vec3(0.0f, 1.0f, 0.0f)) * before.camera.view;
    const TemporalFrame t = step(f);
    ASSERT_TRUE(t.historyValid);
    const glm::dvec3 world(12.0, 3.0, -30.0);
    const glm::vec3 relative(world - glm::dvec3(f.camera.position));
    const glm::vec4 got = t.previousClipFromCurrent * glm::vec4(relative, 1.0f);
    glm::dmat4 rotation(before.camera.view);
    rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const glm::dvec4 expected = glm::dmat4(before.camera.projection) * rotation *
                                glm::dvec4(world - glm::dvec3(before.camera.position), 1.0);
    EXPECT_NEAR(got.x / got.w, expected.x / expected.w, 1e-5);
    EXPECT_NEAR(got.y / got.w, expected.y / expected.w, 1e-5);
    EXPECT_NEAR(t.cameraDelta.x, 1.5f, 1e-6f);
}

}  // namespace
}  // namespace postfx::core
