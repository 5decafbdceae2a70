// The frame plan (docs/frame-plan.md): exact pass lists and memory totals on committed scenes, the
// recorded passes equal to the plan, nothing created or dispatched for an off or empty fog (counted at the
// Vulkan calls themselves), memory released when the need goes away. Empty-space skipping:
// tests/fog/test_fog_empty_space.cpp; the demo drawing its shadow map only when read: tests/demo.
#include "fog_harness.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <postfx/postfx.h>

#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

// ---- Vulkan calls counted through the getDeviceProcAddr a host hands postfx ----

struct CallCounts {
    int pipelines = 0;    // vkCreateComputePipelines
    int allocations = 0;  // vkAllocateMemory
    int frees = 0;        // vkFreeMemory
    int dispatches = 0;   // vkCmdDispatch
};
CallCounts gCounts;
PFN_vkCreateComputePipelines gCreatePipelines = nullptr;
PFN_vkAllocateMemory gAllocateMemory = nullptr;
PFN_vkFreeMemory gFreeMemory = nullptr;
PFN_vkCmdDispatch gCmdDispatch = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL countCreatePipelines(VkDevice d, VkPipelineCache c, uint32_t n,
                                                    const VkComputePipelineCreateInfo* i,
                                                    const VkAllocationCallbacks* a, VkPipeline* p) {
    gCounts.pipelines += int(n);
    return gCreatePipelines(d, c, n, i, a, p);
}
VKAPI_ATTR VkResult VKAPI_CALL countAllocateMemory(VkDevice d, const VkMemoryAllocateInfo* i,
                                                   const VkAllocationCallbacks* a, VkDeviceMemory* m) {
    ++gCounts.allocations;
    return gAllocateMemory(d, i, a, m);
}
VKAPI_ATTR void VKAPI_CALL countFreeMemory(VkDevice d, VkDeviceMemory m, const VkAllocationCallbacks* a) {
    if (m) ++gCounts.frees;
    gFreeMemory(d, m, a);
}
VKAPI_ATTR void VKAPI_CALL countCmdDispatch(VkCommandBuffer c, uint32_t x, uint32_t y, uint32_t z) {
    ++gCounts.dispatches;
    gCmdDispatch(c, x, y, z);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingDeviceProcAddr(VkDevice device, const char* name) {
    const PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
    auto wrap = [&](auto& slot, auto counting) {
        slot = reinterpret_cast<std::remove_reference_t<decltype(slot)>>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(counting);
    };
    if (!std::strcmp(name, "vkCreateComputePipelines")) return wrap(gCreatePipelines, &countCreatePipelines);
    if (!std::strcmp(name, "vkAllocateMemory")) return wrap(gAllocateMemory, &countAllocateMemory);
    if (!std::strcmp(name, "vkFreeMemory")) return wrap(gFreeMemory, &countFreeMemory);
    if (!std::strcmp(name, "vkCmdDispatch")) return wrap(gCmdDispatch, &countCmdDispatch);
    return real;
}

std::vector<std::string> passNames(const postfx::FramePlan& plan) {
    std::vector<std::string> names;
    for (const postfx::PlannedPass& p : plan.passes)
        names.push_back(p.name);
    return names;
}

class CoreFramePlanTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        // A wall 30 m away over the whole 24×16 image, a uniform color.
        images.width = 24;
        images.height = 16;
        images.color.assign(size_t(images.width) * images.height * 4, 100.0f);
        base.camera = testCamera({0.0, 2.0, 0.0}, 60.0f, 1.5f, 0.1f, 1000.0f, true);
        for (uint32_t j = 0; j < images.height; ++j)
            for (uint32_t i = 0; i < images.width; ++i)
                images.depth.push_back(depthAtDistance(
                    base.camera, pixelDirection(base.camera, i, j, images.width, images.height), 30.0));
        base.sun.toSun = {0.3f, 0.5f, -0.8f};
        base.sun.illuminance = glm::vec3(1000.0f);
        base.fog.enabled = true;
        base.fog.steps = 8;
    }

    // Plans `frame` at `frameIndex`, records it, and checks that the passes recorded (their timings) are
    // the plan's. Returns the plan.
    postfx::FramePlan planAndRun(postfx::Context& context, postfx::FrameInfo frame, uint64_t frameIndex,
                                 const FogHarnessImages& imgs, std::vector<float>* color = nullptr) {
        frame.frameIndex = frameIndex;
        postfx::FramePlan plan;
        // The harness fills in the images; plan with stand-ins of the same shape.
        FogHarness harness(*host, gpu);
        std::vector<float> out, output;
        postfx::Status planned = postfx::Status::success();
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) { planned = context.plan(f, plan); };
        const postfx::Status s =
            harness.run(context, imgs, frame, out, imgs.separateOutput ? &output : nullptr);
        EXPECT_TRUE(s.ok()) << s.message;
        EXPECT_TRUE(planned.ok()) << planned.message;
        std::vector<postfx::PassTiming> timings;
        EXPECT_TRUE(context.readPassTimings(frameIndex, timings).ok());
        std::vector<std::string> recorded;
        for (const postfx::PassTiming& t : timings)
            recorded.push_back(t.name);
        EXPECT_EQ(recorded, passNames(plan)) << "frame " << frameIndex;
        if (color) *color = imgs.separateOutput ? output : out;
        return plan;
    }

    postfx::core::Gpu gpu;
    FogHarnessImages images;
    postfx::FrameInfo base;
};

