#include "worst_case.h"
#include "atmosphere/atmosphere_settings.h"

#include "calibration.h"
#include "frame_run.h"
#include "report.h"

#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <postfx/postfx.h>
#include <postfx/settings_table.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

// Sets each of `keys` in `settings` (of `table`'s struct) to the table's maximum; appends "key=value".
void maximize(std::span<const postfx::SettingField> table, void* settings,
              const std::vector<const char*>& keys, std::string& text) {
    for (const char* key : keys) {
        const postfx::SettingField* f = postfx::findSettingByKey(table, key);
        if (!f) {
            text += std::string(text.empty() ? "" : ", ") + key + "=?";
            continue;
        }
        const auto max = uint32_t(f->max);
        switch (f->kind) {
            case postfx::SettingKind::Uint:
                postfx::settingValue<uint32_t>(*f, settings) = max;
                break;
            case postfx::SettingKind::UVec2:
                postfx::settingValue<postfx::UVec2>(*f, settings) = {max, max};
                break;
            case postfx::SettingKind::UVec3:
                postfx::settingValue<postfx::UVec3>(*f, settings) = {max, max, max};
                break;
            case postfx::SettingKind::Float:
                postfx::settingValue<float>(*f, settings) = float(f->max);
                break;
            default:
                break;
        }
        text += std::string(text.empty() ? "" : ", ") + key + "=" + number(f->max);
    }
}

struct Row {
    std::string name, settings;
    std::string refused;  // the library's refusal, when it refused
    uint64_t planBytes = 0;
    double prewarmSeconds = 0.0;                    // Context::prewarm: every pipeline compiled
    double firstSeconds = 0.0, laterSeconds = 0.0;  // record() to the queue idle, after prewarm
    std::string slowestPass;
    double slowestMs = 0.0, firstGpuMs = 0.0;
    RowCalibration calibration;
};

struct Spec {
    const char* name;
    std::function<void(demo::Scene&, std::string&)> setup;  // enables the one effect, maximized
    std::function<void(postfx::FrameInfo&)> frame = {};     // what the scene does not hold
};

// The volumetrics lookup's largest cube (kMaxLookupFroxels).
uint32_t lookupSide() {
    return uint32_t(std::lround(std::cbrt(double(postfx::kMaxLookupFroxels))));
}

std::vector<Spec> specs() {
    using postfx::AtmosphereMultipleScattering;
    const std::vector<const char*> air = {
        "transmittance_lut_size", "transmittance_steps",         "sky_view_lut_size",
        "sky_view_steps",         "aerial_perspective_lut_size", "aerial_perspective_steps_per_slice"};
    auto only = [](demo::Scene& s, bool atmosphere, bool clouds, bool fog, bool froxel) {
        s.atmosphere.enabled = atmosphere;
        s.clouds.enabled = clouds;
        s.fog.enabled = fog;
        s.froxelFog.enabled = froxel;
    };
    return {
        {"atmosphere_hillaire",
         [=](demo::Scene& s, std::string& t) {
             only(s, true, false, false, false);
             s.atmosphere.multipleScattering = AtmosphereMultipleScattering::Hillaire;
             std::vector<const char*> keys = air;
             keys.insert(keys.end(), {"multiple_scattering_lut_size", "multiple_scattering_directions",
                                      "multiple_scattering_steps"});
             maximize(postfx::atmosphereSettingsTable(), &s.atmosphere, keys, t);
         }},
        {"atmosphere_orders",
         [=](demo::Scene& s, std::string& t) {
             only(s, true, false, false, false);
             s.atmosphere.multipleScattering = AtmosphereMultipleScattering::Orders;
             std::vector<const char*> keys = air;
             keys.insert(keys.end(), {"scattering_orders_azimuth_size", "scattering_orders_directions",
                                      "scattering_orders_steps", "scattering_orders"});
             maximize(postfx::atmosphereSettingsTable(), &s.atmosphere, keys, t);
             // Each axis has its own maximum (view, sun, height: atmosphere/atmosphere_settings.h).
             s.atmosphere.scatteringOrdersLutSize = {64, 128, 64};
             t += ", scattering_orders_lut_size=64x128x64";
             // Their product is bounded (kMaxOrdersWork): the orders, steps, then azimuths down until it
             // fits.
             postfx::AtmosphereSettings& a = s.atmosphere;
             while (postfx::atmosphere::scatteringOrdersWork(a) > postfx::atmosphere::kMaxOrdersWork &&
                    a.scatteringOrders > 1)
                 --a.scatteringOrders;
             while (postfx::atmosphere::scatteringOrdersWork(a) > postfx::atmosphere::kMaxOrdersWork &&
                    a.scatteringOrdersSteps > 1)
                 --a.scatteringOrdersSteps;
             while (postfx::atmosphere::scatteringOrdersWork(a) > postfx::atmosphere::kMaxOrdersWork &&
                    a.scatteringOrdersAzimuthSize > 2)
                 --a.scatteringOrdersAzimuthSize;
             t += ", within the orders' work bound: scattering_orders=" + std::to_string(a.scatteringOrders) +
                  ", scattering_orders_steps=" + std::to_string(a.scatteringOrdersSteps) +
                  ", scattering_orders_azimuth_size=" + std::to_string(a.scatteringOrdersAzimuthSize);
         }},
        {"clouds",
         [=](demo::Scene& s, std::string& t) {
             only(s, false, true, false, false);
             s.clouds.quality = postfx::CloudQuality::Custom;
             s.clouds.castShadows = true;
             maximize(postfx::cloudSettingsTable(), &s.clouds,
                      {"steps", "light_steps", "multiple_scattering.octaves", "noise.base_size",
                       "noise.detail_size", "shadow_map.size", "resolution_scale"},
                      t);
         }},
        {"fog",
         [=](demo::Scene& s, std::string& t) {
             s = frameVariant(s, "raymarched");
             only(s, false, false, true, false);
             s.fog.quality = postfx::FogQuality::Custom;
             s.fog.noise.enabled = true;
             maximize(postfx::fogSettingsTable(), &s.fog, {"steps", "noise.texture_size", "resolution_scale"},
                      t);
         }},
        {"froxel_fog",
         [=](demo::Scene& s, std::string& t) {
             only(s, false, false, false, true);
             s.froxelFog.noise.enabled = true;
             s.froxelFog.tileSizePx = 0;
             maximize(postfx::froxelFogSettingsTable(), &s.froxelFog, {"noise.texture_size"}, t);
             // Each axis up to kMaxFroxelGridSize, all of them up to kMaxFroxels: the cube.
             const auto side = uint32_t(std::lround(std::cbrt(double(postfx::kMaxFroxels))));
             s.froxelFog.grid = {side, side, side};
             t += ", grid=" + std::to_string(side) + "^3 (kMaxFroxels)";
         }},
        {"lookup",
         [=](demo::Scene& s, std::string& t) {
             only(s, false, false, false, true);
             t += "froxel fog as in the scene, volumetrics lookup extent=" + std::to_string(lookupSide()) +
                  "^3 (kMaxLookupFroxels)";
         },
         [](postfx::FrameInfo& f) {
             f.volumetricsLookup.enabled = true;
             f.volumetricsLookup.extent = {lookupSide(), lookupSide(), lookupSide()};
         }},
    };
}

