// Small statistics for the benchmark: percentiles, timing summaries, Pareto fronts, the robust error
// metric, the calibration's drift and spread.
#pragma once

#include "bench_types.h"

#include <span>
#include <string>
#include <vector>

namespace bench {

// Linear-interpolated percentile (q in [0, 1]) of `values`; NaN when empty.
double percentile(std::vector<double> values, double q);

// Median, p10, p90, min, max of the per-frame totals; per-pass medians from `passes` (name, ms per frame
// it appeared in).
Timing summarize(const std::vector<double>& frameTotals,
                 const std::vector<std::pair<std::string, std::vector<double>>>& passes);

// Indices of the points not dominated by another (x <= and y <=, one strictly), sorted by x. Points with a
// non-finite coordinate are skipped.
std::vector<size_t> paretoFront(std::span<const double> x, std::span<const double> y);

// Marks Result::pareto1 / pareto16 of the Ours results, per scene.
void markParetoFronts(std::vector<Result>& results);

// The robust error (ErrorStats::tonemappedRmse) of `actual` against `expected`, both RGBA floats of the
// same pixels: the relative RMSE over RGB after the same fixed tonemap of both,
//     k = 0.18 / exp(mean over the reference's pixels with Y > 0 of ln Y),  Y = 0.2126 R + 0.7152 G + 0.0722
//     B T(v) = k·v / (1 + k·|v|)                      (Reinhard's, per channel, on exposure-normalised
//     values) tonemappedRmse = sqrt(Σ (T(a) − T(b))²) / sqrt(Σ T(b)²)
// |T| < 1, so no pixel adds more than 3 to the sum of squared errors however bright it is; a relative
// error ε of a pixel at k·v = x moves T by ε·x / (1 + x)² ≤ ε / 4, by about ε / x on a bright one (the sun's
// disk at x = 10⁴: 10⁻⁴ ε); the exposure is the log-average, which one pixel moves by a factor of at
// most (its luminance / the average)^(1/N), not the mean, which a sun disk sets. Non-finite values of
// `actual` are skipped (ErrorStats::nonFinite counts them). 0 when both images tonemap to 0.
double tonemappedRmse(std::span<const float> actual, std::span<const float> expected);

// A row's calibration drift (RowCalibration::drift): the largest of |after / before − 1|,
// |before / reference − 1| and |after / reference − 1| (the last two without a finite reference); NaN when
// before or after is not finite.
double calibrationDrift(double beforeMs, double afterMs, double referenceMs);

// The spread of a run's calibration measurements [ms]; NaN without any.
struct CalibrationSpread {
    size_t count = 0;
    double min = NAN, median = NAN, max = NAN;
    double ratio = NAN;  // max / min
};
CalibrationSpread calibrationSpread(const CalibrationLog& log);

// Settings measured more than once in a run (the same scene, method and label: `--steps 32,32`): how many,
// and the largest spread of one setting's medians, max / min − 1 (NaN: none), and which.
struct RepeatSpread {
    size_t settings = 0;
    double spread = NAN;
    std::string worst;  // "scene method label"
};
RepeatSpread repeatSpread(const std::vector<Result>& results);

}  // namespace bench
