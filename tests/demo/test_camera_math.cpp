// The demo's projection and shadow-map fitting: depth conventions land where they should.
#include "host/camera_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// Clip-space depth (z/w) of a point at view distance d straight ahead.
float depthAt(const glm::mat4& proj, float d) {
    const glm::vec4 clip = proj * glm::vec4(0.0f, 0.0f, -d, 1.0f);
    return clip.z / clip.w;
}

TEST(DemoCameraMath, StandardZMapsNearToZeroFarToOne) {
    const glm::mat4 p = demo::perspectiveProjection(1.0f, 16.0f / 9.0f, 0.1f, 500.0f, false, false);
    EXPECT_NEAR(depthAt(p, 0.1f), 0.0f, 1e-6f);
    EXPECT_NEAR(depthAt(p, 500.0f), 1.0f, 1e-6f);
    EXPECT_LT(depthAt(p, 1.0f), depthAt(p, 2.0f));
}

TEST(DemoCameraMath, ReversedZMapsNearToOneFarToZero) {
    const glm::mat4 p = demo::perspectiveProjection(1.0f, 1.0f, 0.1f, 500.0f, true, false);
    EXPECT_NEAR(depthAt(p, 0.1f), 1.0f, 1e-6f);
    EXPECT_NEAR(depthAt(p, 500.0f), 0.0f, 1e-6f);
    EXPECT_GT(depthAt(p, 1.0f), depthAt(p, 2.0f));
}

TEST(DemoCameraMath, InfiniteFarHasClosedFormDepth) {
    const float n = 0.25f;
    const glm::mat4 reversed = demo::perspectiveProjection(1.0f, 1.0f, n, 0.0f, true, true);
    const glm::mat4 standard = demo::perspectiveProjection(1.0f, 1.0f, n, 0.0f, false, true);
    for (float d : {0.25f, 1.0f, 10.0f, 1e6f}) {
        EXPECT_NEAR(depthAt(reversed, d), n / d, 1e-6f) << d;
        EXPECT_NEAR(depthAt(standard, d), 1.0f - n / d, 1e-6f) << d;
    }
}

TEST(DemoCameraMath, ImageYPointsUpInViewAndFovIsVertical) {
    const float fov = glm::radians(60.0f);
    const glm::mat4 p = demo::perspectiveProjection(fov, 2.0f, 0.1f, 100.0f, true, false);
    // A point on the top edge of the vertical field of view lands at clip y = -1 (Vulkan: top row).
    const float d = 10.0f;
    const glm::vec4 top = p * glm::vec4(0.0f, d * std::tan(fov / 2), -d, 1.0f);
    EXPECT_NEAR(top.y / top.w, -1.0f, 1e-5f);
    const glm::vec4 right = p * glm::vec4(2.0f * d * std::tan(fov / 2), 0.0f, -d, 1.0f);
    EXPECT_NEAR(right.x / right.w, 1.0f, 1e-5f);
}

TEST(DemoCameraMath, ViewLooksFromPositionTowardLookAt) {
    demo::Camera camera;
    camera.position = {1.0f, 2.0f, 3.0f};
    camera.lookAt = {1.0f, 2.0f, -7.0f};
    const glm::mat4 v = demo::cameraView(camera);
    const glm::vec4 eye = v * glm::vec4(camera.position, 1.0f);
    const glm::vec4 target = v * glm::vec4(camera.lookAt, 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-5f);
    EXPECT_NEAR(target.z, -10.0f, 1e-5f);
    EXPECT_NEAR(target.x, 0.0f, 1e-5f);
    EXPECT_NEAR(target.y, 0.0f, 1e-5f);
}

