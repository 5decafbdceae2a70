#include "atmosphere_run.h"

#include "frame_gpu.h"

#include "image_compare.h"
#include "progress.h"
#include "report.h"
#include "stats.h"

#include "host/gpu_resources.h"
#include "host/vulkan_host.h"

#include <postfx/context.h>
#include <postfx/reference.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

// The frame of `view` with `settings` in `situation`, frame n of a timed run.
postfx::FrameInfo frameOf(const AtmosphereView& view, const postfx::AtmosphereSettings& settings,
                          AtmosphereSituation situation, uint32_t n, uint32_t width, uint32_t height) {
    const bool odd = n % 2 == 1;
    postfx::FrameInfo frame;
    frame.atmosphere = settings;
    frame.atmosphere.enabled = true;
    frame.camera = atmosphereCamera(
        view, width, height, situation == AtmosphereSituation::Camera && odd ? kAtmosphereMotion : 0.0);
    frame.sun.toSun =
        atmosphereToSun(view, situation == AtmosphereSituation::Sun && odd ? kAtmosphereMotion : 0.0);
    frame.sun.illuminance = postfx::Vec3(1.0f);
    if (situation == AtmosphereSituation::Media && odd)
        frame.atmosphere.mieScattering *= 1.0f + kAtmosphereMediaChange;
    return frame;
}

// Reference (a) of the view at every stride-th pixel in x and y: the same rays as the full image's
// (i·stride, j·stride) pixels (bench/runner.h's reference, demo/host/reference_render.cpp's projection).
struct ViewReference {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    std::vector<uint8_t> kind;  // 0: sky, 1: geometry, 2: the sun disk (left out)
};

bool reference(const AtmosphereView& view, const AtmosphereRunArgs& args, const std::vector<float>& color,
               const std::vector<float>& depth, ViewReference& out, std::string& error) {
    const uint32_t W = args.runner.width, H = args.runner.height, s = args.errorStride;
    const uint32_t w = (W + s - 1) / s, h = (H + s - 1) / s;
    const postfx::CameraInput camera = atmosphereCamera(view, W, H);
    std::vector<float> subColor(size_t(w) * h * 4), subDepth(size_t(w) * h);
    out.width = w;
    out.height = h;
    out.kind.assign(size_t(w) * h, 0);
    const postfx::AtmosphereSettings defaults;
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(atmosphereToSun(view)));
    const double disk = 2.0 * glm::radians(double(defaults.sunAngularRadiusDeg));
    for (uint32_t j = 0; j < h; ++j) {
        for (uint32_t i = 0; i < w; ++i) {
            const size_t src = size_t(j) * s * W + size_t(i) * s, dst = size_t(j) * w + i;
            std::memcpy(&subColor[dst * 4], &color[src * 4], 4 * sizeof(float));
            subDepth[dst] = depth[src];
            const glm::dvec3 d = atmospherePixelDirection(camera, double(i) * s, double(j) * s, W, H);
            out.kind[dst] = depth[src] > 0.0f                                             ? 1
                            : std::acos(std::clamp(glm::dot(d, toSun), -1.0, 1.0)) < disk ? 2
                                                                                          : 0;
        }
    }
    postfx::reference::AtmosphereInputs in;
    in.width = w;
    in.height = h;
    in.color = subColor;
    in.depth = subDepth;
    in.depthConvention.reversedZ = true;
    in.camera = camera;
    if (s > 1) {
        // Pixel i of the w-wide image at ndc (i + 0.5) / w · 2 - 1 is the frame's pixel i·s: clip x, y
        // mapped by the inverse of x -> sx·x + ox before the projection's inverse.
        const double sx = double(s) * w / W, sy = double(s) * h / H;
        const double ox = sx - 1.0 + (1.0 - s) / double(W), oy = sy - 1.0 + (1.0 - s) / double(H);
        glm::dmat4 inverseA(1.0);
        inverseA[0][0] = 1.0 / sx;
        inverseA[1][1] = 1.0 / sy;
        inverseA[3][0] = -ox / sx;
        inverseA[3][1] = -oy / sy;
        in.camera.projection = glm::mat4(inverseA * glm::dmat4(camera.projection));
    }
    in.sun.toSun = atmosphereToSun(view);
    in.sun.illuminance = postfx::Vec3(1.0f);
    in.settings = defaults;
    in.settings.enabled = true;
    in.stepsPerPixel = args.referenceSteps;
    in.psiDirections = args.psiDirections;
    in.psiSteps = args.psiSteps;
    if (args.coarseOrders) {
        in.ordersViewNodes = 16;
        in.ordersSunNodes = 32;
        in.ordersHeightNodes = 8;
        in.ordersAzimuthNodes = 4;
        in.ordersDirections = 144;
        in.ordersSteps = 32;
        in.ordersCount = 4;
    }
    if (const postfx::Status st = postfx::reference::renderAtmosphere(in, out.rgba); !st.ok()) {
        error = "renderAtmosphere: " + st.message;
        return false;
    }
    return true;
}

