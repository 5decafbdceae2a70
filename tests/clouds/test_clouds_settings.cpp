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
        {"clouds.shape", [](CloudSettings& s) { s.shape = postfx::CloudShape(7); }},
        {"clouds.quality", [](CloudSettings& s) { s.quality = postfx::CloudQuality(6); }},
        {"clouds.auto_budget_ms", [](CloudSettings& s) { s.autoBudgetMs = 0.0f; }},
        {"clouds.auto_budget_ms", [&](CloudSettings& s) { s.autoBudgetMs = inf; }},
        {"clouds.bottom_height", [](CloudSettings& s) { s.bottomHeight = -1.0f; }},
        {"clouds.bottom_height", [&](CloudSettings& s) { s.bottomHeight = nan; }},
        {"clouds.top_height", [](CloudSettings& s) { s.topHeight = 1000.0f; }},
        {"clouds.top_height", [&](CloudSettings& s) { s.topHeight = inf; }},
        {"clouds.box.center[1]", [](CloudSettings& s) { s.box.center.y = 1e10; }},
        {"clouds.box.half_size[2]", [](CloudSettings& s) { s.box.halfSize.z = 0.0f; }},
        {"clouds.box.yaw_deg", [](CloudSettings& s) { s.box.yawDeg = 400.0f; }},
        {"clouds.box.pitch_deg", [&](CloudSettings& s) { s.box.pitchDeg = nan; }},
        {"clouds.coverage", [](CloudSettings& s) { s.coverage = 1.5f; }},
        {"clouds.cloud_type", [](CloudSettings& s) { s.cloudType = -0.1f; }},
        {"clouds.density", [](CloudSettings& s) { s.density = 2e3f; }},
        {"clouds.density", [](CloudSettings& s) { s.density = -1.0f; }},
        {"clouds.albedo", [](CloudSettings& s) { s.albedo = 1.01f; }},
        {"clouds.anisotropy_forward", [](CloudSettings& s) { s.anisotropyForward = 1.0f; }},
        {"clouds.anisotropy_forward", [](CloudSettings& s) { s.anisotropyForward = -0.2f; }},
        {"clouds.anisotropy_back", [](CloudSettings& s) { s.anisotropyBack = 0.2f; }},
        {"clouds.lobe_mix", [](CloudSettings& s) { s.lobeMix = 2.0f; }},
        {"clouds.multiple_scattering.octaves", [](CloudSettings& s) { s.multipleScattering.octaves = 0; }},
        {"clouds.multiple_scattering.octaves", [](CloudSettings& s) { s.multipleScattering.octaves = 9; }},
        {"clouds.multiple_scattering.attenuation",
         [](CloudSettings& s) { s.multipleScattering.attenuation = 0; }},
        {"clouds.multiple_scattering.contribution",
         [](CloudSettings& s) { s.multipleScattering.contribution = 0.8f; }},
        {"clouds.multiple_scattering.model",
         [](CloudSettings& s) { s.multipleScattering.model = postfx::CloudScatteringModel(7); }},
        {"clouds.multiple_scattering.eccentricity",
         [](CloudSettings& s) { s.multipleScattering.eccentricity = 1.5f; }},
        {"clouds.steps", [](CloudSettings& s) { s.steps = 0; }},
        {"clouds.steps", [](CloudSettings& s) { s.steps = 2000; }},
        {"clouds.light_steps", [](CloudSettings& s) { s.lightSteps = 65; }},
        {"clouds.light_distance", [](CloudSettings& s) { s.lightDistance = 0.0f; }},
        {"clouds.max_distance", [&](CloudSettings& s) { s.maxDistance = inf; }},
        {"clouds.wind[0]", [](CloudSettings& s) { s.wind.x = 2e3f; }},
        {"clouds.noise.base_size", [](CloudSettings& s) { s.noise.baseSize = 100; }},
        {"clouds.noise.base_size", [](CloudSettings& s) { s.noise.baseSize = 512; }},
        {"clouds.noise.detail_size", [](CloudSettings& s) { s.noise.detailSize = 4; }},
        {"clouds.noise.tiling", [](CloudSettings& s) { s.noise.tiling = 0.5f; }},
        {"clouds.noise.detail_strength", [](CloudSettings& s) { s.noise.detailStrength = 1.5f; }},
        {"clouds.noise.host_texture_layout",
         [](CloudSettings& s) {
             s.noise.hostBaseTexture = reinterpret_cast<VkImageView>(uintptr_t(8));
             s.noise.hostTextureLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
         }},
        {"clouds.coverage_map.size", [](CloudSettings& s) { s.coverageMap.size = 0.5f; }},
        {"clouds.coverage_map.origin_x", [&](CloudSettings& s) { s.coverageMap.originX = nan; }},
        {"clouds.coverage_map.origin_z", [](CloudSettings& s) { s.coverageMap.originZ = -2e9; }},
        {"clouds.coverage_map.layout",
         [](CloudSettings& s) {
             s.coverageMap.texture = reinterpret_cast<VkImageView>(uintptr_t(8));
             s.coverageMap.layout = VK_IMAGE_LAYOUT_UNDEFINED;
         }},
        {"clouds.shadow_map.size", [](CloudSettings& s) { s.shadowMap.size = 8; }},
        {"clouds.shadow_map.extent", [](CloudSettings& s) { s.shadowMap.extent = 50.0f; }},
        {"clouds.resolution_scale", [](CloudSettings& s) { s.resolutionScale = 0.2f; }},
        {"clouds.temporal.blend_weight", [](CloudSettings& s) { s.temporal.blendWeight = 0.0f; }},
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
