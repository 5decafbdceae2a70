// The demo renderer with froxel fog (scene `effects.froxel_fog`): the reference path (renderReference,
// postfx-render --reference) gives postfx::reference::renderFroxelFog the frame's inputs (camera, sun,
// shadow map, the noise texture postfx generates, the scene's lights and fog volumes): the same medium as
// the ray-marched fog's reference gives the same image, a hard fog volume on the view axis dims the sky
// behind it by exp(-density·chord), and a point light lights the fog around it.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <cmath>
#include <string>

namespace test {
namespace {

const std::string kScenesDir = POSTFX_DEMO_SCENES_DIR;

class DemoRendererFroxel : public GpuTest {
protected:
    demo::ImageF reference(const demo::Scene& scene, uint32_t width, uint32_t height, uint32_t steps) {
        demo::RenderOptions o;
        o.width = width;
        o.height = height;
        o.shadowMapSize = 512;
        std::string error;
        auto renderer = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(renderer) << error;
        demo::ImageF image;
        if (renderer) {
            EXPECT_TRUE(renderer->renderReference(scene, image, error, steps)) << error;
        }
        return image;
    }
};

// froxel_default.json is fog_default.json's medium as a froxel fog: with the ray-marched fog's reference
// set to march as the froxel reference does (the whole ray, 1x1 shadow taps, no early stop), the two give
// the same image, shadow map and generated noise included (the noise stand-in of renderReference).
TEST_F(DemoRendererFroxel, ReferenceIsTheFogReferenceOnTheSameMedium) {
    demo::Scene froxel, fog;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/froxel_default.json", froxel, error)) << error;
    ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/fog_default.json", fog, error)) << error;
    ASSERT_TRUE(froxel.froxelFog.noise.enabled && froxel.sun.shadows);
    fog.fog.shadowKernel = 1;
    fog.fog.skipEmptySpace = false;
    fog.fog.transmittanceCutoff = 0.0f;
    demo::Scene none = fog;
    none.fog.enabled = false;

    constexpr uint32_t kW = 48, kH = 27, kSteps = 128;
    const demo::ImageF a = reference(froxel, kW, kH, kSteps);
    const demo::ImageF b = reference(fog, kW, kH, kSteps);
    const demo::ImageF clear = reference(none, kW, kH, kSteps);
    ASSERT_EQ(a.rgba.size(), size_t(kW) * kH * 4);
    ASSERT_EQ(b.rgba.size(), a.rgba.size());
    ASSERT_EQ(clear.rgba.size(), a.rgba.size());
    double fogged = 0.0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        EXPECT_NEAR(a.rgba[i], b.rgba[i], 1e-5 * std::abs(b.rgba[i]) + 1e-6) << "value " << i;
        fogged += std::abs(a.rgba[i] - clear.rgba[i]) / (std::abs(clear.rgba[i]) + 1.0);
    }
    EXPECT_GT(fogged / double(a.rgba.size()), 0.05);  // the fog is there
}

// Sky of radiance 100 behind thin homogeneous fog (to 8 m, no tail), no sun, no ambient; a sphere with
// `volume` on the view axis 6 m ahead. 33x33 pixels: the middle one's ray is the axis.
constexpr uint32_t kSize = 33;
constexpr float kMediumDensity = 1e-4f;
constexpr float kMaxDistance = 8.0f;  // 4096 steps of 1/512 m: the sphere's chord [5, 7] m is exact

demo::Scene skyScene() {
    demo::Scene s;
    s.camera.position = {0.0f, 2.0f, 0.0f};
    s.camera.lookAt = {0.0f, 2.0f, -1.0f};
    s.camera.fovYDeg = 40.0f;
    s.sun.illuminance = glm::vec3(0.0f);
    s.sun.shadows = false;
    s.sky = glm::vec3(100.0f);
    s.froxelFog.enabled = true;
    s.froxelFog.density = kMediumDensity;
    s.froxelFog.heightFalloff = 0.0f;
    s.froxelFog.anisotropy = 0.0f;
    s.froxelFog.maxDistance = kMaxDistance;
    s.froxelFog.analyticTail = false;
    return s;
}

postfx::FogVolume axisSphere(float radius, float density) {
    postfx::FogVolume v;
    v.shape = postfx::FogVolumeShape::Sphere;
    v.center = {0.0, 2.0, -6.0};
    v.radius = radius;
    v.density = density;
    v.edgeFalloff = 0.0f;
    return v;
}

TEST_F(DemoRendererFroxel, VolumeOnTheAxisDimsTheSkyByItsChord) {
    demo::Scene scene = skyScene();
    scene.froxelVolumes.push_back(axisSphere(1.0f, 0.5f));
    const demo::ImageF image = reference(scene, kSize, kSize, 4096);
    ASSERT_EQ(image.rgba.size(), size_t(kSize) * kSize * 4);
    const uint32_t mid = kSize / 2;
    // No light: L = 0, so the pixel is sky · T, T = exp(-density·chord - medium·max_distance).
    const double behind = 100.0 * std::exp(-0.5 * 2.0 - double(kMediumDensity) * kMaxDistance);
    const double beside = 100.0 * std::exp(-double(kMediumDensity) * kMaxDistance);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.at(mid, mid)[c], behind, 1e-3 * behind) << "channel " << c;
        EXPECT_NEAR(image.at(0, 0)[c], beside, 1e-4 * beside) << "channel " << c;  // misses the sphere
    }
}

TEST_F(DemoRendererFroxel, PointLightLightsTheFogAroundIt) {
    demo::Scene dark = skyScene();
    dark.sky = glm::vec3(0.0f);
    dark.froxelVolumes.push_back(axisSphere(1.5f, 0.05f));
    demo::Scene lit = dark;
    demo::Light light;
    light.position = {0.0f, 2.0f, -6.0f};  // in the middle of the volume
    light.intensity = {1000.0f, 500.0f, 250.0f};
    light.radius = 0.1f;
    light.range = 20.0f;
    lit.lights.push_back(light);
    const demo::ImageF a = reference(dark, kSize, kSize, 1024);
    const demo::ImageF b = reference(lit, kSize, kSize, 1024);
    ASSERT_EQ(a.rgba.size(), size_t(kSize) * kSize * 4);
    ASSERT_EQ(b.rgba.size(), a.rgba.size());
    const uint32_t mid = kSize / 2;
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(a.at(mid, mid)[c], 0.0f) << "channel " << c;  // nothing lights the fog
        EXPECT_GT(b.at(mid, mid)[c], 1.0f) << "channel " << c;
    }
    // The light's colour, and brightest looking at it.
    EXPECT_GT(b.at(mid, mid)[0], b.at(mid, mid)[1]);
    EXPECT_GT(b.at(mid, mid)[1], b.at(mid, mid)[2]);
    EXPECT_GT(b.at(mid, mid)[0], 4.0f * b.at(0, 0)[0]);
}

}  // namespace
}  // namespace test
