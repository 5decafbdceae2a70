// postfx-bench --atmosphere's results.csv and results.md, and the targets computed from the rows.
#include "atmosphere_bench.h"

#include "report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bench {
namespace {

std::string ms(double value) {
    return std::isfinite(value) ? formatNumber(value, 4) + " ms" : "–";
}

bool isMoving(AtmosphereSituation s) {
    return s == AtmosphereSituation::Camera || s == AtmosphereSituation::Sun;
}

std::string status(const AtmosphereTarget& t) {
    if (!t.row || !std::isfinite(t.measured())) return "not measured";
    const std::string text = formatNumber(t.measured(), 4) + " ms";
    if (t.met()) return "**PASS** (" + text + " ≤ " + formatNumber(t.limit, 3) + " ms)";
    return "**MISS** by " + percentOver(t.measured(), t.limit) + "% (" + text + " > " +
           formatNumber(t.limit, 3) + " ms)";
}

// "apply 30/30, sky_view 30/30": how many timed frames recorded each pass.
std::string passFramesText(const AtmosphereRow& r) {
    std::string text;
    for (const auto& [name, count] : r.passFrames)
        text += (text.empty() ? "" : ", ") + shortPass(name) + " " + std::to_string(count) + "/" +
                std::to_string(r.timing.frames);
    return text;
}

std::string settingText(const AtmospherePoint& p) {
    return p.knob == "default" ? std::string("defaults") : p.knob + "=" + p.value;
}

std::vector<std::string> viewOrder(const std::vector<AtmosphereRow>& rows) {
    std::vector<std::string> views;
    for (const AtmosphereRow& r : rows)
        if (std::find(views.begin(), views.end(), r.view) == views.end()) views.push_back(r.view);
    return views;
}

}  // namespace

double atmospherePassMs(const AtmosphereRow& row, const std::string& pass) {
    for (const auto& [name, value] : row.timing.passMedians)
        if (name == pass) return value;
    return NAN;
}

uint32_t atmospherePassFrames(const AtmosphereRow& row, const std::string& pass) {
    for (const auto& [name, count] : row.passFrames)
        if (name == pass) return count;
    return 0;
}

std::vector<AtmosphereTarget> atmosphereTargets(const std::vector<AtmosphereRow>& rows) {
    std::vector<AtmosphereTarget> targets(3);
    targets[0].name = "still camera and sun ≤ " + formatNumber(kAtmosphereStillTargetMs, 3) + " ms";
    targets[0].limit = kAtmosphereStillTargetMs;
    targets[1].name = "moving camera or sun ≤ " + formatNumber(kAtmosphereMovingTargetMs, 3) + " ms";
    targets[1].limit = kAtmosphereMovingTargetMs;
    targets[2].name =
        "full rebuild after a media change ≤ " + formatNumber(kAtmosphereRebuildTargetMs, 3) + " ms";
    targets[2].limit = kAtmosphereRebuildTargetMs;
    for (const AtmosphereRow& r : rows) {
        if (r.point.knob != "default" || !std::isfinite(r.timing.median)) continue;
        const int k = r.situation == AtmosphereSituation::Still ? 0 : isMoving(r.situation) ? 1 : 2;
        if (!targets[k].row || r.timing.median > targets[k].row->timing.median) targets[k].row = &r;
    }
    return targets;
}

const std::vector<std::string>& atmosphereCsvColumns() {
    static const std::vector<std::string> columns = [] {
        std::vector<std::string> knobs = {"view", "situation", "knob", "value"};
        knobs.insert(knobs.end(), atmosphereKnobs().begin(), atmosphereKnobs().end());  // every knob's value
        return joinColumns(
            {knobs,
             timingColumns(),
             {"transmittance_ms", "multiple_scattering_ms", "scattering_orders_ms", "sky_view_ms",
              "aerial_perspective_ms", "apply_ms", "pass_frames", "sky_pixels", "sky_rel_rmse", "sky_max_abs",
              "geometry_pixels", "geometry_rel_rmse", "geometry_max_abs", "all_rel_rmse", "sky_tm_rel_rmse",
              "geometry_tm_rel_rmse", "all_tm_rel_rmse", "non_finite"}});
    }();
    return columns;
}

