// The clouds' frame plan (docs/frame-plan.md): the first frame generates the two noise textures, later
// frames only the shadow map, march, temporal accumulation and upsample (at full resolution without
// temporal or shadows: the march alone); coverage or density 0 runs nothing; with the atmosphere the march
// follows its passes and reads its LUTs; the fogs read the shadow map after it is made; the recorded passes
// are the plan's; the resources' bytes.
#include "core/context_impl.h"
#include "fog_harness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test {
namespace {

using Passes = std::vector<std::string>;

class CloudsPlanTest : public ReversedZContextTest {
protected:
    void SetUp() override {
        ReversedZContextTest::SetUp();
        frame.clouds.enabled = true;
        frame.clouds.noise.baseSize = 32;
        frame.clouds.noise.detailSize = 16;
        frame.sun.toSun = {0.6f, 0.8f, 0.0f};
        frame.sun.illuminance = postfx::Vec3(1e5f);
        frame.camera = lookCamera({0.0, 10.0, 0.0}, {1.0, 0.4, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        im.width = 16;
        im.height = 8;
        im.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        im.color.assign(16 * 8 * 4, 0.0f);
        im.depth.assign(16 * 8, 0.0f);
    }

    // Plans and records the frame; the recorded passes (timings) must be the plan's.
    Passes planAndRun() {
        frame.frameIndex = frameIndex++;
        last = planAndRecord(*host, gpu, *context, im, frame);
        return passNames(last);
    }

    // The plan's `cached` flag of `name` (false when not held).
    bool cachedOf(const std::string& name) const {
        for (const postfx::PlannedResource& r : last.resources)
            if (r.name == name) return r.cached;
        return false;
    }

    uint64_t bytesOf(const std::string& name) const {
        for (const postfx::PlannedResource& r : last.resources)
            if (r.name == name) return r.bytes;
        return 0;
    }

    postfx::FrameInfo frame;
    FogHarnessImages im;
    postfx::FramePlan last;
    uint64_t frameIndex = 0;
};

// The defaults: shadows, half resolution, temporal. The shadow map is built once and kept while the camera,
// the sun and the clouds stand still (no wind): a still frame records only what depends on the frame.
TEST_F(CloudsPlanTest, DefaultsMakeTheShadowMapMarchAtHalfSizeAccumulateAndUpsample) {
    const Passes every{"clouds.march", "clouds.temporal", "clouds.upsample"};
    const Passes first{"clouds.base_noise", "clouds.detail_noise", "clouds.shadow",
                       "clouds.march",      "clouds.temporal",     "clouds.upsample"};
    EXPECT_EQ(planAndRun(), first);
    EXPECT_FALSE(cachedOf("clouds.shadow_map"));
    EXPECT_EQ(bytesOf("clouds.shadow_map"), 512u * 512 * 4);  // R32F
    EXPECT_EQ(bytesOf("clouds.scatter"), 8u * 4 * 8);         // half of 16×8, the color's RGBA16F
    EXPECT_EQ(bytesOf("clouds.history_a"), 8u * 4 * 16);      // RGBA32F
    EXPECT_EQ(bytesOf("clouds.history_distance_b"), 8u * 4 * 4);
    EXPECT_EQ(planAndRun(), every);
    EXPECT_TRUE(cachedOf("clouds.shadow_map"));
    EXPECT_EQ(bytesOf("clouds.shadow_map"), 512u * 512 * 4);  // still held
    // What moves it rebuilds it: the sun, the wind over time, the camera (its position enters the
    // samples' camera-relative coordinates).
    frame.sun.toSun = {0.6f, 0.7f, 0.1f};
    EXPECT_EQ(planAndRun(), (Passes{"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"}));
    frame.clouds.wind = {10.0f, 0.0f, 0.0f};
    frame.timeSeconds = 1.0;
    EXPECT_EQ(planAndRun(), (Passes{"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"}));
    frame.clouds.wind = {0.0f, 0.0f, 0.0f};
    EXPECT_EQ(planAndRun(), (Passes{"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"}));
    EXPECT_EQ(planAndRun(), every);  // no wind: still again
    frame.camera.position.x += 100.0;
    EXPECT_EQ(planAndRun(), (Passes{"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"}));
    frame.clouds.temporal.enabled = false;  // half size without temporal: march and upsample
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march", "clouds.upsample"}));
    EXPECT_EQ(bytesOf("clouds.history_a"), 0u);
    frame.clouds.castShadows = false;  // no shadow map held
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march", "clouds.upsample"}));
    EXPECT_EQ(bytesOf("clouds.shadow_map"), 0u);
}

// Both fogs read the shadow map the clouds made earlier in the frame (a new sun each time: it is built).
TEST_F(CloudsPlanTest, TheFogsReadTheShadowMapAfterItIsMade) {
    for (bool froxel : {false, true}) {
        frame.fog.enabled = !froxel;
        frame.froxelFog.enabled = froxel;
        frame.sun.toSun = froxel ? glm::vec3(0.5f, 0.8f, 0.2f) : glm::vec3(0.6f, 0.8f, 0.1f);
        const Passes passes = planAndRun();
        const char* consumer = froxel ? "froxel_fog.scatter" : "fog.raymarch";
        const auto shadow = std::find(passes.begin(), passes.end(), "clouds.shadow");
        const auto fog = std::find(passes.begin(), passes.end(), consumer);
        ASSERT_NE(fog, passes.end()) << consumer;
        EXPECT_LT(shadow, fog) << consumer;
        for (const postfx::PlannedPass& p : last.passes) {
            if (p.name != consumer) continue;
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), "clouds.shadow_map"), p.reads.end());
        }
    }
}

