// The proposed presets and the targets' status, from the run's rows.
#include "conclusions.h"

#include "report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bench {
namespace {

std::string ms(double value) {
    return std::isfinite(value) ? formatNumber(value, 4) + " ms" : "–";
}

bool isSweep(const Result& r, const std::string& scene, uint32_t noiseSize) {
    return r.setting.scene == scene && r.setting.method == Method::Ours && r.setting.preset.empty() &&
           r.setting.noiseSize == noiseSize;
}

const Result* committedPreset(const std::vector<Result>& results, const std::string& scene,
                              const std::string& name) {
    for (const Result& r : results)
        if (r.setting.scene == scene && r.setting.preset == name) return &r;
    return nullptr;
}

// The sweep row of `scene` (at its own noise size) with the knobs of `row`, if the run measured it; the
// shadow kernel only counts where both frames have a shadow map.
const Result* sameKnobs(const RunInfo& info, const std::vector<Result>& results, const std::string& scene,
                        const Result& row) {
    for (const Result& r : results)
        if (isSweep(r, scene, sceneNoiseSize(info, scene)) && r.setting.steps == row.setting.steps &&
            r.setting.jitter == row.setting.jitter &&
            r.setting.resolutionScale == row.setting.resolutionScale &&
            (r.setting.shadowKernel == row.setting.shadowKernel || !r.setting.shadowKernel ||
             !row.setting.shadowKernel))
            return &r;
    return nullptr;
}

// The mean over `scenes` of the 16-frame relative RMSE of the row `rowOf(scene)`; NaN when a scene has
// no such row (or no scenes): the proposal's error and the committed presets' column alike.
template <class RowOf>
double meanError16(const std::vector<std::string>& scenes, RowOf rowOf) {
    if (scenes.empty()) return NAN;
    double sum = 0.0;
    for (const std::string& s : scenes) {
        const Result* r = rowOf(s);
        if (!r) return NAN;
        sum += r->error[2].relativeRmse;
    }
    return sum / double(scenes.size());
}

std::string errors(const Result& r) {
    return percent(r.error[0].relativeRmse) + " / " + percent(r.error[1].relativeRmse) + " / " +
           percent(r.error[2].relativeRmse);
}

std::string overFloor(const Result& r) {
    return std::isfinite(r.floorMs) ? formatNumber(r.timing.median / r.floorMs, 3) + "×" : "–";
}

// "met" / "missed by 7%" / "missed: 6.2× the limit" for `value` against an upper `limit`.
std::string atMost(double value, double limit) {
    if (!std::isfinite(value)) return "–";
    if (value <= limit) return "**met**";
    if (value < 2.0 * limit) return "**missed** by " + percentOver(value, limit) + "%";
    return "**missed**: " + formatNumber(value / limit, 3) + "× the limit";
}

struct Speedup {
    const Result* ours = nullptr;
    const Result* baseline = nullptr;
    double factor = NAN;  // baseline time / ours
};

Speedup speedupAt(const RunInfo& info, const std::vector<Result>& results, const std::string& scene,
                  size_t errorIndex) {
    const uint32_t noise = sceneNoiseSize(info, scene);
    Speedup s;
    s.ours = fastestWithin(results, scene, Method::Ours, noise, errorIndex, kTargetRelativeRmse);
    s.baseline =
        fastestWithin(results, scene, Method::SeedFixedRiemann, noise, errorIndex, kTargetRelativeRmse);
    if (s.ours && s.baseline) s.factor = s.baseline->timing.median / s.ours->timing.median;
    return s;
}

std::string speedupText(const Speedup& s, size_t errorIndex) {
    const size_t e = errorIndex;
    std::string text =
        "postfx-fog: " + (s.ours ? "`" + s.ours->setting.label() + "` " + ms(s.ours->timing.median) + " (" +
                                       percent(s.ours->error[e].relativeRmse) + ")"
                                 : "no setting reaches " + percent(kTargetRelativeRmse));
    text += "; seed-fixed-riemann: " +
            (s.baseline ? "`" + s.baseline->setting.label() + "` " + ms(s.baseline->timing.median) + " (" +
                              percent(s.baseline->error[e].relativeRmse) + ")"
                        : "no step length reaches " + percent(kTargetRelativeRmse));
    if (std::isfinite(s.factor)) text += ": **" + formatNumber(s.factor, 3) + "×**";
    return text;
}

std::string speedupStatus(const Speedup& s, bool baselinesRun) {
    if (!baselinesRun) return "not measured (baselines not run)";
    if (!s.ours)
        return "**missed**: postfx-fog does not reach " + percent(kTargetRelativeRmse) + " in the sweep";
    if (!s.baseline)
        return "**met**: the baseline does not reach " + percent(kTargetRelativeRmse) +
               " at any measured step length";
    return s.factor >= kTargetSpeedup ? "**met**" : "**missed**";
}

}  // namespace

