// bench/conclusions.h on made-up rows: the preset proposal rule, the fastest setting under an error, and
// the targets' statuses in results.md.
#include "conclusions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using bench::Method;
using bench::Result;

Result ours(const std::string& scene, uint32_t steps, bool jitter, float scale, uint32_t noise, double ms,
            double error1, double error16, const std::string& preset = "") {
    Result r;
    r.setting.scene = scene;
    r.setting.method = Method::Ours;
    r.setting.steps = steps;
    r.setting.jitter = jitter;
    r.setting.resolutionScale = scale;
    r.setting.noiseSize = noise;
    r.setting.preset = preset;
    r.timing.median = ms;
    r.error[0].relativeRmse = error1;
    r.error[1].relativeRmse = (error1 + error16) / 2;
    r.error[2].relativeRmse = error16;
    return r;
}

Result baseline(const std::string& scene, float stepLength, uint32_t noise, double ms, double error) {
    Result r;
    r.setting.scene = scene;
    r.setting.method = Method::SeedFixedRiemann;
    r.setting.stepLength = stepLength;
    r.setting.jitter = true;
    r.setting.noiseSize = noise;
    r.timing.median = ms;
    for (bench::ErrorStats& e : r.error)
        e.relativeRmse = error;
    return r;
}

// fog_default at noise 128, with distractors the rule must skip.
std::vector<Result> rows() {
    return {
        ours("fog_default", 8, true, 1.0f, 128, 0.30, 0.067, 0.0165),   // 0
        ours("fog_default", 16, true, 1.0f, 128, 0.54, 0.040, 0.0074),  // 1
        ours("fog_default", 16, true, 0.5f, 128, 0.24, 0.021, 0.0051),  // 2
        ours("fog_default", 32, true, 0.5f, 128, 0.40, 0.011, 0.0030),  // 3
        ours("fog_default", 64, true, 0.5f, 128, 0.70, 0.006, 0.0016),  // 4
        ours("fog_default", 64, true, 1.0f, 128, 1.35, 0.012, 0.0014),  // 5
        // Distractors: jitter off (16-frame error = one frame), another noise size, a preset row, another
        // scene; each would win its budget if it were eligible.
        ours("fog_default", 32, false, 0.5f, 128, 0.10, 0.0001, 0.0001),        // 6
        ours("fog_default", 32, true, 0.5f, 32, 0.10, 0.0001, 0.0001),          // 7
        ours("fog_default", 32, true, 0.5f, 128, 0.10, 0.0001, 0.0001, "low"),  // 8
        ours("fog_height", 32, true, 0.5f, 128, 0.10, 0.0001, 0.0001),          // 9
        baseline("fog_default", 1.0f, 128, 1.2, 0.0181),                        // 10
        baseline("fog_default", 0.5f, 128, 2.20, 0.0120),                       // 11
    };
}

bench::RunInfo runOn(std::vector<std::pair<std::string, uint32_t>> sceneNoise,
                     std::vector<bench::PresetBudget> budgets) {
    bench::RunInfo info;
    info.presetScene = sceneNoise.front().first;
    info.sceneNoise = std::move(sceneNoise);
    info.presetBudgets = std::move(budgets);
    return info;
}

Result withKernel(Result r, uint32_t kernel) {
    r.setting.shadowKernel = kernel;
    return r;
}

TEST(BenchConclusions, ProposesTheMostAccurateJitteredSweepPointWithinEachBudget) {
    const std::vector<Result> r = rows();
    const bench::RunInfo info =
        runOn({{"fog_default", 128}}, {{"low", 0.1}, {"medium", 0.5}, {"high", 1.0}, {"ultra", 2.0}});
    const std::vector<bench::ProposedPreset> p = bench::proposePresets(info, r);
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p[0].row, nullptr);  // nothing eligible within 0.1 ms
    EXPECT_EQ(p[1].row, &r[3]);    // 32 steps at half scale: 0.30% in 0.40 ms, beats 16 steps full
    EXPECT_EQ(p[2].row, &r[4]);
    EXPECT_EQ(p[3].row, &r[5]);  // 0.14% beats 0.16% when 1.35 ms fits
    EXPECT_DOUBLE_EQ(p[3].meanError16, 0.0014);
    EXPECT_EQ(p[2].budget.name, "high");
    EXPECT_EQ(p[2].budget.ms, 1.0);
}

