// results.csv and results.md.
#include "report.h"

#include "conclusions.h"
#include "stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace bench {
namespace {

// Ours first (sweep by noise size, scale, jitter on before off, steps; then the presets), then each
// baseline by decreasing step length.
std::vector<const Result*> sortedRows(const std::vector<Result>& results, const std::string& scene) {
    std::vector<const Result*> rows;
    for (const Result& r : results)
        if (r.setting.scene == scene) rows.push_back(&r);
    std::stable_sort(rows.begin(), rows.end(), [](const Result* a, const Result* b) {
        const Setting &x = a->setting, &y = b->setting;
        if (x.method != y.method) return int(x.method) < int(y.method);
        if (x.preset.empty() != y.preset.empty()) return x.preset.empty();
        if (!x.preset.empty()) return false;  // presets in the order measured (low .. ultra)
        if (x.noiseSize != y.noiseSize) return x.noiseSize < y.noiseSize;
        if (x.resolutionScale != y.resolutionScale) return x.resolutionScale > y.resolutionScale;
        if (x.jitter != y.jitter) return x.jitter;
        if (x.steps != y.steps) return x.steps < y.steps;
        return x.stepLength > y.stepLength;
    });
    return rows;
}

}  // namespace

bool writeTextFile(const std::string& path, const std::string& text, std::string& error) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        error = "cannot write '" + path + "'";
        return false;
    }
    return true;
}

std::string orDash(const std::string& s) {
    return s.empty() ? "–" : s;
}

std::string referenceSummary(const RunInfo& info) {
    const uint32_t s = info.errorStride;
    std::string text = std::to_string(info.width) + "×" + std::to_string(info.height);
    if (s > 1) {
        text += "; error on every " + std::to_string(s) + "th pixel in x and y (" +
                std::to_string((info.width + s - 1) / s) + "×" + std::to_string((info.height + s - 1) / s) +
                ")";
    } else {
        text += "; error on every pixel";
    }
    return text + "; CPU reference " + std::to_string(info.referenceSteps) + " steps/pixel, no jitter";
}

std::string textureRateText(const RunInfo& info) {
    return std::isfinite(info.textureRate) ? formatNumber(info.textureRate, 6) + " GTexel/s (--texture-rate)"
                                           : "not given (no texture-fetch floor)";
}

std::string warmupText(const RunInfo& info) {
    return "warm-up of at least " + std::to_string(info.warmup) + " frames and " +
           formatNumber(info.warmupMs, 4) + " ms per setting (" + formatNumber(info.coldWarmupMs, 4) +
           " ms after a CPU reference)";
}

std::string percent(double fraction, int digits) {
    return std::isfinite(fraction) ? formatNumber(fraction * 100.0, digits) + "%" : "–";
}

