#include "froxel_run.h"

#include "froxel_report.h"
#include "motion_report.h"
#include "progress.h"
#include "report.h"

#include <postfx/froxel_fog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

struct ScenePlan {
    std::string name;
    demo::Scene froxel;      // the froxel version (froxelScene)
    bool fog = false;        // the file has the ray-marched fog: its rows run beside
    demo::Scene fogScene;    // the file's scene
    uint32_t noiseSize = 0;  // the froxel fog's generated noise edge; 0: none
    bool shadows = false;    // its frames give postfx a shadow map
};

// The in-motion setting: the scene's (`base`) at the light-count sweep's grid, power slices, trilinear.
Setting motionBase(const Setting& base, const FroxelRunArgs& args) {
    const postfx::FroxelFogSettings defaults;
    Setting s = base;
    s.gridX = args.lightGrid[0];
    s.gridY = args.lightGrid[1];
    s.gridZ = args.lightGrid[2];
    s.logSlices = defaults.depthDistribution == postfx::FroxelDepthDistribution::Log;
    s.tricubic = defaults.tricubic;
    return s;
}

// The sweep's row with `setting`'s froxel knobs on its scene (measured with the scene's own temporal
// settings), a copy; nullptr when the sweep has none.
std::unique_ptr<Result> sweepRow(const std::vector<Result>& results, const Setting& setting) {
    for (const Result& r : results) {
        const Setting& s = r.setting;
        if (s.scene == setting.scene && s.method == Method::Froxel && !s.lightSweep &&
            s.gridX == setting.gridX && s.gridY == setting.gridY && s.gridZ == setting.gridZ &&
            s.logSlices == setting.logSlices && s.tricubic == setting.tricubic)
            return std::make_unique<Result>(r);
    }
    return nullptr;
}

// The references of `frames` of the sequence sceneAt, at the motion's stride.
bool motionReferences(Runner& runner, const std::function<demo::Scene(uint32_t)>& sceneAt,
                      const std::vector<uint32_t>& frames, const FroxelRunArgs& args,
                      std::vector<demo::ImageF>& out, std::string& error) {
    out.assign(frames.size(), {});
    for (size_t k = 0; k < frames.size(); ++k)
        if (!runner.reference(sceneAt(frames[k]), args.referenceSteps, args.motionErrorStride, out[k], error))
            return false;
    return true;
}

