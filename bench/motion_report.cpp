// motion.csv and the "In motion" sections of results.md.
#include "motion_report.h"

#include "report.h"

#include <postfx/fog.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace bench {
namespace {

std::string ms(double value) {
    return orDash(formatNumber(value, 4));
}

// The motion results' presets (ray-marched fog) in the order first measured.
std::vector<std::string> presetOrder(const std::vector<MotionResult>& motion) {
    std::vector<std::string> presets;
    for (const MotionResult& m : motion)
        if (!m.setting.preset.empty() && !std::count(presets.begin(), presets.end(), m.setting.preset))
            presets.push_back(m.setting.preset);
    return presets;
}

std::vector<std::string> motionScenes(const std::vector<MotionResult>& motion) {
    std::vector<std::string> scenes;
    for (const MotionResult& m : motion)
        if (!std::count(scenes.begin(), scenes.end(), m.setting.scene)) scenes.push_back(m.setting.scene);
    return scenes;
}

const MotionResult* find(const std::vector<MotionResult>& motion, const std::string& scene,
                         const std::string& preset, bool temporal, MotionKind kind) {
    for (const MotionResult& m : motion)
        if (m.setting.scene == scene && m.setting.preset == preset && m.temporal == temporal &&
            m.kind == kind)
            return &m;
    return nullptr;
}

// "0.45% (0.52%)": the mean in-motion error and its largest frame.
std::string meanMax(const MotionResult* m) {
    if (!m) return "–";
    return percent(m->meanError()) + " (" + percent(m->maxError()) + ")";
}

std::string framesText(const MotionOptions& o) {
    const std::vector<uint32_t> frames = measuredFrames(o);
    std::string text;
    if (frames.size() <= 3) {
        for (size_t i = 0; i < frames.size(); ++i)
            text += (i ? ", " : "") + std::to_string(frames[i]);
    } else {
        text = std::to_string(frames[0]) + ", " + std::to_string(frames[1]) + ", …, " +
               std::to_string(frames.back());
    }
    return text + " (" + std::to_string(frames.size()) + " frames)";
}

std::string header(const MotionInfo& mi, bool froxel) {
    const MotionOptions& o = mi.options;
    const double perFrameCm = o.cameraSpeed * o.frameSeconds * 100.0;
    const double perFrameDeg = o.yawRateDeg * o.frameSeconds;
    std::ostringstream out;
    out << "Each sequence starts with a camera cut (frame index 0: the temporal history starts anew) and "
           "runs at "
        << formatNumber(1.0 / o.frameSeconds, 3) << " frames per second; after a warm-up of " << o.warmup
        << " frames, the frames " << framesText(o)
        << " are each compared with the CPU reference of that frame's own state (" << mi.referenceSteps
        << " steps per pixel, every " << mi.errorStride
        << "th pixel in x and y). Time is frozen (no wind): only what the sequence moves changes. "
           "**Camera**: "
           "from the scene's camera, walking forward (the view direction, horizontal) at "
        << formatNumber(o.cameraSpeed, 3) << " m/s and turning left at " << formatNumber(o.yawRateDeg, 3)
        << "°/s (" << formatNumber(perFrameCm, 3) << " cm and " << formatNumber(perFrameDeg, 3)
        << "° per frame)";
    if (froxel)
        out << ". **Light**: the camera still, light " << o.light << " of the scene moving at "
            << formatNumber(o.lightSpeed, 3)
            << " m/s along the camera's right (across the view). **Switched off**: the camera still, light "
            << o.light << " switched off at frame " << o.warmup << " (below)";
    out << ". The error is the relative RMSE of each frame; *mean (max)* over the measured frames. GPU time: "
           "the still camera's, measured as the sweep's (median), temporal passes included. Every frame's "
           "numbers are in [motion.csv](motion.csv).";
    if (!mi.referenceSeconds.empty()) {
        out << " CPU references:";
        for (size_t i = 0; i < mi.referenceSeconds.size(); ++i)
            out << (i ? "," : "") << " " << mi.referenceSeconds[i].first << " "
                << formatNumber(mi.referenceSeconds[i].second, 3) << " s";
        out << ".";
    }
    out << "\n\n";
    return out.str();
}

}  // namespace

