// Fault injection: every fallible Vulkan call postfx makes fails in turn (tests/core/vulkan_interposer.h),
// for scenarios that allocate (noise, shadow map, half resolution, separate RGBA32F output, timings off
// with 3 frames in flight, quality Auto, images recreated every frame, all together, pipelines prewarmed).
// Each time, the call that returns (create, record, readPassTimings) returns an error naming the failed
// Vulkan call, record() has recorded nothing (the host may end, reset or even submit its command buffer), the
// same context records the next frame with the same image as a run without faults, and once the context is
// destroyed every object it created is destroyed.
#include "fault_scene.h"
#include "vulkan_interposer.h"

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace test {
namespace {

struct FaultScenario {
    const char* name;
    FaultSceneOptions scene;
    uint32_t framesInFlight = 2;
    bool gpuTimings = true;
    bool resize = false;   // odd frames 6x4 with a 32³ noise texture: images recreated every frame
    bool prewarm = false;  // Context::prewarm on the first frame, before its record()
};

// The scene of frame `f`.
FaultSceneOptions sceneAt(const FaultScenario& scenario, uint64_t f) {
    FaultSceneOptions scene = scenario.scene;
    if (scenario.resize && f % 2) {
        scene.width = 6;
        scene.height = 4;
        scene.noiseSize = 32;
    }
    return scene;
}

void PrintTo(const FaultScenario& scenario, std::ostream* os) {
    *os << scenario.name;
}

std::string scenarioName(const ::testing::TestParamInfo<FaultScenario>& info) {
    return info.param.name;
}

class CoreFaultInjectionTest : public GpuTest, public ::testing::WithParamInterface<FaultScenario> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        interposer = std::make_unique<VulkanInterposer>(vkGetInstanceProcAddr, vkGetDeviceProcAddr);
        ASSERT_TRUE(interposer->errors().empty()) << interposer->errors()[0];
    }
    void TearDown() override {
        interposer.reset();
        GpuTest::TearDown();
    }

    struct Images {
        std::vector<float> color, output;
        bool operator==(const Images&) const = default;
    };

    // One run of the scenario's script: create, then frames 0..frames-1 each recorded, submitted and
    // its timings read. With fallible call `n` failing: checks the failing call's status and, after a
    // fault in a frame, that the next frame records the baseline's image. Returns whether the fault fired.
    bool run(uint64_t n, uint32_t frames, std::vector<Images>& baseline, bool fillBaseline) {
        const FaultScenario& sc = GetParam();
        const std::string at = "N=" + std::to_string(n) + ": ";
        auto faultText = [&] {
            const InjectedFault& f = interposer->fault();
            return f.fired ? "N=" + std::to_string(f.ordinal) + " " + f.call : std::string("no fault");
        };
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        info.maxExtent = {64, 64};
        info.framesInFlight = sc.framesInFlight;
        info.gpuTimings = sc.gpuTimings;
        info = interposer->wrap(hostHandles(info));

        interposer->arm(n);
        std::unique_ptr<postfx::Context> context;
        const postfx::Status created = postfx::Context::create(info, context);
        if (interposer->fault().fired) {
            EXPECT_FALSE(created.ok()) << at << "create() succeeded despite " << faultText();
            EXPECT_NE(created.message.find(interposer->fault().call), std::string::npos)
                << at << "create()'s message does not name " << interposer->fault().call << ": "
                << created.message;
            EXPECT_FALSE(context) << at;
            EXPECT_EQ(interposer->liveTotal(), 0u)
                << at << "after a failed create(), live: " << interposer->liveSummary();
            EXPECT_TRUE(interposer->errors().empty()) << at << interposer->errors()[0];
            return true;
        }
        if (!created.ok()) {
            ADD_FAILURE() << at << "create() failed without a fault: " << created.message;
            return false;
        }

        FogHarness harness(*host, gpu);
        uint64_t commandsBefore = 0;
        bool prewarmed = false, prewarmFault = false;
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            if (sc.prewarm && !prewarmed) {
                // A failed prewarm leaves the context as it was: the frames go on as without faults.
                prewarmed = true;
                const bool firedBefore = interposer->fault().fired;
                const postfx::Status p = context->prewarm(f);
                prewarmFault = interposer->fault().fired && !firedBefore;
                if (prewarmFault) {
                    EXPECT_FALSE(p.ok()) << at << "prewarm() succeeded despite " << faultText();
                    EXPECT_NE(p.message.find(interposer->fault().call), std::string::npos)
                        << at << "prewarm()'s message does not name " << faultText() << ": " << p.message;
                    interposer->disarm();
                } else {
                    EXPECT_TRUE(p.ok()) << at << p.message;
                }
            }
            commandsBefore = interposer->commands();
        };
        std::vector<uint64_t> recorded;  // frames record() succeeded for
        // Records frame f; true when it and its timings succeeded (a fault there has been checked).
        auto frame = [&](uint64_t f, bool expectClean) {
            const bool firedBefore = interposer->fault().fired;
            Images out;
            const postfx::Status s = harness.run(*context, faultSceneImages(sceneAt(sc, f)),
                                                 faultSceneFrame(sceneAt(sc, f), f), out.color, &out.output);
            const bool firedHere = interposer->fault().fired && !firedBefore && !(prewarmFault && f == 0);
            if (!s.ok()) {
                EXPECT_TRUE(firedHere && !expectClean) << at << "frame " << f << ": " << s.message;
                EXPECT_NE(s.message.find(interposer->fault().call), std::string::npos)
                    << at << "frame " << f << ": record()'s message does not name " << faultText() << ": "
                    << s.message;
                EXPECT_EQ(interposer->commands(), commandsBefore)
                    << at << "frame " << f << ": the failed record() recorded commands (" << faultText()
                    << ")";
                return false;
            }
            EXPECT_FALSE(firedHere) << at << "frame " << f << ": record() succeeded despite " << faultText();
            if (fillBaseline)
                baseline.push_back(out);
            else if ((sc.scene.autoQuality || sc.scene.temporal) && expectClean)
                // Auto measures its presets in turn, so a failed frame moves the turns, and a temporal
                // history holds only the frames recorded: the reference is a context without faults
                // recording the frames this one recorded.
                EXPECT_TRUE(out == replay(info, recorded, f)) << at << "frame " << f
                                                              << " differs from a run without faults of the "
                                                                 "same frames, after "
                                                              << faultText();
            else
                EXPECT_TRUE(out == baseline.at(f))
                    << at << "frame " << f << " differs from the run without faults"
                    << (expectClean ? " after " + faultText() : "");
            recorded.push_back(f);
            if (!sc.gpuTimings) return true;
            const bool firedBeforeTimings = interposer->fault().fired;
            std::vector<postfx::PassTiming> timings;
            const postfx::Status t = context->readPassTimings(f, timings);
            if (interposer->fault().fired && !firedBeforeTimings) {
                EXPECT_FALSE(t.ok()) << at << "readPassTimings succeeded despite " << faultText();
                EXPECT_NE(t.message.find(interposer->fault().call), std::string::npos)
                    << at << "readPassTimings' message does not name " << faultText() << ": " << t.message;
                return false;
            }
            EXPECT_TRUE(t.ok() && !timings.empty()) << at << "frame " << f << " timings: " << t.message;
            return true;
        };
        for (uint64_t f = 0; f < frames; ++f) {
            if (frame(f, false)) continue;
            // The fault has cleared: the same context records the next frame as if nothing happened.
            interposer->disarm();
            frame(f + 1, true);
            break;
        }
        const bool fired = interposer->fault().fired;
        context.reset();
        EXPECT_EQ(interposer->liveTotal(), 0u)
            << at << "live after destroying the context: " << interposer->liveSummary() << " (" << faultText()
            << ")";
        EXPECT_EQ(interposer->live(VkObjectKind::MemoryMapping), 0u) << at;
        EXPECT_TRUE(interposer->errors().empty()) << at << interposer->errors()[0];
        return fired;
    }

    // The image of frame `last` from a context created with `info` (without the interposer) that records
    // `frames` and then `last`.
    Images replay(postfx::ContextCreateInfo info, const std::vector<uint64_t>& frames, uint64_t last) {
        std::unique_ptr<postfx::Context> context;
        EXPECT_TRUE(createContext(context, info).ok());
        if (!context) return {};
        FogHarness harness(*host, gpu);
        Images out;
        std::vector<uint64_t> all = frames;
        all.push_back(last);
        for (uint64_t f : all) {
            const FaultSceneOptions scene = sceneAt(GetParam(), f);
            EXPECT_TRUE(
                harness
                    .run(*context, faultSceneImages(scene), faultSceneFrame(scene, f), out.color, &out.output)
                    .ok());
        }
        return out;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<VulkanInterposer> interposer;
};

