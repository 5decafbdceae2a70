// postfx-bench --froxel's results.csv and results.md, and what they conclude.
#include "froxel_report.h"

#include "report.h"
#include "stats.h"

#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace bench {
namespace {

std::string ms(double value) {
    return std::isfinite(value) ? formatNumber(value, 4) + " ms" : "–";
}

std::string errors(const Result& r) {
    return percent(r.error[0].relativeRmse) + " / " + percent(r.error[1].relativeRmse) + " / " +
           percent(r.error[2].relativeRmse);
}

// A sweep row of the froxel fog (not the light-count sweep) or a ray-marched fog row, of `scene`.
bool onFront(const Result& r, const std::string& scene, Method method) {
    return r.setting.scene == scene && r.setting.method == method && !r.setting.lightSweep &&
           std::isfinite(r.timing.median);
}

// The pass of r with the largest median: "scatter (0.071 ms, 64% of the total)".
std::string dominantPass(const Result& r) {
    const std::pair<std::string, double>* top = nullptr;
    for (const auto& p : r.timing.passMedians)
        if (!top || p.second > top->second) top = &p;
    if (!top) return "";
    double sum = 0;
    for (const auto& p : r.timing.passMedians)
        sum += p.second;
    return shortPass(top->first) + " (" + ms(top->second) + ", " +
           formatNumber(std::round(top->second / sum * 100.0), 3) + "% of the passes' sum)";
}

std::string status(const FroxelTarget& t) {
    if (!t.row || !std::isfinite(t.measured)) return "not measured";
    if (t.met())
        return "**PASS** (" + formatNumber(t.measured, 3) + " " + t.unit + " ≤ " + formatNumber(t.limit, 3) +
               " " + t.unit + ")";
    return "**MISS** by " + percentOver(t.measured, t.limit) + "% (" + formatNumber(t.measured, 3) + " " +
           t.unit + " > " + formatNumber(t.limit, 3) + " " + t.unit + ")";
}

std::string gridText(const postfx::UVec3& g) {
    return std::to_string(g.x) + "×" + std::to_string(g.y) + "×" + std::to_string(g.z);
}

std::string bandwidthText(const RunInfo& info) {
    const auto gbps = [](double v) {
        return std::isfinite(v) ? formatNumber(v, 4) + " GB/s" : std::string("– (no timestamps)");
    };
    return "copies measured by this run (device-local buffers, bytes read + written, after a warm-up): " +
           gbps(info.copyBandwidth) + " by a compute pass (bench/shaders/copy_bandwidth.comp), " +
           gbps(info.transferBandwidth) + " by vkCmdCopyBuffer; the apply pass's floor uses " +
           (std::isfinite(info.bandwidth) ? formatNumber(info.bandwidth, 4) + " GB/s" : std::string("–")) +
           (info.bandwidthGiven ? " (--bandwidth)" : " (the larger measured copy)");
}

std::string lightsText(uint32_t count) {
    return count == postfx::kMaxLocalLights + 1 ? std::to_string(count) + " (never)" : std::to_string(count);
}

// Scenes in the order of their first row, the light-count rows' scene included.
std::vector<const Result*> rowsOf(const std::vector<Result>& results, const std::string& scene,
                                  bool lightSweep) {
    std::vector<const Result*> rows;
    for (const Result& r : results)
        if (r.setting.scene == scene && r.setting.lightSweep == lightSweep) rows.push_back(&r);
    // Froxel first (as measured: grid, slices, distribution, tricubic), then the ray-marched fog by scale
    // and steps.
    std::stable_sort(rows.begin(), rows.end(), [](const Result* a, const Result* b) {
        const Setting &x = a->setting, &y = b->setting;
        const int mx = x.method == Method::Froxel ? 0 : 1, my = y.method == Method::Froxel ? 0 : 1;
        if (mx != my) return mx < my;
        if (mx == 0) return false;
        if (x.resolutionScale != y.resolutionScale) return x.resolutionScale > y.resolutionScale;
        return x.steps < y.steps;
    });
    return rows;
}

std::string rowsTable(const RunInfo& info, const std::vector<const Result*>& rows) {
    std::ostringstream out;
    const double floorMs = applyFloorMs(info.width, info.height, info.bandwidth);
    out << "| method | setting | GPU ms median (p10–p90) | light lists | scatter | integrate | apply | "
           "apply × floor | rel. RMSE 1 / 8 / 16 frames | max abs error (1 frame) | pixels > 1% (1 frame) | "
           "Pareto (1 / 16) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Result* r : rows) {
        const bool froxel = r->setting.method == Method::Froxel;
        out << "| " << methodName(r->setting.method) << " | " << r->setting.label() << " | "
            << orDash(formatNumber(r->timing.median, 4)) << " (" << orDash(formatNumber(r->timing.p10, 3))
            << "–" << orDash(formatNumber(r->timing.p90, 3)) << ") | ";
        for (const char* pass : kFroxelPasses)
            out << (froxel ? orDash(formatNumber(passMs(*r, pass), 3)) : "–") << " | ";
        out << (froxel ? orDash(formatNumber(passMs(*r, "froxel_fog.apply") / floorMs, 3)) : "–") << " | "
            << errors(*r) << " | " << orDash(formatNumber(r->error[0].maxAbsError, 3)) << " | "
            << percent(r->error[0].fractionOff) << " | "
            << (r->setting.lightSweep ? ""
                                      : std::string(r->pareto1 ? "●" : "") + " / " + (r->pareto16 ? "●" : ""))
            << " |\n";
    }
    return out.str();
}

}  // namespace