// The error of the full-size `image` against the reference, per pixel kind.
void compare(const std::vector<float>& image, const ViewReference& ref, uint32_t width, uint32_t stride,
             AtmosphereRow& row) {
    std::vector<float> a[3], b[3];  // sky, geometry, all
    for (uint32_t j = 0; j < ref.height; ++j) {
        for (uint32_t i = 0; i < ref.width; ++i) {
            const size_t k = size_t(j) * ref.width + i;
            const size_t src = (size_t(j) * stride * width + size_t(i) * stride) * 4;
            const int kind = ref.kind[k];
            if (kind == 2) continue;
            for (int set : {kind, 2}) {
                a[set].insert(a[set].end(), &image[src], &image[src] + 4);
                b[set].insert(b[set].end(), &ref.rgba[k * 4], &ref.rgba[k * 4] + 4);
            }
        }
    }
    auto stats = [&](int set) {
        ErrorStats e;
        const uint32_t n = uint32_t(a[set].size() / 4);
        if (n == 0) return e;
        const test::ImageStats s = test::compareImages(a[set], b[set], n, 1, 0.01, 1e-6);
        return ErrorStats{s.relativeRmse, s.maxAbsError, s.fractionOff, s.nonFinite,
                          tonemappedRmse(a[set], b[set])};
    };
    row.sky = stats(0);
    row.geometry = stats(1);
    row.all = stats(2);
    row.skyPixels = a[0].size() / 4;
    row.geometryPixels = a[1].size() / 4;
}

}  // namespace

