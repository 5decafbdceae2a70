// Context::prewarm: after prewarm(frame), record() of that frame and of the frames that follow with the
// same settings creates no pipeline, counted at vkCreateComputePipelines through the interposer
// (tests/core/vulkan_interposer.h). Two showcase-like frames: the atmosphere, the clouds and the froxel fog
// with lights, local shadows, the sun's shadow map, temporal accumulation and the volumetrics lookup, over
// frames that change the light count (none, a loop, light lists, shadowed), cut the camera, set the sun
// and turn the froxel fog off and on again; and the ray-marched fog and the clouds on quality Auto
// through their presets' measurement turns. Also: a host VkPipelineCache takes postfx's pipelines.
#include "core/context_impl.h"
#include "fault_scene.h"
#include "vulkan_interposer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

constexpr uint32_t kWidth = 16, kHeight = 8;

// The scene's frames: every effect on, small sizes; lights in front of the camera, the first four sharing
// one shadow of the atlas.
struct Scene {
    postfx::FrameInfo frame;
    std::vector<postfx::LocalLight> lights;
    postfx::LocalShadow shadow;
    FogHarnessImages images;

    explicit Scene(bool froxel) {
        postfx::FrameInfo& f = frame;
        f.camera = lookCamera({0.0, 2.0, 0.0}, {0.0, 0.3, -1.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        f.sun.toSun = {0.3f, 0.5f, -0.8f};
        f.sun.illuminance = postfx::Vec3(1.2e5f);
        f.ambient = postfx::Vec3(100.0f);
        f.atmosphere.enabled = true;
        smallScatteringOrders(f.atmosphere);
        f.clouds.enabled = true;
        f.clouds.noise.baseSize = 32;
        f.clouds.noise.detailSize = 16;
        f.clouds.shadowMap.size = 64;
        postfx::FogMedium medium;
        medium.density = 0.02f;
        medium.noise.enabled = true;
        medium.noise.textureSize = 32;
        if (froxel) {
            static_cast<postfx::FogMedium&>(f.froxelFog) = medium;
            f.froxelFog.enabled = true;
            f.froxelFog.grid = {8, 4, 16};
            f.froxelFog.lightListMinLights = 4;
            f.froxelFog.temporal.enabled = true;
        } else {
            static_cast<postfx::FogMedium&>(f.fog) = medium;
            f.fog.enabled = true;
            f.fog.temporal.enabled = true;
        }
        f.volumetricsLookup.enabled = true;
        f.volumetricsLookup.extent = {8, 4, 8};
        // The sun's shadow map (orthographic from above) and a 4x4 atlas holding one spot light's shadow.
        f.shadowMap.worldToClip =
            glm::orthoRH_ZO(-50.0, 50.0, -50.0, 50.0, 0.0, 200.0) *
            glm::lookAtRH(glm::dvec3(0.0, 100.0, 0.0), glm::dvec3(0.0), {0.0, 0.0, -1.0});
        const glm::dvec3 spot(0.0, 3.0, -6.0);
        shadow.faces[0].extent = {4u, 4u};
        shadow.faces[0].worldToClip =
            glm::perspectiveRH_ZO(1.5, 1.0, 0.1, 30.0) *
            glm::lookAtRH(spot, spot + glm::dvec3(0.0, -1.0, 0.0), {0.0, 0.0, -1.0});
        for (uint32_t k = 0; k < 8; ++k) {
            postfx::LocalLight& l = lights.emplace_back();
            l.position = {-2.0 + 0.5 * k, 2.0, -4.0 - 0.5 * k};
            l.intensity = postfx::Vec3(500.0f);
            l.range = 8.0f;
        }
        images.width = kWidth;
        images.height = kHeight;
        images.color.assign(kWidth * kHeight * 4, 1.0f);
        images.depth.assign(kWidth * kHeight, 0.0f);
        images.shadowWidth = images.shadowHeight = 4;
        images.shadow.assign(16, 1.0f);
        if (froxel) {
            images.localShadowWidth = images.localShadowHeight = 4;
            images.localShadow.assign(16, 1.0f);
        }
    }

    // Frame `index` with `lightCount` lights, the first `shadowed` of them casting the atlas's shadow.
    postfx::FrameInfo at(uint64_t index, uint32_t lightCount, uint32_t shadowed = 0) {
        postfx::FrameInfo f = frame;
        f.frameIndex = index;
        f.timeSeconds = double(index) / 60.0;
        for (uint32_t k = 0; k < lights.size(); ++k)
            lights[k].shadow = k < shadowed ? 0u : postfx::kNoLocalShadow;
        f.lights = lights.data();
        f.lightCount = lightCount;
        if (!images.localShadow.empty()) {
            f.localShadows.shadows = &shadow;
            f.localShadows.shadowCount = 1;
        }
        return f;
    }
};

class CorePrewarmTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        interposer = std::make_unique<VulkanInterposer>(vkGetInstanceProcAddr, vkGetDeviceProcAddr);
    }
    void TearDown() override {
        if (interposer) {
            EXPECT_TRUE(interposer->errors().empty()) << interposer->errors()[0];
        }
        interposer.reset();
        GpuTest::TearDown();
    }