MotionTarget motionTarget(const RunInfo& info, const std::vector<Result>& results,
                          const std::vector<MotionResult>& motion) {
    MotionTarget t;
    (void)results;
    t.motion = find(motion, info.presetScene, "medium", true, MotionKind::Camera);
    // Temporal off: the sweep's preset=medium row now accumulates (the presets turn temporal on).
    t.still = find(motion, info.presetScene, "medium", false, MotionKind::Camera);
    if (t.motion && t.still) t.ratio = t.motion->meanError() / t.still->still[2].relativeRmse;
    return t;
}

std::vector<TemporalPays> temporalPays(const RunInfo& info, const std::vector<MotionResult>& motion) {
    const std::vector<std::string> scenes = motionScenes(motion);
    std::vector<TemporalPays> out;
    for (const std::string& preset : presetOrder(motion)) {
        TemporalPays p;
        p.preset = preset;
        const MotionResult* off = find(motion, info.presetScene, preset, false, MotionKind::Camera);
        const MotionResult* on = find(motion, info.presetScene, preset, true, MotionKind::Camera);
        if (off) p.offMs = off->timing.median;
        if (on) p.onMs = on->timing.median, p.temporalMs = on->temporalMs();
        double sumOff = 0, sumOn = 0;
        size_t n = 0;
        for (const std::string& scene : scenes) {
            const MotionResult* a = find(motion, scene, preset, false, MotionKind::Camera);
            const MotionResult* b = find(motion, scene, preset, true, MotionKind::Camera);
            if (!a || !b) continue;
            sumOff += a->meanError();
            sumOn += b->meanError();
            ++n;
        }
        if (n) p.offError = sumOff / double(n), p.onError = sumOn / double(n);
        out.push_back(p);
    }
    for (TemporalPays& p : out) {
        for (const TemporalPays& q : out)
            if (q.offError <= p.onError && (p.cheapestOff.empty() || q.offMs < p.cheapestOffMs))
                p.cheapestOff = q.preset, p.cheapestOffMs = q.offMs;
        p.pays = p.onError < p.offError && !(p.cheapestOffMs < p.onMs);
    }
    return out;
}

const std::vector<std::string>& motionCsvColumns() {
    static const std::vector<std::string> columns = joinColumns(
        {{"scene",       "method",        "setting",       "preset",      "temporal", "blend_weight",
          "motion",      "frame",         "gpu_ms_median", "temporal_ms", "rel_rmse", "max_abs",
          "frac_off",    "non_finite",    "rel_rmse_16",   "remaining",   "leftover", "shadow_matrix_changes",
          "tm_rel_rmse", "tm_rel_rmse_16"},
         calibrationColumns()});
    return columns;
}

