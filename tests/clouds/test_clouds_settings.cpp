// CloudSettings' checks (clouds_settings.cpp): the defaults pass; every bad value is rejected with a
// message naming its key under effects.clouds.
#include "clouds/clouds_settings.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using postfx::CloudSettings;

TEST(CloudsSettings, DefaultsAreValid) {
    const CloudSettings s;
    const postfx::Status st = postfx::validateCloudSettings(s);
    EXPECT_TRUE(st.ok()) << st.message;
    EXPECT_FALSE(s.enabled);
    EXPECT_LE(s.multipleScattering.contribution, s.multipleScattering.attenuation);
}

struct BadCase {
    const char* key;  // expected at the start of the message
    std::function<void(CloudSettings&)> mutate;
};

TEST(CloudsSettings, BadValuesNameTheirKey) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<BadCase> cases = {
        {"FrameInfo.clouds.shape", [](CloudSettings& s) { s.shape = postfx::CloudShape(7); }},
        {"FrameInfo.clouds.quality", [](CloudSettings& s) { s.quality = postfx::CloudQuality(6); }},
        {"FrameInfo.clouds.autoBudgetMs", [](CloudSettings& s) { s.autoBudgetMs = 0.0f; }},
        {"FrameInfo.clouds.autoBudgetMs", [&](CloudSettings& s) { s.autoBudgetMs = inf; }},
        {"FrameInfo.clouds.bottomHeight", [](CloudSettings& s) { s.bottomHeight = -1.0f; }},
        {"FrameInfo.clouds.bottomHeight", [&](CloudSettings& s) { s.bottomHeight = nan; }},
        {"FrameInfo.clouds.topHeight", [](CloudSettings& s) { s.topHeight = 1000.0f; }},
        {"FrameInfo.clouds.topHeight", [&](CloudSettings& s) { s.topHeight = inf; }},
        {"FrameInfo.clouds.box.center[1]", [](CloudSettings& s) { s.box.center.y = 1e10; }},
        {"FrameInfo.clouds.box.halfSize[2]", [](CloudSettings& s) { s.box.halfSize.z = 0.0f; }},
        {"FrameInfo.clouds.box.yawDeg", [](CloudSettings& s) { s.box.yawDeg = 400.0f; }},
        {"FrameInfo.clouds.box.pitchDeg", [&](CloudSettings& s) { s.box.pitchDeg = nan; }},
        {"FrameInfo.clouds.coverage", [](CloudSettings& s) { s.coverage = 1.5f; }},
        {"FrameInfo.clouds.cloudType", [](CloudSettings& s) { s.cloudType = -0.1f; }},
        {"FrameInfo.clouds.density", [](CloudSettings& s) { s.density = 2e3f; }},
        {"FrameInfo.clouds.density", [](CloudSettings& s) { s.density = -1.0f; }},
        {"FrameInfo.clouds.albedo", [](CloudSettings& s) { s.albedo = 1.01f; }},
        {"FrameInfo.clouds.anisotropyForward", [](CloudSettings& s) { s.anisotropyForward = 1.0f; }},
        {"FrameInfo.clouds.anisotropyForward", [](CloudSettings& s) { s.anisotropyForward = -0.2f; }},
        {"FrameInfo.clouds.anisotropyBack", [](CloudSettings& s) { s.anisotropyBack = 0.2f; }},
        {"FrameInfo.clouds.lobeMix", [](CloudSettings& s) { s.lobeMix = 2.0f; }},
        {"FrameInfo.clouds.multipleScattering.octaves",
         [](CloudSettings& s) { s.multipleScattering.octaves = 0; }},
        {"FrameInfo.clouds.multipleScattering.octaves",
         [](CloudSettings& s) { s.multipleScattering.octaves = 9; }},
        {"FrameInfo.clouds.multipleScattering.attenuation",
         [](CloudSettings& s) { s.multipleScattering.attenuation = 0; }},
        {"FrameInfo.clouds.multipleScattering.contribution",
         [](CloudSettings& s) { s.multipleScattering.contribution = 0.8f; }},
        {"FrameInfo.clouds.multipleScattering.model",
         [](CloudSettings& s) { s.multipleScattering.model = postfx::CloudScatteringModel(7); }},
        {"FrameInfo.clouds.multipleScattering.eccentricity",
         [](CloudSettings& s) { s.multipleScattering.eccentricity = 1.5f; }},
        {"FrameInfo.clouds.steps", [](CloudSettings& s) { s.steps = 0; }},
        {"FrameInfo.clouds.steps", [](CloudSettings& s) { s.steps = 2000; }},
        {"FrameInfo.clouds.lightSteps", [](CloudSettings& s) { s.lightSteps = 65; }},
        {"FrameInfo.clouds.lightDistance", [](CloudSettings& s) { s.lightDistance = 0.0f; }},
        {"FrameInfo.clouds.maxDistance", [&](CloudSettings& s) { s.maxDistance = inf; }},
        {"FrameInfo.clouds.wind[0]", [](CloudSettings& s) { s.wind.x = 2e3f; }},
        {"FrameInfo.clouds.noise.baseSize", [](CloudSettings& s) { s.noise.baseSize = 100; }},
        {"FrameInfo.clouds.noise.baseSize", [](CloudSettings& s) { s.noise.baseSize = 512; }},
        {"FrameInfo.clouds.noise.detailSize", [](CloudSettings& s) { s.noise.detailSize = 4; }},
        {"FrameInfo.clouds.noise.tiling", [](CloudSettings& s) { s.noise.tiling = 0.5f; }},
        {"FrameInfo.clouds.noise.detailStrength", [](CloudSettings& s) { s.noise.detailStrength = 1.5f; }},
        {"FrameInfo.clouds.noise.hostTextureLayout",
         [](CloudSettings& s) {
             s.noise.hostBaseTexture = reinterpret_cast<VkImageView>(uintptr_t(8));
             s.noise.hostTextureLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
         }},
        {"FrameInfo.clouds.coverageMap.size", [](CloudSettings& s) { s.coverageMap.size = 0.5f; }},
        {"FrameInfo.clouds.coverageMap.originX", [&](CloudSettings& s) { s.coverageMap.originX = nan; }},
        {"FrameInfo.clouds.coverageMap.originZ", [](CloudSettings& s) { s.coverageMap.originZ = -2e9; }},
        {"FrameInfo.clouds.coverageMap.layout",
         [](CloudSettings& s) {
             s.coverageMap.texture = reinterpret_cast<VkImageView>(uintptr_t(8));
             s.coverageMap.layout = VK_IMAGE_LAYOUT_UNDEFINED;
         }},
        {"FrameInfo.clouds.shadowMap.size", [](CloudSettings& s) { s.shadowMap.size = 8; }},
        {"FrameInfo.clouds.shadowMap.extent", [](CloudSettings& s) { s.shadowMap.extent = 50.0f; }},
        {"FrameInfo.clouds.resolutionScale", [](CloudSettings& s) { s.resolutionScale = 0.2f; }},
        {"FrameInfo.clouds.temporal.blendWeight", [](CloudSettings& s) { s.temporal.blendWeight = 0.0f; }},
    };
    for (const BadCase& c : cases) {
        CloudSettings s;
        c.mutate(s);
        const postfx::Status st = postfx::validateCloudSettings(s);
        EXPECT_EQ(st.code, postfx::Result::InvalidArgument) << c.key;
        EXPECT_EQ(st.message.rfind(std::string(c.key) + ":", 0), 0u) << c.key << " got: " << st.message;
    }
}

}  // namespace
