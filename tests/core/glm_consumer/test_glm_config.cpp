// A host compiled with another GLM configuration (GLM_FORCE_DEFAULT_ALIGNED_GENTYPES, GLM_FORCE_INTRINSICS:
// glm::vec3 16-byte aligned, glm::mat4 of SIMD columns) hands postfx its structs: the public structs use
// GLM's packed types explicitly, so the library (built with GLM's defaults) reads the same layout, and
// the fog renders its closed form. Built as its own executable with those defines (CMakeLists.txt).
#include "fog_harness.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

static_assert(alignof(glm::vec3) == 16 && sizeof(glm::vec3) == 16,
              "this test must be compiled with GLM's aligned default types");

namespace test {
namespace {

constexpr uint32_t kWidth = 16, kHeight = 8;
constexpr double kWall = 12.0;

double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

class CoreGlmConfigTest : public GpuTest {};

TEST_F(CoreGlmConfigTest, HostWithAlignedGlmTypesGetsTheRightImage) {
    ASSERT_TRUE(host);
    postfx::core::Gpu gpu;
    ASSERT_TRUE(gpu.init(hostHandles()).ok());
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context).ok());

    // Host-side values in the host's own (aligned) GLM types, assigned into postfx's structs.
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
    const glm::vec3 illuminance(1000.0f, 2000.0f, 500.0f), ambient(10.0f, 20.0f, 30.0f),
        albedo(0.9f, 0.5f, 0.7f);
    postfx::FrameInfo frame;
    frame.camera = testCamera({3.0, 4.0, -5.0}, 60.0f, float(kWidth) / kHeight, 0.1f, 1000.0f, true);
    const glm::mat4 view = frame.camera.view;  // aligned copies back and forth
    frame.camera.view = view;
    frame.sun.toSun = toSun;
    frame.sun.illuminance = illuminance;
    frame.ambient = ambient;
    frame.fog.enabled = true;
    frame.fog.density = 0.05f;
    frame.fog.albedo = albedo;
    frame.fog.anisotropy = 0.7f;
    frame.fog.heightFalloff = 0.0f;
    frame.fog.maxDistance = 30.0f;
    frame.fog.steps = 8;
    frame.fog.analyticTail = false;
    frame.fog.transmittanceCutoff = 0.0f;

    FogHarnessImages im;
    im.width = kWidth;
    im.height = kHeight;
    im.color.assign(size_t(kWidth) * kHeight * 4, 100.0f);
    for (uint32_t j = 0; j < kHeight; ++j)
        for (uint32_t i = 0; i < kWidth; ++i)
            im.depth.push_back(
                i < kWidth / 2 ? depthAtDistance(frame.camera,
                                                 pixelDirection(frame.camera, i, j, kWidth, kHeight), kWall)
                               : 0.0f);
    std::vector<float> out;
    const postfx::Status s = FogHarness(*host, gpu).run(*context, im, frame, out);
    ASSERT_TRUE(s.ok()) << s.message;

    // out = color·T + albedo·(E·p(θ) + ambient)·(1 - T), T = e^{-σt·D}, D = min(surface, max distance).
    for (uint32_t j = 0; j < kHeight; ++j)
        for (uint32_t i = 0; i < kWidth; ++i) {
            const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
            const double distance = i < kWidth / 2 ? kWall : 30.0;
            const double t = std::exp(-0.05 * distance);
            const double phase = hg(glm::dot(d, glm::dvec3(toSun)), 0.7);
            for (int c = 0; c < 3; ++c) {
                const double expected =
                    100.0 * t +
                    double(albedo[c]) * (double(illuminance[c]) * phase + double(ambient[c])) * (1.0 - t);
                const double got = out[(size_t(j) * kWidth + i) * 4 + c];
                EXPECT_NEAR(got, expected, 2e-3 * expected) << "pixel " << i << "," << j << " channel " << c;
            }
        }
}

}  // namespace
}  // namespace test
