// Fog quality presets through postfx's public API: the preset table, a preset rendering exactly like
// Custom with the same values, and FogQuality::Auto measuring the presets and choosing by budget.
#include "fog_harness.h"

#include <cmath>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::FogQuality;
using postfx::Result;

class FogQualityTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
    }

    std::unique_ptr<postfx::Context> newContext() {
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        std::unique_ptr<postfx::Context> context;
        const postfx::Status s = createContext(context, info);
        EXPECT_TRUE(s.ok()) << s.message;
        return context;
    }

    // A height fog over a surface at 12 m on the left half, sky on the right.
    postfx::FrameInfo fogFrame() const {
        postfx::FrameInfo frame;
        frame.cameraCut = true;  // each frame on its own (the presets accumulate temporally): single frames
        frame.camera = testCamera({0.0, 1.5, 0.0}, 60.0f, float(kWidth) / kHeight, 0.1f, 1000.0f, true);
        frame.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
        frame.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
        frame.ambient = {10.0f, 20.0f, 30.0f};
        frame.fog.enabled = true;
        frame.fog.density = 0.05f;
        frame.fog.maxDistance = 30.0f;
        return frame;
    }

    FogHarnessImages images(const postfx::FrameInfo& frame) const {
        FogHarnessImages im;
        im.width = kWidth;
        im.height = kHeight;
        im.color.resize(kWidth * kHeight * 4);
        im.depth.resize(kWidth * kHeight);
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const size_t p = size_t(j) * kWidth + i;
                const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                im.depth[p] = i < kWidth / 2 ? depthAtDistance(frame.camera, d, 12.0) : 0.0f;
                for (int c = 0; c < 4; ++c)
                    im.color[p * 4 + c] = 1.0f + float(i + j + c);
            }
        return im;
    }

    static constexpr uint32_t kWidth = 24, kHeight = 16;
    postfx::core::Gpu gpu;
};

TEST_F(FogQualityTest, ApplyFogQualitySetsThePresetTable) {
    postfx::FogSettings custom;
    custom.steps = 77;
    custom.jitter = false;
    custom.shadowKernel = 5;
    custom.resolutionScale = 0.375f;
    custom.density = 0.125f;
    struct Row {
        FogQuality quality;
        uint32_t steps;
        bool jitter;
        uint32_t kernel;
        float scale;
        bool temporal;
    };
    const Row rows[] = {
        {FogQuality::Low, 64, true, 1, 0.5f, true},        {FogQuality::Medium, 32, true, 1, 1.0f, true},
        {FogQuality::High, 128, true, 1, 1.0f, true},      {FogQuality::Ultra, 256, true, 1, 1.0f, true},
        {FogQuality::Custom, 77, false, 5, 0.375f, false}, {FogQuality::Auto, 77, false, 5, 0.375f, false}};
    for (const Row& r : rows) {
        const postfx::FogSettings s = postfx::applyFogQuality(custom, r.quality);
        EXPECT_EQ(s.steps, r.steps) << int(r.quality);
        EXPECT_EQ(s.jitter, r.jitter) << int(r.quality);
        EXPECT_EQ(s.shadowKernel, r.kernel) << int(r.quality);
        EXPECT_EQ(s.resolutionScale, r.scale) << int(r.quality);
        EXPECT_EQ(s.temporal.enabled, r.temporal) << int(r.quality);
        EXPECT_EQ(s.density, custom.density);  // nothing else changes
        EXPECT_EQ(s.quality, custom.quality);
    }
}

TEST_F(FogQualityTest, PresetRendersExactlyLikeCustomWithItsValues) {
    std::unique_ptr<postfx::Context> context = newContext();
    ASSERT_TRUE(context);
    FogHarness harness(*host, gpu);
    for (FogQuality q : {FogQuality::Low, FogQuality::High}) {
        postfx::FrameInfo preset = fogFrame();
        preset.frameIndex = 3;  // the same jitter for both
        preset.fog.quality = q;
        preset.fog.steps = 5;  // replaced by the preset
        preset.fog.jitter = false;
        postfx::FrameInfo custom = preset;
        custom.fog = postfx::applyFogQuality(preset.fog, q);
        custom.fog.quality = FogQuality::Custom;
        ASSERT_NE(custom.fog.steps, 5u);
        const FogHarnessImages im = images(preset);
        std::vector<float> a, b;
        postfx::Status s = harness.run(*context, im, preset, a);
        ASSERT_TRUE(s.ok()) << s.message;
        s = harness.run(*context, im, custom, b);
        ASSERT_TRUE(s.ok()) << s.message;
        ASSERT_EQ(a.size(), b.size());
        EXPECT_EQ(a, b) << "quality " << int(q);
        EXPECT_NE(a, im.color);  // the fog did something
    }
}

