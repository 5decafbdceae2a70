#include "frame_run.h"

#include "small_orders_table.h"

#include "progress.h"
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

const std::vector<std::string> kEffects{"atmosphere", "clouds", "fog", "froxel_fog", "postfx"};

struct Row {
    uint32_t width = 0, height = 0;
    std::string fog, preset;
    std::string chosen;  // budget rows: what the budget chose ("clouds medium + fog low")
    Timing timing;
    std::map<std::string, double> effectMs;  // Σ of each effect's pass medians
    std::array<ErrorStats, 3> error;
    uint32_t stride = 1;
};

// The demo's forward pass (host.forward: the transparent surfaces, lit and through the lookup); 0 where
// none was drawn.
double forwardMs(const Row& r) {
    for (const auto& [pass, ms] : r.timing.passMedians)
        if (pass == "host.forward") return ms;
    return 0.0;
}

std::string fixed(double v, int digits) {
    if (!std::isfinite(v)) return "–";
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

postfx::FogQuality fogQuality(const std::string& preset) {
    if (preset == "budget") return postfx::FogQuality::Auto;
    if (preset == "low") return postfx::FogQuality::Low;
    if (preset == "high") return postfx::FogQuality::High;
    if (preset == "ultra") return postfx::FogQuality::Ultra;
    return postfx::FogQuality::Medium;
}

postfx::CloudQuality cloudQuality(const std::string& preset) {
    if (preset == "budget") return postfx::CloudQuality::Auto;
    if (preset == "low") return postfx::CloudQuality::Low;
    if (preset == "high") return postfx::CloudQuality::High;
    if (preset == "ultra") return postfx::CloudQuality::Ultra;
    return postfx::CloudQuality::Medium;
}

bool writeResults(const FrameRunArgs& args, const std::vector<Row>& rows, const RunInfo& info,
                  std::string& error) {
    std::filesystem::create_directories(args.out);
    std::ofstream csv(args.out + "/results.csv");
    csv << "# postfx-bench --frame results; columns: docs/accuracy-cost/README.md (Whole frame)\n";
    csv << "# device: " << info.device << "\n# vulkan: " << info.vulkanApi << "\n# date: " << info.date
        << "\n# command: " << info.commandLine << "\n# calibration: " << calibrationSummary(info.calibration)
        << "\n";
    std::vector<std::string> header = {"width",         "height",     "fog",       "preset",
                                       "gpu_ms_median", "gpu_ms_p10", "gpu_ms_p90"};
    header.insert(header.end(), calibrationColumns().begin(), calibrationColumns().end());
    for (const std::string& e : kEffects)
        header.push_back(e + "_ms");
    header.push_back("host_forward_ms");
    header.insert(header.end(), {"error_stride", "rel_rmse_1", "rel_rmse_16", "tm_rel_rmse_1",
                                 "tm_rel_rmse_16", "non_finite", "budget_choice"});
    writeCsvRow(csv, header);
    auto number = [](double v) {
        std::ostringstream text;
        text << v;
        return text.str();
    };
    for (const Row& r : rows) {
        std::vector<std::string> cells = {
            std::to_string(r.width), std::to_string(r.height), r.fog, r.preset, number(r.timing.median),
            number(r.timing.p10),    number(r.timing.p90)};
        appendCalibrationCells(cells, r.timing.calibration);
        for (const std::string& e : kEffects)
            cells.push_back(number(r.effectMs.count(e) ? r.effectMs.at(e) : 0.0));
        cells.push_back(number(forwardMs(r)));
        cells.insert(cells.end(), {std::to_string(r.stride), number(r.error[0].relativeRmse),
                                   number(r.error[2].relativeRmse), number(r.error[0].tonemappedRmse),
                                   number(r.error[2].tonemappedRmse),
                                   std::to_string(r.error[0].nonFinite + r.error[2].nonFinite), r.chosen});
        writeCsvRow(csv, cells);
    }
    std::ofstream md(args.out + "/results.md");
    md << "# The whole frame: accuracy–cost results\n\n"
       << "Written by `postfx-bench --frame`; what each number means: `docs/accuracy-cost/README.md` (Whole "
          "frame). Every number is in [results.csv](results.csv).\n\n"
       << "| | |\n|---|---|\n"
       << "| device | " << info.device << " |\n| Vulkan | " << info.vulkanApi << " |\n| date | " << info.date
       << " |\n| command | `" << info.commandLine << "` |\n"
       << "| scene | `demo/scenes/showcase.json` (froxel) and the same with its fog medium as the "
          "ray-marched "
          "fog (raymarched); camera and sun still |\n"
       << "| presets | the clouds' and the ray-marched fog's quality; the atmosphere and the froxel fog at "
          "their settings in the scene |\n"
       << "| GPU time | every postfx pass of a frame (Context::readPassTimings), median of " << info.frames
       << " frames (p10–p90) after a warm-up of at least " << info.warmup << " frames and "
       << fixed(info.warmupMs, 0) << " ms; per effect: the sum of its passes' medians |\n"
       << "| calibration | " << calibrationSummary(info.calibration) << " |\n"
       << "| error | relative RMSE over RGB against the demo's combined CPU reference (Renderer::"
          "renderReference: the atmosphere's reference (a), renderClouds, then renderFog or "
          "renderFroxelFog, "
       << args.referenceSteps
       << " steps) at every stride-th pixel; one frame, and the mean of 16 consecutive frames |\n\n";
    md << "| size | fog | preset | GPU ms (median, p10–p90) | atmosphere | clouds | fog | postfx | rel. "
          "RMSE 1 frame | 16 frames |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        auto ms = [&](const std::string& e) {
            return fixed(r.effectMs.count(e) ? r.effectMs.at(e) : 0.0, 3);
        };
        const std::string fogMs = r.fog == "froxel" ? ms("froxel_fog") : ms("fog");
        const std::string preset = r.chosen.empty() ? r.preset : r.preset + " (" + r.chosen + ")";
        md << "| " << r.width << "×" << r.height << " | " << r.fog << " | " << preset << " | "
           << fixed(r.timing.median, 3) << " (" << fixed(r.timing.p10, 3) << "–" << fixed(r.timing.p90, 3)
           << ") | " << ms("atmosphere") << " | " << ms("clouds") << " | " << fogMs << " | " << ms("postfx")
           << " | " << percent(r.error[0].relativeRmse) << " | " << percent(r.error[2].relativeRmse)
           << " |\n";
    }
    md << "\n## Target\n\nEvery effect on at Medium, 1920×1080: ≤ 1.0 ms (issue 21).\n\n"
       << "| fog | measured | status |\n|---|---|---|\n";
    for (const Row& r : rows) {
        if (r.width != 1920 || r.height != 1080 || r.preset != "medium") continue;
        md << "| " << r.fog << " | " << fixed(r.timing.median, 3) << " ms | "
           << (r.timing.median <= 1.0 ? "**PASS**" : "**MISS**") << " |\n";
    }
    // The lookup's share of the forward pass: the "lookup" row against "lookup unread" (same frame).
    md << "\n## Transparent surfaces\n\nThe showcase's boxes and spheres at opacity 0.5 and 256 smoke quads, "
          "drawn by the demo's forward pass after postfx (host.forward: each fragment lit by the sun, its "
          "shadow map and the local lights, then one `postfxVolumetrics` lookup); \"unread\": the same "
          "frame, "
          "its forward pass without the lookup. The lookup's own passes are in results.csv.\n\n"
       << "| size | fog | host.forward | unread | lookup's share |\n|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        if (r.preset != "lookup") continue;
        for (const Row& u : rows) {
            if (u.preset != "lookup unread" || u.fog != r.fog || u.width != r.width || u.height != r.height)
                continue;
            md << "| " << r.width << "×" << r.height << " | " << r.fog << " | " << fixed(forwardMs(r), 3)
               << " ms | " << fixed(forwardMs(u), 3) << " ms | " << fixed(forwardMs(r) - forwardMs(u), 3)
               << " ms |\n";
        }
    }
    if (!csv || !md) {
        error = "cannot write " + args.out + "/results.csv or results.md";
        return false;
    }
    return true;
}

}  // namespace

