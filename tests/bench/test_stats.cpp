// bench/stats.h on made-up images and calibration measurements: the tonemapped relative RMSE (one bright
// pixel cannot dominate it; the exposure cancels), the calibration's drift and spread, and the report's
// calibration summary.
#include "report.h"
#include "stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

// An RGBA image of `pixels` grey pixels of `value`.
std::vector<float> grey(size_t pixels, float value) {
    std::vector<float> image(pixels * 4, value);
    for (size_t p = 0; p < pixels; ++p)
        image[p * 4 + 3] = 1.0f;
    return image;
}

void setPixel(std::vector<float>& image, size_t p, float value) {
    for (size_t c = 0; c < 3; ++c)
        image[p * 4 + c] = value;
}

TEST(BenchStats, TonemappedRmseIsZeroForEqualImagesAndGrowsWithTheError) {
    const std::vector<float> reference = grey(100, 50.0f);
    EXPECT_EQ(bench::tonemappedRmse(reference, reference), 0.0);
    const double small = bench::tonemappedRmse(grey(100, 50.5f), reference);
    const double large = bench::tonemappedRmse(grey(100, 55.0f), reference);
    EXPECT_GT(small, 0.0);
    EXPECT_GT(large, 5.0 * small);
}

TEST(BenchStats, TonemappedRmseDoesNotDependOnTheExposure) {
    std::vector<float> reference = grey(64, 2.0f), image = grey(64, 2.1f);
    setPixel(reference, 3, 40.0f);
    setPixel(image, 3, 37.0f);
    const double e = bench::tonemappedRmse(image, reference);
    for (float scale : {1e-3f, 1e4f}) {
        std::vector<float> a = image, b = reference;
        for (float& v : a)
            v *= scale;
        for (float& v : b)
            v *= scale;
        EXPECT_NEAR(bench::tonemappedRmse(a, b), e, 1e-5 * e) << scale;
    }
}

// A sun disk's pixel 10⁵ times brighter than the rest, off by 5 %, every other pixel off by 1 %: the
// relative RMSE of linear radiance is the sun's error alone; the tonemapped one is the other pixels'.
TEST(BenchStats, OneSunPixelDoesNotDominateTheTonemappedRmse) {
    const size_t pixels = 10000;
    std::vector<float> reference = grey(pixels, 100.0f), image = grey(pixels, 101.0f);
    setPixel(reference, 0, 1e7f);
    setPixel(image, 0, 1.05e7f);
    std::vector<float> withoutSun = reference, imageWithoutSun = image;
    setPixel(withoutSun, 0, 100.0f);
    setPixel(imageWithoutSun, 0, 101.0f);

    // Linear: sqrt(Σ(a−b)²)/sqrt(Σb²) ≈ 5 %, the sun's.
    double e2 = 0, b2 = 0;
    for (size_t i = 0; i < image.size(); ++i)
        if (i % 4 != 3)
            e2 += double(image[i] - reference[i]) * (image[i] - reference[i]),
                b2 += double(reference[i]) * reference[i];
    EXPECT_NEAR(std::sqrt(e2 / b2), 0.05, 0.001);

    const double withSun = bench::tonemappedRmse(image, reference);
    const double without = bench::tonemappedRmse(imageWithoutSun, withoutSun);
    EXPECT_LT(withSun, 0.01);                       // below the other pixels' 1 % relative error
    EXPECT_NEAR(withSun, without, 0.05 * without);  // the sun changes it by less than 5 %
}

TEST(BenchStats, TonemappedRmseSkipsNonFiniteValues) {
    std::vector<float> reference = grey(4, 1.0f), image = grey(4, 1.0f);
    image[0] = NAN;
    image[5] = INFINITY;
    EXPECT_EQ(bench::tonemappedRmse(image, reference), 0.0);
}

