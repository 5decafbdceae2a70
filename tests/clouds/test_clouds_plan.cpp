// The clouds' frame plan (docs/frame-plan.md): the first frame generates the two noise textures, later
// frames march only; coverage or density 0 runs nothing; with the atmosphere the march follows its passes
// and reads its LUTs; the recorded passes are the plan's; the textures' bytes.
#include "fog_harness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test {
namespace {

using Passes = std::vector<std::string>;

class CloudsPlanTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
        frame.clouds.enabled = true;
        frame.clouds.noise.baseSize = 32;
        frame.clouds.noise.detailSize = 16;
        frame.sun.toSun = {0.6f, 0.8f, 0.0f};
        frame.sun.illuminance = postfx::Vec3(1e5f);
        const glm::dvec3 position(0.0, 10.0, 0.0);
        frame.camera = testCamera(position, 60.0f, 2.0f, 0.1f, 1e5f, true);
        frame.camera.view =
            glm::mat4(glm::lookAt(position, position + glm::dvec3(1.0, 0.4, 0.0), glm::dvec3(0.0, 1.0, 0.0)));
        im.width = 16;
        im.height = 8;
        im.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        im.color.assign(16 * 8 * 4, 0.0f);
        im.depth.assign(16 * 8, 0.0f);
    }

    // Plans and records the frame; the recorded passes (timings) must be the plan's.
    Passes planAndRun() {
        frame.frameIndex = frameIndex++;
        postfx::FramePlan plan;
        postfx::Status planned = postfx::Status::success();
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) { planned = context->plan(f, plan); };
        std::vector<float> out;
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        EXPECT_TRUE(planned.ok()) << planned.message;
        std::vector<postfx::PassTiming> timings;
        EXPECT_TRUE(context->readPassTimings(frame.frameIndex, timings).ok());
        Passes recorded, names;
        for (const postfx::PassTiming& t : timings)
            recorded.push_back(t.name);
        for (const postfx::PlannedPass& p : plan.passes)
            names.push_back(p.name);
        EXPECT_EQ(recorded, names) << "frame " << frame.frameIndex;
        last = plan;
        return names;
    }

    uint64_t bytesOf(const std::string& name) const {
        for (const postfx::PlannedResource& r : last.resources)
            if (r.name == name) return r.bytes;
        return 0;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
    postfx::FrameInfo frame;
    FogHarnessImages im;
    postfx::FramePlan last;
    uint64_t frameIndex = 0;
};

TEST_F(CloudsPlanTest, NoiseOnceThenOnlyTheMarchAndNothingWithoutCoverage) {
    EXPECT_EQ(planAndRun(), (Passes{"clouds.base_noise", "clouds.detail_noise", "clouds.march"}));
    EXPECT_EQ(bytesOf("clouds.base_noise"), 32u * 32 * 32);
    EXPECT_EQ(bytesOf("clouds.detail_noise"), 16u * 16 * 16);
    EXPECT_EQ(planAndRun(), (Passes{"clouds.march"}));
    frame.timeSeconds = 10.0;  // the wind moves the field, not the textures
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
    const Passes passes = planAndRun();
    const auto apply = std::find(passes.begin(), passes.end(), "atmosphere.apply");
    const auto march = std::find(passes.begin(), passes.end(), "clouds.march");
    ASSERT_NE(march, passes.end());
    EXPECT_LT(apply, march);  // the sky first, then the clouds over it
    for (const postfx::PlannedPass& p : last.passes) {
        if (p.name != "clouds.march") continue;
        for (const char* lut : {"atmosphere.uniforms", "atmosphere.transmittance",
                                "atmosphere.aerial_perspective", "atmosphere.aerial_transmittance"})
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), lut), p.reads.end()) << lut;
    }
    EXPECT_EQ(planAndRun(), (Passes{"atmosphere.apply", "clouds.march"})) << "still";
}

}  // namespace
}  // namespace test