TEST_F(FogQualityTest, AutoMeasuresThePresetsThenChoosesByBudget) {
    FogHarness harness(*host, gpu);
    for (const auto& [budget, expected] :
         {std::pair{1e-6f, FogQuality::Low}, std::pair{1e6f, FogQuality::Ultra}}) {
        std::unique_ptr<postfx::Context> context = newContext();
        std::unique_ptr<postfx::Context> asCustom = newContext();  // renders the presets as Custom
        ASSERT_TRUE(context && asCustom);
        FogQuality chosen = FogQuality::Custom;
        EXPECT_EQ(postfx::fogAutoQuality(*context, chosen).code, Result::NotReady);  // nothing recorded yet
        postfx::FrameInfo frame = fogFrame();
        frame.fog.quality = FogQuality::Auto;
        frame.fog.autoBudgetMs = budget;
        const FogHarnessImages im = images(frame);
        std::vector<float> out;
        // Frames 0..11 measure Low, Medium, High, Ultra in turn, three times each. A frame's timings are
        // read once the host has waited for it by the contract (framesInFlight = 2 frames later, though
        // each frame here is waited for at once): frame 12 still waits for frame 11's Ultra and measures
        // Ultra again; frame 13 chooses.
        constexpr uint64_t kMeasuring = 4 * 3;
        const postfx::FogQuality kTurns[] = {FogQuality::Low, FogQuality::Medium, FogQuality::High,
                                             FogQuality::Ultra};
        for (uint64_t i = 0; i < kMeasuring + 3; ++i) {
            frame.frameIndex = i;
            const postfx::Status s = harness.run(*context, im, frame, out);
            ASSERT_TRUE(s.ok()) << s.message;
            if (i == 0) {
                std::vector<postfx::PassTiming> timings;
                if (context->readPassTimings(0, timings).code == Result::Unsupported)
                    GTEST_SKIP() << "no GPU timings on this device";
            }
            const postfx::Status c = postfx::fogAutoQuality(*context, chosen);
            if (i <= kMeasuring) {
                EXPECT_EQ(c.code, Result::NotReady) << "frame " << i;
                // What was rendered is the preset whose turn it is.
                postfx::FrameInfo turn = frame;
                turn.fog =
                    postfx::applyFogQuality(frame.fog, i < kMeasuring ? kTurns[i % 4] : FogQuality::Ultra);
                turn.fog.quality = FogQuality::Custom;
                std::vector<float> expectedImage;
                ASSERT_TRUE(harness.run(*asCustom, im, turn, expectedImage).ok());
                EXPECT_EQ(out, expectedImage) << "frame " << i << " should be preset " << int(kTurns[i % 4]);
            } else {
                ASSERT_TRUE(c.ok()) << "frame " << i << ": " << c.message;
                EXPECT_EQ(chosen, expected) << "budget " << budget;
            }
        }
        // The chosen preset is what was rendered: the last frame equals Custom with its values.
        postfx::FrameInfo custom = frame;
        custom.fog = postfx::applyFogQuality(frame.fog, expected);
        custom.fog.quality = FogQuality::Custom;
        std::vector<float> reference;
        const postfx::Status s = harness.run(*context, im, custom, reference);
        ASSERT_TRUE(s.ok()) << s.message;
        EXPECT_EQ(out, reference);
        // A new key (another extent would need other images; noise on is one) measures again.
        frame.fog.noise.enabled = true;
        frame.frameIndex = kMeasuring + 3;
        ASSERT_TRUE(harness.run(*context, im, frame, out).ok());
        EXPECT_EQ(postfx::fogAutoQuality(*context, chosen).code, Result::NotReady);
    }
}

