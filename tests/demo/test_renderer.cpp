// The demo host renderer: its shading convention checked against the closed form (also under a
// homogeneous cloud layer's shadow), depth conventions agreeing, the default scene and the plain scene (no
// effects) against committed golden images, and its shadow map drawn only when read.
#include "golden.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/constants.hpp>
#include <string>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class DemoRendererTest : public GpuTest {
protected:
    demo::ImageF render(const demo::Scene& scene, demo::RenderOptions options) {
        std::string error;
        auto renderer = demo::Renderer::create(*host, options, error);
        EXPECT_TRUE(renderer) << error;
        demo::ImageF image;
        if (renderer) {
            EXPECT_TRUE(renderer->render(scene, image, error)) << error;
        }
        return image;
    }
    demo::Scene load(const std::string& relativePath) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/" + relativePath, scene, error)) << error;
        return scene;
    }
};

demo::RenderOptions smallOptions(uint32_t width, uint32_t height) {
    demo::RenderOptions o;
    o.width = width;
    o.height = height;
    o.shadowMapSize = 512;
    return o;
}

// L = albedo/π · E · max(0, n·l) + albedo · ambient, on every pixel of a plane filling the view.
TEST_F(DemoRendererTest, LitPlaneMatchesShadingConvention) {
    const demo::Scene scene = load("demo/scenes/lit_plane.json");
    ASSERT_EQ(scene.objects.size(), 1u);
    const demo::Object& plane = scene.objects[0];
    const glm::vec3 expected = plane.albedo / glm::pi<float>() * scene.sun.illuminance *
                                   std::max(0.0f, glm::dot(plane.normal, scene.sun.direction)) +
                               plane.albedo * scene.ambient;
    const demo::ImageF image = render(scene, smallOptions(48, 32));
    ASSERT_EQ(image.rgba.size(), 48u * 32u * 4u);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(image.at(x, y)[c], expected[c], 0.01f * expected[c]) << "pixel " << x << "," << y;
}

// lit_plane.json under a homogeneous cloud layer (noise off, coverage 1, σ = 0.001 /m between 1500 and
// 2000 m, atmosphere off: the planes y = 1500 and 2000) that casts shadows: every pixel of the plane (the
// camera 5 m up looks down at it, so no view ray reaches the layer) has its sunlit term dimmed by the
// layer's transmittance along the sun, the closed form
//   L = albedo/π · E · (n·l) · exp(-σ·(top - bottom)/μ) + albedo · ambient,  μ = l_y (l normalised).
// The lighting reads the clouds' shadow map of the previous frame (Renderer::recordFrame): frame 0 is
// unshadowed, frame 1 shadowed. Two suns: 70° and 27° above the horizon (T = 0.59 and 0.33).
TEST_F(DemoRendererTest, LitPlaneUnderHomogeneousCloudLayerMatchesClosedForm) {
    demo::Scene scene = load("demo/scenes/lit_plane.json");
    ASSERT_EQ(scene.objects.size(), 1u);
    ASSERT_FALSE(scene.atmosphere.enabled);
    postfx::CloudSettings& clouds = scene.clouds;
    clouds.enabled = true;
    clouds.noise.enabled = false;
    clouds.coverage = 1.0f;
    clouds.density = 0.001f;
    clouds.bottomHeight = 1500.0f;
    clouds.topHeight = 2000.0f;
    clouds.castShadows = true;
    const demo::Object& plane = scene.objects[0];
    for (const glm::vec3 sun : {glm::vec3(0.3f, 1.0f, 0.2f), glm::vec3(1.0f, 0.5f, 0.0f)}) {
        scene.sun.direction = sun;
        const glm::vec3 l = glm::normalize(sun);
        const double mu = l.y;
        const double transmittance =
            std::exp(-double(clouds.density) * (clouds.topHeight - clouds.bottomHeight) / mu);
        const glm::vec3 sunlit = plane.albedo / glm::pi<float>() * scene.sun.illuminance *
                                 std::max(0.0f, glm::dot(plane.normal, l));
        const glm::vec3 ambient = plane.albedo * scene.ambient;
        for (const uint32_t frames : {1u, 2u}) {
            demo::RenderOptions options = smallOptions(48, 32);
            options.frames = frames;
            const demo::ImageF image = render(scene, options);
            ASSERT_EQ(image.rgba.size(), 48u * 32u * 4u);
            const double t = frames == 1 ? 1.0 : transmittance;  // frame 0: no shadow map held yet
            double worst = 0.0;
            for (uint32_t y = 0; y < image.height; ++y)
                for (uint32_t x = 0; x < image.width; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const double expected = double(sunlit[c]) * t + double(ambient[c]);
                        worst = std::max(worst, std::abs(image.at(x, y)[c] - expected) / expected);
                    }
            std::printf(
                "[ demo ] lit plane under a cloud layer, sun (%.2f, %.2f, %.2f), frame %u: T = %.4f, "
                "L = %.1f cd/m2, largest relative difference %.3g\n",
                sun.x, sun.y, sun.z, frames - 1, t, double(sunlit[0]) * t + double(ambient[0]), worst);
            EXPECT_LT(worst, 0.01) << "sun " << sun.x << "," << sun.y << "," << sun.z << ", frames "
                                   << frames;
        }
    }
}

