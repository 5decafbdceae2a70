// Small statistics for the benchmark: percentiles, timing summaries, Pareto fronts.
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

}  // namespace bench