// Auto's measurements leave one context and enter another, which then chooses from its first frame; given
// times choose by the budget exactly; bad times are refused whole.
TEST_F(FogQualityTest, AutoTimingsCarryToANewContext) {
    FogHarness harness(*host, gpu);
    postfx::FrameInfo frame = fogFrame();
    frame.fog.quality = FogQuality::Auto;
    frame.fog.autoBudgetMs = 2.5f;
    const FogHarnessImages im = images(frame);
    std::vector<float> out;

    // Given times: 1, 2, 3, 4 ms with a 2.5 ms budget is Medium, from frame 0, rendered as Medium.
    std::unique_ptr<postfx::Context> given = newContext();
    std::unique_ptr<postfx::Context> asCustom = newContext();
    ASSERT_TRUE(given && asCustom);
    EXPECT_TRUE(postfx::fogAutoTimings(*given).empty());
    postfx::FogAutoTimings t;
    t.width = kWidth;
    t.height = kHeight;
    t.presetMs[0] = 1.0f, t.presetMs[1] = 2.0f, t.presetMs[2] = 3.0f, t.presetMs[3] = 4.0f;
    postfx::FogAutoTimings otherKey = t;
    otherKey.noise = true;
    ASSERT_TRUE(postfx::setFogAutoTimings(*given, {t, otherKey}).ok());
    ASSERT_EQ(postfx::fogAutoTimings(*given).size(), 2u);
    EXPECT_EQ(postfx::fogAutoTimings(*given)[0].presetMs[2], 3.0f);
    frame.frameIndex = 0;
    ASSERT_TRUE(harness.run(*given, im, frame, out).ok());
    FogQuality chosen = FogQuality::Custom;
    ASSERT_TRUE(postfx::fogAutoQuality(*given, chosen).ok());
    EXPECT_EQ(chosen, FogQuality::Medium);
    postfx::FrameInfo medium = frame;
    medium.fog = postfx::applyFogQuality(frame.fog, FogQuality::Medium);
    medium.fog.quality = FogQuality::Custom;
    std::vector<float> expected;
    ASSERT_TRUE(harness.run(*asCustom, im, medium, expected).ok());
    EXPECT_EQ(out, expected);

    // Refused whole: a NaN time, a negative one, a zero extent.
    std::unique_ptr<postfx::Context> refused = newContext();
    ASSERT_TRUE(refused);
    postfx::FogAutoTimings nan = t, negative = t, empty = t;
    nan.presetMs[2] = NAN;
    negative.presetMs[0] = -1.0f;
    empty.width = 0;
    for (const auto& [bad, field] :
         {std::pair{nan, "presetMs[2]"}, std::pair{negative, "presetMs[0]"}, std::pair{empty, "extent"}}) {
        const postfx::Status s = postfx::setFogAutoTimings(*refused, {t, bad});
        EXPECT_EQ(s.code, Result::InvalidArgument) << field;
        EXPECT_NE(s.message.find("timings[1]"), std::string::npos) << s.message;
        EXPECT_NE(s.message.find(field), std::string::npos) << s.message;
    }
    EXPECT_TRUE(postfx::fogAutoTimings(*refused).empty());

    // Measured on one context, given to another: the same times, and the new one chooses at once.
    std::unique_ptr<postfx::Context> measuring = newContext();
    ASSERT_TRUE(measuring);
    frame.fog.autoBudgetMs = 1e6f;       // Ultra
    for (uint64_t i = 0; i < 14; ++i) {  // 12 measured, their last read two frames later
        frame.frameIndex = i;
        ASSERT_TRUE(harness.run(*measuring, im, frame, out).ok());
        std::vector<postfx::PassTiming> timings;
        if (i == 0 && measuring->readPassTimings(0, timings).code == Result::Unsupported)
            GTEST_SKIP() << "no GPU timings on this device";
    }
    const std::vector<postfx::FogAutoTimings> measured = postfx::fogAutoTimings(*measuring);
    ASSERT_EQ(measured.size(), 1u);
    EXPECT_EQ(measured[0].width, kWidth);
    EXPECT_EQ(measured[0].height, kHeight);
    EXPECT_FALSE(measured[0].noise);
    EXPECT_FALSE(measured[0].shadowMap);
    for (float ms : measured[0].presetMs)
        EXPECT_TRUE(std::isfinite(ms) && ms > 0.0f) << ms;
    std::unique_ptr<postfx::Context> next = newContext();
    ASSERT_TRUE(next && postfx::setFogAutoTimings(*next, measured).ok());
    frame.frameIndex = 0;
    ASSERT_TRUE(harness.run(*next, im, frame, out).ok());
    ASSERT_TRUE(postfx::fogAutoQuality(*next, chosen).ok());
    EXPECT_EQ(chosen, FogQuality::Ultra);
    const std::vector<postfx::FogAutoTimings> carried = postfx::fogAutoTimings(*next);
    ASSERT_EQ(carried.size(), 1u);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(carried[0].presetMs[i], measured[0].presetMs[i]);
}

