// Leak cycles: contexts with 1, 2, 3 and 8 frames in flight, timings on and off, record frame after frame
// with every fog setting that allocates changing each frame (noise sizes, resolution scales, separate
// output, RGBA16F / RGBA32F, shadow map, the froxel fog with few and many lights, fog off) and the extent
// changing from 1x1 to the context's maxExtent, counting every Vulkan object postfx creates through
// tests/core/vulkan_interposer.h.
//
// The bound: a context holds `base` objects after create() (descriptor pools, query pool); one frame of
// configuration c adds owned(c) (images, views, memory, uniform rings, pipelines, samplers). What a frame
// stops using is retired and destroyed framesInFlight - 1 frames later (collected at the start of a
// frame, so with one frame in flight the next frame), so besides what the frame holds at most
// framesInFlight frames' retirements are live: live <= base + (framesInFlight + 1) * max_c owned(c),
// within a frame too. After the fog has been off for framesInFlight + 1 frames no image, buffer or
// memory is live, and after destruction nothing is.
#include "fault_scene.h"
#include "vulkan_interposer.h"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace test {
namespace {

struct CycleConfig {
    FaultSceneOptions scene;
    bool fog = true;
};

const CycleConfig kConfigs[] = {
    {{}},
    {{.noise = true, .noiseSize = 16}},
    {{.format = VK_FORMAT_R32G32B32A32_SFLOAT, .noise = true, .noiseSize = 32}},
    {{.resolutionScale = 0.5f}},
    {{.noise = true, .noiseSize = 16, .resolutionScale = 0.25f}},
    {{.format = VK_FORMAT_R32G32B32A32_SFLOAT, .separateOutput = true}},
    {{.shadowMap = true}},
    {{.noise = true, .noiseSize = 32, .shadowMap = true, .resolutionScale = 0.5f, .separateOutput = true}},
    {{.froxel = true}},
    {{.noise = true, .noiseSize = 16, .shadowMap = true, .froxel = true, .lights = 12, .temporal = true}},
    {{.resolutionScale = 0.5f, .temporal = true}},  // the fog's histories
    {{.format = VK_FORMAT_R32G32B32A32_SFLOAT, .separateOutput = true, .froxel = true, .lights = 3}},
    {{.separateOutput = true}, false},  // fog off: only postfx.copy
    {{}, false},                        // fog off, in place: nothing
};
constexpr VkExtent2D kMaxExtent = {16, 16};
const VkExtent2D kExtents[] = {{1, 1}, kMaxExtent, {5, 3}, {9, 16}, {16, 1}};

class CoreLeakCyclesTest : public GpuTest {
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

    std::unique_ptr<postfx::Context> create(uint32_t framesInFlight, bool gpuTimings) {
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        info.maxExtent = kMaxExtent;
        info.framesInFlight = framesInFlight;
        info.gpuTimings = gpuTimings;
        std::unique_ptr<postfx::Context> context;
        const postfx::Status s = postfx::Context::create(interposer->wrap(hostHandles(info)), context);
        EXPECT_TRUE(s.ok()) << s.message;
        return context;
    }

    postfx::Status record(postfx::Context& context, const CycleConfig& config, VkExtent2D extent,
                          uint64_t frameIndex) {
        FaultSceneOptions scene = config.scene;
        scene.width = extent.width;
        scene.height = extent.height;
        postfx::FrameInfo frame = faultSceneFrame(scene, frameIndex);
        if (!config.fog) frame.fog.enabled = frame.froxelFog.enabled = false;
        std::vector<float> color, output;
        FogHarness harness(*host, gpu);
        return harness.run(context, faultSceneImages(scene), frame, color, &output);
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<VulkanInterposer> interposer;
};

TEST_F(CoreLeakCyclesTest, LiveObjectsStayBoundedAndNoneOutliveTheContext) {
    // owned(c): objects one frame of each configuration adds to a fresh context.
    uint64_t maxOwned = 0;
    for (const CycleConfig& config : kConfigs) {
        std::unique_ptr<postfx::Context> context = create(1, true);
        ASSERT_TRUE(context);
        const uint64_t base = interposer->liveTotal();
        const postfx::Status s = record(*context, config, kMaxExtent, 0);
        ASSERT_TRUE(s.ok()) << s.message;
        maxOwned = std::max(maxOwned, interposer->liveTotal() - base);
        context.reset();
        ASSERT_EQ(interposer->liveTotal(), 0u) << interposer->liveSummary();
    }

    struct Run {
        uint32_t framesInFlight;
        bool gpuTimings;
    };
    for (const Run run : {Run{1, true}, Run{2, false}, Run{3, true}, Run{8, true}}) {
        SCOPED_TRACE("framesInFlight " + std::to_string(run.framesInFlight));
        std::unique_ptr<postfx::Context> context = create(run.framesInFlight, run.gpuTimings);
        ASSERT_TRUE(context);
        const uint64_t base = interposer->liveTotal();
        const uint64_t bound = base + (run.framesInFlight + 1) * maxOwned;
        interposer->resetPeak();
        uint64_t frameIndex = 0;
        // Each configuration after each other one (retiring what the previous held), at changing extents.
        constexpr size_t n = std::size(kConfigs);
        for (size_t step = 0; step < n * 3; ++step) {
            const CycleConfig& config = kConfigs[(step * 7) % n];
            const VkExtent2D extent = kExtents[step % std::size(kExtents)];
            const postfx::Status s = record(*context, config, extent, frameIndex++);
            ASSERT_TRUE(s.ok()) << "step " << step << ": " << s.message;
            ASSERT_LE(interposer->liveTotal(), bound)
                << "step " << step << " (config " << (step * 7) % n << ", " << extent.width << "x"
                << extent.height << "): " << interposer->liveSummary();
        }
        EXPECT_LE(interposer->peakLiveTotal(), bound) << "within a frame";
        // Fog off, in place, for framesInFlight + 1 frames: everything retired is gone, no memory is held.
        for (uint32_t i = 0; i <= run.framesInFlight; ++i)
            ASSERT_TRUE(record(*context, kConfigs[n - 1], {4, 4}, frameIndex++).ok());
        for (VkObjectKind kind : {VkObjectKind::Image, VkObjectKind::ImageView, VkObjectKind::Buffer,
                                  VkObjectKind::DeviceMemory, VkObjectKind::MemoryMapping})
            EXPECT_EQ(interposer->live(kind), 0u)
                << objectKindName(kind) << " live with the fog off: " << interposer->liveSummary();
        std::cout << "[ cycles ] framesInFlight " << run.framesInFlight << ": " << frameIndex
                  << " frames, base " << base << ", peak " << interposer->peakLiveTotal()
                  << " live objects (bound " << bound << ")\n";
        context.reset();
        ASSERT_EQ(interposer->liveTotal(), 0u)
            << "after destroying the context: " << interposer->liveSummary();
    }
    for (size_t k = 0; k < size_t(VkObjectKind::Count); ++k)
        std::cout << "[ cycles ] " << objectKindName(VkObjectKind(k)) << ": "
                  << interposer->created(VkObjectKind(k)) << " created, all destroyed\n";
}

}  // namespace
}  // namespace test