struct Bench {
    std::unique_ptr<demo::VulkanHost> host;
    std::unique_ptr<demo::Renderer> renderer;
    std::unique_ptr<Calibration> calibration;  // destroyed before the host
    VkCommandBuffer cmd = VK_NULL_HANDLE;

    // One attempt at a row: its frames bracketed by `calibrated` (before the first frame, after prewarm;
    // after the last), unless the library refuses it.
    bool run(const demo::Scene& scene, const Spec& spec, uint32_t frames, Row& out, CalibratedRow& calibrated,
             std::string& error) {
        postfx::ContextCreateInfo info = renderer->postfxContext().createInfo();
        info.messageCallback = nullptr;
        info.gpuTimings = true;
        std::unique_ptr<postfx::Context> context;
        if (const postfx::Status s = postfx::Context::create(info, context); !s) {
            error = "postfx create: " + s.message;
            return false;
        }
        std::vector<double> later;
        for (uint32_t n = 0; n < frames; ++n) {
            VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            if (vkBeginCommandBuffer(cmd, &bi) != VK_SUCCESS) {
                error = "vkBeginCommandBuffer failed";
                return false;
            }
            postfx::FrameInfo f = renderer->frameInputs(cmd, scene, n);
            f.cameraCut = n == 0;
            if (spec.frame) spec.frame(f);
            if (n == 0) {
                postfx::FramePlan plan;
                const postfx::Status s = context->plan(f, plan);
                out.planBytes = plan.totalBytes();
                if (!s) {
                    out.refused = s.message;
                    vkEndCommandBuffer(cmd);
                    return true;
                }
                // The pipelines first, so the frames' times are their work (a driver's compile time does
                // not follow the sizes).
                const auto start = std::chrono::steady_clock::now();
                if (const postfx::Status p = context->prewarm(f); !p) {
                    error = "postfx prewarm: " + p.message;
                    return false;
                }
                out.prewarmSeconds = secondsSince(start);
                if (!calibrated.before(error)) return false;
            }
            const auto start = std::chrono::steady_clock::now();
            if (const postfx::Status s = context->record(f); !s) {
                out.refused = s.message;
                vkEndCommandBuffer(cmd);
                return true;
            }
            VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            si.commandBufferCount = 1;
            si.pCommandBuffers = &cmd;
            if (vkEndCommandBuffer(cmd) != VK_SUCCESS || vkQueueSubmit(host->queue, 1, &si, VK_NULL_HANDLE) ||
                vkQueueWaitIdle(host->queue) != VK_SUCCESS) {
                error = "vkEndCommandBuffer, vkQueueSubmit or vkQueueWaitIdle failed";
                return false;
            }
            const double seconds = secondsSince(start);
            if (n == 0) {
                out.firstSeconds = seconds;
                std::vector<postfx::PassTiming> timings;
                if (context->readPassTimings(0, timings))
                    for (const postfx::PassTiming& t : timings) {
                        out.firstGpuMs += t.milliseconds;
                        if (t.milliseconds > out.slowestMs) {
                            out.slowestMs = t.milliseconds;
                            out.slowestPass = t.name;
                        }
                    }
            } else {
                later.push_back(seconds);
            }
        }
        if (!later.empty()) {
            std::sort(later.begin(), later.end());
            out.laterSeconds = later[later.size() / 2];
        }
        vkDeviceWaitIdle(host->device);
        return calibrated.after(error);
    }
};

}  // namespace