TEST(DemoCameraMath, ShadowFitCoversEveryFiniteObject) {
    const demo::Scene scene = demo::defaultScene();
    const demo::ShadowFit fit = demo::fitShadowMap(scene, 2048);
    ASSERT_TRUE(fit.valid);
    EXPECT_GT(fit.texelWorldSize, 0.0f);
    for (const demo::Object& o : scene.objects) {
        if (o.type == demo::ObjectType::Plane) continue;
        const glm::vec3 extent = o.type == demo::ObjectType::Box ? o.halfSize : glm::vec3(o.radius);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 s((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f,
                              (corner & 4) ? 1.0f : -1.0f);
            const glm::vec4 c = fit.viewProj * glm::vec4(o.position + s * extent, 1.0f);
            EXPECT_LE(std::abs(c.x / c.w), 1.0f);
            EXPECT_LE(std::abs(c.y / c.w), 1.0f);
            EXPECT_GE(c.z / c.w, 0.0f);
            EXPECT_LE(c.z / c.w, 1.0f);
        }
    }
    demo::Scene planesOnly = scene;
    std::erase_if(planesOnly.objects,
                  [](const demo::Object& o) { return o.type != demo::ObjectType::Plane; });
    EXPECT_FALSE(demo::fitShadowMap(planesOnly, 2048).valid);
}

// A floating slab seen from the side, sun straight up: without fog the map's depth range ends under the
// slab; with fog it reaches down to what the fog's march reaches (max_distance around the camera inside
// the footprint), and with a ground plane under the camera no farther than the ground.
TEST(DemoCameraMath, ShadowFitReachesTheFogUnderAFloatingCaster) {
    demo::Scene scene;
    scene.sun.direction = {0.0f, 1.0f, 0.0f};
    demo::Object slab;
    slab.type = demo::ObjectType::Box;
    slab.position = {0.0f, 10.0f, 0.0f};
    slab.halfSize = {5.0f, 0.5f, 5.0f};
    scene.objects = {slab};
    scene.camera.position = {0.0f, 2.0f, 30.0f};
    scene.camera.lookAt = {0.0f, 2.0f, 0.0f};
    scene.fog.maxDistance = 100.0f;
    auto depth = [](const demo::ShadowFit& fit, glm::vec3 p) {
        const glm::vec4 c = fit.viewProj * glm::vec4(p, 1.0f);
        EXPECT_LE(std::abs(c.x / c.w), 1.0f);  // the point is over the slab's footprint
        EXPECT_LE(std::abs(c.y / c.w), 1.0f);
        return c.z / c.w;
    };
    const glm::vec3 underSlab(0.0f, 2.0f, 0.0f), deepUnder(4.0f, -60.0f, -4.0f);

    scene.fog.enabled = false;
    const demo::ShadowFit casters = demo::fitShadowMap(scene, 1024);
    ASSERT_TRUE(casters.valid);
    EXPECT_GT(depth(casters, underSlab), 1.0f);  // beyond the far plane: only the slab is in depth

    scene.fog.enabled = true;
    const demo::ShadowFit fog = demo::fitShadowMap(scene, 1024);
    EXPECT_EQ(fog.texelWorldSize, casters.texelWorldSize);      // xy stays the casters' footprint
    EXPECT_GE(depth(fog, glm::vec3(0.0f, 10.5f, 0.0f)), 0.0f);  // the slab's top is still inside
    EXPECT_LE(depth(fog, underSlab), 1.0f);
    // Farthest fog inside the footprint: the camera is 25 - margin from it in the light's xy, so the
    // ball of 100 m reaches about sqrt(100² - 25²) ≈ 97 m below the camera's height.
    EXPECT_LE(depth(fog, deepUnder), 1.0f);
    EXPECT_GT(depth(fog, glm::vec3(0.0f, 2.0f - 100.0f, 0.0f)), 1.0f);

    // A ground plane under the camera: the fog sees nothing below it, the range ends there (+ margin).
    demo::Object ground;
    ground.position = {0.0f, 0.0f, 0.0f};
    ground.normal = {0.0f, 1.0f, 0.0f};
    scene.objects.push_back(ground);
    const demo::ShadowFit grounded = demo::fitShadowMap(scene, 1024);
    EXPECT_LE(depth(grounded, glm::vec3(0.0f, 0.0f, 0.0f)), 1.0f);
    EXPECT_GT(depth(grounded, glm::vec3(0.0f, -5.0f, 0.0f)), 1.0f);

    // A camera whose fog never reaches the footprint adds nothing.
    scene.objects.pop_back();
    scene.camera.position = {0.0f, 2.0f, 300.0f};
    const demo::ShadowFit far = demo::fitShadowMap(scene, 1024);
    EXPECT_GT(depth(far, underSlab), 1.0f);
}

}  // namespace
