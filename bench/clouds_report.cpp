// postfx-bench --clouds's results.csv and results.md, and the targets computed from the rows.
#include "clouds_bench.h"

#include "report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bench {
namespace {

std::string settingText(const CloudsPoint& p) {
    return p.knob == "default" ? std::string("medium (default)") : p.knob + "=" + p.value;
}

std::string settingsText(const postfx::CloudSettings& s) {
    return "steps " + std::to_string(s.steps) + ", light " + std::to_string(s.lightSteps) + ", scale " +
           cloudsKnobValue(s, "resolution_scale") + ", temporal " + cloudsKnobValue(s, "temporal") +
           ", noise " + std::to_string(s.noise.baseSize) + "/" + std::to_string(s.noise.detailSize);
}

std::vector<std::string> viewOrder(const std::vector<CloudsRow>& rows) {
    std::vector<std::string> views;
    for (const CloudsRow& r : rows)
        if (std::find(views.begin(), views.end(), r.view) == views.end()) views.push_back(r.view);
    return views;
}

std::string targetValue(const CloudsTarget& t, double value) {
    return t.error ? percent(value) : formatNumber(value, 4) + " ms";
}

std::string status(const CloudsTarget& t) {
    if (!t.row || !std::isfinite(t.measured())) return "not measured";
    const std::string text = targetValue(t, t.measured()), limit = targetValue(t, t.limit);
    if (t.met()) return "**PASS** (" + text + " ≤ " + limit + ")";
    return "**MISS** by " + percentOver(t.measured(), t.limit) + "% (" + text + " > " + limit + ")";
}

// "+1.23%" / "-1.23%"; "–" when not finite.
std::string signedPercent(double fraction) {
    if (!std::isfinite(fraction)) return "–";
    return (fraction >= 0.0 ? "+" : "-") + percent(std::abs(fraction));
}

}  // namespace

double cloudsPassMs(const CloudsRow& row, const std::string& pass) {
    for (const auto& [name, value] : row.timing.passMedians)
        if (name == pass) return value;
    return NAN;
}

bool isCloudsMediumRow(const CloudsRow& row) {
    return row.point.knob == "default" || (row.point.knob == "preset" && row.point.value == "medium");
}

double CloudsTarget::measured() const {
    if (!row) return NAN;
    return error ? row->still.stats.relativeRmse : row->timing.median;
}

std::vector<CloudsTarget> cloudsTargets(const std::vector<CloudsRow>& rows) {
    std::vector<CloudsTarget> targets(2);
    targets[0].name = "Medium, temporal on, still ≤ " + formatNumber(kCloudsMediumTargetMs, 3) + " ms";
    targets[0].limit = kCloudsMediumTargetMs;
    targets[1].name = "Medium, converged still error ≤ " + percent(kCloudsMediumTargetError, 2);
    targets[1].limit = kCloudsMediumTargetError;
    targets[1].error = true;
    for (const CloudsRow& r : rows) {
        if (!isCloudsMediumRow(r) || !r.point.settings.temporal.enabled) continue;
        for (CloudsTarget& t : targets) {
            const double v = t.error ? r.still.stats.relativeRmse : r.timing.median;
            if (!std::isfinite(v)) continue;
            if (!t.row || v > t.measured()) t.row = &r;
        }
    }
    return targets;
}

const std::vector<std::string>& cloudsCsvColumns() {
    static const std::vector<std::string> columns =
        joinColumns({{"view", "knob", "value", "steps", "light_steps", "resolution_scale", "base_size",
                      "detail_size", "temporal"},
                     timingColumns(),
                     {"base_noise_ms",
                      "detail_noise_ms",
                      "shadow_ms",
                      "march_ms",
                      "temporal_ms",
                      "upsample_ms",
                      "pass_frames",
                      "still_frames",
                      "still_rel_rmse",
                      "still_mean_rel_luminance",
                      "still_max_abs",
                      "still_tm_rel_rmse",
                      "motion_frames",
                      "motion_rel_rmse",
                      "motion_mean_rel_luminance",
                      "motion_max_abs",
                      "motion_tm_rel_rmse",
                      "non_finite",
                      "model",
                      "truth_model_bias",
                      "truth_model_rel_rmse",
                      "truth_gpu_bias",
                      "truth_gpu_rel_rmse"}});
    return columns;
}