// Timed on the preset scene, judged by the mean over the scenes: a half-scale march that wins on the
// preset scene loses to a full-scale one when another scene's edges make half scale much worse.
TEST(BenchConclusions, ProposalAveragesTheErrorOverTheScenesButNotTheUnskippedTwins) {
    const std::vector<Result> r = {
        ours("a", 32, true, 0.5f, 128, 0.30, 0.011, 0.0020),      // 0: a's best
        ours("a", 16, true, 1.0f, 128, 0.40, 0.040, 0.0070),      // 1
        ours("a", 64, true, 1.0f, 128, 0.45, 0.020, 0.0030),      // 2: no row on b: not a candidate
        ours("b", 32, true, 0.5f, 0, 0.20, 0.030, 0.0300),        // 3: edges at half scale
        ours("b", 16, true, 1.0f, 0, 0.20, 0.010, 0.0030),        // 4
        ours("b_unskipped", 32, true, 0.5f, 0, 0.2, 0.0, 0.0),    // 5: the twin would favour 0
        ours("b_unskipped", 16, true, 1.0f, 0, 0.2, 0.09, 0.09),  // 6
    };
    const bench::RunInfo info = runOn({{"a", 128}, {"b", 0}, {"b_unskipped", 0}}, {{"medium", 0.5}});
    EXPECT_EQ(bench::proposalScenes(info), (std::vector<std::string>{"a", "b"}));
    const auto p = bench::proposePresets(info, r);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].row, &r[1]);  // mean (0.70% + 0.30%) / 2 = 0.5% against (0.2% + 3%) / 2
    EXPECT_DOUBLE_EQ(p[0].meanError16, 0.005);
}

// The shadow kernel is a knob: a scene with a shadow map matches it, one without matches any kernel.
TEST(BenchConclusions, ProposalMatchesTheShadowKernelWhereTheSceneHasAShadowMap) {
    const std::vector<Result> r = {
        withKernel(ours("a", 32, true, 1.0f, 0, 0.30, 0.02, 0.004), 1),      // 0: cheaper
        withKernel(ours("a", 32, true, 1.0f, 0, 0.45, 0.02, 0.004), 3),      // 1
        withKernel(ours("shadowed", 32, true, 1.0f, 0, 0.3, 0.1, 0.02), 1),  // 2
        withKernel(ours("shadowed", 32, true, 1.0f, 0, 0.3, 0.1, 0.01), 3),  // 3
        ours("unshadowed", 32, true, 1.0f, 0, 0.3, 0.1, 0.006),              // 4: kernel 0
    };
    const bench::RunInfo info = runOn({{"a", 0}, {"shadowed", 0}, {"unshadowed", 0}}, {{"high", 1.0}});
    const auto p = bench::proposePresets(info, r);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].row, &r[1]);  // (0.4 + 1 + 0.6) / 3 % beats (0.4 + 2 + 0.6) / 3 %
    EXPECT_DOUBLE_EQ(p[0].meanError16, 0.02 / 3);
}

TEST(BenchConclusions, EqualErrorsGoToTheFasterSetting) {
    std::vector<Result> r = {ours("s", 16, true, 1.0f, 0, 0.4, 0.03, 0.005),
                             ours("s", 32, true, 0.5f, 0, 0.3, 0.02, 0.005)};
    const auto p = bench::proposePresets(runOn({{"s", 0}}, {{"medium", 0.5}}), r);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].row, &r[1]);
}