TEST(BenchStats, CalibrationDriftIsTheLargestChange) {
    EXPECT_NEAR(bench::calibrationDrift(1.0, 1.02, NAN), 0.02, 1e-12);
    EXPECT_NEAR(bench::calibrationDrift(1.0, 1.02, 1.1), 1.0 - 1.0 / 1.1, 1e-12);
    EXPECT_NEAR(bench::calibrationDrift(2.0, 2.0, 2.0), 0.0, 1e-12);
    EXPECT_NEAR(bench::calibrationDrift(1.0, 0.9, 1.0), 0.1, 1e-12);
    EXPECT_TRUE(std::isnan(bench::calibrationDrift(NAN, 1.0, 1.0)));
    EXPECT_TRUE(std::isnan(bench::calibrationDrift(1.0, NAN, 1.0)));
}

TEST(BenchStats, CalibrationSpreadAndSummary) {
    bench::CalibrationLog log;
    log.enabled = true;
    log.iterations = 64;
    log.groups = 1024;
    log.repeats = 5;
    log.referenceMs = 2.0;
    log.measurements = {2.0, 2.1, NAN, 1.9, 2.0, 2.2};
    log.rows = 2;
    log.remeasuredRows = 1;
    log.remeasurements = 3;
    log.flaggedRows = 1;
    const bench::CalibrationSpread s = bench::calibrationSpread(log);
    EXPECT_EQ(s.count, 5u);
    EXPECT_DOUBLE_EQ(s.min, 1.9);
    EXPECT_DOUBLE_EQ(s.median, 2.0);
    EXPECT_DOUBLE_EQ(s.max, 2.2);
    EXPECT_DOUBLE_EQ(s.ratio, 2.2 / 1.9);
    const std::string text = bench::calibrationSummary(log);
    EXPECT_EQ(text.rfind("reference 2 ms", 0), 0u) << text;
    EXPECT_NE(text.find("5 measurements min 1.9 / median 2 / max 2.2 ms, max/min 1.158"), std::string::npos)
        << text;
    EXPECT_NE(text.find("re-measured 1 of 2 rows (3 more attempts), 1 flagged"), std::string::npos) << text;
    log.enabled = false;
    EXPECT_EQ(bench::calibrationSummary(log).rfind("not run", 0), 0u);
}

TEST(BenchStats, CalibrationCellsFollowTheColumns) {
    bench::RowCalibration c;
    c.beforeMs = 2.0;
    c.afterMs = 2.2;
    c.drift = 0.1;
    c.remeasured = 3;
    c.flagged = true;
    std::vector<std::string> row;
    bench::appendCalibrationCells(row, c);
    ASSERT_EQ(row.size(), bench::calibrationColumns().size());
    EXPECT_EQ(row, (std::vector<std::string>{"2.1", "2", "2.2", "0.1", "3", "1"}));
    EXPECT_EQ(bench::remeasuredText(c), "3!");
    EXPECT_EQ(bench::calibrationMsText(bench::RowCalibration{}), "–");
    bench::Timing timing;
    bench::RunInfo info;
    row.clear();
    bench::appendTimingCells(row, info, timing);
    EXPECT_EQ(row.size(), bench::timingColumns().size());
    row.clear();
    std::array<bench::ErrorStats, 3> errors{};
    bench::appendErrorCells(row, errors);
    EXPECT_EQ(row.size(), bench::errorColumns().size());
}

TEST(BenchStats, RepeatSpreadIsTheLargestOverSettingsMeasuredTwice) {
    std::vector<bench::Result> results(5);
    for (size_t i = 0; i < results.size(); ++i) {
        results[i].setting.scene = "fog_default";
        results[i].setting.steps = i < 2 ? 32 : i < 4 ? 64 : 16;
    }
    results[0].timing.median = 1.0;
    results[1].timing.median = 1.02;
    results[2].timing.median = 2.1;
    results[3].timing.median = 2.0;
    results[4].timing.median = 9.0;  // measured once
    const bench::RepeatSpread r = bench::repeatSpread(results);
    EXPECT_EQ(r.settings, 2u);
    EXPECT_NEAR(r.spread, 0.05, 1e-12);
    EXPECT_NE(r.worst.find("steps=64"), std::string::npos) << r.worst;
    EXPECT_EQ(bench::repeatSpreadText({results[4]}), "");
}

}  // namespace