demo::Scene frameVariant(const demo::Scene& showcase, const std::string& fog) {
    demo::Scene s = showcase;
    if (fog == "raymarched") {
        postfx::FogSettings f;
        static_cast<postfx::FogMedium&>(f) = static_cast<const postfx::FogMedium&>(showcase.froxelFog);
        f.enabled = true;
        f.temporal.enabled = true;
        s.fog = f;
        s.froxelFog.enabled = false;
    }
    return s;
}

void withTransparentSurfaces(demo::Scene& scene, uint32_t width, uint32_t height) {
    // Every box and sphere drawn forward, half transparent (each fragment lit and one lookup; the ground
    // stays opaque), and a smoke emitter.
    for (demo::Object& o : scene.objects)
        if (o.type != demo::ObjectType::Plane) o.opacity = 0.5f;
    demo::ParticleEmitter smoke;
    smoke.center = {0.0f, 2.0f, -10.0f};
    smoke.halfSize = {2.0f, 2.0f, 2.0f};
    smoke.count = 256;
    smoke.quadSize = 1.0f;
    scene.particles.push_back(smoke);
    // The default lookup; below 1280 wide (--quick's 64x36 on lavapipe) no more columns than pixels.
    scene.volumetricsLookup = {};
    if (width < 1280) scene.volumetricsLookup.extent = {std::min(160u, width), std::min(90u, height), 32u};
}