TEST_P(CoreFaultInjectionTest, EveryFallibleCallFailsInTurn) {
    const FaultScenario& sc = GetParam();
    const uint32_t frames = sc.framesInFlight + 1;
    std::vector<Images> baseline;
    ASSERT_FALSE(run(~0ull, frames + 1, baseline, true));
    ASSERT_EQ(baseline.size(), frames + 1);
    ASSERT_FALSE(HasFailure());

    std::map<std::string, int> calls;
    uint64_t n = 0;
    for (; n < 1000; ++n) {
        if (!run(n, frames, baseline, false)) break;
        ++calls[interposer->fault().call];
        if (HasFailure()) break;  // the first fault's messages are the useful ones
    }
    ASSERT_LT(n, 1000u) << "the script never completed";
    ASSERT_GT(n, 0u);
    std::string summary;
    for (const auto& [call, count] : calls)
        summary += " " + call + " " + std::to_string(count);
    std::cout << "[ faults ] " << sc.name << ": " << n << " fault points:" << summary << "\n";
}

const FaultScenario kScenarios[] = {
    {"plain", {}},
    {"noise", {.noise = true}},
    {"shadow_map", {.shadowMap = true}},
    {"half_resolution", {.resolutionScale = 0.5f}},
    {"separate_output_rgba32f", {.format = VK_FORMAT_R32G32B32A32_SFLOAT, .separateOutput = true}},
    {"no_timings_three_in_flight", {.noise = true}, 3, false},
    {"auto_quality", {.noise = true, .autoQuality = true}, 2},
    {"resize_every_frame", {.noise = true, .resolutionScale = 0.5f}, 2, true, true},
    {"everything", {.noise = true, .shadowMap = true, .resolutionScale = 0.5f, .separateOutput = true}, 3},
    {"froxel_fog_light_lists",
     {.noise = true, .shadowMap = true, .froxel = true, .lights = 12, .temporal = true},
     2},
    {"temporal_half_resolution",
     {.noise = true, .shadowMap = true, .resolutionScale = 0.5f, .temporal = true},
     2},
    {"prewarm",
     {.noise = true, .shadowMap = true, .resolutionScale = 0.5f, .temporal = true},
     2,
     true,
     false,
     true},
};

INSTANTIATE_TEST_SUITE_P(Scenarios, CoreFaultInjectionTest, ::testing::ValuesIn(kScenarios), scenarioName);

}  // namespace
}  // namespace test