uint64_t applyFloorBytes(uint32_t width, uint32_t height) {
    return uint64_t(width) * height * (8 + 8 + 4);
}

double applyFloorMs(uint32_t width, uint32_t height, double gbPerSecond) {
    if (!(gbPerSecond > 0)) return NAN;
    return double(applyFloorBytes(width, height)) / (gbPerSecond * 1e9) * 1e3;
}

double passMs(const Result& r, const std::string& name) {
    for (const auto& [pass, value] : r.timing.passMedians)
        if (pass == name) return value;
    return NAN;
}

void markFroxelFronts(std::vector<Result>& results) {
    std::set<std::string> scenes;
    for (const Result& r : results)
        scenes.insert(r.setting.scene);
    for (const std::string& scene : scenes) {
        for (Method method : {Method::Froxel, Method::Ours}) {
            std::vector<size_t> rows;
            std::vector<double> time, error1, error16;
            for (size_t i = 0; i < results.size(); ++i) {
                const Result& r = results[i];
                if (r.setting.scene != scene || r.setting.method != method || r.setting.lightSweep) continue;
                rows.push_back(i);
                time.push_back(r.timing.median);
                error1.push_back(r.error[0].relativeRmse);
                error16.push_back(r.error[2].relativeRmse);
            }
            for (size_t k : paretoFront(time, error1))
                results[rows[k]].pareto1 = true;
            for (size_t k : paretoFront(time, error16))
                results[rows[k]].pareto16 = true;
        }
    }
}

std::vector<LightListPoint> lightListPoints(const std::vector<Result>& results) {
    std::vector<LightListPoint> points;
    for (const Result& r : results) {
        if (!r.setting.lightSweep || r.setting.method != Method::Froxel || r.setting.lights == 0) continue;
        auto it = std::find_if(points.begin(), points.end(),
                               [&](const LightListPoint& p) { return p.lights == r.setting.lights; });
        if (it == points.end()) {
            points.push_back({});
            it = points.end() - 1;
            it->lights = r.setting.lights;
        }
        if (r.setting.lightLists) {
            it->lists = &r;
            const double lists = passMs(r, "froxel_fog.light_lists");
            it->listsMs = (std::isfinite(lists) ? lists : 0.0) + passMs(r, "froxel_fog.scatter");
        } else {
            it->loop = &r;
            it->loopMs = passMs(r, "froxel_fog.scatter");
        }
    }
    std::erase_if(points, [](const LightListPoint& p) { return !p.loop || !p.lists; });
    std::sort(points.begin(), points.end(),
              [](const LightListPoint& a, const LightListPoint& b) { return a.lights < b.lights; });
    return points;
}

