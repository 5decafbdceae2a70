// The whole frame's plan: the atmosphere, the clouds (casting shadows) and the froxel fog with a
// light, camera and sun still and no wind. The first frame builds every persistent image; every later
// frame records exactly the passes that depend on the frame (the jittered, temporally accumulated march,
// scatter and their composites) and lists every LUT, noise texture and the clouds' shadow map as cached.
// Shared inputs are made once: the host's depth is unprojected by one pass (postfx.view_distance) that
// every effect reads, one pass makes the clouds' shadow map that the fog reads, the atmosphere's
// transmittance LUT is the one every effect reads, the clouds' base noise is the froxel fog's noise (same
// formula, size and seed), and no two passes of the frame do the same work.
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

using namespace test;

namespace {

using Passes = std::vector<std::string>;

class FramePlanTest : public ReversedZContextTest {
protected:
    void SetUp() override {
        ReversedZContextTest::SetUp();
        frame.camera = lookCamera({0.0, 2.0, 0.0}, {0.0, 0.3, -1.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        frame.sun.toSun = {0.3f, 0.5f, -0.8f};
        frame.sun.illuminance = postfx::Vec3(1.2e5f);
        frame.atmosphere.enabled = true;
        smallScatteringOrders(frame.atmosphere);
        frame.clouds.enabled = true;
        frame.clouds.noise.baseSize = 32;
        frame.clouds.noise.detailSize = 16;
        frame.clouds.shadowMap.size = 64;
        frame.froxelFog.enabled = true;
        frame.froxelFog.grid = {16, 8, 16};
        frame.froxelFog.noise.enabled = true;
        frame.froxelFog.noise.textureSize = 32;
        light.type = postfx::LightType::Point;
        light.position = {0.0, 2.0, -5.0};
        light.intensity = postfx::Vec3(1000.0f);
        frame.lights = &light;
        frame.lightCount = 1;
        im.width = 16;
        im.height = 8;
        im.color.assign(16 * 8 * 4, 1.0f);
        im.depth.assign(16 * 8, 0.0f);
    }

    Passes planAndRun() {
        frame.frameIndex = frameIndex++;
        last = planAndRecord(*host, gpu, *context, im, frame);
        return passNames(last);
    }
    std::set<std::string> cached() const {
        std::set<std::string> out;
        for (const postfx::PlannedResource& r : last.resources)
            if (r.cached) out.insert(r.name);
        return out;
    }

    postfx::FrameInfo frame;
    postfx::LocalLight light;
    FogHarnessImages im;
    postfx::FramePlan last;
    uint64_t frameIndex = 0;
};

}  // namespace

TEST_F(FramePlanTest, StillFramesRecordOnlyWhatDependsOnTheFrame) {
    const Passes first = planAndRun();
    // Every persistent image is built in the first frame.
    for (const char* build : {"atmosphere.transmittance", "atmosphere.scattering_orders", "clouds.base_noise",
                              "clouds.detail_noise", "clouds.shadow"})
        EXPECT_NE(std::find(first.begin(), first.end(), build), first.end()) << build;
    EXPECT_TRUE(cached().empty());
    // The froxel fog's noise (32³, seed 1) is the clouds' base noise: generated once, read by both.
    EXPECT_EQ(std::find(first.begin(), first.end(), "froxel_fog.noise"), first.end());
    const postfx::PlannedPass* firstScatter = last.pass("froxel_fog.scatter");
    ASSERT_TRUE(firstScatter);
    EXPECT_NE(std::find(firstScatter->reads.begin(), firstScatter->reads.end(), "clouds.base_noise"),
              firstScatter->reads.end());

    const Passes still = planAndRun();
    EXPECT_EQ(still,
              (Passes{"postfx.view_distance", "atmosphere.apply", "clouds.march", "clouds.temporal",
                      "clouds.upsample", "froxel_fog.scatter", "froxel_fog.integrate", "froxel_fog.apply"}));
    EXPECT_EQ(cached(), (std::set<std::string>{"atmosphere.transmittance", "atmosphere.multiple_scattering",
                                               "atmosphere.sky_view", "atmosphere.aerial_perspective",
                                               "atmosphere.aerial_transmittance", "clouds.base_noise",
                                               "clouds.detail_noise", "clouds.shadow_map"}));
    EXPECT_EQ(planAndRun(), still);  // and so on

    // Shared inputs, made once: the fog reads the clouds' shadow map and the atmosphere's transmittance LUT,
    // and no pass name repeats.
    const postfx::PlannedPass* scatter = last.pass("froxel_fog.scatter");
    ASSERT_TRUE(scatter);
    for (const char* shared : {"clouds.shadow_map", "atmosphere.transmittance"})
        EXPECT_NE(std::find(scatter->reads.begin(), scatter->reads.end(), shared), scatter->reads.end())
            << shared;
    const postfx::PlannedPass* march = last.pass("clouds.march");
    ASSERT_TRUE(march);
    EXPECT_NE(std::find(march->reads.begin(), march->reads.end(), "atmosphere.transmittance"),
              march->reads.end());
    EXPECT_EQ(std::set<std::string>(still.begin(), still.end()).size(), still.size());
    // The host's depth is read by one pass; every pass that needs surface distances reads its result.
    for (const postfx::PlannedPass& p : last.passes) {
        const bool readsDepth = std::find(p.reads.begin(), p.reads.end(), "host.depth") != p.reads.end();
        EXPECT_EQ(readsDepth, p.name == "postfx.view_distance") << p.name;
    }
    for (const char* reader : {"atmosphere.apply", "clouds.march", "clouds.upsample", "froxel_fog.apply"}) {
        const postfx::PlannedPass* p = last.pass(reader);
        ASSERT_TRUE(p) << reader;
        EXPECT_NE(std::find(p->reads.begin(), p->reads.end(), "postfx.view_distance"), p->reads.end())
            << reader;
    }

    // The sun moves: the atmosphere's view LUTs and the clouds' shadow map are rebuilt, the noise is not.
    frame.sun.toSun = {0.3f, 0.45f, -0.8f};
    const Passes moved = planAndRun();
    for (const char* rebuilt : {"clouds.shadow"})
        EXPECT_NE(std::find(moved.begin(), moved.end(), rebuilt), moved.end()) << rebuilt;
    for (const char* kept : {"clouds.base_noise", "clouds.detail_noise"})
        EXPECT_EQ(std::find(moved.begin(), moved.end(), kept), moved.end()) << kept;
}

// The shared noise is found by either effect's name: the host reads the froxel fog's noise
// (kFroxelFogNoiseTexture) though the clouds declared, named and built it (clouds.base_noise).
TEST_F(FramePlanTest, SharedNoiseIsHeldUnderEveryEffectsName) {
    planAndRun();
    const VkImageView shared = context->imageView(postfx::kCloudsBaseNoise);
    ASSERT_NE(shared, VkImageView(VK_NULL_HANDLE));
    EXPECT_EQ(context->imageView(postfx::kFroxelFogNoiseTexture), shared);
    VkExtent3D fogExtent{}, cloudsExtent{};
    const std::vector<uint8_t> fog =
        readHeldImage(*host, gpu, *context, postfx::kFroxelFogNoiseTexture.value, fogExtent);
    const std::vector<uint8_t> clouds =
        readHeldImage(*host, gpu, *context, postfx::kCloudsBaseNoise.value, cloudsExtent);
    EXPECT_EQ(fogExtent.width, 32u);
    EXPECT_EQ(fog, clouds);

    // Without the clouds the froxel fog holds its own, under its name only.
    frame.clouds.enabled = false;
    planAndRun();
    EXPECT_EQ(context->imageView(postfx::kCloudsBaseNoise), VkImageView(VK_NULL_HANDLE));
    EXPECT_NE(context->imageView(postfx::kFroxelFogNoiseTexture), VkImageView(VK_NULL_HANDLE));
}