bool writeMotionCsv(const std::string& path, const RunInfo& info, const MotionInfo& mi,
                    const std::vector<MotionResult>& motion, const std::vector<SwitchOffResult>& switchOff,
                    std::string& error) {
    std::ostringstream out;
    const MotionOptions& o = mi.options;
    std::ostringstream extra;
    extra
        << "# motion: warm-up " << o.warmup << " frames, measured frames " << framesText(o) << ", "
        << formatNumber(1.0 / o.frameSeconds, 3) << " frames/s; camera " << formatNumber(o.cameraSpeed, 3)
        << " m/s forward, yaw " << formatNumber(o.yawRateDeg, 3) << " deg/s; light " << o.light << " at "
        << formatNumber(o.lightSpeed, 3) << " m/s; references every " << mi.errorStride << "th pixel, "
        << mi.referenceSteps << " steps\n"
        << "# rows: motion=still (the still camera: gpu_ms_median and its calibration, rel_rmse of one frame "
           "and rel_rmse_16 of the mean of 16, tm_rel_rmse and tm_rel_rmse_16 tonemapped), camera or light "
           "(one row per measured frame), switch_off and "
           "switch_off_control and never_lit (frame: frames since the switch-off, -1 the last lit; "
           "remaining, "
           "leftover)\n";
    writeCsvPreamble(out, "postfx-bench in motion", info, extra.str(), motionCsvColumns());
    auto base = [&](const Setting& s, bool temporal, float blend) {
        return std::vector<std::string>{
            s.scene,  methodName(s.method), s.label(),
            s.preset, temporal ? "1" : "0", temporal ? formatNumber(blend, 4) : ""};
    };
    auto errorCells = [](std::vector<std::string>& row, const ErrorStats& e) {
        row.push_back(formatNumber(e.relativeRmse, 6));
        row.push_back(formatNumber(e.maxAbsError, 6));
        row.push_back(formatNumber(e.fractionOff, 6));
        row.push_back(std::to_string(e.nonFinite));
    };
    for (const MotionResult& m : motion) {
        std::vector<std::string> still = base(m.setting, m.temporal, m.blendWeight);
        still.insert(still.end(),
                     {"still", "", formatNumber(m.timing.median, 5), formatNumber(m.temporalMs(), 5)});
        errorCells(still, m.still[0]);
        still.insert(still.end(), {formatNumber(m.still[2].relativeRmse, 6), "", "", "",
                                   formatNumber(m.still[0].tonemappedRmse, 6),
                                   formatNumber(m.still[2].tonemappedRmse, 6)});
        appendCalibrationCells(still, m.timing.calibration);
        writeCsvRow(out, still);
        for (size_t k = 0; k < m.frames.size() && k < m.errors.size(); ++k) {
            std::vector<std::string> row = base(m.setting, m.temporal, m.blendWeight);
            row.insert(row.end(), {motionKindName(m.kind), std::to_string(m.frames[k]), "", ""});
            errorCells(row, m.errors[k]);
            row.insert(row.end(), {"", "", "", std::to_string(m.shadowMatrixChanges),
                                   formatNumber(m.errors[k].tonemappedRmse, 6), ""});
            row.resize(motionCsvColumns().size());  // no calibration: not a timed row
            writeCsvRow(out, row);
        }
    }
    for (const SwitchOffResult& s : switchOff) {
        for (int control = 0; control < 3; ++control) {
            const std::vector<double>& values = control == 2 ? s.neverLitRemaining
                                                : control    ? s.controlRemaining
                                                             : s.remaining;
            for (size_t k = 0; k <= values.size(); ++k) {
                // k = 0: frame F - 1 (lit; the control has no row), then F + k - 1.
                if (control && k == 0) continue;
                const double remaining = k == 0 ? s.lastLitRemaining : values[k - 1];
                const double leftover = control ? NAN : k == 0 ? s.lastLitLeftover : s.leftover[k - 1];
                std::vector<std::string> row = base(s.setting, s.temporal, s.blendWeight);
                const char* kind = control == 2 ? "never_lit" : control ? "switch_off_control" : "switch_off";
                row.insert(row.end(), {kind, std::to_string(int(k) - 1), "", ""});
                row.insert(row.end(), {"", "", "", "", ""});
                row.push_back(formatNumber(remaining, 6));
                row.push_back(formatNumber(leftover, 6));
                row.resize(motionCsvColumns().size());
                writeCsvRow(out, row);
            }
        }
    }
    return writeTextFile(path, out.str(), error);
}

