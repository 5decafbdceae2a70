// The froxel fog's frame plan (docs/frame-plan.md, docs/effects/froxel-fog.md#frame-plan): off or empty
// records nothing; without local lights no light buffer and no light lists; few lights a buffer, many
// also the light lists; every pass's workgroups and every resource's bytes exactly; the recorded passes
// are the plan's; a grid over the limits is refused, not clamped.
#include "froxel_case.h"

#include <algorithm>
#include <string>
#include <vector>

namespace test {
namespace {

std::vector<std::string> passNames(const postfx::FramePlan& plan) {
    std::vector<std::string> names;
    for (const postfx::PlannedPass& p : plan.passes)
        names.push_back(p.name);
    return names;
}

uint64_t resourceBytes(const postfx::FramePlan& plan, const std::string& name) {
    for (const postfx::PlannedResource& r : plan.resources)
        if (r.name == name) return r.bytes;
    ADD_FAILURE() << "no resource " << name;
    return 0;
}

std::string sizedBy(const postfx::FramePlan& plan, const std::string& name) {
    for (const postfx::PlannedResource& r : plan.resources)
        if (r.name == name) return r.sizedBy;
    ADD_FAILURE() << "no resource " << name;
    return {};
}

constexpr uint64_t kUniformSlot = 2560;  // sizeof(FogUniforms) + sizeof(FroxelUniforms) = 2544, to 256
constexpr uint64_t kLightSlot = 20480;   // 256 lights × 80 bytes

class FroxelFogPlanTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
        c = froxelCase(40, 24, 1.0, 20, 10.0);
        c.frame.froxelFog.grid = {20, 12, 40};
        c.frame.froxelFog.temporal.enabled = false;  // the single-frame layout (TemporalHistories: on)
    }

    // Plans and records `fc` at `frameIndex`; the recorded passes (timings) must be the plan's.
    postfx::FramePlan planAndRun(const FroxelCase& fc, uint64_t frameIndex,
                                 std::vector<float>* color = nullptr) {
        postfx::FrameInfo frame = fc.prepared();
        frame.frameIndex = frameIndex;
        postfx::FramePlan plan;
        postfx::Status planned = postfx::Status::success();
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) { planned = context->plan(f, plan); };
        std::vector<float> out;
        const postfx::Status s = harness.run(*context, fc.images, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        EXPECT_TRUE(planned.ok()) << planned.message;
        std::vector<postfx::PassTiming> timings;
        EXPECT_TRUE(context->readPassTimings(frameIndex, timings).ok());
        std::vector<std::string> recorded;
        for (const postfx::PassTiming& t : timings)
            recorded.push_back(t.name);
        EXPECT_EQ(recorded, passNames(plan)) << "frame " << frameIndex;
        if (color) *color = out;
        return plan;
    }