bool writeAtmosphereCsv(const std::string& path, const AtmosphereInfo& info,
                        const std::vector<AtmosphereRow>& rows, std::string& error) {
    std::ostringstream out;
    writeCsvPreamble(out,
                     "postfx-bench --atmosphere results; columns: docs/accuracy-cost/README.md (Atmosphere)",
                     info.run,
                     "# reference (a): postfx::reference::renderAtmosphere, Psi table " +
                         std::to_string(info.psiDirections) + " directions x " +
                         std::to_string(info.psiSteps) + " steps\n",
                     atmosphereCsvColumns());
    for (const AtmosphereRow& r : rows) {
        std::vector<std::string> row = {r.view, situationName(r.situation), r.point.knob, r.point.value};
        for (const std::string& knob : atmosphereKnobs())
            row.push_back(atmosphereKnobValue(r.point.settings, knob));
        appendTimingCells(row, info.run, r.timing);
        for (const char* pass : kAtmospherePasses)
            row.push_back(formatNumber(atmospherePassMs(r, pass), 6));
        std::string frames;
        for (const auto& [name, count] : r.passFrames)
            frames += (frames.empty() ? "" : ";") + name + "=" + std::to_string(count);
        row.push_back(frames);
        row.push_back(std::to_string(r.skyPixels));
        row.push_back(formatNumber(r.sky.relativeRmse, 6));
        row.push_back(formatNumber(r.sky.maxAbsError, 6));
        row.push_back(std::to_string(r.geometryPixels));
        row.push_back(formatNumber(r.geometry.relativeRmse, 6));
        row.push_back(formatNumber(r.geometry.maxAbsError, 6));
        row.push_back(formatNumber(r.all.relativeRmse, 6));
        row.push_back(formatNumber(r.sky.tonemappedRmse, 6));
        row.push_back(formatNumber(r.geometry.tonemappedRmse, 6));
        row.push_back(formatNumber(r.all.tonemappedRmse, 6));
        row.push_back(std::isfinite(r.all.relativeRmse) ? std::to_string(r.all.nonFinite) : "");
        writeCsvRow(out, row);
    }
    return writeTextFile(path, out.str(), error);
}

