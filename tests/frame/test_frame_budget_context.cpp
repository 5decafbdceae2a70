// One budget for the frame through a context (FrameInfo::budgetMs, Context::budgetChoice): the ray-marched
// fog and the clouds both on quality Auto, their presets' times given (made up) and their errors the
// committed fronts'; the context picks the combination core/budget.h's rule gives, renders exactly as
// those presets set by hand, re-chooses when the scene's effects change, counts the other active
// effects' measured time against the budget, and reports nothing without a budget.
#include "clouds/clouds_settings.h"
#include "core/budget.h"
#include "fog/fog_settings.h"
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <memory>
#include <string>
#include <vector>

using namespace test;
using postfx::CloudQuality;
using postfx::FogQuality;

namespace {

constexpr uint32_t kWidth = 24, kHeight = 16;
// Made-up times of the fog's and the clouds' presets, Low..Ultra [ms].
const std::vector<float> kFogMs{0.2f, 0.4f, 0.7f, 1.3f};
const std::vector<float> kCloudsMs{0.15f, 0.5f, 0.8f, 1.9f};

class FrameBudgetContextTest : public GpuTest {
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

    // Height fog in front of a surface 12 m away on the left half, under a homogeneous cloud layer
    // 100–200 m up (the sky on the right); both on Auto.
    postfx::FrameInfo frame() const {
        postfx::FrameInfo f;
        f.cameraCut = true;
        f.camera = testCamera({0.0, 1.5, 0.0}, 60.0f, float(kWidth) / kHeight, 0.1f, 1000.0f, true);
        f.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.8f, -0.5f));
        f.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
        f.ambient = {10.0f, 20.0f, 30.0f};
        f.fog.enabled = true;
        f.fog.density = 0.05f;
        f.fog.maxDistance = 30.0f;
        f.fog.noise.enabled = false;
        f.fog.quality = FogQuality::Auto;
        f.clouds.enabled = true;
        f.clouds.bottomHeight = 100.0f;
        f.clouds.topHeight = 200.0f;
        f.clouds.coverage = 1.0f;
        f.clouds.density = 0.002f;
        f.clouds.noise.enabled = false;
        f.clouds.castShadows = false;
        f.clouds.quality = CloudQuality::Auto;
        return f;
    }

    FogHarnessImages images(const postfx::FrameInfo& f) const {
        FogHarnessImages im;
        im.width = kWidth;
        im.height = kHeight;
        im.color.resize(kWidth * kHeight * 4);
        im.depth.resize(kWidth * kHeight);
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const size_t p = size_t(j) * kWidth + i;
                const glm::dvec3 d = pixelDirection(f.camera, i, j, kWidth, kHeight);
                im.depth[p] = i < kWidth / 2 ? depthAtDistance(f.camera, d, 12.0) : 0.0f;
                for (int c = 0; c < 4; ++c)
                    im.color[p * 4 + c] = 1.0f + float(i + j + c);
            }
        return im;
    }

    // The made-up times for the fog's and the clouds' keys of `f`.
    static void giveTimings(postfx::Context& context, const postfx::FrameInfo& f) {
        postfx::AutoQualityTimings fog{"fog", kWidth, kHeight, 0, kFogMs, {}};
        fog.features = (f.fog.noise.enabled ? postfx::kFogAutoFeatureNoise : 0u) |
                       (f.shadowMap.image.present() ? postfx::kFogAutoFeatureShadowMap : 0u);
        postfx::AutoQualityTimings clouds{"clouds", kWidth, kHeight, 0, kCloudsMs, {}};
        clouds.features = (f.atmosphere.enabled ? postfx::kCloudAutoFeatureAtmosphere : 0u) |
                          (f.clouds.castShadows ? postfx::kCloudAutoFeatureShadows : 0u) |
                          (f.clouds.noise.enabled ? postfx::kCloudAutoFeatureNoise : 0u);
        const postfx::Status s = context.setAutoQualityTimings({fog, clouds});
        ASSERT_TRUE(s.ok()) << s.message;
    }

    // core/budget.h's rule on the given times and the committed errors (clouds first: composite order).
    static std::vector<uint32_t> expected(double budgetMs, bool clouds) {
        std::vector<postfx::core::PresetFront> fronts;
        if (clouds) {
            postfx::core::PresetFront c;
            for (size_t p = 0; p < 4; ++p) {
                c.ms.push_back(kCloudsMs[p]);
                c.error.push_back(postfx::clouds::kQualityPresets[p].error);
            }
            fronts.push_back(c);
        }
        postfx::core::PresetFront fog;
        fog.ms.assign(kFogMs.begin(), kFogMs.end());
        fog.error = postfx::fog::qualityPresetErrors();
        fronts.push_back(fog);
        return postfx::core::chooseWithinBudget(fronts, budgetMs).presets;
    }

    postfx::core::Gpu gpu;
};

}  // namespace