bool writeCloudsCsv(const std::string& path, const CloudsInfo& info, const std::vector<CloudsRow>& rows,
                    std::string& error) {
    std::ostringstream out;
    writeCsvPreamble(
        out, "postfx-bench --clouds results; columns: docs/accuracy-cost/README.md (Clouds)", info.run,
        "# reference: postfx::reference::renderClouds, " + std::to_string(info.run.referenceSteps) +
            " view steps x " + std::to_string(info.referenceLightSteps) +
            " light steps; still: " + std::to_string(info.convergedFrames) +
            " frames (temporal), motion: " + std::to_string(info.motionFrames) + " frames panning " +
            formatNumber(kCloudsPanDegPerFrame, 3) + " deg/frame\n",
        cloudsCsvColumns());
    for (const CloudsRow& r : rows) {
        std::vector<std::string> row = {r.view, r.point.knob, r.point.value};
        for (const char* knob :
             {"steps", "light_steps", "resolution_scale", "base_size", "detail_size", "temporal"})
            row.push_back(cloudsKnobValue(r.point.settings, knob));
        appendTimingCells(row, info.run, r.timing);
        for (const char* pass : kCloudsPasses)
            row.push_back(formatNumber(cloudsPassMs(r, pass), 6));
        std::string frames;
        for (const auto& [name, count] : r.passFrames)
            frames += (frames.empty() ? "" : ";") + name + "=" + std::to_string(count);
        row.push_back(frames);
        for (const auto& [n, e] :
             {std::pair{r.stillFrames, &r.still}, std::pair{r.motionFrames, &r.motion}}) {
            row.push_back(std::to_string(n));
            row.push_back(formatNumber(e->stats.relativeRmse, 6));
            row.push_back(formatNumber(e->meanRelativeLuminance, 6));
            row.push_back(formatNumber(e->stats.maxAbsError, 6));
            row.push_back(formatNumber(e->stats.tonemappedRmse, 6));
        }
        row.push_back(std::to_string(r.still.stats.nonFinite + r.motion.stats.nonFinite));
        row.push_back(cloudsKnobValue(r.point.settings, "model"));
        for (const CloudsTruthError* e : {&r.model, &r.total}) {
            row.push_back(formatNumber(e->bias, 6));
            row.push_back(formatNumber(e->relativeRmse, 6));
        }
        writeCsvRow(out, row);
    }
    return writeTextFile(path, out.str(), error);
}