int runWorstCase(const WorstCaseArgs& args, const std::string& commandLine) {
    demo::Scene showcase;
    std::string error;
    if (!demo::loadSceneFile(args.sceneDir + "/showcase.json", showcase, error)) return fail(error);
    Bench b;
    demo::HostOptions hostOptions;
    hostOptions.validation = args.validation;
    b.host = demo::VulkanHost::create(hostOptions, error);
    if (!b.host) return fail("Vulkan: " + error);
    demo::RenderOptions render;
    render.width = args.width;
    render.height = args.height;
    b.renderer = demo::Renderer::create(*b.host, render, error);
    if (!b.renderer) return fail(error);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = b.host->commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    if (vkAllocateCommandBuffers(b.host->device, &ai, &b.cmd) != VK_SUCCESS)
        return fail("vkAllocateCommandBuffers failed");
    // The host's images as a frame leaves them: drawn once with postfx off.
    demo::Scene off = showcase;
    off.atmosphere.enabled = off.clouds.enabled = off.fog.enabled = off.froxelFog.enabled = false;
    bool drawn = false;
    if (!b.renderer->setScene(showcase, error) ||
        !b.host->submitAndWait([&](VkCommandBuffer c) { drawn = b.renderer->recordFrame(c, off, 0, error); },
                               error) ||
        !drawn)
        return fail(error);
    CalibrationLog calibrationLog;
    b.calibration = Calibration::create(*b.host, args.calibration, calibrationLog, error);
    if (!b.calibration || !b.calibration->reference(args.calibrationWarmupMs, error)) return fail(error);
    std::printf("postfx-bench --worst-case: %s, %ux%u, %u frames per row, memory budget %.1f GiB\n",
                b.host->deviceDescription().c_str(), args.width, args.height, args.frames,
                double(b.renderer->postfxContext().createInfo().memoryBudgetBytes) / double(1u << 30));
    std::printf("command: %s\n\n", commandLine.c_str());
    std::printf(
        "| row | settings at their maximum | plan MiB | prewarm s | first frame s | later frame s | first "
        "frame's GPU passes ms (slowest) | calibration ms | re-measured "
        "|\n|---|---|---|---|---|---|---|---|---|\n");
    for (const Spec& spec : specs()) {
        if (!args.rows.empty() && std::find(args.rows.begin(), args.rows.end(), spec.name) == args.rows.end())
            continue;
        demo::Scene scene = showcase;
        std::string settings;
        spec.setup(scene, settings);
        // Timed again, each time in a new context, while the calibration drifts (bench/calibration.h).
        Row row;
        CalibratedRow calibrated(b.calibration.get());
        do {
            Row attempt;
            attempt.name = spec.name;
            attempt.settings = settings;
            if (!b.run(scene, spec, args.frames, attempt, calibrated, error))
                return fail(std::string(spec.name) + ": " + error);
            if (!attempt.refused.empty()) {
                row = attempt;
                break;
            }
            if (calibrated.kept()) row = attempt;
        } while (calibrated.again());
        row.calibration = calibrated.finish();
        if (!row.refused.empty())
            std::printf("| %s | %s | %.1f | refused: %s | | | | | |\n", row.name.c_str(),
                        row.settings.c_str(), double(row.planBytes) / 1048576.0, row.refused.c_str());
        else
            std::printf("| %s | %s | %.1f | %.1f | %.2f | %.2f | %.0f (%s %.0f) | %s | %s |\n",
                        row.name.c_str(), row.settings.c_str(), double(row.planBytes) / 1048576.0,
                        row.prewarmSeconds, row.firstSeconds, row.laterSeconds, row.firstGpuMs,
                        row.slowestPass.c_str(), row.slowestMs, calibrationMsText(row.calibration).c_str(),
                        remeasuredText(row.calibration).c_str());
        std::fflush(stdout);
    }
    std::printf("\ncalibration: %s\n", calibrationSummary(calibrationLog).c_str());
    return 0;
}

}  // namespace bench