uint32_t recommendedLightListMin(const std::vector<LightListPoint>& points) {
    if (points.empty()) return 0;
    uint32_t answer = postfx::kMaxLocalLights + 1;
    // From the largest count down, while the lists are not slower.
    for (auto it = points.rbegin(); it != points.rend(); ++it) {
        if (!(it->listsMs <= it->loopMs)) break;
        answer = it->lights;
    }
    return answer;
}

std::vector<EqualErrorPoint> equalErrorPoints(const std::vector<Result>& results, const std::string& scene,
                                              Method method, Method other, size_t errorIndex) {
    std::vector<const Result*> rows;
    std::vector<double> time, error;
    for (const Result& r : results) {
        if (!onFront(r, scene, method)) continue;
        rows.push_back(&r);
        time.push_back(r.timing.median);
        error.push_back(r.error[errorIndex].relativeRmse);
    }
    std::vector<EqualErrorPoint> points;
    for (size_t k : paretoFront(time, error)) {
        EqualErrorPoint p;
        p.front = rows[k];
        for (const Result& r : results) {
            if (!onFront(r, scene, other) ||
                !(r.error[errorIndex].relativeRmse <= p.front->error[errorIndex].relativeRmse))
                continue;
            if (!p.other || r.timing.median < p.other->timing.median) p.other = &r;
        }
        points.push_back(p);
    }
    return points;
}

const Result* froxelTargetRow(const RunInfo& info, const std::vector<Result>& results) {
    const postfx::UVec3 grid = postfx::FroxelFogSettings{}.grid;
    const bool log = postfx::FroxelFogSettings{}.depthDistribution == postfx::FroxelDepthDistribution::Log;
    for (const Result& r : results) {
        const Setting& s = r.setting;
        if (s.scene == info.froxelTargetScene && s.method == Method::Froxel && !s.lightSweep &&
            s.gridX == grid.x && s.gridY == grid.y && s.gridZ == grid.z && s.logSlices == log && !s.tricubic)
            return &r;
    }
    return nullptr;
}

std::vector<FroxelTarget> froxelTargets(const RunInfo& info, const std::vector<Result>& results) {
    std::vector<FroxelTarget> targets(4);
    const Result* row = froxelTargetRow(info, results);
    targets[0].name = "all passes ≤ " + formatNumber(kFroxelTargetMs, 3) + " ms";
    targets[0].row = row;
    targets[0].measured = row ? row->timing.median : NAN;
    targets[0].limit = kFroxelTargetMs;
    targets[0].unit = "ms";

    const bool lists = kFroxelTargetLights >= info.lightListDefault;
    targets[1].name = "with " + std::to_string(kFroxelTargetLights) + " point lights, all passes ≤ " +
                      formatNumber(kFroxelLightsTargetMs, 3) + " ms";
    for (const Result& r : results)
        if (r.setting.lightSweep && r.setting.method == Method::Froxel &&
            r.setting.scene == info.froxelTargetScene && r.setting.lights == kFroxelTargetLights &&
            r.setting.lightLists == lists)
            targets[1].row = &r;
    targets[1].measured = targets[1].row ? targets[1].row->timing.median : NAN;
    targets[1].limit = kFroxelLightsTargetMs;
    targets[1].unit = "ms";

    targets[2].name =
        "apply pass within " + formatNumber(kApplyFloorTarget, 3) + "× its memory-bandwidth floor";
    targets[2].row = row;
    targets[2].measured =
        row ? passMs(*row, "froxel_fog.apply") / applyFloorMs(info.width, info.height, info.bandwidth) : NAN;
    targets[2].limit = kApplyFloorTarget;
    targets[2].unit = "× floor";

    targets[3].name = "with " + std::to_string(kFroxelTargetLights) + " point lights of which " +
                      std::to_string(kFroxelTargetShadowed) + " shadowed, all passes ≤ " +
                      formatNumber(kFroxelLightsTargetMs, 3) + " ms";
    for (const Result& r : results)
        if (r.setting.shadowSweep && r.setting.scene == info.froxelTargetScene &&
            r.setting.lights == kFroxelTargetLights && r.setting.shadowedLights == kFroxelTargetShadowed)
            targets[3].row = &r;
    targets[3].measured = targets[3].row ? targets[3].row->timing.median : NAN;
    targets[3].limit = kFroxelLightsTargetMs;
    targets[3].unit = "ms";
    return targets;
}

