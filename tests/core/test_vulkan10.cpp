// postfx on a Vulkan 1.0 instance (VkApplicationInfo::apiVersion 1.0, as tutorial renderers create
// theirs): its SPIR-V is 1.0 and it calls only Vulkan 1.0 functions, so every effect renders with no
// validation message (GpuTest fails on any).
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <cmath>
#include <string>
#include <vector>

namespace test {
namespace {

class CoreVulkan10Test : public GpuTest {
protected:
    void SetUp() override {
        demo::HostOptions options;
        options.validation = true;
        options.apiVersion = VK_API_VERSION_1_0;
        std::string error;
        host = demo::VulkanHost::create(options, error);
        ASSERT_TRUE(host) << error;
        ASSERT_EQ(host->apiVersion, VK_API_VERSION_1_0);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
    }
    postfx::core::Gpu gpu;
};

TEST_F(CoreVulkan10Test, EveryEffectRendersWithoutValidationMessages) {
    postfx::ContextCreateInfo info;
    info.depth.reversedZ = true;
    info.maxExtent = {32, 16};
    std::unique_ptr<postfx::Context> context;
    postfx::Status s = createContext(context, info);
    ASSERT_TRUE(s.ok()) << s.message;

    postfx::FrameInfo f;
    f.camera = lookCamera({0.0, 2.0, 0.0}, {0.0, 0.2, -1.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
    f.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.5f, -0.8f));
    f.sun.illuminance = postfx::Vec3(1.2e5f);
    f.atmosphere.enabled = true;
    smallScatteringOrders(f.atmosphere);
    f.clouds.enabled = true;
    f.clouds.noise.baseSize = 32;
    f.clouds.noise.detailSize = 16;
    f.clouds.shadowMap.size = 64;
    f.froxelFog.enabled = true;
    f.froxelFog.grid = {16, 8, 16};
    postfx::LocalLight light;
    light.type = postfx::LightType::Point;
    light.position = {0.0, 2.0, -5.0};
    light.intensity = postfx::Vec3(1000.0f);
    f.lights = &light;
    f.lightCount = 1;
    f.volumetricsLookup.enabled = true;
    f.volumetricsLookup.extent = {16, 8, 16};
    const FogHarnessImages images = surfaceImages(
        f.camera, 32, 16, [](uint32_t, uint32_t j) { return j < 6 ? INFINITY : 40.0; },
        [](uint32_t, uint32_t, int) { return 1.0f; });
    FogHarness harness(*host, gpu);
    std::vector<float> color;
    for (uint64_t frame = 0; frame < 2; ++frame) {
        f.frameIndex = frame;
        s = harness.run(*context, images, f, color);
        ASSERT_TRUE(s.ok()) << s.message;
    }
    double sum = 0.0;
    for (float v : color)
        sum += v;
    EXPECT_TRUE(std::isfinite(sum));
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace test