std::string formatNumber(double value, int digits) {
    if (std::isnan(value)) return "";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

std::string percentOver(double value, double limit) {
    return formatNumber((value / limit - 1.0) * 100.0, 2);
}

std::string shortPass(const std::string& name) {
    const size_t dot = name.find('.');
    return dot == std::string::npos ? name : name.substr(dot + 1);
}

std::string passBreakdown(const Timing& timing) {
    std::string text;
    for (const auto& [name, value] : timing.passMedians)
        text += (text.empty() ? "" : ", ") + shortPass(name) + " " + formatNumber(value, 3);
    return text.empty() ? "" : " (" + text + " ms)";
}

std::string xmlEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::vector<std::string> sceneOrder(const std::vector<Result>& results) {
    std::vector<std::string> scenes;
    for (const Result& r : results)
        if (std::find(scenes.begin(), scenes.end(), r.setting.scene) == scenes.end())
            scenes.push_back(r.setting.scene);
    return scenes;
}

const std::vector<std::string>& calibrationColumns() {
    static const std::vector<std::string> columns = {"calib_ms",    "calib_before_ms", "calib_after_ms",
                                                     "calib_drift", "remeasured",      "calib_flagged"};
    return columns;
}

const std::vector<std::string>& timingColumns() {
    static const std::vector<std::string> columns =
        joinColumns({{"width", "height", "warmup", "frames", "gpu_ms_median", "gpu_ms_p10", "gpu_ms_p90",
                      "gpu_ms_min", "gpu_ms_max"},
                     calibrationColumns()});
    return columns;
}

const std::vector<std::string>& errorColumns() {
    static const std::vector<std::string> columns = [] {
        std::vector<std::string> c;
        for (uint32_t n : kAveragedFrames)
            for (const char* what : {"rel_rmse_", "max_abs_", "frac_off_"})
                c.push_back(what + std::to_string(n));
        for (uint32_t n : kAveragedFrames)
            c.push_back("tm_rel_rmse_" + std::to_string(n));
        return c;
    }();
    return columns;
}

std::vector<std::string> joinColumns(std::initializer_list<std::vector<std::string>> parts) {
    std::vector<std::string> out;
    for (const std::vector<std::string>& part : parts)
        out.insert(out.end(), part.begin(), part.end());
    return out;
}

const std::vector<std::string>& csvColumns() {
    static const std::vector<std::string> columns = joinColumns(
        {{"scene", "method", "preset", "steps", "step_length_m", "jitter", "resolution_scale", "noise_size",
          "shadow_kernel"},
         timingColumns(),
         {"pass_ms"},
         errorColumns(),
         {"non_finite", "fetches_per_pixel", "floor_ms", "time_over_floor", "pareto_1", "pareto_16"}});
    return columns;
}

std::string calibrationSummary(const CalibrationLog& log) {
    if (!log.enabled) return "not run (--no-calibration, or the queue has no timestamps)";
    const CalibrationSpread spread = calibrationSpread(log);
    return "reference " + formatNumber(log.referenceMs, 4) + " ms (" + std::to_string(log.iterations) +
           " iterations x " + std::to_string(log.groups) + " groups of 64, median of " +
           std::to_string(log.repeats) + "); " + std::to_string(spread.count) + " measurements min " +
           formatNumber(spread.min, 4) + " / median " + formatNumber(spread.median, 4) + " / max " +
           formatNumber(spread.max, 4) + " ms, max/min " + formatNumber(spread.ratio, 4) + "; re-measured " +
           std::to_string(log.remeasuredRows) + " of " + std::to_string(log.rows) + " rows (" +
           std::to_string(log.remeasurements) + " more attempts), " + std::to_string(log.flaggedRows) +
           " flagged (tolerance " + formatNumber(log.tolerance * 100.0, 3) + "%, at most " +
           std::to_string(log.retries) + " more)";
}

std::string calibrationMsText(const RowCalibration& calibration) {
    return orDash(formatNumber(calibration.ms(), 4));
}

std::string repeatSpreadText(const std::vector<Result>& results) {
    const RepeatSpread r = repeatSpread(results);
    if (r.settings == 0) return "";
    return "repeated settings: " + std::to_string(r.settings) + ", the largest spread of one's medians " +
           percent(r.spread) + " (" + r.worst + ")\n";
}

std::string remeasuredText(const RowCalibration& calibration) {
    return std::to_string(calibration.remeasured) + (calibration.flagged ? "!" : "");
}

void writeCsvPreamble(std::ostream& out, const std::string& title, const RunInfo& info,
                      const std::string& extraLines, const std::vector<std::string>& columns) {
    out << "# " << title << "\n"
        << "# device: " << info.device << "\n"
        << "# vulkan: " << info.vulkanApi << "\n"
        << "# date: " << info.date << "\n"
        << "# command: " << info.commandLine << "\n"
        << "# image: " << referenceSummary(info) << "\n"
        << "# timing: " << warmupText(info) << ", then " << info.frames << " timed frames\n"
        << "# calibration: " << calibrationSummary(info.calibration) << "\n"
        << extraLines;
    writeCsvRow(out, columns);
}

void appendCalibrationCells(std::vector<std::string>& row, const RowCalibration& c) {
    row.insert(row.end(), {formatNumber(c.ms(), 6), formatNumber(c.beforeMs, 6), formatNumber(c.afterMs, 6),
                           formatNumber(c.drift, 4), std::to_string(c.remeasured), c.flagged ? "1" : "0"});
}

void appendTimingCells(std::vector<std::string>& row, const RunInfo& info, const Timing& timing) {
    row.insert(row.end(),
               {std::to_string(info.width), std::to_string(info.height), std::to_string(info.warmup),
                std::to_string(timing.frames), formatNumber(timing.median, 6), formatNumber(timing.p10, 6),
                formatNumber(timing.p90, 6), formatNumber(timing.min, 6), formatNumber(timing.max, 6)});
    appendCalibrationCells(row, timing.calibration);
}

uint64_t appendErrorCells(std::vector<std::string>& row, const std::array<ErrorStats, 3>& error) {
    uint64_t nonFinite = 0;
    for (const ErrorStats& e : error) {
        row.push_back(formatNumber(e.relativeRmse, 6));
        row.push_back(formatNumber(e.maxAbsError, 6));
        row.push_back(formatNumber(e.fractionOff, 6));
        nonFinite = std::max(nonFinite, e.nonFinite);
    }
    for (const ErrorStats& e : error)
        row.push_back(formatNumber(e.tonemappedRmse, 6));
    return nonFinite;
}

void writeCsvRow(std::ostream& out, const std::vector<std::string>& row) {
    for (size_t i = 0; i < row.size(); ++i)
        out << (i ? "," : "") << row[i];
    out << "\n";
}

bool writeCsv(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
              std::string& error) {
    std::ostringstream out;
    writeCsvPreamble(out, "postfx-bench results; columns: docs/accuracy-cost/README.md", info,
                     "# texture rate: " + textureRateText(info) + "\n", csvColumns());
    for (const Result& r : results) {
        const Setting& s = r.setting;
        const bool ours = s.method == Method::Ours;
        std::string passes;
        for (const auto& [name, ms] : r.timing.passMedians)
            passes += (passes.empty() ? "" : ";") + name + "=" + formatNumber(ms, 5);
        std::vector<std::string> row = {
            s.scene,
            methodName(s.method),
            s.preset,
            ours ? std::to_string(s.steps) : "",
            ours ? "" : formatNumber(s.stepLength, 6),
            s.jitter ? "1" : "0",
            ours ? formatNumber(s.resolutionScale, 4) : "",
            std::to_string(s.noiseSize),
            std::to_string(s.shadowKernel),
        };
        appendTimingCells(row, info, r.timing);
        row.push_back(passes);
        row.push_back(std::to_string(appendErrorCells(row, r.error)));
        row.push_back(formatNumber(r.fetchesPerPixel, 6));
        row.push_back(formatNumber(r.floorMs, 6));
        row.push_back(formatNumber(r.timing.median / r.floorMs, 4));
        const bool swept = ours && s.preset.empty();
        row.push_back(swept ? (r.pareto1 ? "1" : "0") : "");
        row.push_back(swept ? (r.pareto16 ? "1" : "0") : "");
        writeCsvRow(out, row);
    }
    return writeTextFile(path, out.str(), error);
}

bool writeMarkdown(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                   std::string& error, const std::string& sections) {
    std::ostringstream out;
    out << "# Accuracy–cost results\n\n"
        << "Written by `postfx-bench`; how to run it and what each number means: "
           "`docs/accuracy-cost/README.md`. "
           "Every number is in [results.csv](results.csv).\n\n"
        << "| | |\n|---|---|\n"
        << "| device | " << info.device << " |\n"
        << "| Vulkan | " << info.vulkanApi << " |\n"
        << "| date | " << info.date << " |\n"
        << "| command | `" << info.commandLine << "` |\n"
        << "| image | " << referenceSummary(info) << " |\n"
        << "| GPU time | " << warmupText(info) << ", then the median of " << info.frames
        << " frames (p10–p90), Vulkan timestamps around the pass(es) |\n"
        << "| calibration | " << calibrationSummary(info.calibration) << " |\n"
        << "| texture rate | " << textureRateText(info) << " |\n"
        << "| baselines | " << (info.baselines ? "seed-as-written, seed-fixed-riemann" : "not run")
        << " |\n\n"
        << "![relative RMSE against GPU time](plot.svg)\n\n";
    if (!info.referenceSeconds.empty()) {
        out << "CPU references:";
        for (size_t i = 0; i < info.referenceSeconds.size(); ++i)
            out << (i ? "," : "") << " " << info.referenceSeconds[i].first << " "
                << formatNumber(info.referenceSeconds[i].second, 3) << " s";
        out << ".\n\n";
    }
    out << conclusionsMarkdown(info, results);
    out << sections;

    for (const std::string& scene : sceneOrder(results)) {
        const std::vector<const Result*> rows = sortedRows(results, scene);
        out << "## " << scene << "\n\n"
            << "| method | setting | GPU ms median (p10–p90) | rel. RMSE 1 / 8 / 16 frames | max abs error "
               "(1 frame) | pixels > 1% (1 frame) | fetches/pixel | floor ms | × floor | Pareto (1 / 16) |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
        for (const Result* r : rows) {
            const bool ours = r->setting.method == Method::Ours;
            out << "| " << methodName(r->setting.method) << " | " << r->setting.label() << " | "
                << orDash(formatNumber(r->timing.median, 4)) << " (" << orDash(formatNumber(r->timing.p10, 3))
                << "–" << orDash(formatNumber(r->timing.p90, 3)) << ") | "
                << percent(r->error[0].relativeRmse) << " / " << percent(r->error[1].relativeRmse) << " / "
                << percent(r->error[2].relativeRmse) << " | "
                << orDash(formatNumber(r->error[0].maxAbsError, 3)) << " | "
                << percent(r->error[0].fractionOff) << " | " << orDash(formatNumber(r->fetchesPerPixel, 5))
                << " | " << orDash(formatNumber(r->floorMs, 3)) << " | "
                << orDash(formatNumber(r->timing.median / r->floorMs, 3)) << " | "
                << (ours && r->setting.preset.empty()
                        ? std::string(r->pareto1 ? "●" : "") + " / " + (r->pareto16 ? "●" : "")
                        : "")
                << " |\n";
        }
        out << "\n";

        for (int which = 0; which < 2; ++which) {
            out << "Pareto front of postfx-fog, " << (which == 0 ? "one frame" : "mean of 16 frames")
                << " (no other setting is both faster and more accurate): ";
            std::vector<const Result*> front;
            for (const Result* r : rows)
                if (r->setting.method == Method::Ours && (which == 0 ? r->pareto1 : r->pareto16))
                    front.push_back(r);
            std::sort(front.begin(), front.end(),
                      [](const Result* a, const Result* b) { return a->timing.median < b->timing.median; });
            for (size_t i = 0; i < front.size(); ++i)
                out << (i ? ", " : "") << front[i]->setting.label() << " ("
                    << formatNumber(front[i]->timing.median, 3) << " ms, "
                    << percent(front[i]->error[which == 0 ? 0 : 2].relativeRmse) << ")";
            out << (front.empty() ? "none (no timings).\n\n" : ".\n\n");
        }

        // Each baseline point against the cheapest postfx-fog setting at least as accurate (one frame).
        bool header = false;
        for (const Result* b : rows) {
            if (b->setting.method == Method::Ours) continue;
            if (!header) {
                out << "| baseline | its GPU ms | its rel. RMSE | cheapest postfx-fog at ≤ that error | GPU "
                       "ms | "
                       "speed-up |\n|---|---|---|---|---|---|\n";
                header = true;
            }
            const Result* best = nullptr;
            for (const Result* r : rows) {
                if (r->setting.method != Method::Ours || !r->setting.preset.empty() ||
                    !(r->error[0].relativeRmse <= b->error[0].relativeRmse) ||
                    !std::isfinite(r->timing.median))
                    continue;
                if (!best || r->timing.median < best->timing.median) best = r;
            }
            out << "| " << methodName(b->setting.method) << " " << b->setting.label() << " | "
                << orDash(formatNumber(b->timing.median, 4)) << " | " << percent(b->error[0].relativeRmse)
                << " | " << (best ? best->setting.label() : "none in the sweep") << " | "
                << (best ? orDash(formatNumber(best->timing.median, 4)) : "–") << " | "
                << (best ? orDash(formatNumber(b->timing.median / best->timing.median, 3)) + "×" : "–")
                << " |\n";
        }
        if (header) out << "\n";
    }
    return writeTextFile(path, out.str(), error);
}

}  // namespace bench