std::vector<PresetBudget> defaultPresetBudgets() {
    return {{"low", 0.25}, {"medium", kTargetDefaultMs}, {"high", 1.0}, {"ultra", 2.0}};
}

std::vector<std::string> proposalScenes(const RunInfo& info) {
    std::vector<std::string> scenes;
    for (const auto& [name, noise] : info.sceneNoise) {
        const size_t n = std::string_view(kUnskippedSuffix).size();
        const bool twin = name.size() > n && name.compare(name.size() - n, n, kUnskippedSuffix) == 0 &&
                          std::any_of(info.sceneNoise.begin(), info.sceneNoise.end(), [&](const auto& other) {
                              return other.first == name.substr(0, name.size() - n);
                          });
        if (!twin) scenes.push_back(name);
    }
    return scenes;
}

std::vector<ProposedPreset> proposePresets(const RunInfo& info, const std::vector<Result>& results) {
    const std::string& scene = info.presetScene;
    const uint32_t noiseSize = sceneNoiseSize(info, scene);
    const std::vector<std::string> scenes = proposalScenes(info);
    // Each eligible row of the preset scene with its mean 16-frame error over the scenes.
    std::vector<std::pair<const Result*, double>> candidates;
    for (const Result& r : results) {
        if (!isSweep(r, scene, noiseSize) || !r.setting.jitter || !std::isfinite(r.timing.median)) continue;
        const double mean = meanError16(
            scenes, [&](const std::string& s) { return s == scene ? &r : sameKnobs(info, results, s, r); });
        if (std::isfinite(mean)) candidates.emplace_back(&r, mean);
    }
    std::vector<ProposedPreset> proposed;
    for (const PresetBudget& budget : info.presetBudgets) {
        ProposedPreset p;
        p.budget = budget;
        for (const auto& [row, mean] : candidates) {
            if (row->timing.median > budget.ms) continue;
            if (!p.row || mean < p.meanError16 ||
                (mean == p.meanError16 && row->timing.median < p.row->timing.median)) {
                p.row = row;
                p.meanError16 = mean;
            }
        }
        proposed.push_back(p);
    }
    return proposed;
}

const Result* fastestWithin(const std::vector<Result>& results, const std::string& scene, Method method,
                            uint32_t noiseSize, size_t errorIndex, double maxError) {
    const Result* best = nullptr;
    for (const Result& r : results) {
        if (r.setting.scene != scene || r.setting.method != method || r.setting.noiseSize != noiseSize ||
            (method == Method::Ours && !r.setting.preset.empty()) || !std::isfinite(r.timing.median) ||
            !(r.error[errorIndex].relativeRmse <= maxError))
            continue;
        if (!best || r.timing.median < best->timing.median) best = &r;
    }
    return best;
}