const std::vector<std::string>& froxelCsvColumns() {
    static const std::vector<std::string> columns =
        joinColumns({{"scene", "method", "grid_x", "grid_y", "grid_z", "distribution", "tricubic", "jitter",
                      "lights", "light_lists", "light_sweep", "shadow_sweep", "shadowed_lights", "steps",
                      "resolution_scale", "shadow_kernel", "noise_size"},
                     timingColumns(),
                     {"light_lists_ms", "scatter_ms", "integrate_ms", "apply_ms", "pass_ms"},
                     errorColumns(),
                     {"non_finite", "apply_floor_ms", "apply_over_floor", "pareto_1", "pareto_16"}});
    return columns;
}

bool writeFroxelCsv(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                    std::string& error) {
    std::ostringstream out;
    writeCsvPreamble(out, "postfx-bench --froxel results; columns: docs/accuracy-cost/README.md (Froxel fog)",
                     info, "# bandwidth: " + bandwidthText(info) + "\n", froxelCsvColumns());
    const double floorMs = applyFloorMs(info.width, info.height, info.bandwidth);
    for (const Result& r : results) {
        const Setting& s = r.setting;
        const bool froxel = s.method == Method::Froxel;
        std::string passes;
        for (const auto& [name, value] : r.timing.passMedians)
            passes += (passes.empty() ? "" : ";") + name + "=" + formatNumber(value, 5);
        std::vector<std::string> row = {
            s.scene,
            methodName(s.method),
            froxel ? std::to_string(s.gridX) : "",
            froxel ? std::to_string(s.gridY) : "",
            froxel ? std::to_string(s.gridZ) : "",
            froxel ? (s.logSlices ? "log" : "power") : "",
            froxel ? (s.tricubic ? "1" : "0") : "",
            s.jitter ? "1" : "0",
            std::to_string(s.lights),
            froxel && s.lights ? (s.lightLists ? "1" : "0") : "",
            s.lightSweep ? "1" : "0",
            s.shadowSweep ? "1" : "0",
            std::to_string(s.shadowedLights),
            froxel ? "" : std::to_string(s.steps),
            froxel ? "" : formatNumber(s.resolutionScale, 4),
            std::to_string(s.shadowKernel),
            std::to_string(s.noiseSize),
        };
        appendTimingCells(row, info, r.timing);
        for (const char* pass : kFroxelPasses)
            row.push_back(froxel ? formatNumber(passMs(r, pass), 6) : "");
        row.push_back(passes);
        const uint64_t nonFinite = appendErrorCells(row, r.error);
        row.push_back(std::isfinite(r.error[0].relativeRmse) ? std::to_string(nonFinite) : "");
        row.push_back(froxel ? formatNumber(floorMs, 6) : "");
        row.push_back(froxel ? formatNumber(passMs(r, "froxel_fog.apply") / floorMs, 4) : "");
        row.push_back(s.lightSweep ? "" : (r.pareto1 ? "1" : "0"));
        row.push_back(s.lightSweep ? "" : (r.pareto16 ? "1" : "0"));
        writeCsvRow(out, row);
    }
    return writeTextFile(path, out.str(), error);
}