    std::unique_ptr<postfx::Context> create(VkPipelineCache cache = VK_NULL_HANDLE) {
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        info.maxExtent = {64, 64};
        info.pipelineCache = cache;
        std::unique_ptr<postfx::Context> context;
        const postfx::Status s = postfx::Context::create(interposer->wrap(hostHandles(info)), context);
        EXPECT_TRUE(s.ok()) << s.message;
        return context;
    }
    uint64_t pipelines() const { return interposer->created(VkObjectKind::Pipeline); }

    // Records `frame` (the harness fills in its images); with `prewarm`, Context::prewarm(frame) first, on
    // the frame as record() gets it: nothing recorded, no image created.
    void record(postfx::Context& context, Scene& scene, const postfx::FrameInfo& frame,
                bool prewarm = false) {
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            if (!prewarm) return;
            const uint64_t commands = interposer->commands(),
                           images = interposer->created(VkObjectKind::Image);
            const postfx::Status s = context.prewarm(f);
            EXPECT_TRUE(s.ok()) << s.message;
            EXPECT_EQ(interposer->commands(), commands) << "prewarm recorded commands";
            EXPECT_EQ(interposer->created(VkObjectKind::Image), images) << "prewarm created images";
        };
        std::vector<float> color;
        const postfx::Status s = harness.run(context, scene.images, frame, color);
        EXPECT_TRUE(s.ok()) << "frame " << frame.frameIndex << ": " << s.message;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<VulkanInterposer> interposer;
};

TEST_F(CorePrewarmTest, FroxelFrameCompilesNothingAfterPrewarm) {
    Scene scene(true);
    // Without prewarm the first frame compiles its pipelines (what the count below would see).
    {
        auto cold = create();
        const uint64_t before = pipelines();
        record(*cold, scene, scene.at(0, 2));
        EXPECT_GT(pipelines(), before);
    }
    auto context = create();
    const uint64_t before = pipelines();
    postfx::FrameInfo first = scene.at(0, 2);
    first.cameraCut = true;
    record(*context, scene, first, true);
    const uint64_t prewarmed = pipelines() - before;
    std::printf("[ prewarm ] froxel frame: %llu pipelines\n", (unsigned long long)prewarmed);
    struct Step {
        uint32_t lights, shadowed;
        bool cut = false, sunDark = false, froxelOff = false;
    };
    const Step script[] = {
        {2, 0},  // a loop over the lights
        {6, 0},  // light lists
        {6, 2},  // light lists, shadowed
        {0, 0},  // none
        {1, 1},  // one shadowed light
        {6, 0, true},
        {2, 0, false, true},  // the sun dark: no shadow map read
        {2, 0, false, false, true},
        {2, 0, false, false, true},
        {2, 1},  // the froxel fog on again
        {8, 4, true},
    };
    uint64_t index = 1;
    for (const Step& step : script) {
        postfx::FrameInfo f = scene.at(index++, step.lights, step.shadowed);
        f.cameraCut = step.cut;
        if (step.sunDark) f.sun.illuminance = postfx::Vec3(0.0f);
        f.froxelFog.enabled = !step.froxelOff;
        record(*context, scene, f);
        EXPECT_EQ(pipelines() - before, prewarmed) << "frame " << f.frameIndex << " compiled a pipeline";
    }
}