TEST_F(FogQualityTest, AutoWithoutTimingsUsesMedium) {
    postfx::ContextCreateInfo info;
    info.depth.reversedZ = true;
    info.gpuTimings = false;
    struct Messages {
        int warnings = 0;
    } messages;
    info.messageCallback = [](postfx::MessageSeverity severity, const char*, void* user) {
        if (severity == postfx::MessageSeverity::Warning) ++static_cast<Messages*>(user)->warnings;
    };
    info.messageUserData = &messages;
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context, info).ok());
    FogHarness harness(*host, gpu);
    postfx::FrameInfo frame = fogFrame();
    frame.fog.quality = FogQuality::Auto;
    const FogHarnessImages im = images(frame);
    std::vector<float> out;
    for (uint64_t i = 0; i < 2; ++i) {
        frame.frameIndex = i;
        ASSERT_TRUE(harness.run(*context, im, frame, out).ok());
        FogQuality chosen = FogQuality::Custom;
        ASSERT_TRUE(postfx::fogAutoQuality(*context, chosen).ok());
        EXPECT_EQ(chosen, FogQuality::Medium);
    }
    EXPECT_EQ(messages.warnings, 1);
}

// Timings carry their origin (postfx version, device, driver); a new context skips, with a warning,
// those of another origin, so a host's stored cache is remeasured after an upgrade; zero device
// fields match any device.
TEST_F(FogQualityTest, AutoTimingsOfAnotherOriginAreSkipped) {
    postfx::ContextCreateInfo info;
    info.depth.reversedZ = true;
    struct Messages {
        std::vector<std::string> warnings;
    } messages;
    info.messageCallback = [](postfx::MessageSeverity severity, const char* text, void* user) {
        if (severity == postfx::MessageSeverity::Warning)
            static_cast<Messages*>(user)->warnings.push_back(text);
    };
    info.messageUserData = &messages;
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context, info).ok());
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(host->physicalDevice, &properties);

    postfx::FogAutoTimings here;  // default origin: this postfx, any device
    here.width = kWidth;
    here.height = kHeight;
    here.presetMs[0] = 1.0f, here.presetMs[1] = 2.0f, here.presetMs[2] = 3.0f, here.presetMs[3] = 4.0f;
    EXPECT_EQ(here.origin.postfxVersion, postfx::version());
    postfx::FogAutoTimings olderPostfx = here, otherDevice = here, otherDriver = here, sameDevice = here;
    olderPostfx.width = kWidth + 1;
    olderPostfx.origin.postfxVersion = POSTFX_MAKE_VERSION(0, 0, 1);
    otherDevice.width = kWidth + 2;
    otherDevice.origin.vendorId = properties.vendorID;
    otherDevice.origin.deviceId = properties.deviceID + 1;
    otherDriver.width = kWidth + 3;
    otherDriver.origin = {postfx::version(), properties.vendorID, properties.deviceID,
                          properties.driverVersion + 1};
    sameDevice.width = kWidth + 4;
    sameDevice.origin = {postfx::version(), properties.vendorID, properties.deviceID,
                         properties.driverVersion};
    ASSERT_TRUE(
        postfx::setFogAutoTimings(*context, {here, olderPostfx, otherDevice, otherDriver, sameDevice}).ok());

    const std::vector<postfx::FogAutoTimings> kept = postfx::fogAutoTimings(*context);
    ASSERT_EQ(kept.size(), 2u);
    for (const postfx::FogAutoTimings& t : kept) {
        EXPECT_TRUE(t.width == here.width || t.width == sameDevice.width) << t.width;
        // Returned with this context's origin, whatever they were given with.
        EXPECT_EQ(t.origin.postfxVersion, postfx::version());
        EXPECT_EQ(t.origin.vendorId, properties.vendorID);
        EXPECT_EQ(t.origin.deviceId, properties.deviceID);
        EXPECT_EQ(t.origin.driverVersion, properties.driverVersion);
    }
    ASSERT_EQ(messages.warnings.size(), 3u);
    EXPECT_NE(messages.warnings[0].find("timings[1]: measured with postfx 0.0.1"), std::string::npos)
        << messages.warnings[0];
    EXPECT_NE(messages.warnings[1].find("timings[2]: measured with another device"), std::string::npos)
        << messages.warnings[1];
    EXPECT_NE(messages.warnings[2].find("timings[3]: measured with another driver version"),
              std::string::npos)
        << messages.warnings[2];
}

}  // namespace
}  // namespace test