    static postfx::LocalLight light(double x) {
        postfx::LocalLight l;
        l.position = {x, 1.0, -8.0};
        l.intensity = {50.0f, 50.0f, 50.0f};
        l.range = 5.0f;
        return l;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
    FroxelCase c;
};

// Off, density 0 without volumes, noise that is 0 everywhere, volumes of density 0 or of zero size:
// no pass, no resource, the color as it was.
TEST_F(FroxelFogPlanTest, OffOrEmptyRecordsNothing) {
    std::vector<FroxelCase> cases(5, c);
    cases[0].frame.froxelFog.enabled = false;
    cases[1].frame.froxelFog.density = 0.0f;
    cases[2].frame.froxelFog.noise.enabled = true;
    cases[2].frame.froxelFog.noise.threshold = 1.0f;
    cases[3].frame.froxelFog.density = 0.0f;
    cases[3].volumes.resize(2);
    cases[3].volumes[0].density = 0.0f;
    cases[3].volumes[1].shape = postfx::FogVolumeShape::Sphere;
    cases[3].volumes[1].radius = 0.0f;
    cases[4].frame.froxelFog.enabled = false;
    cases[4].lights = {light(0.0)};  // lights alone light nothing
    uint64_t frameIndex = 0;
    for (const FroxelCase& fc : cases) {
        std::vector<float> color;
        const postfx::FramePlan plan = planAndRun(fc, frameIndex++, &color);
        EXPECT_TRUE(plan.passes.empty()) << "frame " << frameIndex - 1;
        EXPECT_TRUE(plan.resources.empty());
        EXPECT_EQ(color, fc.images.color);
    }
}

// No local light: scatter, integrate, apply; the two rgba16f volumes, the 1-texel noise stand-in and the
// uniform slots (two frames in flight).
TEST_F(FroxelFogPlanTest, WithoutLightsNoLightWork) {
    const postfx::FramePlan plan = planAndRun(c, 0);
    EXPECT_EQ(passNames(plan),
              (std::vector<std::string>{"froxel_fog.scatter", "froxel_fog.integrate", "froxel_fog.apply"}));
    const uint64_t volume = 20 * 12 * 40 * 8;
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.scatter"), volume);
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.integrated"), volume);
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.no_noise"), 1u);
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.uniforms"), 2 * kUniformSlot);
    EXPECT_EQ(plan.totalBytes(), 2 * volume + 1 + 2 * kUniformSlot);
    EXPECT_EQ(plan.resources.size(), 4u);
    const postfx::PlannedPass* scatter = plan.pass("froxel_fog.scatter");
    ASSERT_TRUE(scatter);
    EXPECT_EQ(std::vector<uint32_t>(scatter->groups, scatter->groups + 3), (std::vector<uint32_t>{3, 2, 40}));
    const postfx::PlannedPass* integrate = plan.pass("froxel_fog.integrate");
    ASSERT_TRUE(integrate);
    EXPECT_EQ(std::vector<uint32_t>(integrate->groups, integrate->groups + 3),
              (std::vector<uint32_t>{3, 2, 1}));
    const postfx::PlannedPass* apply = plan.pass("froxel_fog.apply");
    ASSERT_TRUE(apply);
    EXPECT_EQ(std::vector<uint32_t>(apply->groups, apply->groups + 3), (std::vector<uint32_t>{5, 3, 1}));
    EXPECT_EQ(apply->reads, (std::vector<std::string>{"host.color", "host.depth", "froxel_fog.uniforms",
                                                      "froxel_fog.integrated"}));
    EXPECT_FALSE(plan.reads("host.shadow_map"));  // no sun
}

// A tile size whose grid would exceed the limits is refused naming tileSizePx and the extent, not
// clamped (a 1-px tile at 1024×600 would be 1024×600 froxels); a grid over kMaxFroxels likewise; each
// setting names the key that sizes the volumes in the plan.
TEST_F(FroxelFogPlanTest, GridOverTheLimitsIsRefusedNotClamped) {
    const postfx::FrameInfo frame = c.prepared();
    FogHarness harness(*host, gpu);
    std::vector<std::pair<postfx::Status, postfx::FramePlan>> plans;
    harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
        // Only the plan: the extents are not the images' (plan() creates and records nothing).
        auto plan = [&](uint32_t tile, uint32_t slices, uint32_t width, uint32_t height) {
            postfx::FrameInfo g = f;
            g.froxelFog.tileSizePx = tile;
            g.froxelFog.grid.z = slices;
            g.color.extent = g.depth.extent = {width, height};
            postfx::FramePlan p;
            const postfx::Status s = context->plan(g, p);
            plans.emplace_back(s, p);
        };
        plan(1, 40, 1024, 600);
        plan(2, 40, 1024, 600);
        plan(2, 512, 1024, 600);
        plan(0, 40, 40, 24);
    };
    std::vector<float> out;
    ASSERT_TRUE(harness.run(*context, c.images, frame, out).ok());
    ASSERT_EQ(plans.size(), 4u);
    EXPECT_EQ(
        plans[0].first.message,
        "FrameInfo.froxelFog.tileSizePx: 1 px at 1024x600 gives 1024x600 froxels, more than 512 across or "
        "down (kMaxFroxelGridSize): at least 2 px at this extent");
    ASSERT_TRUE(plans[1].first.ok()) << plans[1].first.message;
    EXPECT_EQ(resourceBytes(plans[1].second, "froxel_fog.integrated"), 512u * 300 * 40 * 8);
    EXPECT_EQ(sizedBy(plans[1].second, "froxel_fog.integrated"), "froxel_fog.tile_size_px");
    EXPECT_EQ(plans[2].first.message,
              "FrameInfo.froxelFog.tileSizePx: 2 px at 1024x600 gives 512x300x512 = 78643200 froxels, more "
              "than kMaxFroxels (8388608)");
    EXPECT_EQ(sizedBy(plans[3].second, "froxel_fog.integrated"), "froxel_fog.grid");
    postfx::FroxelFogSettings s;
    s.grid = {512, 512, 33};
    EXPECT_EQ(postfx::validateFroxelFogSettings(s).message,
              "FrameInfo.froxelFog.grid: 512x512x33 = 8650752 froxels, more than kMaxFroxels (8388608)");
}