// One scene in motion (froxel_run's part of docs/accuracy-cost/README.md, "In motion"): the camera moving
// with temporal off and on; with `lightMoves`, the light moving and the light switched off too.
bool measureMotion(Runner& runner, const std::string& name, const demo::Scene& sceneIn,
                   const Setting& setting, const std::unique_ptr<Result>& sweep, bool lightMoves,
                   const demo::ImageF& stillReference, const FroxelRunArgs& args, Progress& progress,
                   MotionInfo& info, std::vector<MotionResult>& motion,
                   std::vector<SwitchOffResult>& switchOff, std::string& error) {
    const MotionOptions& mo = args.motionOptions;
    const std::vector<uint32_t> frames = measuredFrames(mo);
    const uint32_t length = sequenceLength(mo);
    demo::Scene scene = sceneIn;
    if (mo.temporalBlend > 0.0f) scene.froxelFog.temporal.blendWeight = mo.temporalBlend;
    auto fail = [&](const std::string& what) {
        error = name + " in motion, " + what + ": " + error;
        return false;
    };
    auto timed = [&](const std::string& what, auto&& body) {
        const auto start = std::chrono::steady_clock::now();
        const bool ok = body();
        info.referenceSeconds.emplace_back(
            name + " " + what,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        return ok;
    };
    std::unique_ptr<Result> still[2];  // the still camera's timing and errors, temporal off and on
    for (MotionKind kind : {MotionKind::Camera, MotionKind::Light}) {
        if (kind == MotionKind::Light && !lightMoves) continue;
        std::function<demo::Scene(uint32_t)> sceneOf = [&, kind](uint32_t n) {
            return kind == MotionKind::Camera ? cameraMotionScene(scene, mo, n)
                                              : lightMotionScene(scene, mo, n);
        };
        progress.show(name + " in motion (" + motionKindName(kind) + "): " + std::to_string(frames.size()) +
                      " CPU references");
        std::vector<demo::ImageF> references;
        if (!timed(motionKindName(kind),
                   [&] { return motionReferences(runner, sceneOf, frames, args, references, error); }))
            return fail("reference");
        if (!runner.setScene(scene, error)) return fail("setScene");
        progress.advance();
        for (bool temporal : {false, true}) {
            demo::Scene s = scene;
            s.froxelFog.temporal.enabled = temporal;
            MotionResult m;
            m.setting = setting;
            m.temporal = temporal;
            m.blendWeight = s.froxelFog.temporal.blendWeight;
            m.kind = kind;
            m.frames = frames;
            progress.show(name + " in motion (" + motionKindName(kind) + ") temporal " +
                          (temporal ? "on" : "off"));
            // The still camera: measured once per temporal setting; the sweep's row when it ran these
            // temporal settings (the scene's own).
            const postfx::TemporalSettings& own = sceneIn.froxelFog.temporal;
            if (!still[temporal] && sweep && own.enabled == temporal &&
                (!temporal || own.blendWeight == s.froxelFog.temporal.blendWeight))
                still[temporal] = std::make_unique<Result>(*sweep);
            if (!still[temporal]) {
                still[temporal] = std::make_unique<Result>();
                if (!runner.measure(s, Method::Froxel, 0.0f, stillReference, args.errorStride,
                                    still[temporal]->timing, still[temporal]->error, error))
                    return fail("still");
            }
            m.timing = still[temporal]->timing;
            m.still = still[temporal]->error;
            auto sceneAt = [&](uint32_t n) {
                demo::Scene f = sceneOf(n);
                f.froxelFog.temporal.enabled = temporal;
                return f;
            };
            if (!runner.sequence(
                    length, sceneAt, frames, args.motionErrorStride,
                    [&](uint32_t, const std::vector<float>& image) {
                        m.errors.push_back(Runner::compare(image, references[m.errors.size()]));
                        return true;
                    },
                    error))
                return fail("sequence");
            m.shadowMatrixChanges = runner.shadowMatrixChanges(sceneAt, length);
            motion.push_back(std::move(m));
            progress.advance();
        }
    }
    if (!lightMoves) return true;

    // The light switched off at frame F = warm-up (the camera still): references with and without it, then
    // per temporal setting the sequence (frames F - 1 .. F + switchOffFrames - 1) and its control (the light
    // dimmed to invisible before F, off from F: the same history rejected in the same frames).
    progress.show(name + " light " + std::to_string(mo.light) + " switched off: 2 CPU references");
    const demo::Scene off = lightOffScene(scene, mo.light), dimmed = dimmedLightScene(scene, mo.light);
    demo::ImageF with, without;
    if (!timed("switch-off", [&] {
            return runner.reference(scene, args.referenceSteps, args.motionErrorStride, with, error) &&
                   runner.reference(off, args.referenceSteps, args.motionErrorStride, without, error);
        }))
        return fail("switch-off reference");
    if (!runner.setScene(scene, error)) return fail("setScene");
    progress.advance();
    const uint32_t offFrame = std::max(mo.warmup, 1u);
    std::vector<uint32_t> readback;
    for (uint32_t n = offFrame - 1; n < offFrame + mo.switchOffFrames; ++n)
        readback.push_back(n);
    const std::vector<uint8_t> touched = touchedPixels(with.rgba, without.rgba, kTouchedTolerance);
    for (bool temporal : {false, true}) {
        SwitchOffResult r;
        r.setting = setting;
        r.temporal = temporal;
        r.blendWeight = scene.froxelFog.temporal.blendWeight;
        r.light = mo.light;
        r.offFrame = offFrame;
        r.touchedPixels = uint64_t(std::count(touched.begin(), touched.end(), uint8_t(1)));
        progress.show(name + " light " + std::to_string(mo.light) + " switched off, temporal " +
                      (temporal ? "on" : "off"));
        // [0]: switched off at F, [1]: the control (dimmed, then off), [2]: never on
        std::vector<std::vector<float>> images[3];
        for (int control = 0; control < 3; ++control) {
            auto sceneAt = [&](uint32_t n) {
                demo::Scene f = n >= offFrame || control == 2 ? off : control ? dimmed : scene;
                f.froxelFog.temporal.enabled = temporal;
                return f;
            };
            if (!runner.sequence(
                    offFrame + mo.switchOffFrames, sceneAt, readback, args.motionErrorStride,
                    [&](uint32_t, const std::vector<float>& image) {
                        images[control].push_back(image);
                        return true;
                    },
                    error))
                return fail("switch-off sequence");
        }
        r.lastLitRemaining = remainingContribution(images[0][0], with.rgba, without.rgba, touched);
        r.lastLitLeftover =
            leftoverContribution(images[0][0], images[1][0], with.rgba, without.rgba, touched);
        for (size_t k = 1; k < readback.size(); ++k) {
            r.remaining.push_back(remainingContribution(images[0][k], with.rgba, without.rgba, touched));
            r.controlRemaining.push_back(
                remainingContribution(images[1][k], with.rgba, without.rgba, touched));
            r.leftover.push_back(
                leftoverContribution(images[0][k], images[1][k], with.rgba, without.rgba, touched));
            r.neverLitRemaining.push_back(
                remainingContribution(images[2][k], with.rgba, without.rgba, touched));
        }
        switchOff.push_back(std::move(r));
        progress.advance();
    }
    return true;
}

}  // namespace