std::string motionMarkdown(const RunInfo& info, const MotionInfo& mi, const std::vector<Result>& results,
                           const std::vector<MotionResult>& motion) {
    if (motion.empty()) return "";
    std::ostringstream out;
    out << "## In motion\n\n"
        << "The quality presets with the temporal pass off and on (`fog.temporal`, blend weight "
        << formatNumber(mi.options.temporalBlend > 0.0f ? mi.options.temporalBlend
                                                        : postfx::FogSettings{}.temporal.blendWeight,
                        3)
        << (mi.options.temporalBlend > 0.0f ? " by --temporal-blend" : ", the default")
        << ") while the camera moves. " << header(mi, false);

    const MotionTarget t = motionTarget(info, results, motion);
    out << "### Target\n\n| target | measured in this run | status |\n|---|---|---|\n"
        << "| at the Medium preset, the in-motion error with temporal on within "
        << formatNumber(kMotionTargetRatio, 3) << "× the still camera's 16-frame error (" << info.presetScene
        << ") | ";
    if (t.motion && t.still) {
        out << "in motion, temporal on: " << meanMax(t.motion)
            << "; still, mean of 16 frames (temporal off): " << percent(t.still->still[2].relativeRmse)
            << "; ratio **" << formatNumber(t.ratio, 3) << "×** | " << (t.met() ? "**PASS**" : "**MISS**")
            << " (" << formatNumber(t.ratio, 3) << "× " << (t.met() ? "≤ " : "> ")
            << formatNumber(kMotionTargetRatio, 3) << "×) |\n\n";
    } else {
        out << "not measured (the preset scene's Medium preset in motion with temporal on, and its still "
               "row) | – "
               "|\n\n";
    }

    const std::vector<TemporalPays> pays = temporalPays(info, motion);
    out << "### Where the temporal pass pays\n\n"
        << "GPU time on " << info.presetScene << " (the presets' scene), in-motion error averaged over the "
        << motionScenes(motion).size()
        << " scenes below. The temporal pass pays at a preset when it lowers the in-motion error and no "
           "preset "
           "without it reaches that error in less time (the cheapest such preset is named).\n\n"
        << "| preset | GPU ms, temporal off | on | fog.temporal pass | in-motion error, off | on | change | "
           "cheapest preset off at ≤ that error | its GPU ms | pays |\n"
        << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const TemporalPays& p : pays)
        out << "| " << p.preset << " | " << ms(p.offMs) << " | " << ms(p.onMs) << " | " << ms(p.temporalMs)
            << " | " << percent(p.offError) << " | " << percent(p.onError) << " | "
            << (std::isfinite(p.onError / p.offError)
                    ? (p.onError > p.offError ? "+" : "") +
                          formatNumber((p.onError / p.offError - 1.0) * 100.0, 3) + "%"
                    : "–")
            << " | " << orDash(p.cheapestOff) << " | " << ms(p.cheapestOffMs) << " | "
            << (p.pays ? "yes" : "no") << " |\n";
    out << "\n";

    out << "### Per scene\n\n"
        << "| scene | preset | GPU ms, temporal off / on (fog.temporal) | still, temporal off: 1 frame / "
           "mean of 16 | "
           "still, temporal on: 1 frame | in motion, temporal off: mean (max) | temporal on: mean (max) | on "
           "/ "
           "still 16 | shadow map moved |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    for (const std::string& scene : motionScenes(motion)) {
        for (const std::string& preset : presetOrder(motion)) {
            const MotionResult* off = find(motion, scene, preset, false, MotionKind::Camera);
            const MotionResult* on = find(motion, scene, preset, true, MotionKind::Camera);
            const MotionResult* any = off ? off : on;
            if (!any) continue;
            out << "| " << scene << " | " << preset << " | " << (off ? ms(off->timing.median) : "–") << " / "
                << (on ? ms(on->timing.median) : "–") << " (" << (on ? ms(on->temporalMs()) : "–") << ") | "
                << (off ? percent(off->still[0].relativeRmse) + " / " + percent(off->still[2].relativeRmse)
                        : "–")
                << " | " << (on ? percent(on->still[0].relativeRmse) : "–") << " | " << meanMax(off) << " | "
                << meanMax(on) << " | "
                << (on && off ? orDash(formatNumber(on->meanError() / off->still[2].relativeRmse, 3)) + "×"
                              : "–")
                << " | "
                << (any->shadowMatrixChanges ? std::to_string(any->shadowMatrixChanges) + " frames" : "no")
                << " |\n";
        }
    }
    out << "\n";
    return out.str();
}