bool writeAtmosphereMarkdown(const std::string& path, const AtmosphereInfo& info,
                             const std::vector<AtmosphereRow>& rows, std::string& error) {
    const RunInfo& run = info.run;
    std::ostringstream out;
    out << "# Sky and atmosphere: accuracy–cost results\n\n"
        << "Written by `postfx-bench --atmosphere`; how to run it and what each number means: "
           "`docs/accuracy-cost/README.md` (Atmosphere). Every number is in [results.csv](results.csv).\n\n"
        << "| | |\n|---|---|\n"
        << "| device | " << run.device << " |\n"
        << "| Vulkan | " << run.vulkanApi << " |\n"
        << "| date | " << run.date << " |\n"
        << "| command | `" << run.commandLine << "` |\n"
        << "| image | " << referenceSummary(run) << " |\n"
        << "| reference (a) | postfx::reference::renderAtmosphere (no LUTs, double), Ψ table "
        << info.psiDirections << " directions × " << info.psiSteps << " steps |\n"
        << "| GPU time | " << warmupText(run) << ", then the median of " << run.frames
        << " frames (p10–p90), Vulkan timestamps around each pass; a row's time is the sum of the "
           "atmosphere.* "
           "passes its frames recorded |\n"
        << "| calibration | " << calibrationSummary(run.calibration) << " |\n\n";
    if (!info.referenceSeconds.empty()) {
        out << "CPU references:";
        for (size_t i = 0; i < info.referenceSeconds.size(); ++i)
            out << (i ? "," : "") << " " << info.referenceSeconds[i].first << " "
                << formatNumber(info.referenceSeconds[i].second, 3) << " s";
        out << ".\n\n";
    }

    out << "## Targets\n\nOn the H100 at 1920×1080: each the slowest view's row at postfx's default "
           "settings; this run: "
        << run.device << ", " << run.width << "×" << run.height << ".";
    if (run.width != 1920 || run.height != 1080)
        out << " **Not 1920×1080: the statuses below are not the targets'.**";
    out << "\n\n| target | row | measured in this run | status |\n|---|---|---|---|\n";
    for (const AtmosphereTarget& t : atmosphereTargets(rows)) {
        out << "| " << t.name << " | "
            << (t.row ? t.row->view + ", " + situationName(t.row->situation) : std::string("not measured"))
            << " | " << (t.row ? ms(t.measured()) + passBreakdown(t.row->timing) : std::string("–")) << " | "
            << status(t) << " |\n";
    }
    out << "\n";

    out << "## What each frame rebuilds (postfx's defaults)\n\n"
        << "still: camera and sun still; camera: the camera turning " << formatNumber(kAtmosphereMotion, 3)
        << " rad every frame; sun: the sun's elevation changing " << formatNumber(kAtmosphereMotion, 3)
        << " rad every frame; media: the Mie scattering coefficient changing by a factor "
        << formatNumber(1.0 + kAtmosphereMediaChange, 6)
        << " every frame. Each pass's median over the frames that recorded it, and in how many of the timed "
           "frames it was recorded.\n\n"
        << "| view | situation | GPU ms median (p10–p90) | transmittance | multiple_scattering | sky_view | "
           "aerial_perspective | apply | passes recorded |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const AtmosphereRow& r : rows) {
        if (r.point.knob != "default") continue;
        out << "| " << r.view << " | " << situationName(r.situation) << " | "
            << orDash(formatNumber(r.timing.median, 4)) << " (" << orDash(formatNumber(r.timing.p10, 3))
            << "–" << orDash(formatNumber(r.timing.p90, 3)) << ") | ";
        for (const char* pass : kAtmospherePasses)
            out << orDash(formatNumber(atmospherePassMs(r, pass), 3)) << " | ";
        out << passFramesText(r) << " |\n";
    }
    out << "\n";

    out << "## LUT sizes and sample counts\n\n"
        << "One knob at a time around postfx's defaults (the paper's), each row timed with a media change "
           "every frame (every LUT rebuilt: each pass's own time) and its error against reference (a) "
           "(relative RMSE over RGB; sky: pixels without geometry, the sun disk's pixels left out; geometry: "
           "the "
           "terrain's pixels, aerial perspective).\n\n";
    for (const std::string& view : viewOrder(rows)) {
        out << "### " << view << "\n\n"
            << "| setting | all passes (ms) | transmittance | multiple_scattering | sky_view | "
               "aerial_perspective "
               "| apply | sky rel. RMSE | geometry rel. RMSE | all rel. RMSE "
               "|\n|---|---|---|---|---|---|---|---|---|"
               "---|\n";
        for (const AtmosphereRow& r : rows) {
            if (r.view != view || r.situation != AtmosphereSituation::Media) continue;
            out << "| " << settingText(r.point) << " | " << orDash(formatNumber(r.timing.median, 4)) << " | ";
            for (const char* pass : kAtmospherePasses)
                out << orDash(formatNumber(atmospherePassMs(r, pass), 3)) << " | ";
            out << percent(r.sky.relativeRmse) << " | "
                << (r.geometryPixels ? percent(r.geometry.relativeRmse) : std::string("–")) << " | "
                << percent(r.all.relativeRmse) << " |\n";
        }
        out << "\n";
    }
    return writeTextFile(path, out.str(), error);
}

std::string atmosphereSummary(const AtmosphereInfo& info, const std::vector<AtmosphereRow>& rows) {
    std::ostringstream out;
    out << "targets (" << info.run.width << "x" << info.run.height
        << ", postfx's defaults, the slowest view):\n";
    for (const AtmosphereTarget& t : atmosphereTargets(rows)) {
        out << "  " << t.name << ": ";
        if (t.row)
            out << t.row->view << " " << situationName(t.row->situation) << ": "
                << formatNumber(t.measured(), 4) << " ms " << (t.met() ? "PASS" : "MISS");
        else
            out << "not measured";
        out << "\n";
    }
    return out.str();
}

}  // namespace bench