demo::Scene withPreset(const demo::Scene& scene, const std::string& preset) {
    demo::Scene s = scene;
    s.clouds.quality = cloudQuality(preset);
    if (s.fog.enabled) s.fog.quality = fogQuality(preset);
    return s;
}

std::string passEffect(const std::string& pass) {
    return pass.substr(0, pass.find('.'));
}

int runFrame(const FrameRunArgs& args, const std::string& commandLine, const std::string& date) {
    demo::Scene showcase;
    std::string error;
    const std::string path = args.sceneDir + "/showcase.json";
    if (!demo::loadSceneFile(path, showcase, error)) return fail(error);
    if (!showcase.atmosphere.enabled || !showcase.clouds.enabled || !showcase.froxelFog.enabled)
        return fail(path + ": the showcase needs the atmosphere, the clouds and the froxel fog");
    if (args.shadowMapSize > 0) showcase.clouds.shadowMap.size = args.shadowMapSize;
    if (args.quickScene) {
        test::smallScatteringOrders(showcase.atmosphere);
        showcase.froxelFog.grid = {32, 18, 32};
        for (demo::Light& l : showcase.lights)
            l.shadowResolution = std::min(l.shadowResolution, 128u);
    }
    std::vector<Row> rows;
    RunInfo info;
    for (const auto& [width, height] : args.sizes) {
        RunnerOptions options = args.runner;
        options.width = width;
        options.height = height;
        std::unique_ptr<Runner> runner = Runner::create(options, error);
        if (!runner) return fail(error);
        fillRunHeader(info, runner->host(), options, args.errorStride, args.referenceSteps, date,
                      commandLine);
        // One log for every size: the reference is the first device's.
        if (!runner->calibrate(info.calibration, error)) return fail(error);
        const uint32_t stride =
            std::max(1u, uint32_t(std::lround(double(args.errorStride) * width / 1920.0)));
        for (const std::string fog : {"froxel", "raymarched"}) {
            const demo::Scene variant = frameVariant(showcase, fog);
            if (!runner->setScene(variant, error)) return fail(error);
            // The reference does not depend on the presets: the scene's media, every pixel's own ray (a
            // preset below resolution scale 1 is compared at the same pixels: its upsampling's error counts).
            demo::Scene referenceScene = variant;
            referenceScene.fog.resolutionScale = 1.0f;
            demo::ImageF reference;
            std::printf("%ux%u %s: reference...\n", width, height, fog.c_str());
            std::fflush(stdout);
            if (!runner->reference(referenceScene, args.referenceSteps, stride, reference, error))
                return fail(error);
            std::vector<std::string> rowsOf = args.presets;
            if (args.budgetMs > 0.0f) rowsOf.push_back("budget");
            rowsOf.push_back("lookup");
            rowsOf.push_back("lookup unread");
            rowsOf.push_back("lookup alone");
            for (const std::string& preset : rowsOf) {
                Row row;
                row.width = width;
                row.height = height;
                row.fog = fog;
                row.preset = preset;
                row.stride = stride;
                const bool lookup = preset.rfind("lookup", 0) == 0;
                demo::Scene scene = withPreset(variant, lookup ? "medium" : preset);
                if (preset == "budget") scene.budgetMs = args.budgetMs;
                if (lookup) withTransparentSurfaces(scene, width, height);
                // The fog's lookup passes first in the frame: their time without the drain of the passes
                // before them (a pass's first timestamp is at the top of the pipe).
                if (preset == "lookup alone") scene.atmosphere.enabled = scene.clouds.enabled = false;
                // "lookup unread": the same frame, its forward pass without the lookup (host.forward's
                // difference from the "lookup" row is the lookup's share of it).
                runner->setForwardLookup(preset != "lookup unread");
                // The reference has no transparent surfaces: the lookup row measures time only.
                const demo::ImageF none;
                const bool measured =
                    runner->measure(scene, fog == "froxel" ? Method::Froxel : Method::Ours, 0.0f,
                                    lookup ? none : reference, stride, row.timing, row.error, error);
                runner->setForwardLookup(true);
                if (!measured) return fail(error);
                if (preset == "budget") {
                    postfx::BudgetChoice choice;
                    const postfx::Status s = runner->postfxContext().budgetChoice(choice);
                    if (!s.ok()) return fail("budget row: " + s.message);
                    static const char* const kNames[] = {"low", "medium", "high", "ultra"};
                    for (const postfx::BudgetChoice::EffectChoice& e : choice.effects)
                        row.chosen += (row.chosen.empty() ? "" : " + ") + e.effect + " " +
                                      (e.preset < 4 ? kNames[e.preset] : "?");
                    for (const postfx::AutoQualityTimings& t : runner->postfxContext().autoQualityTimings()) {
                        std::printf("  auto measured %s at %ux%u (features %u), presets [ms]:",
                                    t.effect.c_str(), t.width, t.height, t.features);
                        for (float ms : t.presetMs)
                            std::printf(" %.4f", ms);
                        std::printf("\n");
                    }
                    std::printf("  budget: other work %.4f ms + chosen %.4f ms (%s)\n", choice.otherMs,
                                choice.chosenMs, choice.fits ? "fits" : "does not fit");
                    char b[64];
                    std::snprintf(b, sizeof b, "%.3g", double(args.budgetMs));
                    row.preset = std::string("budget ") + b + " ms";
                }
                for (const auto& [pass, ms] : row.timing.passMedians)
                    row.effectMs[passEffect(pass)] += ms;
                std::printf(
                    "%ux%u %-10s %-6s %8.4f ms  atmosphere %.4f clouds %.4f fog %.4f  rel. RMSE %s / %s  TM "
                    "%s / "
                    "%s  calib %s ms re %s %s\n",
                    width, height, fog.c_str(), row.preset.c_str(), row.timing.median,
                    row.effectMs["atmosphere"], row.effectMs["clouds"],
                    row.effectMs[fog == "froxel" ? "froxel_fog" : "fog"],
                    percent(row.error[0].relativeRmse).c_str(), percent(row.error[2].relativeRmse).c_str(),
                    percent(row.error[0].tonemappedRmse).c_str(),
                    percent(row.error[2].tonemappedRmse).c_str(),
                    calibrationMsText(row.timing.calibration).c_str(),
                    remeasuredText(row.timing.calibration).c_str(), row.chosen.c_str());
                for (const auto& [pass, ms] : row.timing.passMedians)
                    if (pass.find("lookup") != std::string::npos || pass == "host.forward")
                        std::printf("  %-22s %8.4f ms\n", pass.c_str(), ms);
                std::fflush(stdout);
                rows.push_back(row);
            }
        }
        for (const std::string& m : runner->validationMessages())
            return fail("validation: " + m);
    }
    if (!writeResults(args, rows, info, error)) return fail(error);
    std::printf("calibration: %s\n", calibrationSummary(info.calibration).c_str());
    std::printf("wrote %s/results.csv, %s/results.md\n", args.out.c_str(), args.out.c_str());
    return 0;
}

}  // namespace bench
