// The benchmark's report: results.csv (every number), results.md (tables, Pareto fronts) and plot.svg
// (error against GPU time, log–log), each with the run's device, driver, date and command line.
#pragma once

#include "bench_types.h"

#include <array>
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
// `title`, the run's device, API, date, command, image and timing, then `extraLines` (each "# ...\n"), then
// the header row of `columns`.
void writeCsvPreamble(std::ostream& out, const std::string& title, const RunInfo& info,
                      const std::string& extraLines, const std::vector<std::string>& columns);
// The run columns and the timing columns of a row: width, height, warm-up, frames, median, p10, p90, min,
// max.
void appendTimingCells(std::vector<std::string>& row, const RunInfo& info, const Timing& timing);
// rel_rmse, max_abs, frac_off of each averaged-frames error; returns the largest non-finite count.
uint64_t appendErrorCells(std::vector<std::string>& row, const std::array<ErrorStats, 3>& error);
void writeCsvRow(std::ostream& out, const std::vector<std::string>& row);
// The scenes in the order their first result appears.
std::vector<std::string> sceneOrder(const std::vector<Result>& results);

}  // namespace bench