int runAtmosphere(const AtmosphereRunArgs& args, const std::string& commandLine, const std::string& date) {
    std::string error;
    std::vector<AtmosphereView> views;
    for (const AtmosphereView& v : atmosphereViews())
        if (args.views.empty() || std::count(args.views.begin(), args.views.end(), v.name))
            views.push_back(v);
    for (const std::string& name : args.views)
        if (std::none_of(views.begin(), views.end(), [&](const AtmosphereView& v) { return v.name == name; }))
            return fail("--atmosphere-views: unknown view '" + name + "'");
    std::vector<AtmospherePoint> points;
    if (!atmosphereSweep(args.sweep, points, error)) return fail("--atmosphere-sweep: " + error);
    auto sweeps = [&](const std::string& view) {
        return args.sweepViews.empty() ||
               std::count(args.sweepViews.begin(), args.sweepViews.end(), view) > 0;
    };

    FrameGpu gpu;
    if (!gpu.create(args.runner, error)) return fail(error);
    AtmosphereInfo info;
    fillRunHeader(info.run, *gpu.host, args.runner, args.errorStride, args.referenceSteps, date, commandLine);
    if (!gpu.calibrate(info.run.calibration, error)) return fail(error);
    info.psiDirections = args.psiDirections;
    info.psiSteps = args.psiSteps;

    constexpr AtmosphereSituation kSituations[] = {AtmosphereSituation::Still, AtmosphereSituation::Camera,
                                                   AtmosphereSituation::Sun, AtmosphereSituation::Media};
    size_t total = 0;
    for (const AtmosphereView& v : views)
        total += 1 + std::size(kSituations) + (sweeps(v.name) ? points.size() - 1 : 0);
    std::fprintf(stderr, "postfx-bench --atmosphere on %s, %ux%u, %zu measurements\n",
                 info.run.device.c_str(), info.run.width, info.run.height, total);

    const uint32_t W = args.runner.width, H = args.runner.height;
    std::vector<AtmosphereRow> rows;
    {
        Progress progress(total);
        for (const AtmosphereView& view : views) {
            std::vector<float> color, depth;
            atmosphereImages(view, atmosphereCamera(view, W, H), W, H, depth, color);
            progress.show(view.name + " reference (a) (" + std::to_string(args.referenceSteps) +
                          " steps/pixel)");
            ViewReference ref;
            const auto start = std::chrono::steady_clock::now();
            if (!reference(view, args, color, depth, ref, error)) return fail(view.name + ": " + error);
            info.referenceSeconds.emplace_back(view.name, secondsSince(start));
            gpu.idle = true;
            progress.advance();
            if (!gpu.upload(color, depth, error)) return fail(view.name + ": " + error);

            for (const AtmospherePoint& point : points) {
                const bool isDefault = point.knob == "default";
                if (!isDefault && !sweeps(view.name)) continue;
                std::vector<float> image;
                if (!gpu.render(frameOf(view, point.settings, AtmosphereSituation::Still, 0, W, H), image,
                                error))
                    return fail(view.name + " " + point.knob + " " + point.value + ": " + error);
                AtmosphereRow errors;
                compare(image, ref, W, args.errorStride, errors);
                for (AtmosphereSituation situation : kSituations) {
                    if (!isDefault && situation != AtmosphereSituation::Media) continue;
                    AtmosphereRow row = errors;
                    row.view = view.name;
                    row.situation = situation;
                    row.point = point;
                    progress.show(view.name + " " + situationName(situation) + " " +
                                  (isDefault ? std::string("defaults") : point.knob + "=" + point.value));
                    if (!gpu.measure(
                            [&](uint32_t n) { return frameOf(view, point.settings, situation, n, W, H); },
                            row.timing, row.passFrames, error))
                        return fail(view.name + " " + situationName(situation) + ": " + error);
                    rows.push_back(std::move(row));
                    progress.advance();
                }
            }
        }
        progress.show("writing the report");
    }

    const std::vector<std::string> messages = gpu.host->validationMessages();
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) return fail("cannot create '" + args.out + "': " + ec.message());
    const std::string csv = args.out + "/results.csv", md = args.out + "/results.md";
    if (!writeAtmosphereCsv(csv, info, rows, error) || !writeAtmosphereMarkdown(md, info, rows, error))
        return fail(error);

    std::printf("postfx-bench --atmosphere: %s, %ux%u, error stride %u, reference %u steps\n",
                info.run.device.c_str(), W, H, args.errorStride, args.referenceSteps);
    std::printf("%-14s %-7s %-26s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %8s %3s\n", "view", "frame",
                "setting", "GPU ms", "trans", "ms", "orders", "sky_view", "ap", "apply", "sky RMSE",
                "geo RMSE", "sky TM", "calib ms", "re");
    for (const AtmosphereRow& r : rows) {
        const std::string setting =
            r.point.knob == "default" ? "defaults" : r.point.knob + "=" + r.point.value;
        std::printf("%-14s %-7s %-26s %9s", r.view.c_str(), situationName(r.situation), setting.c_str(),
                    formatNumber(r.timing.median, 4).c_str());
        for (const char* pass : kAtmospherePasses)
            std::printf(" %9s", orDash(formatNumber(atmospherePassMs(r, pass), 3)).c_str());
        std::printf(" %9s %9s %9s %8s %3s\n", percent(r.sky.relativeRmse).c_str(),
                    r.geometryPixels ? percent(r.geometry.relativeRmse).c_str() : "–",
                    percent(r.sky.tonemappedRmse).c_str(), calibrationMsText(r.timing.calibration).c_str(),
                    remeasuredText(r.timing.calibration).c_str());
    }
    std::printf("%s", atmosphereSummary(info, rows).c_str());
    std::printf("calibration: %s\n", calibrationSummary(info.run.calibration).c_str());
    std::printf("wrote %s, %s\n", csv.c_str(), md.c_str());
    if (!messages.empty()) {
        for (const std::string& m : messages)
            std::fprintf(stderr, "validation: %s\n", m.c_str());
        return fail(std::to_string(messages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace bench
