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