TEST_F(FrameBudgetContextTest, ChoosesTheLowestSummedErrorAndRendersThoseVeryPresets) {
    FogHarness harness(*host, gpu);
    std::unique_ptr<postfx::Context> context = newContext();
    ASSERT_TRUE(context);
    postfx::FrameInfo f = frame();
    f.budgetMs = 1.35f;
    giveTimings(*context, f);
    const FogHarnessImages im = images(f);
    std::vector<float> out;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());

    // Within 1.35 ms: fog High (0.7) + clouds Medium (0.5), error 0.000954 + 0.00981, beats fog Medium +
    // clouds High (1.2 ms, 0.002829 + 0.00868) and fog Ultra alone (clouds' Low does not fit beside it).
    EXPECT_EQ(expected(f.budgetMs, true), (std::vector<uint32_t>{1, 2}));
    postfx::BudgetChoice choice;
    ASSERT_TRUE(context->budgetChoice(choice).ok());
    ASSERT_EQ(choice.effects.size(), 2u);
    EXPECT_EQ(choice.effects[0].effect, "clouds");
    EXPECT_EQ(choice.effects[0].preset, 1u);
    EXPECT_EQ(choice.effects[1].effect, "fog");
    EXPECT_EQ(choice.effects[1].preset, 2u);
    EXPECT_FLOAT_EQ(choice.effects[1].ms, 0.7f);
    EXPECT_DOUBLE_EQ(choice.effects[0].error, postfx::clouds::kQualityPresets[1].error);
    EXPECT_NEAR(choice.chosenMs, 1.2f, 1e-5f);
    EXPECT_EQ(choice.otherMs, 0.0f);  // the first frame: nothing measured before it, nothing else active
    EXPECT_TRUE(choice.fits);
    uint32_t preset = 0;
    ASSERT_TRUE(context->autoQuality("fog", preset).ok());
    EXPECT_EQ(preset, 2u);

    // The same frame with those presets set by hand, in a new context: the same image, bit for bit.
    std::unique_ptr<postfx::Context> byHand = newContext();
    ASSERT_TRUE(byHand);
    postfx::FrameInfo h = f;
    h.budgetMs = 0.0f;
    h.fog.quality = FogQuality::High;
    h.clouds.quality = CloudQuality::Medium;
    std::vector<float> expectedImage;
    ASSERT_TRUE(harness.run(*byHand, im, h, expectedImage).ok());
    EXPECT_EQ(out, expectedImage);
}