std::string froxelConclusionsMarkdown(const RunInfo& info, const std::vector<Result>& results) {
    std::ostringstream out;
    const postfx::FroxelFogSettings defaults;
    const double floorMs = applyFloorMs(info.width, info.height, info.bandwidth);
    const double copyFloorMs = applyFloorMs(info.width, info.height, info.copyBandwidth);

    // --- Targets
    out << "## Targets\n\n"
        << "Issue 17's targets are set for the NVIDIA H100 at 1920×1080, on postfx's default grid "
        << gridText(defaults.grid) << " (power slices, trilinear) with sun shadows and noise: here "
        << info.froxelTargetScene << "; this run: " << info.device << ", " << info.width << "×" << info.height
        << ".";
    if (info.width != 1920 || info.height != 1080)
        out << " **Not 1920×1080: the statuses below are not the targets'.**";
    out << "\n\n| target | setting | measured in this run | status | largest pass |\n|---|---|---|---|---|\n";
    for (const FroxelTarget& t : froxelTargets(info, results)) {
        out << "| " << t.name << " | " << (t.row ? "`" + t.row->setting.label() + "`" : "not measured")
            << " | ";
        if (t.row && t.unit == "ms") {
            out << ms(t.measured) << passBreakdown(t.row->timing);
        } else if (t.row) {
            const double apply = passMs(*t.row, "froxel_fog.apply");
            out << "apply " << ms(apply) << " against a floor of " << ms(floorMs) << " ("
                << formatNumber(double(applyFloorBytes(info.width, info.height)) / 1e6, 4) << " MB at "
                << formatNumber(info.bandwidth, 4) << " GB/s): " << formatNumber(t.measured, 3)
                << "×; at the compute copy's measured " << formatNumber(info.copyBandwidth, 4)
                << " GB/s the floor is " << ms(copyFloorMs) << ", " << formatNumber(apply / copyFloorMs, 3)
                << "×";
        }
        out << " | " << status(t) << " | " << (t.row && t.unit == "ms" ? dominantPass(*t.row) : "") << " |\n";
    }
    out << "\n";

    // --- Light lists
    const std::vector<LightListPoint> points = lightListPoints(results);
    std::vector<const Result*> sweep;
    for (const Result& r : results)
        if (r.setting.lightSweep) sweep.push_back(&r);
    if (!sweep.empty()) {
        const Setting& first = sweep.front()->setting;
        out << "## Light lists\n\n"
            << "The light-count sweep on " << info.froxelTargetScene << " (grid "
            << gridText(postfx::UVec3(first.gridX, first.gridY, first.gridZ)) << ", "
            << (first.logSlices ? "log" : "power") << ", " << (first.tricubic ? "tricubic" : "trilinear")
            << ") with generated point lights (bench/froxel_scenes.h: a Vogel spiral "
               "over a disc of 25 m about the camera's look-at point, range 10 m, 0.5–4 m up), timed "
               "only. Without lists (lightListMinLights 257) every froxel loops over every light in the "
               "scatter pass; with them (lightListMinLights 1) the light-list pass bins the lights into "
               "clusters first and each froxel loops over its cluster's.\n\n"
            << "| lights | without lists: scatter | all passes | with lists: light_lists + scatter | all "
               "passes | lists / no lists (light work) |\n|---|---|---|---|---|---|\n";
        for (const Result* r : sweep) {
            if (r->setting.lights != 0) continue;
            out << "| 0 | " << ms(passMs(*r, "froxel_fog.scatter")) << " | " << ms(r->timing.median)
                << " | – | – | – |\n";
        }
        for (const LightListPoint& p : points)
            out << "| " << p.lights << " | " << ms(p.loopMs) << " | " << ms(p.loop->timing.median) << " | "
                << ms(passMs(*p.lists, "froxel_fog.light_lists")) << " + "
                << ms(passMs(*p.lists, "froxel_fog.scatter")) << " = " << ms(p.listsMs) << " | "
                << ms(p.lists->timing.median) << " | " << formatNumber(p.listsMs / p.loopMs, 3) << "× |\n";
        const uint32_t answer = recommendedLightListMin(points);
        out << "\nRule (docs/accuracy-cost/README.md, Froxel fog): lightListMinLights is the smallest "
               "measured light count from which the lists (their pass and the scatter) are never slower "
               "than the loop over every light. This run: **"
            << (answer ? lightsText(answer) : std::string("no light counts with both rows"))
            << "**; this build's default: " << info.lightListDefault << ".\n\n";
    }

    // --- Local light shadows: the shadow sweep
    std::vector<const Result*> shadowRows;
    for (const Result& r : results)
        if (r.setting.shadowSweep) shadowRows.push_back(&r);
    if (!shadowRows.empty()) {
        const Result *none = nullptr, *one = nullptr;
        for (const Result* r : shadowRows) {
            if (r->setting.shadowedLights == 0) none = r;
            if (r->setting.shadowedLights == 1) one = r;
        }
        out << "## Local light shadows\n\n"
            << "The light-count sweep's " << shadowRows.front()->setting.lights << " point lights on "
            << info.froxelTargetScene << " (grid "
            << gridText(postfx::UVec3(shadowRows.front()->setting.gridX, shadowRows.front()->setting.gridY,
                                      shadowRows.front()->setting.gridZ))
            << ", light lists as the default decides), the first n of them casting shadows (the demo "
               "renderer's cube maps in one atlas; each shadowed light's faces read in the scatter pass), "
               "timed only. Over none: all passes less the unshadowed row's (the first shadowed light also "
               "switches the scatter pass to its variant with shadows and, with temporal accumulation, adds "
               "the shadow-change pass, one test per block of 2×2×2 froxels); each further light: (all "
               "passes − the 1-shadowed row's) / (n − 1).\n\n"
            << "| shadowed | shadow change | scatter | all passes | over none | each further light "
               "|\n|---|---|---|---|---|---|\n";
        for (const Result* r : shadowRows) {
            const uint32_t n = r->setting.shadowedLights;
            out << "| " << n << " | " << ms(passMs(*r, "froxel_fog.shadow_change")) << " | "
                << ms(passMs(*r, "froxel_fog.scatter")) << " | " << ms(r->timing.median) << " | "
                << (n && none ? ms(r->timing.median - none->timing.median) : std::string("–")) << " | "
                << (n > 1 && one ? ms((r->timing.median - one->timing.median) / double(n - 1))
                                 : std::string("–"))
                << " |\n";
        }
        out << "\n";
    }

    // --- Froxel against ray-marched at equal error
    std::vector<std::string> both;
    for (const std::string& scene : sceneOrder(results)) {
        bool froxel = false, fog = false;
        for (const Result& r : results) {
            froxel = froxel || onFront(r, scene, Method::Froxel);
            fog = fog || onFront(r, scene, Method::Ours);
        }
        if (froxel && fog) both.push_back(scene);
    }
    if (!both.empty()) {
        out << "## Froxel fog against the ray-marched fog at equal error\n\n"
            << "Both against the same CPU reference (the froxel fog's model, 1×1 shadow-map tap; the "
               "ray-marched rows run shadow kernel 1, so the ray-marched fog's reference is the same "
               "image). For each point of one fog's Pareto front (time against error), the cheapest "
               "setting of the other at no more error; speed-up = the other's time / the front point's "
               "(> 1: the front point's fog is faster at that error).\n\n";
        for (const std::string& scene : both) {
            for (size_t e : {size_t(0), size_t(2)}) {
                const char* frames = e == 0 ? "one frame" : "mean of 16 frames";
                out << "### " << scene << ", " << frames << "\n\n"
                    << "| front of | setting | GPU ms | rel. RMSE | cheapest of the other at ≤ that error | "
                       "GPU ms | rel. RMSE | speed-up of the front point "
                       "|\n|---|---|---|---|---|---|---|---|\n";
                int froxelWins = 0, fogWins = 0, froxelPoints = 0, fogPoints = 0;
                for (Method method : {Method::Froxel, Method::Ours}) {
                    const Method other = method == Method::Froxel ? Method::Ours : Method::Froxel;
                    for (const EqualErrorPoint& p : equalErrorPoints(results, scene, method, other, e)) {
                        const bool wins =
                            !p.other || p.other->timing.median >= p.front->timing.median;  // ties: front
                        (method == Method::Froxel ? froxelPoints : fogPoints)++;
                        if (wins) (method == Method::Froxel ? froxelWins : fogWins)++;
                        out << "| " << methodName(method) << " | " << p.front->setting.label() << " | "
                            << formatNumber(p.front->timing.median, 4) << " | "
                            << percent(p.front->error[e].relativeRmse) << " | "
                            << (p.other ? methodName(other) + std::string(" ") + p.other->setting.label()
                                        : std::string("none gets that low"))
                            << " | " << (p.other ? formatNumber(p.other->timing.median, 4) : "–") << " | "
                            << (p.other ? percent(p.other->error[e].relativeRmse) : "–") << " | "
                            << (p.other
                                    ? formatNumber(p.other->timing.median / p.front->timing.median, 3) + "×"
                                    : "∞")
                            << " |\n";
                    }
                }
                out << "\nFroxel front points the ray-marched fog cannot match faster: " << froxelWins
                    << " of " << froxelPoints
                    << "; ray-marched front points the froxel fog cannot match faster: " << fogWins << " of "
                    << fogPoints << ".\n\n";
            }
        }
    }
    return out.str();
}