// Below light_list_min_lights (its default) the lights' buffer only (zero-intensity lights do not count);
// at it, the light lists: clusters of 8×8 froxels × 16 slices, one 32-bit word per 32 lights each.
TEST_F(FroxelFogPlanTest, LightListsOnlyForManyLights) {
    const uint32_t threshold = postfx::FroxelFogSettings{}.lightListMinLights;
    ASSERT_GT(threshold, 1u);
    ASSERT_LE(threshold, 40u) << "`many` below has 40 lights";
    FroxelCase few = c;
    for (uint32_t k = 0; k + 1 < threshold; ++k)
        few.lights.push_back(light(k));
    few.lights.push_back(light(9.0));
    few.lights.back().intensity = glm::vec3(0.0f);  // the threshold-th light adds nothing
    postfx::FramePlan plan = planAndRun(few, 0);
    EXPECT_EQ(passNames(plan),
              (std::vector<std::string>{"froxel_fog.scatter", "froxel_fog.integrate", "froxel_fog.apply"}));
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.lights"), 2 * kLightSlot);
    EXPECT_TRUE(plan.reads("froxel_fog.lights"));

    FroxelCase many = c;
    for (int k = 0; k < 40; ++k)
        many.lights.push_back(light(0.25 * k - 5.0));
    plan = planAndRun(many, 1);
    EXPECT_EQ(passNames(plan), (std::vector<std::string>{"froxel_fog.light_lists", "froxel_fog.scatter",
                                                         "froxel_fog.integrate", "froxel_fog.apply"}));
    // 20×12×40 froxels: 3×2×3 clusters, 2 words (40 lights) each.
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.light_lists"), 3u * 2 * 3 * 2 * 4);
    const postfx::PlannedPass* lists = plan.pass("froxel_fog.light_lists");
    ASSERT_TRUE(lists);
    EXPECT_EQ(std::vector<uint32_t>(lists->groups, lists->groups + 3), (std::vector<uint32_t>{3, 2, 6}));
    EXPECT_EQ(plan.totalBytes(),
              2u * 20 * 12 * 40 * 8 + 1 + 2 * kUniformSlot + 2 * kLightSlot + 3 * 2 * 3 * 2 * 4);

    many.frame.froxelFog.lightListMinLights = postfx::kMaxLocalLights + 1;  // never
    plan = planAndRun(many, 2);
    EXPECT_FALSE(plan.pass("froxel_fog.light_lists"));
}

// Local lights' shadows: the scatter pass reads the host's atlas and the shadows' faces (a storage buffer
// of 80 bytes a face, each shadow once however many lights share it); with temporal accumulation the
// shadow-change pass writes the shadowed lights' light per block of 2×2×2 froxels (two R32F volumes, this
// frame's and the last's) and where it changed (RGBA8), which the scatter pass reads. Without a light that
// names a shadow, none of it.
TEST_F(FroxelFogPlanTest, LocalShadowsOnlyWhenALightHasOne) {
    FroxelCase shadowed = c;
    shadowed.lights = {light(0.0), light(1.0), light(2.0)};
    shadowed.images.localShadow.assign(64 * 32, 1.0f);
    shadowed.images.localShadowWidth = 64;
    shadowed.images.localShadowHeight = 32;
    postfx::LocalShadow cube;
    cube.faceCount = 6;
    for (uint32_t f = 0; f < 6; ++f) {
        cube.faces[f].offset = {f % 3 * 16, f / 3 * 16};
        cube.faces[f].extent = {16, 16};
    }
    postfx::LocalShadow spot;
    spot.faces[0].offset = {48, 0};
    spot.faces[0].extent = {16, 16};
    shadowed.localShadows = {cube, spot};
    postfx::FramePlan plan = planAndRun(shadowed, 0);
    EXPECT_FALSE(plan.reads("host.local_shadow_atlas"));  // no light names a shadow
    EXPECT_FALSE(plan.reads("froxel_fog.shadow_faces"));

    shadowed.lights[0].shadow = 0;
    shadowed.lights[1].shadow = 1;
    shadowed.lights[2].shadow = 0;  // shares the cube
    plan = planAndRun(shadowed, 1);
    const postfx::PlannedPass* scatter = plan.pass("froxel_fog.scatter");
    ASSERT_TRUE(scatter);
    EXPECT_TRUE(std::find(scatter->reads.begin(), scatter->reads.end(), "host.local_shadow_atlas") !=
                scatter->reads.end());
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.shadow_faces"), 2u * 768);  // 7 faces × 80 = 560, to 256
    EXPECT_FALSE(plan.reads("froxel_fog.shadowed_light_a"));              // temporal off
    EXPECT_FALSE(plan.pass("froxel_fog.shadow_change"));

    shadowed.frame.froxelFog.temporal.enabled = true;
    plan = planAndRun(shadowed, 2);
    EXPECT_EQ(passNames(plan), (std::vector<std::string>{"froxel_fog.shadow_change", "froxel_fog.scatter",
                                                         "froxel_fog.integrate", "froxel_fog.apply"}));
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.shadowed_light_a"), 10u * 6 * 20 * 4);  // 20×12×40 in blocks
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.shadowed_light_b"), 10u * 6 * 20 * 4);
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.shadow_change"), 10u * 6 * 20 * 4);
    const postfx::PlannedPass* change = plan.pass("froxel_fog.shadow_change");
    ASSERT_TRUE(change);
    EXPECT_EQ(std::vector<uint32_t>(change->groups, change->groups + 3), (std::vector<uint32_t>{3, 2, 5}));
    scatter = plan.pass("froxel_fog.scatter");
    ASSERT_TRUE(scatter);
    EXPECT_TRUE(std::find(scatter->reads.begin(), scatter->reads.end(), "froxel_fog.shadow_change") !=
                scatter->reads.end());
    for (const char* r : {"froxel_fog.shadowed_light_a", "froxel_fog.shadowed_light_b"})
        EXPECT_TRUE(std::find(scatter->reads.begin(), scatter->reads.end(), r) == scatter->reads.end()) << r;
}