std::string conclusionsMarkdown(const RunInfo& info, const std::vector<Result>& results) {
    const std::string& scene = info.presetScene;
    const uint32_t noise = sceneNoiseSize(info, scene);
    const std::string noiseText = noise ? "noise " + std::to_string(noise) + "³" : "no noise";
    std::ostringstream out;
    const std::vector<std::string> scenes = proposalScenes(info);
    std::string sceneList;
    for (size_t i = 0; i < scenes.size(); ++i)
        sceneList += (i ? ", " : "") + scenes[i];
    out << "## Presets proposed by this run\n\n"
        << "Rule (docs/accuracy-cost/README.md, Presets): per preset, among " << scene
        << "'s postfx-fog sweep points at its own " << noiseText
        << " with jitter on whose median GPU time on " << scene
        << " is within the preset's budget, the one whose knobs (steps, scale, shadow kernel) give the "
           "lowest "
           "relative RMSE after 16 frames averaged over "
        << sceneList
        << " (each at its own noise size). `kQualityPresets` (postfx/src/fog/fog_settings.cpp) holds the "
           "committed presets, measured as such in the `preset=` rows.\n\n"
        << "| preset | budget | proposed | GPU ms | rel. RMSE 1 / 8 / 16 frames | × floor | 16 frames, mean "
           "of the scenes | committed | its GPU ms | its rel. RMSE 1 / 8 / 16 | its 16 frames, mean of the "
           "scenes |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    const std::vector<ProposedPreset> proposed = proposePresets(info, results);
    for (const ProposedPreset& p : proposed) {
        const Result* committed = committedPreset(results, scene, p.budget.name);
        // The committed preset's rows on every scene of the rule (measured as the host selects it).
        const double committedMean = meanError16(
            scenes, [&](const std::string& s) { return committedPreset(results, s, p.budget.name); });
        out << "| " << p.budget.name << " | " << ms(p.budget.ms) << " | "
            << (p.row ? "`" + p.row->setting.label() + "`" : "none fits") << " | "
            << (p.row ? ms(p.row->timing.median) : "–") << " | " << (p.row ? errors(*p.row) : "–") << " | "
            << (p.row ? overFloor(*p.row) : "–") << " | " << (p.row ? percent(p.meanError16) : "–") << " | "
            << (committed ? "`" + committed->setting.label() + "`" : "not measured") << " | "
            << (committed ? ms(committed->timing.median) : "–") << " | "
            << (committed ? errors(*committed) : "–") << " | " << percent(committedMean) << " |\n";
    }
    out << "\n";

    // The proposed knobs on the other scenes (each at its own noise size).
    bool header = false;
    for (const std::string& other : sceneOrder(results)) {
        if (other == scene) continue;
        for (const ProposedPreset& p : proposed) {
            const Result* r = p.row ? sameKnobs(info, results, other, *p.row) : nullptr;
            if (!r) continue;
            if (!header) {
                out << "The proposed knobs on the other scenes:\n\n"
                    << "| scene | preset | setting | GPU ms | rel. RMSE 1 / 8 / 16 frames "
                       "|\n|---|---|---|---|---|\n";
                header = true;
            }
            out << "| " << other << " | " << p.budget.name << " | `" << r->setting.label() << "` | "
                << ms(r->timing.median) << " | " << errors(*r) << " |\n";
        }
    }
    if (header) out << "\n";

    out << "## Targets\n\n"
        << "The issue's targets are set for the NVIDIA H100 at 1920×1080 on " << scene
        << "; this run: " << info.device << ", " << info.width << "×" << info.height << ".";
    if (info.width != 1920 || info.height != 1080)
        out << " **Not 1920×1080: the statuses below are not the targets'.**";
    out << "\n\n| target | measured in this run | status |\n|---|---|---|\n";

    const Result* committedMedium = committedPreset(results, scene, "medium");
    const Result* proposedMedium = nullptr;
    for (const ProposedPreset& p : proposed)
        if (p.budget.name == "medium") proposedMedium = p.row;
    out << "| default (Medium) preset ≤ " << formatNumber(kTargetDefaultMs, 3) << " ms, all fog passes | "
        << "committed: "
        << (committedMedium
                ? "`" + committedMedium->setting.label() + "` " + ms(committedMedium->timing.median)
                : "not measured (--no-presets)")
        << "; proposed: "
        << (proposedMedium ? "`" + proposedMedium->setting.label() + "` " + ms(proposedMedium->timing.median)
                           : "none fits")
        << " | committed: "
        << atMost(committedMedium ? committedMedium->timing.median : NAN, kTargetDefaultMs)
        << "; proposed: " << atMost(proposedMedium ? proposedMedium->timing.median : NAN, kTargetDefaultMs)
        << " |\n";

    for (size_t e : {size_t(0), size_t(2)}) {
        const Speedup s = speedupAt(info, results, scene, e);
        out << "| to reach " << percent(kTargetRelativeRmse) << " relative RMSE ("
            << (e == 0 ? "one frame" : "mean of 16 frames") << "), our fastest ≥ "
            << formatNumber(kTargetSpeedup, 3) << "× faster than baseline (b) | " << speedupText(s, e)
            << " | " << speedupStatus(s, info.baselines) << " |\n";
    }

    double lo = INFINITY, hi = -INFINITY;
    for (const Result& r : results)
        if (isSweep(r, scene, noise) && std::isfinite(r.timing.median / r.floorMs)) {
            lo = std::min(lo, r.timing.median / r.floorMs);
            hi = std::max(hi, r.timing.median / r.floorMs);
        }
    out << "| texture-fetch floor computed, our time as a multiple of it | ";
    if (std::isfinite(lo)) {
        out << "committed Medium: " << (committedMedium ? overFloor(*committedMedium) : "–")
            << "; proposed Medium: " << (proposedMedium ? overFloor(*proposedMedium) : "–")
            << "; every sweep point at " << noiseText << ": " << formatNumber(lo, 3) << "–"
            << formatNumber(hi, 3) << "× | **computed** |\n";
    } else {
        out << "no texture rate given (--texture-rate) | not computed |\n";
    }
    out << "\n";

    // The 2% comparison on every scene.
    if (info.baselines) {
        out << "Speed-up at " << percent(kTargetRelativeRmse)
            << " relative RMSE over seed-fixed-riemann on every scene (fastest setting of each that reaches "
               "it):\n\n| scene | one frame | mean of 16 frames |\n|---|---|---|\n";
        for (const std::string& s : sceneOrder(results)) {
            out << "| " << s;
            for (size_t e : {size_t(0), size_t(2)}) {
                const Speedup sp = speedupAt(info, results, s, e);
                out << " | "
                    << (std::isfinite(sp.factor) ? formatNumber(sp.factor, 3) + "×"
                        : !sp.ours               ? "postfx-fog does not reach it"
                                                 : "baseline does not reach it");
            }
            out << " |\n";
        }
        out << "\n";
    }
    out << skippingMarkdown(info, results);
    return out.str();
}

