// The benchmark's report: results.csv (every number), results.md (tables, Pareto fronts) and plot.svg
// (error against GPU time, log–log), each with the run's device, driver, date and command line.
#pragma once

#include "bench_types.h"

#include <array>
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

namespace bench {

// The CSV's columns, in order (tests/bench parses them by name).
const std::vector<std::string>& csvColumns();

bool writeCsv(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
              std::string& error);
// results.md; `sections` (markdown: the in-motion section, bench/motion_report.h) follows the run's
// conclusions.
bool writeMarkdown(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                   std::string& error, const std::string& sections = "");
bool writeSvg(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
              std::string& error);

// Helpers shared by the writers.
std::string formatNumber(double value, int digits = 4);  // "" for NaN
// How far `value` is over `limit`, in percent, two significant digits ("0.15", "7.3"): a small miss is not
// rounded to "0".
std::string percentOver(double value, double limit);
std::string percent(double fraction, int digits = 3);  // "1.23%"; "–" when not finite
std::string xmlEscape(const std::string& text);
// A pass's name without its effect's prefix: "apply" for "atmosphere.apply".
std::string shortPass(const std::string& name);
// " (transmittance 0.01, apply 0.004 ms)": each pass's median in recording order; "" when none.
std::string passBreakdown(const Timing& timing);
// `text` into `path`; false with "cannot write 'PATH'" otherwise.
bool writeTextFile(const std::string& path, const std::string& text, std::string& error);
std::string orDash(const std::string& s);  // "–" for ""
// The header's "image" line: size, error stride, reference steps.
std::string referenceSummary(const RunInfo& info);
// The header's warm-up text.
std::string warmupText(const RunInfo& info);
std::string textureRateText(const RunInfo& info);
// CSV files (writeCsv, writeFroxelCsv): the metadata comment lines (pandas: comment='#') starting with
// `title`, the run's device, API, date, command, image, timing and calibration, then `extraLines` (each
// "# ...\n"), then the header row of `columns`.
void writeCsvPreamble(std::ostream& out, const std::string& title, const RunInfo& info,
                      const std::string& extraLines, const std::vector<std::string>& columns);
// The columns appendTimingCells writes: width, height, warmup, frames, gpu_ms_median, _p10, _p90, _min,
// _max, then the row's calibration (calibrationColumns).
const std::vector<std::string>& timingColumns();
// A timed row's calibration (bench/calibration.h): calib_ms (the mean of before and after), calib_before_ms,
// calib_after_ms, calib_drift, remeasured (how many more times the row was timed), calib_flagged (1: kept
// out of tolerance).
const std::vector<std::string>& calibrationColumns();
// The columns appendErrorCells writes: rel_rmse_N, max_abs_N, frac_off_N for N = 1, 8, 16, then
// tm_rel_rmse_N (ErrorStats::tonemappedRmse) for each.
const std::vector<std::string>& errorColumns();
// The parts one after the other.
std::vector<std::string> joinColumns(std::initializer_list<std::vector<std::string>> parts);
// The run columns and the timing columns of a row (timingColumns).
void appendTimingCells(std::vector<std::string>& row, const RunInfo& info, const Timing& timing);
void appendCalibrationCells(std::vector<std::string>& row, const RowCalibration& calibration);
// errorColumns' cells of each averaged-frames error; returns the largest non-finite count.
uint64_t appendErrorCells(std::vector<std::string>& row, const std::array<ErrorStats, 3>& error);
// The run's calibration in one line: "reference 2.01 ms (131072 iterations x 1024 groups, median of 5);
// 84 measurements min 1.98 / median 2.01 / max 2.1 ms, max/min 1.061; re-measured 3 of 40 rows (5 more
// attempts), 0 flagged (tolerance 5%, at most 3 more)", or why there is none.
std::string calibrationSummary(const CalibrationLog& log);
// A row's calibration for the stdout tables: its mean [ms] ("–" without), and how many times it was timed
// again ("0", "2"; "3!" when flagged).
std::string calibrationMsText(const RowCalibration& calibration);
// "repeated settings: 2, the largest spread of one's medians 1.2% (fog_default postfx-fog steps=32 ...)\n"
// for stdout; "" when no setting was measured twice.
std::string repeatSpreadText(const std::vector<Result>& results);
std::string remeasuredText(const RowCalibration& calibration);
void writeCsvRow(std::ostream& out, const std::vector<std::string>& row);
// The scenes in the order their first result appears.
std::vector<std::string> sceneOrder(const std::vector<Result>& results);

}  // namespace bench
