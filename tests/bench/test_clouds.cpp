// postfx-bench --clouds's plain-C++ parts (bench/clouds_bench.h): the sweep's points, the knobs' parsing,
// the views and the targets' choice of rows.
#include "clouds_bench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bench {
namespace {

TEST(CloudsBench, DefaultRowIsTheMediumPresetWithTheCloudsOn) {
    const postfx::CloudSettings s = cloudsBaseSettings();
    const postfx::CloudSettings medium =
        postfx::applyCloudQuality(postfx::CloudSettings{}, postfx::CloudQuality::Medium);
    EXPECT_TRUE(s.enabled);
    EXPECT_EQ(s.steps, medium.steps);
    EXPECT_EQ(s.lightSteps, medium.lightSteps);
    EXPECT_EQ(s.resolutionScale, medium.resolutionScale);
    EXPECT_EQ(s.temporal.enabled, medium.temporal.enabled);
    EXPECT_TRUE(s.noise.enabled);
}

TEST(CloudsBench, SweepStartsWithTheDefaultAndSkipsItsValues) {
    std::vector<CloudsPoint> points;
    std::string error;
    ASSERT_TRUE(cloudsSweep(defaultCloudsSweep(false), points, error)) << error;
    ASSERT_FALSE(points.empty());
    EXPECT_EQ(points[0].knob, "default");
    const postfx::CloudSettings base = cloudsBaseSettings();
    size_t presets = 0;
    for (size_t i = 1; i < points.size(); ++i) {
        const CloudsPoint& p = points[i];
        EXPECT_TRUE(postfx::validateCloudSettings(p.settings).ok()) << p.knob << "=" << p.value;
        EXPECT_TRUE(p.settings.enabled);
        if (p.knob == "preset") {
            ++presets;
            continue;
        }
        EXPECT_NE(p.value, cloudsKnobValue(base, p.knob)) << p.knob;  // the default's value is its row
        EXPECT_EQ(cloudsKnobValue(p.settings, p.knob), p.value);
    }
    EXPECT_EQ(presets, 4u);  // low, medium, high, ultra: each its own row
    // Each steps value of the sweep but the default's, and the other knobs one at a time.
    size_t expectedSteps = 0;
    for (const auto& [knob, values] : defaultCloudsSweep(false).values)
        if (knob == "steps")
            expectedSteps =
                values.size() - size_t(std::count(values.begin(), values.end(), std::to_string(base.steps)));
    size_t steps = 0;
    for (const CloudsPoint& p : points)
        if (p.knob == "steps") {
            ++steps;
            EXPECT_EQ(p.settings.lightSteps, base.lightSteps);
            EXPECT_EQ(p.settings.resolutionScale, base.resolutionScale);
        }
    EXPECT_EQ(steps, expectedSteps);
}

TEST(CloudsBench, QuickSweepIsTiny) {
    std::vector<CloudsPoint> points;
    std::string error;
    ASSERT_TRUE(cloudsSweep(defaultCloudsSweep(true), points, error)) << error;
    // default, model=octaves, steps=16, resolution_scale=1, base_size=32, preset=low
    EXPECT_EQ(points.size(), 6u);
}

TEST(CloudsBench, KnobsParseAndRejectBadValues) {
    postfx::CloudSettings s = cloudsBaseSettings();
    std::string error;
    EXPECT_TRUE(applyCloudsKnob(s, "model", "octaves", error));
    EXPECT_EQ(s.multipleScattering.model, postfx::CloudScatteringModel::Octaves);
    EXPECT_EQ(cloudsKnobValue(s, "model"), "octaves");
    EXPECT_FALSE(applyCloudsKnob(s, "model", "diffusion", error));
    EXPECT_TRUE(applyCloudsKnob(s, "model", "slab", error));
    EXPECT_EQ(s.multipleScattering.model, postfx::CloudScatteringModel::Slab);
    EXPECT_TRUE(applyCloudsKnob(s, "steps", "96", error));
    EXPECT_EQ(s.steps, 96u);
    EXPECT_TRUE(applyCloudsKnob(s, "light_steps", "16", error));
    EXPECT_EQ(s.lightSteps, 16u);
    EXPECT_TRUE(applyCloudsKnob(s, "resolution_scale", "0.25", error));
    EXPECT_EQ(s.resolutionScale, 0.25f);
    EXPECT_EQ(cloudsKnobValue(s, "resolution_scale"), "0.25");
    EXPECT_TRUE(applyCloudsKnob(s, "base_size", "256", error));
    EXPECT_EQ(s.noise.baseSize, 256u);
    EXPECT_TRUE(applyCloudsKnob(s, "detail_size", "64", error));
    EXPECT_EQ(s.noise.detailSize, 64u);
    EXPECT_TRUE(applyCloudsKnob(s, "temporal", "off", error));
    EXPECT_FALSE(s.temporal.enabled);
    EXPECT_TRUE(applyCloudsKnob(s, "preset", "ultra", error));
    const postfx::CloudSettings ultra = postfx::applyCloudQuality(s, postfx::CloudQuality::Ultra);
    EXPECT_EQ(s.steps, ultra.steps);
    EXPECT_EQ(s.temporal.enabled, ultra.temporal.enabled);

    EXPECT_FALSE(applyCloudsKnob(s, "steps", "x", error));
    EXPECT_NE(error.find("steps"), std::string::npos);
    EXPECT_FALSE(applyCloudsKnob(s, "resolution_scale", "half", error));
    EXPECT_FALSE(applyCloudsKnob(s, "temporal", "yes", error));
    EXPECT_FALSE(applyCloudsKnob(s, "preset", "extreme", error));
    EXPECT_FALSE(applyCloudsKnob(s, "march", "1", error));
    EXPECT_NE(error.find("unknown knob"), std::string::npos);

    std::vector<CloudsPoint> points;
    CloudsSweepOptions bad;
    bad.values = {{"base_size", {"48"}}};  // not a power of two: validateCloudSettings
    EXPECT_FALSE(cloudsSweep(bad, points, error));
    EXPECT_NE(error.find("base_size"), std::string::npos) << error;
    bad.values = {{"nope", {"1"}}};
    EXPECT_FALSE(cloudsSweep(bad, points, error));
}

TEST(CloudsBench, ViewsLookIntoTheLayer) {
    const std::vector<CloudsView> views = cloudsViews();
    ASSERT_EQ(views.size(), 3u);
    const postfx::CloudSettings s = cloudsBaseSettings();
    for (const CloudsView& v : views) {
        const bool above = v.altitude > s.topHeight;
        EXPECT_EQ(above, v.pitchDeg < 0.0) << v.name;  // from below looking up, from above looking down
        EXPECT_GT(cloudsToSun(v).y, 0.0f) << v.name;
    }
    EXPECT_EQ(views[0].name, "ground_noon");
    EXPECT_EQ(views[1].sunElevationDeg, 5.0);
}

CloudsRow row(const std::string& view, const std::string& knob, const std::string& value, double ms,
              double error, bool temporal = true) {
    CloudsRow r;
    r.view = view;
    r.point.knob = knob;
    r.point.value = value;
    r.point.settings = cloudsBaseSettings();
    r.point.settings.temporal.enabled = temporal;
    r.timing.median = ms;
    r.still.stats.relativeRmse = error;
    return r;
}

TEST(CloudsBench, TargetsTakeTheWorstMediumRowWithTemporal) {
    const std::vector<CloudsRow> rows = {
        row("a", "default", "", 0.3, 0.010),      row("b", "default", "", 0.45, 0.008),
        row("b", "preset", "medium", 0.44, 0.02), row("b", "steps", "128", 2.0, 0.001),  // not Medium
        row("c", "preset", "high", 3.0, 0.5),     row("c", "temporal", "off", 9.0, 0.9, false),
    };
    const std::vector<CloudsTarget> t = cloudsTargets(rows);
    ASSERT_EQ(t.size(), 2u);
    ASSERT_TRUE(t[0].row && t[1].row);
    EXPECT_FALSE(t[0].error);
    EXPECT_EQ(t[0].limit, kCloudsMediumTargetMs);
    EXPECT_EQ(t[0].measured(), 0.45);  // the slowest view's Medium row
    EXPECT_TRUE(t[0].met());
    EXPECT_TRUE(t[1].error);
    EXPECT_EQ(t[1].limit, kCloudsMediumTargetError);
    EXPECT_EQ(t[1].measured(), 0.02);  // the worst converged error of a Medium row
    EXPECT_FALSE(t[1].met());
    EXPECT_TRUE(cloudsTargets({}).front().row == nullptr);
    EXPECT_FALSE(cloudsTargets({}).front().met());  // not measured is not met
}

}  // namespace
}  // namespace bench
