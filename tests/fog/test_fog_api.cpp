// The fog through postfx's public API on a minimal host: the homogeneous medium against its closed
// form, both color formats, in-place and separate output, host layouts preserved, bad input rejected.
#include "fog_harness.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::Result;

double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

class FogApiTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
    }

    // A homogeneous fog frame: camera at `cameraPos`, sun toward `toSun`, no shadow map, no noise.
    postfx::FrameInfo homogeneousFrame(glm::dvec3 cameraPos) const {
        postfx::FrameInfo frame;
        frame.camera = testCamera(cameraPos, 60.0f, float(kWidth) / kHeight, 0.1f, 1000.0f, true);
        frame.sun.toSun =
            glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));  // in front: forward scattering visible
        frame.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
        frame.ambient = {10.0f, 20.0f, 30.0f};
        postfx::FogSettings& fog = frame.fog;
        fog.enabled = true;
        fog.density = 0.05f;
        fog.albedo = {0.9f, 0.5f, 0.7f};
        fog.anisotropy = 0.7f;
        fog.heightFalloff = 0.0f;
        fog.maxDistance = 30.0f;
        fog.steps = 8;  // each step is exact in a homogeneous medium
        fog.jitter = true;
        fog.analyticTail = false;
        fog.transmittanceCutoff = 0.0f;
        return frame;
    }

    // Half the pixels (left half) see a surface at distance 12 m, the others nothing.
    FogHarnessImages images(const postfx::FrameInfo& frame, VkFormat format) const {
        FogHarnessImages im;
        im.width = kWidth;
        im.height = kHeight;
        im.colorFormat = format;
        im.color.resize(kWidth * kHeight * 4);
        im.depth.resize(kWidth * kHeight);
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const size_t p = size_t(j) * kWidth + i;
                const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                im.depth[p] = i < kWidth / 2 ? depthAtDistance(frame.camera, d, kWall) : 0.0f;
                im.color[p * 4 + 0] = 100.0f + i;
                im.color[p * 4 + 1] = 50.0f + j;
                im.color[p * 4 + 2] = 7.0f;
                im.color[p * 4 + 3] = 0.25f;
            }
        return im;
    }

    // out = color·e^{-σt·D} + albedo·(E·p(θ) + ambient)·(1 - e^{-σt·D}), D = min(surface, max distance).
    void expectClosedForm(const postfx::FrameInfo& frame, const FogHarnessImages& im,
                          const std::vector<float>& out, double tolerance) const {
        const postfx::FogSettings& fog = frame.fog;
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const size_t p = size_t(j) * kWidth + i;
                const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                const double distance =
                    i < kWidth / 2 ? std::min<double>(kWall, fog.maxDistance) : fog.maxDistance;
                const double T = std::exp(-double(fog.density) * distance);
                const double phase =
                    hg(glm::dot(d, glm::dvec3(glm::normalize(frame.sun.toSun))), fog.anisotropy);
                for (int c = 0; c < 3; ++c) {
                    const double light = double(frame.sun.illuminance[c]) * phase + double(frame.ambient[c]);
                    const double expected =
                        im.color[p * 4 + c] * T + double(fog.albedo[c]) * light * (1.0 - T);
                    ASSERT_NEAR(out[p * 4 + c], expected, tolerance * expected)
                        << "pixel " << i << "," << j << " c" << c;
                }
                ASSERT_EQ(out[p * 4 + 3], im.color[p * 4 + 3]);  // alpha untouched
            }
    }

    static constexpr uint32_t kWidth = 24, kHeight = 16;
    static constexpr double kWall = 12.0;
    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
};

TEST_F(FogApiTest, HomogeneousMediumMatchesClosedFormRgba16f) {
    const postfx::FrameInfo frame = homogeneousFrame({0.0, 1.5, 0.0});
    const FogHarnessImages im = images(frame, VK_FORMAT_R16G16B16A16_SFLOAT);
    std::vector<float> out;
    FogHarness harness(*host, gpu);
    postfx::Status s = harness.run(*context, im, frame, out);
    ASSERT_TRUE(s.ok()) << s.message;
    expectClosedForm(frame, im, out, 2e-3);  // half floats: 11-bit mantissa
}

TEST_F(FogApiTest, HomogeneousMediumMatchesClosedFormRgba32fFarFromOrigin) {
    // A million metres from the origin: camera-relative marching keeps full precision.
    const postfx::FrameInfo frame = homogeneousFrame({1.0e6, 1.5, -2.0e6});
    const FogHarnessImages im = images(frame, VK_FORMAT_R32G32B32A32_SFLOAT);
    std::vector<float> out;
    FogHarness harness(*host, gpu);
    postfx::Status s = harness.run(*context, im, frame, out);
    ASSERT_TRUE(s.ok()) << s.message;
    expectClosedForm(frame, im, out, 1e-4);
}

// Reduced resolution: with g = 0 the light is the same in every direction, so (L, T) depend only on the
// distance, and the depth-aware upsample must reproduce the closed form at every pixel: wall pixels blend
// only wall texels, sky pixels only sky texels, including at the wall's edge and at non-integer ratios.
TEST_F(FogApiTest, ReducedResolutionMatchesClosedFormEverywhere) {
    for (VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT}) {
        for (float scale : {0.5f, 0.3f, 0.25f}) {
            postfx::FrameInfo frame = homogeneousFrame({0.0, 1.5, 0.0});
            frame.fog.anisotropy = 0.0f;
            frame.fog.resolutionScale = scale;
            FogHarnessImages im = images(frame, format);
            im.separateOutput = scale == 0.3f;
            std::vector<float> color, output;
            FogHarness harness(*host, gpu);
            const postfx::Status s =
                harness.run(*context, im, frame, color, im.separateOutput ? &output : nullptr);
            ASSERT_TRUE(s.ok()) << s.message;
            SCOPED_TRACE("scale " + std::to_string(scale) +
                         (format == VK_FORMAT_R16G16B16A16_SFLOAT ? " rgba16f" : " rgba32f"));
            expectClosedForm(frame, im, im.separateOutput ? output : color,
                             format == VK_FORMAT_R16G16B16A16_SFLOAT ? 2e-3 : 1e-4);
        }
    }
}