int runFroxel(const FroxelRunArgs& args, const std::string& commandLine, const std::string& date) {
    std::string error;
    std::vector<ScenePlan> plans;
    for (const std::string& name : args.scenes) {
        ScenePlan p;
        p.name = name;
        const std::string path = args.sceneDir + "/" + name + ".json";
        if (!demo::loadSceneFile(path, p.fogScene, error)) return fail(error);
        if (!froxelScene(p.fogScene, p.froxel, error)) return fail(path + ": " + error);
        p.fog = p.fogScene.fog.enabled;
        const postfx::FogNoiseSettings& noise = p.froxel.froxelFog.noise;
        p.noiseSize = noise.enabled && !noise.hostTexture ? noise.textureSize : 0;
        plans.push_back(std::move(p));
    }
    if (std::none_of(plans.begin(), plans.end(),
                     [&](const ScenePlan& p) { return p.name == args.targetScene; }))
        return fail("--froxel-target-scene '" + args.targetScene + "' is not in --scenes");

    auto runner = Runner::create(args.runner, error);
    if (!runner) return fail(error);
    const demo::VulkanHost& host = runner->host();

    RunInfo info;
    fillRunHeader(info, host, args.runner, args.errorStride, args.referenceSteps, date, commandLine);
    if (!runner->calibrate(info.calibration, error)) return fail(error);
    info.froxelTargetScene = args.targetScene;
    info.lightListDefault = postfx::FroxelFogSettings{}.lightListMinLights;
    for (const ScenePlan& p : plans)
        info.sceneNoise.emplace_back(p.name, p.noiseSize);

    // The in-motion scenes.
    std::vector<std::string> motionScenes;
    if (args.motion) {
        motionScenes = args.motionScenes;
        if (motionScenes.empty())
            for (const ScenePlan& p : plans)
                if ((p.name == args.targetScene && !args.motionQuick) || froxelLightCount(p.froxel) > 0)
                    motionScenes.push_back(p.name);
    }
    auto inMotion = [&](const std::string& name) {
        return std::count(motionScenes.begin(), motionScenes.end(), name) > 0;
    };
    const MotionOptions& mo = args.motionOptions;
    auto lightMoves = [&](const ScenePlan& p) {
        return inMotion(p.name) && mo.light < p.froxel.lights.size() &&
               froxelLightCount(lightOffScene(p.froxel, mo.light)) < froxelLightCount(p.froxel);
    };
    MotionInfo motionInfo;
    motionInfo.options = mo;
    motionInfo.errorStride = args.motionErrorStride;
    motionInfo.referenceSteps = args.referenceSteps;
    std::vector<MotionResult> motion;
    std::vector<SwitchOffResult> switchOff;

    size_t total = 1;  // the bandwidth
    for (ScenePlan& p : plans) {
        p.shadows = runner->hasShadowMap(p.froxel);
        total += 1 + froxelSweep(Setting{}, args.sweep).size() +
                 (p.fog ? args.fogSteps.size() * args.fogScales.size() : 0);
        if (p.name == args.targetScene)
            for (uint32_t n : args.lightCounts)
                total += n ? 2 : 1;
        if (inMotion(p.name)) total += 3;   // references, temporal off and on
        if (lightMoves(p)) total += 3 + 3;  // the same for the moving light; switched off
    }
    std::fprintf(stderr, "postfx-bench --froxel on %s, %ux%u, %zu measurements\n", info.device.c_str(),
                 info.width, info.height, total);

    std::vector<Result> results;
    {
        Progress progress(total);
        progress.show("copy bandwidth");
        if (!runner->copyBandwidth(args.copyBytes, 20, info.transferBandwidth, info.copyBandwidth, error))
            return fail("copy bandwidth: " + error);
        info.bandwidthGiven = std::isfinite(args.bandwidth);
        info.bandwidth = info.bandwidthGiven ? args.bandwidth
                         : std::isfinite(info.transferBandwidth)
                             ? std::max(info.copyBandwidth, info.transferBandwidth)
                             : info.copyBandwidth;
        progress.advance();

        for (const ScenePlan& p : plans) {
            if (!runner->setScene(p.froxel, error)) return fail(p.name + ": " + error);
            progress.show(p.name + " CPU reference of the froxel fog's model (" +
                          std::to_string(args.referenceSteps) + " steps/pixel)");
            demo::ImageF reference;
            const auto start = std::chrono::steady_clock::now();
            if (!runner->reference(p.froxel, args.referenceSteps, args.errorStride, reference, error))
                return fail(p.name + " reference: " + error);
            info.referenceSeconds.emplace_back(
                p.name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            progress.advance();

            auto measure = [&](const demo::Scene& s, const Setting& setting,
                               const demo::ImageF& ref) -> bool {
                progress.show(p.name + " " + methodName(setting.method) + " " + setting.label());
                Result r;
                r.setting = setting;
                if (!runner->measure(s, setting.method, 0.0f, ref, args.errorStride, r.timing, r.error,
                                     error)) {
                    error = p.name + " " + methodName(setting.method) + " " + setting.label() + ": " + error;
                    return false;
                }
                results.push_back(std::move(r));
                progress.advance();
                return true;
            };

            Setting base;
            base.scene = p.name;
            base.method = Method::Froxel;
            base.jitter = p.froxel.froxelFog.jitter;
            base.noiseSize = p.noiseSize;
            base.shadowKernel = p.shadows ? 1 : 0;
            base.lights = froxelLightCount(p.froxel);
            base.lightLists = base.lights > 0 && base.lights >= p.froxel.froxelFog.lightListMinLights;
            for (const Setting& setting : froxelSweep(base, args.sweep))
                if (!measure(withFroxelKnobs(p.froxel, setting), setting, reference)) return fail(error);

            if (p.fog) {
                for (float scale : args.fogScales) {
                    for (uint32_t steps : args.fogSteps) {
                        demo::Scene s = p.fogScene;
                        s.fog.quality = postfx::FogQuality::Custom;
                        s.fog.steps = steps;
                        s.fog.jitter = true;
                        s.fog.resolutionScale = scale;
                        s.fog.shadowKernel = 1;
                        Setting setting;
                        setting.scene = p.name;
                        setting.method = Method::Ours;
                        setting.steps = steps;
                        setting.jitter = true;
                        setting.resolutionScale = scale;
                        setting.noiseSize =
                            p.fogScene.fog.noise.enabled ? p.fogScene.fog.noise.textureSize : 0;
                        setting.shadowKernel = p.shadows ? 1 : 0;
                        if (!measure(s, setting, reference)) return fail(error);
                    }
                }
            }

            if (inMotion(p.name) &&
                !measureMotion(*runner, p.name, withFroxelKnobs(p.froxel, motionBase(base, args)),
                               motionBase(base, args), sweepRow(results, motionBase(base, args)),
                               lightMoves(p), reference, args, progress, motionInfo, motion, switchOff,
                               error))
                return fail(error);

            if (p.name != args.targetScene) continue;
            // The light-count sweep: timed only (an empty reference), at args.lightGrid.
            const postfx::FroxelFogSettings defaults;
            Setting lightBase = base;
            lightBase.gridX = args.lightGrid[0];
            lightBase.gridY = args.lightGrid[1];
            lightBase.gridZ = args.lightGrid[2];
            lightBase.logSlices = defaults.depthDistribution == postfx::FroxelDepthDistribution::Log;
            lightBase.tricubic = defaults.tricubic;
            lightBase.lightSweep = true;
            const demo::ImageF noReference;
            for (uint32_t count : args.lightCounts) {
                demo::Scene lit = p.froxel;
                lit.lights = sweepLights(p.froxel.camera, count);
                for (bool lists : {false, true}) {
                    if (lists && count == 0) continue;
                    Setting setting = lightBase;
                    setting.lights = froxelLightCount(lit);
                    setting.lightLists = lists;
                    if (!measure(withFroxelKnobs(lit, setting), setting, noReference)) return fail(error);
                }
            }
            for (uint32_t shadowed : args.shadowedCounts) {
                demo::Scene lit = p.froxel;
                lit.lights = sweepLights(p.froxel.camera, kFroxelTargetLights);
                for (uint32_t i = 0; i < shadowed && i < lit.lights.size(); ++i) {
                    lit.lights[i].shadows = true;
                    lit.lights[i].shadowResolution = args.shadowResolution;
                }
                Setting setting = lightBase;
                setting.lightSweep = false;
                setting.shadowSweep = true;
                setting.lights = froxelLightCount(lit);
                setting.lightLists = setting.lights > 0 && setting.lights >= defaults.lightListMinLights;
                setting.shadowedLights = std::min(shadowed, setting.lights);
                if (!measure(withFroxelKnobs(lit, setting), setting, noReference)) return fail(error);
            }
        }
        progress.show("writing the report");
    }
    markFroxelFronts(results);

    const std::vector<std::string> messages = runner->validationMessages();
    runner.reset();

    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) return fail("cannot create '" + args.out + "': " + ec.message());
    const std::string csv = args.out + "/results.csv", md = args.out + "/results.md",
                      motionCsv = args.out + "/motion.csv";
    if (!writeFroxelCsv(csv, info, results, error) ||
        !writeFroxelMarkdown(md, info, results, error,
                             froxelMotionMarkdown(info, motionInfo, motion, switchOff)) ||
        (!(motion.empty() && switchOff.empty()) &&
         !writeMotionCsv(motionCsv, info, motionInfo, motion, switchOff, error)))
        return fail(error);

    std::printf(
        "postfx-bench --froxel: %s, %ux%u, error stride %u, reference %u steps, copy %s GB/s "
        "(compute), %s GB/s (vkCmdCopyBuffer)\n",
        info.device.c_str(), info.width, info.height, info.errorStride, info.referenceSteps,
        formatNumber(info.copyBandwidth, 4).c_str(), formatNumber(info.transferBandwidth, 4).c_str());
    std::printf("%-14s %-14s %-52s %9s %9s %9s %9s %9s %9s %8s %3s %6s\n", "scene", "method", "setting",
                "GPU ms", "scatter", "apply", "RMSE 1", "RMSE 16", "TM 16", "calib ms", "re", "pareto");
    for (const Result& r : results) {
        const char* pareto = r.pareto1 && r.pareto16 ? "1, 16" : r.pareto1 ? "1" : r.pareto16 ? "16" : "";
        std::printf(
            "%-14s %-14s %-52s %9s %9s %9s %9s %9s %9s %8s %3s %6s\n", r.setting.scene.c_str(),
            methodName(r.setting.method), r.setting.label().c_str(), formatNumber(r.timing.median, 4).c_str(),
            formatNumber(passMs(r, "froxel_fog.scatter"), 3).c_str(),
            formatNumber(passMs(r, "froxel_fog.apply"), 3).c_str(), percent(r.error[0].relativeRmse).c_str(),
            percent(r.error[2].relativeRmse).c_str(), percent(r.error[2].tonemappedRmse).c_str(),
            calibrationMsText(r.timing.calibration).c_str(), remeasuredText(r.timing.calibration).c_str(),
            pareto);
    }
    std::printf("%s", froxelSummary(info, results).c_str());
    std::printf("%s", motionSummary(info, results, motion, switchOff).c_str());
    std::printf("calibration: %s\n", calibrationSummary(info.calibration).c_str());
    std::printf("%s", repeatSpreadText(results).c_str());
    std::printf("wrote %s, %s%s\n", csv.c_str(), md.c_str(),
                motion.empty() && switchOff.empty() ? "" : (", " + motionCsv).c_str());
    if (!messages.empty()) {
        for (const std::string& m : messages)
            std::fprintf(stderr, "validation: %s\n", m.c_str());
        return fail(std::to_string(messages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace bench
