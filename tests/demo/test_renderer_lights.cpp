// The demo host renderer's local lights (scene `lights`): a point light above a floor against the closed
// form E·albedo/π, a spot light's cone (lit inside, dark outside), both through the GPU lighting pass
// (render) and the reference path (renderReference, postfx-render --reference), and the lights scene.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;
constexpr uint32_t kSize = 33;  // odd: the middle pixel's centre is on the view axis
constexpr float kCameraHeight = 6.0f;
constexpr float kLightHeight = 2.0f;
constexpr float kAlbedo = 0.5f;

// A floor seen straight down from 6 m (fov 60°), no sun, no ambient, one light 2 m above the origin.
demo::Scene floorScene(const demo::Light& light) {
    demo::Scene s;
    s.camera.position = {0.0f, kCameraHeight, 0.0f};
    s.camera.lookAt = {0.0f, 0.0f, 0.0f};
    s.camera.up = {0.0f, 0.0f, -1.0f};
    s.camera.fovYDeg = 60.0f;
    // Exposed for a room lit by one lamp (as lights.json): the image is stored pre-exposed, and at the
    // default ev100 15 (direct sun) a few cd/m² would fall among half's subnormals.
    s.camera.ev100 = 4.0f;
    s.sun.illuminance = glm::vec3(0.0f);
    s.sun.shadows = false;
    demo::Object floor;
    floor.albedo = glm::vec3(kAlbedo);
    s.objects.push_back(floor);
    s.lights.push_back(light);
    return s;
}

// World x of the floor point seen by pixel (px, middle row): the middle row looks at z = 0.
double floorX(uint32_t px) {
    const double ndc = (px + 0.5) / kSize * 2.0 - 1.0;
    return ndc * kCameraHeight * std::tan(glm::radians(30.0));
}

// Closed form on the floor at x, for a light straight above the origin (spot factor 1): L = albedo/π · E,
// E = I · cosθ / (d² + r²) · window(d).
double expectedRadiance(double x, double intensity, double radius, double range) {
    const double d2 = x * x + double(kLightHeight) * kLightHeight;
    const double d = std::sqrt(d2);
    const double cosTheta = kLightHeight / d;
    const double window = std::pow(std::clamp(1.0 - std::pow(d / range, 4.0), 0.0, 1.0), 2.0);
    return kAlbedo / glm::pi<double>() * intensity * cosTheta * window / (d2 + radius * radius);
}

class DemoRendererLights : public GpuTest {
protected:
    // The GPU frame (render) and the reference path (renderReference): two images of the scene.
    std::array<demo::ImageF, 2> renderBoth(const demo::Scene& scene) {
        demo::RenderOptions o;
        o.width = kSize;
        o.height = kSize;
        o.shadowMapSize = 64;
        std::string error;
        auto renderer = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(renderer) << error;
        std::array<demo::ImageF, 2> images;
        if (renderer) {
            EXPECT_TRUE(renderer->render(scene, images[0], error)) << error;
            EXPECT_TRUE(renderer->renderReference(scene, images[1], error)) << error;
        }
        return images;
    }
};

TEST_F(DemoRendererLights, PointLightAboveFloorMatchesClosedForm) {
    demo::Light light;
    light.position = {0.0f, kLightHeight, 0.0f};
    light.intensity = {100.0f, 200.0f, 400.0f};
    light.radius = 0.25f;
    light.range = 8.0f;  // the window matters at the image's edge (d up to 4.1 m)
    for (const demo::ImageF& image : renderBoth(floorScene(light))) {
        ASSERT_EQ(image.rgba.size(), size_t(kSize) * kSize * 4);
        const uint32_t mid = kSize / 2;
        for (uint32_t px = 0; px < kSize; ++px) {
            for (int c = 0; c < 3; ++c) {
                const double expected =
                    expectedRadiance(floorX(px), light.intensity[c], light.radius, light.range);
                // Half-float storage and float shading: 0.5 %.
                EXPECT_NEAR(image.at(px, mid)[c], expected, 0.005 * expected)
                    << "pixel " << px << " channel " << c;
            }
        }
        // Right below the light: albedo/π · I / (h² + r²).
        const double below = kAlbedo / glm::pi<double>() * 100.0 / (4.0 + 0.0625) *
                             std::pow(1.0 - std::pow(2.0 / 8.0, 4.0), 2.0);
        EXPECT_NEAR(image.at(mid, mid)[0], below, 0.005 * below);
    }
}

