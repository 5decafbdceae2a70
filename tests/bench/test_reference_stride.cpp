// Renderer::renderReference with a stride (postfx-bench --error-stride): the subsampled reference equals
// the full reference at the pixels (i·stride, j·stride), for a stride that divides the size and one that
// does not. Runs on any Vulkan device (lavapipe in CI) under the validation layer.
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace {

struct StrideCase {
    const char* scene;
    uint32_t width, height, stride;
};

void PrintTo(const StrideCase& c, std::ostream* os) {
    *os << c.scene << " " << c.width << "x" << c.height << " stride " << c.stride;
}

class BenchReferenceStride : public ::testing::TestWithParam<StrideCase> {};

TEST_P(BenchReferenceStride, MatchesTheFullReferenceAtItsPixels) {
    const StrideCase c = GetParam();
    std::string error;
    demo::HostOptions hostOptions;
    hostOptions.validation = true;
    auto host = demo::VulkanHost::create(hostOptions, error);
    ASSERT_TRUE(host) << error;
    demo::Scene scene;
    ASSERT_TRUE(
        demo::loadSceneFile(std::string(POSTFX_DEMO_SCENES_DIR) + "/" + c.scene + ".json", scene, error))
        << error;
    demo::RenderOptions options;
    options.width = c.width;
    options.height = c.height;
    options.fixedTimeSeconds = 0.0;
    {
        auto renderer = demo::Renderer::create(*host, options, error);
        ASSERT_TRUE(renderer) << error;
        demo::ImageF full, sub;
        ASSERT_TRUE(renderer->renderReference(scene, full, error, 256)) << error;
        ASSERT_TRUE(renderer->renderReference(scene, sub, error, 256, c.stride)) << error;
        ASSERT_EQ(sub.width, (c.width + c.stride - 1) / c.stride);
        ASSERT_EQ(sub.height, (c.height + c.stride - 1) / c.stride);
        double worst = 0.0;
        for (uint32_t j = 0; j < sub.height; ++j) {
            for (uint32_t i = 0; i < sub.width; ++i) {
                const float* a = sub.at(i, j);
                const float* b = full.at(i * c.stride, j * c.stride);
                for (int ch = 0; ch < 4; ++ch) {
                    // The same rays up to the float rounding of the adjusted projection.
                    const double d =
                        std::abs(double(a[ch]) - double(b[ch])) / std::max(1.0, std::abs(double(b[ch])));
                    worst = std::max(worst, d);
                }
            }
        }
        std::printf("%s stride %u: largest relative difference %.3g\n", c.scene, c.stride, worst);
        EXPECT_LT(worst, 1e-5) << c.scene << " stride " << c.stride;
    }
    EXPECT_EQ(host->validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BenchReferenceStride,
                         ::testing::Values(StrideCase{"fog_default", 40, 24, 4},
                                           StrideCase{"fog_shadowed", 37, 22, 3},
                                           StrideCase{"fog_height", 33, 20, 5}),
                         [](const ::testing::TestParamInfo<StrideCase>& info) {
                             return std::string(info.param.scene) + "_stride" +
                                    std::to_string(info.param.stride);
                         });

}  // namespace