TEST_F(DemoRendererTest, EmptySceneShowsSkyRadiance) {
    demo::Scene scene = load("demo/scenes/lit_plane.json");
    scene.objects.clear();
    scene.sky = {1234.0f, 2345.0f, 3456.0f};
    const demo::ImageF image = render(scene, smallOptions(16, 8));
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(image.at(x, y)[c], scene.sky[c], 2.0f);  // half precision
}

// Standard and reversed Z, finite and infinite far plane: the same image (depth precision aside).
TEST_F(DemoRendererTest, DepthConventionsRenderTheSameImage) {
    const demo::Scene scene = demo::defaultScene();
    demo::RenderOptions reversed = smallOptions(64, 36);
    const demo::ImageF a = render(scene, reversed);
    demo::RenderOptions standard = reversed;
    standard.reversedZ = false;
    demo::RenderOptions infinite = reversed;
    infinite.infiniteFar = true;
    for (const demo::RenderOptions& o : {standard, infinite}) {
        const demo::ImageF b = render(scene, o);
        const ImageStats stats = compareImages(b.rgba, a.rgba, a.width, a.height, 0.02, 1.0);
        EXPECT_LT(stats.relativeRmse, 0.01) << stats.summary();
        EXPECT_LT(stats.fractionOff, 0.01) << stats.summary();
    }
}

// The default scene against tests/demo/golden/default_scene.exr (tolerance in golden.h).
TEST_F(DemoRendererTest, DefaultSceneMatchesGolden) {
    expectMatchesGolden(render(demo::defaultScene(), smallOptions(160, 90)), "demo", "default_scene");
}

// The demo host draws its shadow map only when something reads it: with no sunlight neither its lighting
// nor postfx's fog (plan) reads it.
TEST_F(DemoRendererTest, DrawsTheShadowMapOnlyWhenRead) {
    std::string error;
    demo::RenderOptions options;
    options.width = 32;
    options.height = 18;
    options.shadowMapSize = 256;
    auto renderer = demo::Renderer::create(*host, options, error);
    ASSERT_TRUE(renderer) << error;
    demo::Scene scene = load("demo/scenes/fog_valley.json");
    scene.fog.steps = 8;
    scene.fog.jitter = false;
    scene.fog.transmittanceCutoff = 0.0f;
    demo::ImageF image;
    ASSERT_TRUE(renderer->render(scene, image, error)) << error;
    EXPECT_TRUE(renderer->shadowMap().enabled);
    scene.sun.illuminance = glm::vec3(0.0f);
    postfx::FramePlan plan;
    ASSERT_TRUE(renderer->plan(scene, 1, plan, error)) << error;
    EXPECT_FALSE(plan.reads("host.shadow_map"));
    ASSERT_TRUE(renderer->render(scene, image, error)) << error;
    EXPECT_FALSE(renderer->shadowMap().enabled);
}

// The host renderer alone (no effects: G-buffer, shadow map, lighting) against
// tests/demo/golden/plain_scene.exr.
TEST_F(DemoRendererTest, PlainSceneMatchesGolden) {
    expectMatchesGolden(render(load("demo/scenes/plain.json"), smallOptions(160, 90)), "demo", "plain_scene");
}

}  // namespace
}  // namespace test