TEST_F(DemoRendererLights, SpotLightLitInsideTheConeDarkOutside) {
    demo::Light spot;
    spot.kind = demo::LightKind::Spot;
    spot.position = {0.0f, kLightHeight, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = glm::vec3(1000.0f);
    spot.innerAngleDeg = 20.0f;
    spot.outerAngleDeg = 30.0f;
    int inside = 0, outside = 0, edge = 0;
    for (const demo::ImageF& image : renderBoth(floorScene(spot))) {
        for (uint32_t px = 0; px < kSize; ++px) {
            const double x = floorX(px);
            const double angleDeg = glm::degrees(std::atan(std::abs(x) / kLightHeight));
            const float value = image.at(px, kSize / 2)[1];
            const double full = expectedRadiance(x, 1000.0, spot.radius, spot.range);
            if (angleDeg < 19.5) {
                EXPECT_NEAR(value, full, 0.005 * full) << "pixel " << px << " at " << angleDeg << " deg";
                ++inside;
            } else if (angleDeg > 30.5) {
                EXPECT_EQ(value, 0.0f) << "pixel " << px << " at " << angleDeg << " deg";
                ++outside;
            } else {
                EXPECT_GT(value, 0.0f) << "pixel " << px << " at " << angleDeg << " deg";
                EXPECT_LT(value, full) << "pixel " << px << " at " << angleDeg << " deg";
                ++edge;
            }
        }
    }
    EXPECT_GT(inside, 4);
    EXPECT_GT(outside, 4);
    EXPECT_GT(edge, 1);
}

// A spot light with shadows (scene lights[i].shadows) over a sphere: the floor in the sphere's shadow gets
// none of its light on the surfaces, the floor beside it all of it, through the GPU lighting pass and the
// reference path; without shadows both are lit.
TEST_F(DemoRendererLights, ShadowedSpotDarkensTheFloorBehindASphere) {
    demo::Light spot;
    spot.kind = demo::LightKind::Spot;
    spot.position = {-2.0f, 3.0f, 0.0f};
    spot.direction = glm::normalize(glm::vec3(0.8f, -0.6f, 0.0f));  // at the sphere, then the floor at x 2
    spot.intensity = glm::vec3(1000.0f);
    spot.innerAngleDeg = 20.0f;
    spot.outerAngleDeg = 30.0f;
    spot.range = 20.0f;
    spot.shadowResolution = 256;
    demo::Scene scene = floorScene(spot);
    demo::Object sphere;
    sphere.type = demo::ObjectType::Sphere;
    sphere.position = {0.0f, 1.5f, 0.0f};
    sphere.radius = 0.4f;
    sphere.albedo = glm::vec3(kAlbedo);
    scene.objects.push_back(sphere);

    // Floor pixels: (x 2, z 0) in the middle of the shadow (the ray from the light through the sphere's
    // centre), (x 2, z 1.2) beside it in the cone's core (13.6° off its axis). Image x is world x, rows
    // grow with z (the camera's up is -z).
    const auto pixel = [](double world) {
        return uint32_t((world / (kCameraHeight * std::tan(glm::radians(30.0))) + 1.0) / 2.0 * kSize);
    };
    const uint32_t x = pixel(2.0), shadowRow = pixel(0.0), litRow = pixel(1.2);
    const std::array<demo::ImageF, 2> unshadowed = renderBoth(scene);
    scene.lights[0].shadows = true;
    const std::array<demo::ImageF, 2> shadowed = renderBoth(scene);
    for (size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(i == 0 ? "render" : "renderReference");
        ASSERT_EQ(shadowed[i].rgba.size(), size_t(kSize) * kSize * 4);
        ASSERT_EQ(unshadowed[i].rgba.size(), size_t(kSize) * kSize * 4);
        const float open = unshadowed[i].at(x, shadowRow)[1];
        EXPECT_GT(open, 0.0f);  // lit without shadows
        EXPECT_EQ(shadowed[i].at(x, shadowRow)[1], 0.0f) << "unshadowed " << open;
        const float beside = unshadowed[i].at(x, litRow)[1];
        EXPECT_GT(beside, 0.0f);
        EXPECT_NEAR(shadowed[i].at(x, litRow)[1], beside, 1e-6f * beside);
    }
}

// The froxel fog's reference path reads the atlas back (postfx-render --reference on a scene with shadowed
// lights): it renders, its surfaces shadowed as the GPU frame's.
TEST_F(DemoRendererLights, ReferenceReadsTheLocalShadowAtlasBack) {
    demo::Light point;
    point.position = {-2.0f, 3.0f, 0.0f};
    point.intensity = glm::vec3(1000.0f);
    point.range = 20.0f;
    point.shadows = true;
    point.shadowResolution = 64;
    demo::Scene scene = floorScene(point);
    demo::Object sphere;
    sphere.type = demo::ObjectType::Sphere;
    sphere.position = {0.0f, 1.5f, 0.0f};
    sphere.radius = 0.4f;
    scene.objects.push_back(sphere);
    scene.froxelFog.enabled = true;
    scene.froxelFog.density = 0.01f;
    scene.froxelFog.grid = {8, 8, 16};
    scene.froxelFog.maxDistance = 10.0f;
    demo::RenderOptions o;
    o.width = o.height = 16;
    o.shadowMapSize = 64;
    std::string error;
    auto renderer = demo::Renderer::create(*host, o, error);
    ASSERT_TRUE(renderer) << error;
    demo::ImageF image;
    ASSERT_TRUE(renderer->render(scene, image, error)) << error;
    ASSERT_TRUE(renderer->renderReference(scene, image, error, 64)) << error;
    EXPECT_EQ(image.rgba.size(), size_t(16) * 16 * 4);
}

// Lights beyond the limit are a clear error, not a silently shortened list.
TEST_F(DemoRendererLights, MoreLightsThanTheLimitIsAnError) {
    demo::Light light;
    light.intensity = glm::vec3(1.0f);
    demo::Scene scene = floorScene(light);
    scene.lights.assign(postfx::kMaxLocalLights + 1, light);
    demo::RenderOptions o;
    o.width = o.height = 8;
    o.shadowMapSize = 64;
    std::string error;
    auto renderer = demo::Renderer::create(*host, o, error);
    ASSERT_TRUE(renderer) << error;
    demo::ImageF image;
    EXPECT_FALSE(renderer->render(scene, image, error));
    EXPECT_NE(error.find("257 lights"), std::string::npos) << error;
}

// demo/scenes/lights.json against tests/demo/golden/lights_scene.exr (tolerance in golden.h).
TEST_F(DemoRendererLights, LightsSceneMatchesGolden) {
    demo::Scene scene;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/lights.json", scene, error)) << error;
    ASSERT_EQ(scene.lights.size(), 4u);
    demo::RenderOptions o;
    o.width = 160;
    o.height = 90;
    o.shadowMapSize = 512;
    auto renderer = demo::Renderer::create(*host, o, error);
    ASSERT_TRUE(renderer) << error;
    demo::ImageF image;
    ASSERT_TRUE(renderer->render(scene, image, error)) << error;
    expectMatchesGolden(image, "demo", "lights_scene");
}

}  // namespace
}  // namespace test