TEST_F(FrameBudgetContextTest, ReChosenWhenTheScenesEffectsChange) {
    FogHarness harness(*host, gpu);
    std::unique_ptr<postfx::Context> context = newContext();
    ASSERT_TRUE(context);
    postfx::FrameInfo f = frame();
    f.budgetMs = 1.35f;
    giveTimings(*context, f);
    const FogHarnessImages im = images(f);
    std::vector<float> out;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    uint32_t fog = 0;
    ASSERT_TRUE(context->autoQuality("fog", fog).ok());
    EXPECT_EQ(fog, 2u);

    // Without the clouds the fog has the budget alone: Ultra (1.3 ms).
    f.frameIndex = 1;
    f.clouds.enabled = false;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    EXPECT_EQ(expected(f.budgetMs, false), (std::vector<uint32_t>{3}));
    postfx::BudgetChoice choice;
    ASSERT_TRUE(context->budgetChoice(choice).ok());
    ASSERT_EQ(choice.effects.size(), 1u);
    EXPECT_EQ(choice.effects[0].effect, "fog");
    EXPECT_EQ(choice.effects[0].preset, 3u);
    // Frame 0's clouds passes are not counted: the clouds are not active in this frame.
    EXPECT_EQ(choice.otherMs, 0.0f);

    // A tighter budget: re-chosen in the next frame (0.5 ms: fog Medium).
    f.frameIndex = 2;
    f.budgetMs = 0.5f;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    ASSERT_TRUE(context->autoQuality("fog", fog).ok());
    EXPECT_EQ(fog, 1u);

    // Below every preset: the fastest, reported as not fitting.
    f.frameIndex = 3;
    f.budgetMs = 0.1f;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    ASSERT_TRUE(context->budgetChoice(choice).ok());
    EXPECT_FALSE(choice.fits);
    EXPECT_EQ(choice.effects[0].preset, 0u);

    // No budget: each Auto effect on its own budget (fog.autoBudgetMs 0.5: Medium), no joint choice.
    f.frameIndex = 4;
    f.budgetMs = 0.0f;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    EXPECT_EQ(context->budgetChoice(choice).code, postfx::Result::NotReady);
    ASSERT_TRUE(context->autoQuality("fog", fog).ok());
    EXPECT_EQ(fog, 1u);
}

TEST_F(FrameBudgetContextTest, OtherActiveEffectsTimeComesOffTheBudget) {
    // The fog on Auto, the clouds on a fixed preset: the clouds' measured time (on this device) is taken
    // off the budget before the fog's preset is chosen.
    FogHarness harness(*host, gpu);
    std::unique_ptr<postfx::Context> context = newContext();
    ASSERT_TRUE(context);
    postfx::FrameInfo f = frame();
    f.clouds.quality = CloudQuality::Low;
    giveTimings(*context, f);
    const FogHarnessImages im = images(f);
    std::vector<float> out;
    std::vector<postfx::PassTiming> timings;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());  // frames 0 and 1, no budget
    f.frameIndex = 1;
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    ASSERT_TRUE(context->readPassTimings(0, timings).ok());
    // The other work: the clouds' passes and the context's own (postfx.view_distance: two effects run).
    double cloudsMs = 0.0, viewDistanceMs = 0.0;
    for (const postfx::PassTiming& t : timings) {
        if (t.name.rfind("clouds.", 0) == 0) cloudsMs += t.milliseconds;
        if (t.name == "postfx.view_distance") viewDistanceMs += t.milliseconds;
    }
    ASSERT_GT(cloudsMs, 0.0);
    ASSERT_GT(viewDistanceMs, 0.0);
    cloudsMs += viewDistanceMs;

    // A budget of that time plus 0.75 ms leaves the fog 0.75 ms: High (0.7). The other work's time is the
    // newest frame the host has waited for by the contract, framesInFlight (2) frames back: frame 0.
    f.frameIndex = 2;
    f.budgetMs = float(cloudsMs + 0.75);
    ASSERT_TRUE(harness.run(*context, im, f, out).ok());
    postfx::BudgetChoice choice;
    ASSERT_TRUE(context->budgetChoice(choice).ok());
    EXPECT_NEAR(choice.otherMs, cloudsMs, 1e-4);
    ASSERT_EQ(choice.effects.size(), 1u);
    EXPECT_EQ(choice.effects[0].effect, "fog");
    EXPECT_EQ(choice.effects[0].preset, 2u);
    EXPECT_TRUE(choice.fits);
}