TEST_F(FogApiTest, SeparateOutputLeavesColorUntouched) {
    const postfx::FrameInfo frame = homogeneousFrame({0.0, 1.5, 0.0});
    FogHarnessImages im = images(frame, VK_FORMAT_R16G16B16A16_SFLOAT);
    im.separateOutput = true;
    std::vector<float> color, output;
    FogHarness harness(*host, gpu);
    postfx::Status s = harness.run(*context, im, frame, color, &output);
    ASSERT_TRUE(s.ok()) << s.message;
    for (size_t k = 0; k < color.size(); ++k)
        ASSERT_NEAR(color[k], im.color[k], 1e-3f * im.color[k]);
    expectClosedForm(frame, im, output, 2e-3);
}

// Host images in layouts other than the ones the fog uses come back in those layouts (the harness reads
// the color back assuming its original layout; the validation layer reports any mismatch).
TEST_F(FogApiTest, ReturnsHostImagesInTheirLayouts) {
    const postfx::FrameInfo frame = homogeneousFrame({0.0, 1.5, 0.0});
    FogHarnessImages im = images(frame, VK_FORMAT_R16G16B16A16_SFLOAT);
    im.colorLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    im.depthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    std::vector<float> out;
    FogHarness harness(*host, gpu);
    postfx::Status s = harness.run(*context, im, frame, out);
    ASSERT_TRUE(s.ok()) << s.message;
    expectClosedForm(frame, im, out, 2e-3);
}

TEST_F(FogApiTest, RejectsBadSettingsNamingTheField) {
    struct Case {
        const char* field;
        void (*edit)(postfx::FrameInfo&);
    };
    const Case cases[] = {
        {"FrameInfo.fog.density", [](postfx::FrameInfo& f) { f.fog.density = -1.0f; }},
        {"FrameInfo.fog.albedo", [](postfx::FrameInfo& f) { f.fog.albedo.g = NAN; }},
        {"FrameInfo.fog.anisotropy", [](postfx::FrameInfo& f) { f.fog.anisotropy = 1.5f; }},
        {"FrameInfo.fog.steps", [](postfx::FrameInfo& f) { f.fog.steps = 0; }},
        {"FrameInfo.fog.resolutionScale", [](postfx::FrameInfo& f) { f.fog.resolutionScale = 0.2f; }},
        {"FrameInfo.fog.resolutionScale", [](postfx::FrameInfo& f) { f.fog.resolutionScale = NAN; }},
        {"FrameInfo.fog.maxDistance", [](postfx::FrameInfo& f) { f.fog.maxDistance = 0.0f; }},
        {"FrameInfo.fog.shadowKernel", [](postfx::FrameInfo& f) { f.fog.shadowKernel = 4; }},
        {"FrameInfo.fog.noise.tiling",
         [](postfx::FrameInfo& f) {
             f.fog.noise.enabled = true;
             f.fog.noise.tiling = 0.0f;
         }},
        {"FrameInfo.fog.noise.textureSize",
         [](postfx::FrameInfo& f) {
             f.fog.noise.enabled = true;
             f.fog.noise.textureSize = 100;
         }},
        {"sun.illuminance", [](postfx::FrameInfo& f) { f.sun.illuminance.r = -1.0f; }},
        {"sun.toSun", [](postfx::FrameInfo& f) { f.sun.toSun = glm::vec3(0.0f); }},
        {"camera.position", [](postfx::FrameInfo& f) { f.camera.position.x = INFINITY; }},
        {"camera.projection", [](postfx::FrameInfo& f) { f.camera.projection = glm::mat4(0.0f); }},
        {"shadowMap.image.format",
         [](postfx::FrameInfo& f) {
             f.shadowMap.image = {reinterpret_cast<VkImage>(uintptr_t(1)),
                                  reinterpret_cast<VkImageView>(uintptr_t(1)),
                                  VK_FORMAT_R8G8B8A8_UNORM,
                                  {4, 4},
                                  VK_IMAGE_LAYOUT_GENERAL,
                                  VK_IMAGE_USAGE_SAMPLED_BIT};
         }},
    };
    const postfx::FrameInfo base = homogeneousFrame({0.0, 1.5, 0.0});
    const FogHarnessImages im = images(base, VK_FORMAT_R16G16B16A16_SFLOAT);
    FogHarness harness(*host, gpu);
    for (const Case& c : cases) {
        postfx::FrameInfo frame = base;
        c.edit(frame);
        std::vector<float> out;
        postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_EQ(s.code, Result::InvalidArgument) << c.field;
        EXPECT_NE(s.message.find(c.field), std::string::npos) << s.message;
        // Nothing was recorded: the color comes back as it went in.
        for (size_t k = 0; k < out.size(); ++k)
            ASSERT_NEAR(out[k], im.color[k], 1e-3f * im.color[k]) << c.field;
    }
}

}  // namespace
}  // namespace test