// Temporal accumulation (on by default): the scatter volume is two RGBA32F histories, the one written last
// frame read (sampled) by the scatter pass and the other written, then integrated; froxel_fog.scatter is
// not held; the temporal uniforms (1136 bytes, a 1280-byte slot per frame in flight).
TEST_F(FroxelFogPlanTest, TemporalHistories) {
    FroxelCase fc = c;
    fc.frame.froxelFog.temporal.enabled = true;
    const uint64_t volume = 20 * 12 * 40 * 8;
    for (uint64_t frameIndex = 0; frameIndex < 3; ++frameIndex) {
        const postfx::FramePlan plan = planAndRun(fc, frameIndex);
        EXPECT_EQ(passNames(plan), (std::vector<std::string>{"froxel_fog.scatter", "froxel_fog.integrate",
                                                             "froxel_fog.apply"}));
        const std::string written = frameIndex % 2 == 0 ? "froxel_fog.history_a" : "froxel_fog.history_b";
        const std::string read = frameIndex % 2 == 0 ? "froxel_fog.history_b" : "froxel_fog.history_a";
        const postfx::PlannedPass* scatter = plan.pass("froxel_fog.scatter");
        ASSERT_TRUE(scatter);
        EXPECT_EQ(scatter->reads,
                  (std::vector<std::string>{"froxel_fog.uniforms", read, "froxel_fog.temporal_uniforms"}));
        EXPECT_EQ(scatter->writes, (std::vector<std::string>{written}));
        EXPECT_EQ(plan.pass("froxel_fog.integrate")->reads,
                  (std::vector<std::string>{"froxel_fog.uniforms", written}));
        EXPECT_EQ(resourceBytes(plan, "froxel_fog.history_a"), 2 * volume);  // RGBA32F
        EXPECT_EQ(resourceBytes(plan, "froxel_fog.history_b"), 2 * volume);
        EXPECT_EQ(resourceBytes(plan, "froxel_fog.temporal_uniforms"), 2u * 1280);
        EXPECT_EQ(plan.totalBytes(), 5 * volume + 1 + 2 * kUniformSlot + 2 * 1280);
        EXPECT_EQ(plan.resources.size(), 6u);
        for (const postfx::PlannedResource& r : plan.resources)
            EXPECT_EQ(r.history, r.name == "froxel_fog.history_a" || r.name == "froxel_fog.history_b")
                << r.name;
    }
}

// The sun with a shadow map: scatter reads it; generated noise: froxel_fog.noise in the first frame only.
TEST_F(FroxelFogPlanTest, NoiseGeneratedOnceAndShadowMapRead) {
    FroxelCase fc = c;
    fc.frame.sun.illuminance = glm::vec3(100.0f);
    fc.frame.froxelFog.noise.enabled = true;
    fc.frame.froxelFog.noise.textureSize = 16;
    fc.images.shadowWidth = fc.images.shadowHeight = 8;
    fc.images.shadow.assign(64, 1.0f);
    fc.frame.shadowMap.worldToClip = glm::dmat4(1.0);
    postfx::FramePlan plan = planAndRun(fc, 0);
    EXPECT_EQ(passNames(plan), (std::vector<std::string>{"froxel_fog.noise", "froxel_fog.scatter",
                                                         "froxel_fog.integrate", "froxel_fog.apply"}));
    EXPECT_EQ(resourceBytes(plan, "froxel_fog.noise"), 16u * 16 * 16);
    EXPECT_TRUE(plan.pass("froxel_fog.scatter") &&
                plan.pass("froxel_fog.scatter")->reads.front() == std::string("host.shadow_map"));
    plan = planAndRun(fc, 1);
    EXPECT_EQ(passNames(plan),
              (std::vector<std::string>{"froxel_fog.scatter", "froxel_fog.integrate", "froxel_fog.apply"}));
    EXPECT_NE(context->imageView(postfx::kFroxelFogNoiseTexture), VkImageView(VK_NULL_HANDLE));
}

}  // namespace
}  // namespace test