std::string froxelMotionMarkdown(const RunInfo& info, const MotionInfo& mi,
                                 const std::vector<MotionResult>& motion,
                                 const std::vector<SwitchOffResult>& switchOff) {
    (void)info;
    if (motion.empty() && switchOff.empty()) return "";
    std::ostringstream out;
    out << "## In motion\n\n"
        << "The froxel fog at the grid of the light-count sweep with its temporal accumulation off and on "
           "(on is "
           "the default; blend weight "
        << (mi.options.temporalBlend > 0.0f
                ? formatNumber(mi.options.temporalBlend, 3) + " by --temporal-blend"
                : std::string("as the scene has it"))
        << "). " << header(mi, true);
    out << "| scene | motion | setting | temporal | GPU ms | still: 1 frame / mean of 16 | in motion: mean "
           "(max) | "
           "per frame | shadow map moved |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    for (const MotionResult& m : motion) {
        std::string frames;
        for (size_t k = 0; k < m.errors.size(); ++k)
            frames += (k ? " " : "") + percent(m.errors[k].relativeRmse);
        out << "| " << m.setting.scene << " | " << motionKindName(m.kind) << " | " << m.setting.label()
            << " | " << (m.temporal ? "on (" + formatNumber(m.blendWeight, 3) + ")" : "off") << " | "
            << ms(m.timing.median) << " | " << percent(m.still[0].relativeRmse) << " / "
            << percent(m.still[2].relativeRmse) << " | " << meanMax(&m) << " | " << frames << " | "
            << (m.shadowMatrixChanges ? std::to_string(m.shadowMatrixChanges) + " frames" : "no") << " |\n";
    }
    out << "\n";
    if (switchOff.empty()) return out.str();

    const SwitchOffResult& first = switchOff.front();
    out << "### A light switched off\n\n"
        << first.setting.scene << ", light " << first.light
        << ", the camera still: the light is on for frames 0 .. " << first.offFrame - 1
        << " and off from frame " << first.offFrame << " (F) on. Over the RGB of the " << first.touchedPixels
        << " compared pixels it touches (it adds more than " << formatNumber(kTouchedTolerance * 100.0, 3)
        << "% of the pixel in the references), per frame F + n:\n\n"
        << "- *leftover*: Σ|image − control| / Σ|reference with the light − reference without it|, the "
           "control "
           "being the same sequence with the light dimmed to "
        << formatNumber(kControlDim, 3)
        << " of its intensity before F (on for postfx, invisible) and switched off at F too: postfx rejects "
           "the "
           "same history in the same frames and both sequences share every jitter offset, so the two frames "
           "differ by the light's light alone. The target is read on it.\n"
        << "- *remaining*: Σ|image − reference without the light| / the same denominator (the issue's "
           "wording), "
           "and the control's: they include the fog's own error against the reference (the control's is that "
           "error alone, a floor the remaining contribution does not go below).\n"
        << "- *never lit*: the remaining of a sequence with the light never on: no history is rejected "
           "there, "
           "so it is the error a settled history has; the control's remaining above it is what restarting "
           "the "
           "rejected history costs in noise.\n\n"
        << "*Settled*: the first n from which every measured frame is below "
        << formatNumber(kSwitchOffRemaining * 100.0, 3)
        << "%; F − 1 is the last frame with the light on.\n\n";
    const size_t n = first.remaining.size();
    out << "| temporal | measure | F − 1 (lit) |";
    for (size_t k = 0; k < n; ++k)
        out << " F" << (k ? " + " + std::to_string(k) : "") << " |";
    out << " settled after |\n|---|---|---|";
    for (size_t k = 0; k < n; ++k)
        out << "---|";
    out << "---|\n";
    auto series = [&](const SwitchOffResult& s, const char* name, const std::vector<double>& v, double lit) {
        out << "| " << (s.temporal ? "on (" + formatNumber(s.blendWeight, 3) + ")" : "off") << " | " << name
            << " | " << percent(lit) << " |";
        for (size_t k = 0; k < n; ++k)
            out << " " << (k < v.size() ? percent(v[k]) : "–") << " |";
        const size_t settled = settledAfter(v, kSwitchOffRemaining);
        out << " "
            << (settled < v.size() ? std::to_string(settled) + " frames"
                                   : "not within " + std::to_string(v.size()))
            << " |\n";
    };
    for (const SwitchOffResult& s : switchOff) {
        series(s, "leftover", s.leftover, s.lastLitLeftover);
        series(s, "remaining", s.remaining, s.lastLitRemaining);
        series(s, "control's remaining", s.controlRemaining, NAN);
        series(s, "never lit: remaining", s.neverLitRemaining, NAN);
    }
    out << "\n### Target\n\n| target | measured in this run | status |\n|---|---|---|\n";
    for (const SwitchOffResult& s : switchOff) {
        if (!s.temporal) continue;
        const size_t settled = settledAfter(s.leftover, kSwitchOffRemaining);
        const bool met = settled <= kSwitchOffFrames && settled < s.leftover.size();
        out << "| a light switched off leaves less than " << formatNumber(kSwitchOffRemaining * 100.0, 3)
            << "% of its fog contribution after at most " << kSwitchOffFrames << " frames (temporal on, "
            << s.setting.scene << ") | leftover below " << formatNumber(kSwitchOffRemaining * 100.0, 3)
            << "% from F + "
            << (settled < s.leftover.size() ? std::to_string(settled)
                                            : "– (never within " + std::to_string(s.leftover.size()) + ")")
            << " on (F: " << (s.leftover.empty() ? "–" : percent(s.leftover.front())) << ") | "
            << (met ? "**PASS**" : "**MISS**") << " |\n";
    }
    out << "\n";
    return out.str();
}