// Fog off, density 0, noise threshold 1 or multiplier 0: no pipeline, no memory, no dispatch, the color
// unchanged; then a real fog creates them, and going back to an empty medium frees all its memory once the
// frames in flight are done.
TEST_F(CoreFramePlanTest, OffOrEmptyFogCreatesNothingAndReleasesWhatItHeld) {
    postfx::ContextCreateInfo info = hostHandles();
    info.getDeviceProcAddr = countingDeviceProcAddr;
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(postfx::Context::create(info, context).ok());
    gCounts = {};

    postfx::FrameInfo off = base;
    off.fog.enabled = false;
    postfx::FrameInfo zero = base;
    zero.fog.density = 0.0f;
    postfx::FrameInfo threshold = base;
    threshold.fog.noise.enabled = true;
    threshold.fog.noise.threshold = 1.0f;
    postfx::FrameInfo multiplier = base;
    multiplier.fog.noise.enabled = true;
    multiplier.fog.noise.multiplier = 0.0f;
    uint64_t frameIndex = 0;
    for (const postfx::FrameInfo* f : {&off, &zero, &threshold, &multiplier}) {
        std::vector<float> color;
        const postfx::FramePlan plan = planAndRun(*context, *f, frameIndex++, images, &color);
        EXPECT_TRUE(plan.passes.empty());
        EXPECT_TRUE(plan.resources.empty());
        EXPECT_EQ(color, images.color);
    }
    EXPECT_EQ(gCounts.pipelines, 0);
    EXPECT_EQ(gCounts.allocations, 0);
    EXPECT_EQ(gCounts.dispatches, 0);

    postfx::FrameInfo fog = base;
    fog.fog.noise.enabled = true;
    fog.fog.noise.textureSize = 16;
    fog.fog.resolutionScale = 0.5f;
    postfx::FramePlan plan = planAndRun(*context, fog, frameIndex++, images);
    EXPECT_EQ(passNames(plan), (std::vector<std::string>{"fog.noise", "fog.raymarch", "fog.upsample"}));
    // 16³ noise texels, the 12×8 RGBA16F scatter image, two 512-byte uniform slots.
    EXPECT_EQ(plan.totalBytes(), 16u * 16 * 16 + 12 * 8 * 8 + 2 * 512);
    EXPECT_GT(gCounts.pipelines, 0);
    EXPECT_EQ(gCounts.allocations, 3);  // the plan's three resources, one allocation each
    plan = planAndRun(*context, fog, frameIndex++, images);  // the noise is not generated again
    EXPECT_EQ(passNames(plan), (std::vector<std::string>{"fog.raymarch", "fog.upsample"}));

    const CallCounts withFog = gCounts;
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(planAndRun(*context, zero, frameIndex++, images).passes.empty());
    EXPECT_EQ(gCounts.dispatches, withFog.dispatches);
    EXPECT_EQ(gCounts.pipelines, withFog.pipelines);
    EXPECT_EQ(gCounts.frees, gCounts.allocations) << "memory still held after the frames in flight";
    EXPECT_EQ(postfx::fogNoiseView(*context), VkImageView(VK_NULL_HANDLE));
}