TEST_F(CloudsPlanTest, NoiseOnceThenOnlyTheMarchAndNothingWithoutCoverage) {
    frame.clouds.resolutionScale = 1.0f;  // at full size, without temporal and shadows: the march alone
    frame.clouds.temporal.enabled = false;
    frame.clouds.castShadows = false;
    EXPECT_EQ(planAndRun(), (Passes{"clouds.base_noise", "clouds.detail_noise", "clouds.march"}));
    EXPECT_EQ(bytesOf("clouds.base_noise"), 32u * 32 * 32);
    EXPECT_EQ(bytesOf("clouds.detail_noise"), 16u * 16 * 16);
    EXPECT_FALSE(cachedOf("clouds.base_noise"));  // built in this frame
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march"}));
    EXPECT_TRUE(cachedOf("clouds.base_noise"));  // held, not rebuilt: the plan says cached
    EXPECT_TRUE(cachedOf("clouds.detail_noise"));
    EXPECT_FALSE(cachedOf("clouds.uniforms"));  // buffers are written every frame
    frame.timeSeconds = 10.0;                   // the wind moves the field, not the textures
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march"}));
    frame.clouds.noise.seed = 2;  // a new base and detail texture
    EXPECT_EQ(planAndRun(), (Passes{"clouds.base_noise", "clouds.detail_noise", "clouds.march"}));
    frame.clouds.coverage = 0.0f;  // no clouds: nothing runs, nothing is held
    EXPECT_EQ(planAndRun(), Passes{});
    EXPECT_EQ(bytesOf("clouds.base_noise"), 0u);
    frame.clouds.coverage = 0.5f;
    frame.clouds.density = 0.0f;
    EXPECT_EQ(planAndRun(), Passes{});
    frame.clouds.density = 0.02f;
    frame.clouds.noise.enabled = false;  // homogeneous: no textures
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march"}));
}

TEST_F(CloudsPlanTest, WithTheAtmosphereTheMarchReadsItsLuts) {
    frame.atmosphere.enabled = true;
    smallScatteringOrders(frame.atmosphere);
    frame.clouds.resolutionScale = 1.0f;
    frame.clouds.temporal.enabled = false;
    frame.clouds.castShadows = false;
    const Passes passes = planAndRun();
    const auto apply = std::find(passes.begin(), passes.end(), "atmosphere.apply");
    const auto march = std::find(passes.begin(), passes.end(), "clouds.march");
    ASSERT_NE(march, passes.end());
    EXPECT_LT(apply, march);  // the sky first, then the clouds over it
    for (const postfx::PlannedPass& p : last.passes) {
        if (p.name != "clouds.march") continue;
        for (const char* lut :
             {"atmosphere.uniforms", "atmosphere.transmittance", "atmosphere.aerial_perspective",
              "atmosphere.aerial_transmittance", "atmosphere.multiple_scattering"})
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), lut), p.reads.end()) << lut;
    }
    // Two effects: the depth is unprojected once, before both (docs/architecture.md, "Shared inputs").
    EXPECT_EQ(planAndRun(), (Passes{"postfx.view_distance", "atmosphere.apply", "clouds.march"})) << "still";
}