bool writeFroxelMarkdown(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                         std::string& error, const std::string& sections) {
    std::ostringstream out;
    out << "# Froxel fog: accuracy–cost results\n\n"
        << "Written by `postfx-bench --froxel`; how to run it and what each number means: "
           "`docs/accuracy-cost/README.md` (Froxel fog). Every number is in [results.csv](results.csv).\n\n"
        << "| | |\n|---|---|\n"
        << "| device | " << info.device << " |\n"
        << "| Vulkan | " << info.vulkanApi << " |\n"
        << "| date | " << info.date << " |\n"
        << "| command | `" << info.commandLine << "` |\n"
        << "| image | " << referenceSummary(info) << " |\n"
        << "| GPU time | " << warmupText(info) << ", then the median of " << info.frames
        << " frames (p10–p90), Vulkan timestamps around each pass; a row's time is the sum of its passes "
           "(froxel_fog.* or fog.*) |\n"
        << "| calibration | " << calibrationSummary(info.calibration) << " |\n"
        << "| memory bandwidth | " << bandwidthText(info) << " |\n"
        << "| apply floor | " << info.width << "×" << info.height
        << " × 20 B = " << formatNumber(double(applyFloorBytes(info.width, info.height)) / 1e6, 4)
        << " MB per frame (colour read and written, RGBA16F; depth read, D32; the volume's texels not "
           "counted): "
        << ms(applyFloorMs(info.width, info.height, info.bandwidth)) << " |\n\n";
    if (!info.referenceSeconds.empty()) {
        out << "CPU references:";
        for (size_t i = 0; i < info.referenceSeconds.size(); ++i)
            out << (i ? "," : "") << " " << info.referenceSeconds[i].first << " "
                << formatNumber(info.referenceSeconds[i].second, 3) << " s";
        out << ".\n\n";
    }
    out << froxelConclusionsMarkdown(info, results);
    out << sections;
    for (const std::string& scene : sceneOrder(results)) {
        const std::vector<const Result*> rows = rowsOf(results, scene, false);
        if (!rows.empty()) {
            out << "## " << scene << "\n\n" << rowsTable(info, rows) << "\n";
            for (Method method : {Method::Froxel, Method::Ours}) {
                for (size_t e : {size_t(0), size_t(2)}) {
                    std::vector<const Result*> front;
                    for (const Result* r : rows)
                        if (r->setting.method == method && (e == 0 ? r->pareto1 : r->pareto16))
                            front.push_back(r);
                    if (front.empty()) continue;
                    std::sort(front.begin(), front.end(), [](const Result* a, const Result* b) {
                        return a->timing.median < b->timing.median;
                    });
                    out << "Pareto front of " << methodName(method) << ", "
                        << (e == 0 ? "one frame" : "mean of 16 frames") << ": ";
                    for (size_t i = 0; i < front.size(); ++i)
                        out << (i ? ", " : "") << front[i]->setting.label() << " ("
                            << formatNumber(front[i]->timing.median, 3) << " ms, "
                            << percent(front[i]->error[e].relativeRmse) << ")";
                    out << ".\n\n";
                }
            }
        }
        const std::vector<const Result*> lightRows = rowsOf(results, scene, true);
        if (!lightRows.empty())
            out << "## " << scene << ": light-count sweep\n\n" << rowsTable(info, lightRows) << "\n";
    }
    return writeTextFile(path, out.str(), error);
}

std::string froxelSummary(const RunInfo& info, const std::vector<Result>& results) {
    std::ostringstream out;
    out << "targets (" << info.froxelTargetScene << ", " << info.width << "x" << info.height << "):\n";
    for (const FroxelTarget& t : froxelTargets(info, results)) {
        out << "  " << t.name << ": " << (t.row ? t.row->setting.label() : std::string("not measured"));
        if (t.row)
            out << ": " << formatNumber(t.measured, 4) << " " << t.unit << " " << (t.met() ? "PASS" : "MISS");
        out << "\n";
    }
    const uint32_t answer = recommendedLightListMin(lightListPoints(results));
    if (answer)
        out << "light lists: lightListMinLights " << lightsText(answer) << " by the measurement (default "
            << info.lightListDefault << ")\n";
    return out.str();
}

}  // namespace bench
