// The demo host renderer: its shading convention checked against the closed form, depth conventions
// agreeing, and the default scene against a committed golden image.
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/constants.hpp>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class RendererTest : public GpuTest {
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
TEST_F(RendererTest, LitPlaneMatchesShadingConvention) {
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

TEST_F(RendererTest, EmptySceneShowsSkyRadiance) {
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
TEST_F(RendererTest, DepthConventionsRenderTheSameImage) {
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

// The default scene against tests/golden/default_scene.exr. Tolerance: relative RMSE below 1% and at
// most 0.5% of pixels off by more than 2% (shadow-edge texels may differ between drivers).
// POSTFX_ACCEPT_GOLDENS=1 (scripts/accept-goldens.sh) writes the new image as the golden instead.
TEST_F(RendererTest, DefaultSceneMatchesGolden) {
    const std::string golden = kSourceDir + "/tests/golden/default_scene.exr";
    const demo::ImageF image = render(demo::defaultScene(), smallOptions(160, 90));
    std::string error;
    if (const char* accept = std::getenv("POSTFX_ACCEPT_GOLDENS"); accept && std::string(accept) == "1") {
        ASSERT_TRUE(demo::writeImage(golden, image, 15.0f, error)) << error;
        GTEST_SKIP() << "accepted new golden " << golden;
    }
    demo::ImageF expected;
    ASSERT_TRUE(demo::readImage(golden, expected, error)) << error;
    ASSERT_EQ(expected.width, image.width);
    ASSERT_EQ(expected.height, image.height);
    const ImageStats stats = compareImages(image.rgba, expected.rgba, image.width, image.height, 0.02, 1.0);
    const bool pass = stats.relativeRmse < 0.01 && stats.fractionOff < 0.005 && stats.nonFinite == 0;
    if (!pass) {
        const std::filesystem::path dir = std::filesystem::current_path() / "golden-failures";
        std::filesystem::create_directories(dir);
        EXPECT_TRUE(demo::writeImage((dir / "default_scene.actual.exr").string(), image, 15.0f, error))
            << error;
        const std::vector<float> diff = diffImage(image.rgba, expected.rgba, 0.05 * 10000.0);
        auto out = OIIO::ImageOutput::create((dir / "default_scene.diff.png").string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::UINT8);
        out->open((dir / "default_scene.diff.png").string(), spec);
        out->write_image(OIIO::TypeDesc::FLOAT, diff.data());
        out->close();
        ADD_FAILURE() << "default scene differs from " << golden << ": " << stats.summary() << "; wrote "
                      << (dir / "default_scene.actual.exr") << " and " << (dir / "default_scene.diff.png");
    }
}

}  // namespace
}  // namespace test