// A separate output that no effect writes gets the host's color through postfx.copy; with a fog, the fog
// writes it and there is no copy.
TEST_F(CoreFramePlanTest, SeparateOutputWithoutEffectsIsACopy) {
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context).ok());
    FogHarnessImages separate = images;
    separate.separateOutput = true;
    for (size_t k = 0; k < separate.color.size(); ++k)
        separate.color[k] = float(k % 1000) * 0.5f;  // distinct, exact in half precision
    postfx::FrameInfo zero = base;
    zero.fog.density = 0.0f;
    std::vector<float> output;
    postfx::FramePlan plan = planAndRun(*context, zero, 0, separate, &output);
    ASSERT_EQ(passNames(plan), std::vector<std::string>{"postfx.copy"});
    EXPECT_EQ(plan.passes[0].reads, std::vector<std::string>{"host.color"});
    EXPECT_EQ(plan.passes[0].writes, std::vector<std::string>{"host.output"});
    EXPECT_EQ(plan.totalBytes(), 0u);
    EXPECT_EQ(output, separate.color);

    plan = planAndRun(*context, base, 1, separate, &output);
    EXPECT_EQ(passNames(plan), std::vector<std::string>{"fog.raymarch"});
    EXPECT_TRUE(plan.writes("host.output"));
    EXPECT_FALSE(plan.writes("host.color"));
}

// ---- committed scenes through the demo host ----

struct SceneExpectation {
    const char* scene;
    std::vector<std::string> firstFrame, laterFrames;  // pass names of frame 0 and of frame 1
    uint64_t bytes;                                    // postfx's memory
    bool readsShadowMap;
};

void PrintTo(const SceneExpectation& e, std::ostream* os) {
    *os << e.scene << " (" << e.bytes << " bytes)";
}

class CoreFramePlanScenes : public GpuTest, public ::testing::WithParamInterface<SceneExpectation> {};

TEST_P(CoreFramePlanScenes, ExactPassesAndMemory) {
    const SceneExpectation& e = GetParam();
    demo::Scene scene;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + e.scene, scene, error)) << error;
    demo::RenderOptions options;
    options.width = 64;
    options.height = 36;
    options.shadowMapSize = 256;
    auto renderer = demo::Renderer::create(*host, options, error);
    ASSERT_TRUE(renderer) << error;
    ASSERT_TRUE(renderer->setScene(scene, error)) << error;
    postfx::FramePlan plan;
    ASSERT_TRUE(renderer->plan(scene, 0, plan, error)) << error;
    EXPECT_EQ(passNames(plan), e.firstFrame);
    EXPECT_EQ(plan.totalBytes(), e.bytes);
    EXPECT_EQ(plan.reads("host.shadow_map"), e.readsShadowMap);
    demo::ImageF image;
    ASSERT_TRUE(renderer->render(scene, image, error)) << error;  // frame 0
    std::vector<postfx::PassTiming> timings;
    ASSERT_TRUE(renderer->postfxContext().readPassTimings(0, timings).ok());
    std::vector<std::string> recorded;
    for (const postfx::PassTiming& t : timings)
        recorded.push_back(t.name);
    EXPECT_EQ(recorded, e.firstFrame) << "the recorded passes are the plan's";
    ASSERT_TRUE(renderer->plan(scene, 1, plan, error)) << error;
    EXPECT_EQ(passNames(plan), e.laterFrames);
    EXPECT_EQ(plan.totalBytes(), e.bytes);
}

const std::vector<std::string> kNone, kMarch{"fog.raymarch"}, kNoiseAndMarch{"fog.noise", "fog.raymarch"};
// A quality preset (default.json: "medium") accumulates temporally (docs/effects/fog.md#quality-presets).
const std::vector<std::string> kTemporal{"fog.raymarch", "fog.temporal"},
    kNoiseAndTemporal{"fog.noise", "fog.raymarch", "fog.temporal"};
INSTANTIATE_TEST_SUITE_P(
    Committed, CoreFramePlanScenes,
    ::testing::Values(
        // No effects, and a fog of density 0: nothing at all.
        SceneExpectation{"plain.json", kNone, kNone, 0, false},
        SceneExpectation{"fog_zero_density.json", kNone, kNone, 0, false},
        // Valley fog without noise: the march, its 1-byte noise stand-in and two 512-byte uniform slots.
        SceneExpectation{"fog_valley.json", kMarch, kMarch, 1 + 1024, true},
        // Full fog: noise generated once (128³ bytes), then only the march.
        SceneExpectation{"fog_default.json", kNoiseAndMarch, kMarch, 128 * 128 * 128 + 1024, true},
        // The built-in scene (the high preset: full resolution; temporal): the march into the scatter image
        // (64×36 RGBA16F), accumulated into an RGBA32F history and an R32F distance (two of each), the
        // temporal uniforms (two 1280-byte slots), composited.
        SceneExpectation{"default.json", kNoiseAndTemporal, kTemporal,
                         128 * 128 * 128 + 1024 + 64 * 36 * (8 + 2 * 16 + 2 * 4) + 2 * 1280, true}),
    [](const auto& info) {
        std::string name = info.param.scene;
        return name.substr(0, name.find('.'));
    });

}  // namespace
}  // namespace test