TEST_F(CorePrewarmTest, AutoQualityCyclesThroughItsPresetsWithoutCompiling) {
    Scene scene(false);
    scene.frame.fog.quality = postfx::FogQuality::Auto;
    scene.frame.clouds.quality = postfx::CloudQuality::Auto;
    auto context = create();
    const uint64_t before = pipelines();
    record(*context, scene, scene.at(0, 0), true);
    const uint64_t prewarmed = pipelines() - before;
    std::printf("[ prewarm ] ray-marched fog and clouds on Auto: %llu pipelines\n",
                (unsigned long long)prewarmed);
    // Auto measures each preset in turns of three frames; a camera cut on the way.
    uint32_t preset = 0;
    for (uint64_t index = 1; index < 40; ++index) {
        postfx::FrameInfo f = scene.at(index, 0);
        f.cameraCut = index == 20;
        record(*context, scene, f);
        EXPECT_EQ(pipelines() - before, prewarmed) << "frame " << index << " compiled a pipeline";
    }
    EXPECT_TRUE(context->autoQuality("fog", preset).ok()) << "Auto is still measuring the fog's presets";
    EXPECT_TRUE(context->autoQuality("clouds", preset).ok()) << "Auto is still measuring the clouds' presets";
}

// A host switching between more specializations of one pass than the graph keeps of those record()
// compiles (4): the ray-marched fog's march for four shadow kernels and the sun dark, prewarmed in four
// calls; frames cycling through them compile nothing (the variants' limit spares prewarmed ones).
TEST_F(CorePrewarmTest, PrewarmedSpecializationsOutlastTheVariantLimit) {
    const FaultSceneOptions options{.width = 8, .height = 8, .shadowMap = true};
    const FogHarnessImages images = faultSceneImages(options);
    auto frameOf = [&](uint64_t index, uint32_t kernel, bool sunDark) {
        postfx::FrameInfo f = faultSceneFrame(options, index);
        f.fog.shadowKernel = kernel;
        if (sunDark) f.sun.illuminance = postfx::Vec3(0.0f);
        return f;
    };
    auto context = create();
    const uint64_t before = pipelines();
    FogHarness harness(*host, gpu);
    std::vector<float> color;
    uint64_t index = 0;
    for (const uint32_t kernel : {1u, 3u, 5u, 7u}) {
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) { EXPECT_TRUE(context->prewarm(f).ok()); };
        ASSERT_TRUE(harness.run(*context, images, frameOf(index++, kernel, false), color).ok());
    }
    const uint64_t prewarmed = pipelines() - before;
    const size_t marches = postfx::ContextAccess::of(*context).graph.heldPipelines("fog.raymarch");
    std::printf("[ prewarm ] four shadow kernels: %llu pipelines, %zu of fog.raymarch\n",
                (unsigned long long)prewarmed, marches);
    EXPECT_EQ(marches, 5u);  // four kernels with the sun lit; dark, no kernel: one for all
    harness.onBeforeRecord = nullptr;
    for (int round = 0; round < 2; ++round)
        for (const uint32_t kernel : {1u, 3u, 5u, 7u})
            for (const bool dark : {false, true}) {
                ASSERT_TRUE(harness.run(*context, images, frameOf(index++, kernel, dark), color).ok());
                EXPECT_EQ(pipelines() - before, prewarmed)
                    << "kernel " << kernel << (dark ? ", sun dark" : "");
            }
}

// The host's VkPipelineCache takes every pipeline postfx creates (where the driver stores pipelines in it,
// its data grows; lavapipe keeps only the header).
TEST_F(CorePrewarmTest, PipelinesGoThroughTheHostsCache) {
    Scene scene(true);
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    VkPipelineCache cache = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreatePipelineCache(host->device, &info, nullptr, &cache), VK_SUCCESS);
    auto cacheBytes = [&] {
        size_t size = 0;
        EXPECT_EQ(vkGetPipelineCacheData(host->device, cache, &size, nullptr), VK_SUCCESS);
        return size;
    };
    const size_t empty = cacheBytes();
    const uint64_t before = pipelines(), beforeCached = interposer->pipelinesWithCache();
    {
        auto context = create(cache);
        record(*context, scene, scene.at(0, 2), true);
        record(*context, scene, scene.at(1, 6, 2));
    }
    EXPECT_GT(pipelines(), before);
    EXPECT_EQ(interposer->pipelinesWithCache() - beforeCached, pipelines() - before)
        << "a pipeline was created without the host's cache";
    const size_t filled = cacheBytes();
    std::printf("[ prewarm ] pipeline cache: %zu bytes empty, %zu after a prewarmed frame\n", empty, filled);
    EXPECT_GE(filled, empty);
    vkDestroyPipelineCache(host->device, cache, nullptr);
}

}  // namespace
}  // namespace test