std::string motionSummary(const RunInfo& info, const std::vector<Result>& results,
                          const std::vector<MotionResult>& motion,
                          const std::vector<SwitchOffResult>& switchOff) {
    std::ostringstream out;
    const MotionTarget t = motionTarget(info, results, motion);
    if (t.motion && t.still)
        out << "in motion: medium, temporal on " << percent(t.motion->meanError())
            << " against still 16 frames " << percent(t.still->still[2].relativeRmse) << ": "
            << formatNumber(t.ratio, 3) << "x " << (t.met() ? "PASS" : "MISS") << "\n";
    for (const TemporalPays& p : temporalPays(info, motion))
        out << "  temporal at " << p.preset << ": " << percent(p.offError) << " -> " << percent(p.onError)
            << ", +" << formatNumber(p.onMs - p.offMs, 3) << " ms" << (p.pays ? " (pays)" : "") << "\n";
    for (const MotionResult& m : motion)
        if (m.setting.preset.empty())
            out << "in motion: " << m.setting.scene << " " << motionKindName(m.kind) << " temporal "
                << (m.temporal ? "on" : "off") << ": " << percent(m.meanError()) << " (max "
                << percent(m.maxError()) << ")\n";
    for (const SwitchOffResult& s : switchOff) {
        const size_t settled = settledAfter(s.leftover, kSwitchOffRemaining);
        out << "switched-off light, temporal " << (s.temporal ? "on" : "off") << ": leftover";
        for (double v : s.leftover)
            out << " " << percent(v);
        out << "; below 1% from frame "
            << (settled < s.remaining.size() ? std::to_string(settled) : std::string("(never)")) << "\n";
    }
    return out.str();
}

}  // namespace bench