TEST(BenchConclusions, FastestWithinAnErrorPerMethod) {
    const std::vector<Result> r = rows();
    // One frame at 2%: any sweep point of this scene and noise size, jitter off included (row 6 is the
    // fastest); not the preset row, the other noise size or the other scene.
    EXPECT_EQ(bench::fastestWithin(r, "fog_default", Method::Ours, 128, 0, 0.02), &r[6]);
    EXPECT_EQ(bench::fastestWithin(r, "fog_default", Method::SeedFixedRiemann, 128, 0, 0.02), &r[10]);
    EXPECT_EQ(bench::fastestWithin(r, "fog_default", Method::SeedFixedRiemann, 128, 0, 0.015), &r[11]);
    EXPECT_EQ(bench::fastestWithin(r, "fog_default", Method::SeedFixedRiemann, 128, 0, 0.01), nullptr);
    EXPECT_EQ(bench::fastestWithin(r, "fog_default", Method::Ours, 64, 0, 0.02), nullptr);
}

TEST(BenchConclusions, TargetsSayMetOrMissedFromTheRows) {
    std::vector<Result> r = rows();
    r.erase(r.begin() + 6, r.begin() + 10);  // no distractors
    r.push_back(ours("fog_default", 16, true, 1.0f, 128, 0.536, 0.040, 0.0074, "medium"));
    bench::RunInfo info;
    info.device = "a GPU";
    info.width = 1920;
    info.height = 1080;
    info.baselines = true;
    info.presetScene = "fog_default";
    info.sceneNoise = {{"fog_default", 128}};
    info.presetBudgets = bench::defaultPresetBudgets();
    const std::string md = bench::conclusionsMarkdown(info, r);
    // Committed Medium 0.536 ms against 0.5 ms; proposed Medium: 32 steps at half scale, 0.40 ms.
    EXPECT_NE(md.find("committed: **missed** by 7.2%; proposed: **met**"), std::string::npos) << md;
    // 2% in one frame: 32 steps at half scale, 0.40 ms, against the baseline's 1.2 ms: 3×, missed.
    EXPECT_NE(md.find("**3×** | **missed**"), std::string::npos) << md;
    // 2% after 16 frames: 16 steps at half scale, 0.24 ms: 5×, met.
    EXPECT_NE(md.find("**5×** | **met**"), std::string::npos) << md;
    EXPECT_NE(md.find("no texture rate given"), std::string::npos);
    EXPECT_EQ(md.find("Not 1920×1080"), std::string::npos);

    info.width = 64;
    EXPECT_NE(bench::conclusionsMarkdown(info, r).find("Not 1920×1080"), std::string::npos);
}

TEST(BenchConclusions, SkippingPairsEachSweepPointWithItsUnskippedTwin) {
    const std::vector<Result> r = {
        ours("valley", 16, true, 1.0f, 0, 0.30, 0.016, 0.003),
        ours("valley", 64, true, 1.0f, 0, 0.50, 0.004, 0.001),
        ours("valley_unskipped", 16, true, 1.0f, 0, 0.60, 0.021, 0.0035),
        ours("valley_unskipped", 64, true, 1.0f, 0, 1.00, 0.0057, 0.0011),
        ours("valley", 32, true, 1.0f, 0, 0.40, 0.008, 0.002),  // no twin: not listed
    };
    bench::RunInfo info;
    const std::string md = bench::skippingMarkdown(info, r);
    EXPECT_NE(md.find("## Empty-space skipping: valley against valley_unskipped"), std::string::npos) << md;
    EXPECT_NE(md.find("| `steps=16 jitter=on scale=1` | 0.3 / 0.6 | -50% | 1.6% / 2.1% | 0.3% / 0.35% |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| `steps=64 jitter=on scale=1` | 0.5 / 1 | -50% |"), std::string::npos) << md;
    EXPECT_EQ(md.find("steps=32"), std::string::npos) << md;
    EXPECT_EQ(bench::skippingMarkdown(info, {r[0], r[1]}), "");  // no pair, no section
}

}  // namespace