std::string skippingMarkdown(const RunInfo& info, const std::vector<Result>& results) {
    std::ostringstream out;
    const std::vector<std::string> scenes = sceneOrder(results);
    for (const std::string& skipped : scenes) {
        const std::string unskipped = skipped + kUnskippedSuffix;
        if (std::find(scenes.begin(), scenes.end(), unskipped) == scenes.end()) continue;
        out << "## Empty-space skipping: " << skipped << " against " << unskipped << "\n\n"
            << "The same scene with `skip_empty_space` on and off, every postfx-fog sweep point measured in "
               "both (time change: negative is faster with skipping).\n\n"
            << "| setting | GPU ms skipped / un-skipped | change | rel. RMSE 1 frame skipped / un-skipped | "
               "16 frames skipped / un-skipped |\n|---|---|---|---|---|\n";
        for (const Result& r : results) {
            if (!isSweep(r, skipped, sceneNoiseSize(info, skipped))) continue;
            const Result* u = sameKnobs(info, results, unskipped, r);
            if (!u) continue;
            const double change = r.timing.median / u->timing.median - 1.0;
            out << "| `" << r.setting.label() << "` | " << formatNumber(r.timing.median, 4) << " / "
                << formatNumber(u->timing.median, 4) << " | "
                << (std::isfinite(change) ? (change > 0 ? "+" : "") + formatNumber(change * 100.0, 3) + "%"
                                          : "–")
                << " | " << percent(r.error[0].relativeRmse) << " / " << percent(u->error[0].relativeRmse)
                << " | " << percent(r.error[2].relativeRmse) << " / " << percent(u->error[2].relativeRmse)
                << " |\n";
        }
        out << "\n";
    }
    return out.str();
}

std::string conclusionsSummary(const RunInfo& info, const std::vector<Result>& results) {
    std::ostringstream out;
    const std::string& scene = info.presetScene;
    out << "presets proposed (timed on " << scene
        << ", lowest 16-frame error averaged over the scenes, jitter on):\n";
    for (const ProposedPreset& p : proposePresets(info, results)) {
        out << "  " << p.budget.name << " (<= " << formatNumber(p.budget.ms, 3) << " ms): ";
        if (p.row)
            out << p.row->setting.label() << ", " << formatNumber(p.row->timing.median, 4) << " ms, "
                << formatNumber(p.row->error[0].relativeRmse * 100, 3) << "% / "
                << formatNumber(p.row->error[2].relativeRmse * 100, 3) << "% (1 / 16 frames)\n";
        else
            out << "none fits\n";
    }
    for (size_t e : {size_t(0), size_t(2)}) {
        const Speedup s = speedupAt(info, results, scene, e);
        out << "speed-up at " << percent(kTargetRelativeRmse) << " over seed-fixed-riemann ("
            << (e == 0 ? "one frame" : "16 frames")
            << "): " << (std::isfinite(s.factor) ? formatNumber(s.factor, 3) + "x" : "n/a") << "\n";
    }
    return out.str();
}

}  // namespace bench