bool writeCloudsMarkdown(const std::string& path, const CloudsInfo& info, const std::vector<CloudsRow>& rows,
                         std::string& error) {
    const RunInfo& run = info.run;
    std::ostringstream out;
    out << "# Volumetric clouds: accuracy–cost results\n\n"
        << "Written by `postfx-bench --clouds`; how to run it and what each number means: "
           "`docs/accuracy-cost/README.md` (Clouds). Every number is in [results.csv](results.csv).\n\n"
        << "| | |\n|---|---|\n"
        << "| device | " << run.device << " |\n"
        << "| Vulkan | " << run.vulkanApi << " |\n"
        << "| date | " << run.date << " |\n"
        << "| command | `" << run.commandLine << "` |\n"
        << "| image | " << referenceSummary(run) << " |\n"
        << "| reference | postfx::reference::renderClouds (double, no jitter, no early exit), "
        << run.referenceSteps << " view steps × " << info.referenceLightSteps
        << " light steps, the GPU's noise texels, over the GPU's atmosphere-only image |\n"
        << "| GPU time | camera and sun still: " << warmupText(run) << ", then the median of " << run.frames
        << " frames (p10–p90), Vulkan timestamps around each pass; a row's time is the sum of the clouds.* "
           "passes its frames recorded (the atmosphere's passes are not counted) |\n"
        << "| calibration | " << calibrationSummary(run.calibration) << " |\n"
        << "| error | relative RMSE over RGB and mean relative luminance error; still: the last of "
        << info.convergedFrames << " still frames with temporal on (1 frame without); motion: the last of "
        << info.motionFrames << " frames of the camera panning " << formatNumber(kCloudsPanDegPerFrame, 3)
        << "°/frame, against its own view's reference (the model's: discretisation error) |\n";
    if (info.truthPaths) {
        out << "| truth | postfx::reference::renderClouds' path-traced mode (every scattering order), "
            << info.truthPaths << " paths per pixel at every " << info.truthStride
            << "th pixel; its mean relative standard error:";
        for (size_t i = 0; i < info.truthStandardError.size(); ++i)
            out << (i ? "," : "") << " " << info.truthStandardError[i].first << " "
                << percent(info.truthStandardError[i].second) << " ("
                << formatNumber(info.truthSeconds[i].second, 3) << " s)";
        out << ". vs truth: the bias (mean luminance / the truth's - 1 over the pixels the clouds change) "
               "and "
               "relative RMSE (the truth's noise included) of the model's reference (model error) and of the "
               "GPU's still image (model + discretisation) |\n";
    }
    out << "\n";
    if (!info.referenceSeconds.empty()) {
        out << "CPU references:";
        for (size_t i = 0; i < info.referenceSeconds.size(); ++i)
            out << (i ? "," : "") << " " << info.referenceSeconds[i].first << " "
                << formatNumber(info.referenceSeconds[i].second, 3) << " s";
        out << ".\n\n";
    }

    out << "## Targets\n\nOn the H100 at 1920×1080: the Medium preset with temporal on (the default row and "
           "preset=medium), the slowest view's time and the worst view's converged still error; this run: "
        << run.device << ", " << run.width << "×" << run.height << ".";
    if (run.width != 1920 || run.height != 1080)
        out << " **Not 1920×1080: the statuses below are not the targets'.**";
    out << "\n\n| target | row | measured in this run | status |\n|---|---|---|---|\n";
    for (const CloudsTarget& t : cloudsTargets(rows)) {
        out << "| " << t.name << " | "
            << (t.row ? t.row->view + ", " + settingText(t.row->point) : "not measured") << " | "
            << (t.row ? targetValue(t, t.measured()) + (t.error ? "" : passBreakdown(t.row->timing))
                      : std::string("–"))
            << " | " << status(t) << " |\n";
    }
    out << "\nPublished anchors (other renderers, not comparable settings): about "
        << formatNumber(kCloudsAnchorPs4Ms, 3) << " ms on a PS4 (Horizon Zero Dawn), about "
        << formatNumber(kCloudsAnchorRtx4080Ms, 3) << " ms on an RTX 4080 (a public implementation).\n\n";

    out << "## Sweep\n\nThe Medium preset's settings with one knob changed, and each preset. A noise-size "
           "row's reference uses that row's own noise (the field changes with it): its error is the march's, "
           "not the field's detail.\n\n";
    for (const std::string& view : viewOrder(rows)) {
        out << "### " << view << "\n\n"
            << "| setting | settings | clouds.* ms median (p10–p90) | shadow | march | temporal | upsample | "
               "still rel. RMSE | still mean rel. Y | motion rel. RMSE | motion mean rel. Y | vs truth: "
               "model "
               "bias | GPU bias | GPU rel. RMSE |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const CloudsRow& r : rows) {
            if (r.view != view) continue;
            out << "| " << settingText(r.point) << " | " << settingsText(r.point.settings) << " | "
                << orDash(formatNumber(r.timing.median, 4)) << " (" << orDash(formatNumber(r.timing.p10, 3))
                << "–" << orDash(formatNumber(r.timing.p90, 3)) << ") | ";
            for (const char* pass : {"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"})
                out << orDash(formatNumber(cloudsPassMs(r, pass), 3)) << " | ";
            out << percent(r.still.stats.relativeRmse) << " | " << percent(r.still.meanRelativeLuminance)
                << " | " << percent(r.motion.stats.relativeRmse) << " | "
                << percent(r.motion.meanRelativeLuminance) << " | " << signedPercent(r.model.bias) << " | "
                << signedPercent(r.total.bias) << " | " << percent(r.total.relativeRmse) << " |\n";
        }
        out << "\n";
    }
    return writeTextFile(path, out.str(), error);
}

std::string cloudsSummary(const CloudsInfo& info, const std::vector<CloudsRow>& rows) {
    std::ostringstream out;
    out << "targets (" << info.run.width << "x" << info.run.height << ", Medium, temporal on):\n";
    for (const CloudsTarget& t : cloudsTargets(rows)) {
        out << "  " << t.name << ": ";
        if (t.row)
            out << t.row->view << ": " << targetValue(t, t.measured()) << " " << (t.met() ? "PASS" : "MISS");
        else
            out << "not measured";
        out << "\n";
    }
    return out.str();
}

}  // namespace bench