// The march is one shader whose atmosphere, own image and temporal distances are specialization
// constants: a frame switching between its 6 combinations keeps at most 4 pipelines of it (the graph's
// rule per description), the plan still the combination's.
TEST_F(CloudsPlanTest, SwitchingTheMarchsCombinationsKeepsAtMostFourPipelines) {
    const postfx::core::FrameGraph& graph = postfx::ContextAccess::of(*context).graph;
    frame.clouds.castShadows = false;
    for (int round = 0; round < 2; ++round)
        for (bool atmosphere : {false, true})
            for (int mode = 0; mode < 3; ++mode) {  // composite, own image, own image with temporal
                frame.atmosphere.enabled = atmosphere;
                frame.clouds.resolutionScale = mode == 0 ? 1.0f : 0.5f;
                frame.clouds.temporal.enabled = mode == 2;
                const Passes passes = planAndRun();
                const bool upsample =
                    std::find(passes.begin(), passes.end(), "clouds.upsample") != passes.end();
                const bool temporal =
                    std::find(passes.begin(), passes.end(), "clouds.temporal") != passes.end();
                EXPECT_EQ(upsample, mode != 0) << atmosphere << mode;
                EXPECT_EQ(temporal, mode == 2) << atmosphere << mode;
                EXPECT_EQ(bytesOf("clouds.no_atmosphere"), atmosphere ? 0u : 2u) << atmosphere << mode;
                EXPECT_EQ(bytesOf("clouds.no_distance"), mode == 2 ? 0u : 4u) << atmosphere << mode;
                const size_t held = graph.heldPipelines("clouds.march");
                EXPECT_GE(held, 1u);
                EXPECT_LE(held, 4u) << atmosphere << mode;
            }
    EXPECT_EQ(graph.heldPipelines("clouds.march"), 4u);
}

// The sparse update (update_block): a frame with history marches one texel of each block (a quarter or a
// sixteenth of the rays) and its temporal pass reads the depth (the skipped texels' surfaces); the
// first frame and a camera cut march every texel. 64×32 pixels: a 32×16 march at half resolution.
TEST_F(CloudsPlanTest, SparseUpdateMarchesOneTexelPerBlock) {
    im.width = 64;
    im.height = 32;
    im.color.assign(64 * 32 * 4, 0.0f);
    im.depth.assign(64 * 32, 0.0f);
    frame.clouds.castShadows = false;
    auto marchGroups = [&]() {
        const postfx::PlannedPass* march = last.pass("clouds.march");
        return march ? std::vector<uint32_t>{march->groups[0], march->groups[1]} : std::vector<uint32_t>{};
    };
    auto temporalReadsDepth = [&]() {
        const postfx::PlannedPass* t = last.pass("clouds.temporal");
        return t && std::find(t->reads.begin(), t->reads.end(), "host.depth") != t->reads.end();
    };
    for (uint32_t block : {1u, 2u, 4u}) {
        frame.clouds.updateBlock = block;
        frame.cameraCut = true;
        planAndRun();
        // A march this small (at most 512 rays) shares each ray among 8 invocations (march.comp's
        // segments): 32 rays a row of 8-wide groups.
        EXPECT_EQ(marchGroups(), (std::vector<uint32_t>{32, 2})) << "update_block " << block << ", a cut";
        // The temporal pass reads the depth (its skipped texels' surfaces; sync validation counts it
        // whenever the shader has it).
        EXPECT_TRUE(temporalReadsDepth()) << "update_block " << block << ", a cut";
        frame.cameraCut = false;
        planAndRun();
        const uint32_t x = 32 / block, y = (16 / block + 7) / 8;
        EXPECT_EQ(marchGroups(), (std::vector<uint32_t>{x, y})) << "update_block " << block;
        EXPECT_TRUE(temporalReadsDepth()) << "update_block " << block;
    }
    frame.clouds.temporal.enabled = false;  // without temporal the block is not used: every texel
    frame.clouds.updateBlock = 4;
    planAndRun();
    EXPECT_EQ(marchGroups(), (std::vector<uint32_t>{32, 2}));
}

}  // namespace
}  // namespace test
