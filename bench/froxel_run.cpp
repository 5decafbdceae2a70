#include "froxel_run.h"

#include "froxel_report.h"
#include "progress.h"
#include "report.h"

#include <postfx/froxel_fog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

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
    info.froxelTargetScene = args.targetScene;
    info.lightListDefault = postfx::FroxelFogSettings{}.lightListMinLights;
    for (const ScenePlan& p : plans)
        info.sceneNoise.emplace_back(p.name, p.noiseSize);

    size_t total = 1;  // the bandwidth
    for (ScenePlan& p : plans) {
        p.shadows = runner->hasShadowMap(p.froxel);
        total += 1 + froxelSweep(Setting{}, args.sweep).size() +
                 (p.fog ? args.fogSteps.size() * args.fogScales.size() : 0);
        if (p.name == args.targetScene)
            for (uint32_t n : args.lightCounts)
                total += n ? 2 : 1;
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
        }
        progress.show("writing the report");
    }
    markFroxelFronts(results);

    const std::vector<std::string> messages = runner->validationMessages();
    runner.reset();

    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) return fail("cannot create '" + args.out + "': " + ec.message());
    const std::string csv = args.out + "/results.csv", md = args.out + "/results.md";
    if (!writeFroxelCsv(csv, info, results, error) || !writeFroxelMarkdown(md, info, results, error))
        return fail(error);

    std::printf(
        "postfx-bench --froxel: %s, %ux%u, error stride %u, reference %u steps, copy %s GB/s "
        "(compute), %s GB/s (vkCmdCopyBuffer)\n",
        info.device.c_str(), info.width, info.height, info.errorStride, info.referenceSteps,
        formatNumber(info.copyBandwidth, 4).c_str(), formatNumber(info.transferBandwidth, 4).c_str());
    std::printf("%-14s %-14s %-52s %9s %9s %9s %9s %9s %6s\n", "scene", "method", "setting", "GPU ms",
                "scatter", "apply", "RMSE 1", "RMSE 16", "pareto");
    for (const Result& r : results) {
        const char* pareto = r.pareto1 && r.pareto16 ? "1, 16" : r.pareto1 ? "1" : r.pareto16 ? "16" : "";
        std::printf(
            "%-14s %-14s %-52s %9s %9s %9s %9s %9s %6s\n", r.setting.scene.c_str(),
            methodName(r.setting.method), r.setting.label().c_str(), formatNumber(r.timing.median, 4).c_str(),
            formatNumber(passMs(r, "froxel_fog.scatter"), 3).c_str(),
            formatNumber(passMs(r, "froxel_fog.apply"), 3).c_str(), percent(r.error[0].relativeRmse).c_str(),
            percent(r.error[2].relativeRmse).c_str(), pareto);
    }
    std::printf("%s", froxelSummary(info, results).c_str());
    std::printf("wrote %s, %s\n", csv.c_str(), md.c_str());
    if (!messages.empty()) {
        for (const std::string& m : messages)
            std::fprintf(stderr, "validation: %s\n", m.c_str());
        return fail(std::to_string(messages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace bench
