#include "clouds_run.h"

#include "frame_gpu.h"
#include "image_compare.h"
#include "progress.h"
#include "report.h"

#include <postfx/reference.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <tuple>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

const postfx::Vec3 kAmbient(0.03f, 0.04f, 0.06f);

// Frame of `view` with the camera turned by `yaw` [rad]; clouds off: the atmosphere alone.
postfx::FrameInfo frameOf(const CloudsView& view, const postfx::CloudSettings* clouds, double yaw, bool cut,
                          uint32_t width, uint32_t height) {
    postfx::FrameInfo frame;
    frame.atmosphere.enabled = true;
    if (clouds) frame.clouds = *clouds;
    frame.clouds.enabled = clouds != nullptr;
    frame.camera = cloudsCamera(view, width, height, yaw);
    frame.sun.toSun = cloudsToSun(view);
    frame.sun.illuminance = postfx::Vec3(1.0f);
    frame.ambient = kAmbient;
    frame.cameraCut = cut;
    frame.timeSeconds = 0.0;
    return frame;
}

double panYaw(uint32_t frame) {
    return glm::radians(kCloudsPanDegPerFrame * double(frame));
}

// The reference of the frame's view at every stride-th pixel in x and y, over the GPU's atmosphere-only
// image `sky` (full size), with the noise texels `base` and `detail`.
// With `paths` > 0 the path-traced truth instead of the model, and its standard error in `standardError`.
bool reference(const postfx::FrameInfo& frame, const CloudsRunArgs& args, const std::vector<float>& sky,
               const std::vector<float>& base, const std::vector<float>& detail, std::vector<float>& out,
               std::string& error, uint32_t s, uint32_t paths = 0,
               std::vector<float>* standardError = nullptr) {
    const uint32_t W = args.runner.width, H = args.runner.height;
    const uint32_t w = (W + s - 1) / s, h = (H + s - 1) / s;
    std::vector<float> subColor(size_t(w) * h * 4), subDepth(size_t(w) * h, 0.0f);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const size_t src = size_t(j) * s * W + size_t(i) * s, dst = size_t(j) * w + i;
            std::memcpy(&subColor[dst * 4], &sky[src * 4], 4 * sizeof(float));
        }
    postfx::reference::CloudInputs in;
    in.width = w;
    in.height = h;
    in.color = subColor;
    in.depth = subDepth;
    in.depthConvention.reversedZ = true;
    in.camera = frame.camera;
    if (s > 1) {
        // As bench/atmosphere_run.cpp: pixel i of the w-wide image is the frame's pixel i·s.
        const double sx = double(s) * w / W, sy = double(s) * h / H;
        const double ox = sx - 1.0 + (1.0 - s) / double(W), oy = sy - 1.0 + (1.0 - s) / double(H);
        glm::dmat4 inverseA(1.0);
        inverseA[0][0] = 1.0 / sx;
        inverseA[1][1] = 1.0 / sy;
        inverseA[3][0] = -ox / sx;
        inverseA[3][1] = -oy / sy;
        in.camera.projection = glm::mat4(inverseA * glm::dmat4(frame.camera.projection));
    }
    in.sun = frame.sun;
    in.ambient = frame.ambient;
    in.timeSeconds = frame.timeSeconds;
    in.settings = frame.clouds;
    in.atmosphere = frame.atmosphere;
    in.baseNoise = base;
    in.detailNoise = detail;
    in.stepsPerPixel = args.referenceSteps;
    in.lightSteps = args.referenceLightSteps;
    in.pathTraced = paths > 0;
    in.pathSamples = std::max(paths, 2u);
    if (const postfx::Status st = postfx::reference::renderClouds(in, out, standardError); !st.ok()) {
        error = "renderClouds: " + st.message;
        return false;
    }
    return true;
}

double luminance(const float* p) {
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The error of the full-size `image` against the strided reference.
CloudsError compare(const std::vector<float>& image, const std::vector<float>& ref, uint32_t width,
                    uint32_t height, uint32_t stride) {
    const uint32_t w = (width + stride - 1) / stride, h = (height + stride - 1) / stride;
    std::vector<float> a;
    a.reserve(size_t(w) * h * 4);
    double relY = 0.0;
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const size_t src = (size_t(j) * stride * width + size_t(i) * stride) * 4;
            a.insert(a.end(), &image[src], &image[src] + 4);
            const double yr = luminance(&ref[(size_t(j) * w + i) * 4]);
            relY += std::abs(luminance(&image[src]) - yr) / std::max(yr, 1e-6);
        }
    const test::ImageStats s = test::compareImages(a, ref, w, h, 0.01, 1e-6);
    CloudsError e;
    e.stats = ErrorStats{s.relativeRmse, s.maxAbsError, s.fractionOff, s.nonFinite, tonemappedRmse(a, ref)};
    e.meanRelativeLuminance = relY / (double(w) * h);
    return e;
}

// Every k-th pixel in x and y of the w-wide `image` (k = 1: all of it).
std::vector<float> subsample(const std::vector<float>& image, uint32_t width, uint32_t height, uint32_t k) {
    const uint32_t w = (width + k - 1) / k, h = (height + k - 1) / k;
    std::vector<float> out;
    out.reserve(size_t(w) * h * 4);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const size_t src = (size_t(j) * k * width + size_t(i) * k) * 4;
            out.insert(out.end(), &image[src], &image[src] + 4);
        }
    return out;
}

// `image` against the truth, both w×h, over the pixels where the truth differs from the sky by more than
// 1 % in luminance (the clouds' pixels).
CloudsTruthError compareTruth(const std::vector<float>& image, const std::vector<float>& truth,
                              const std::vector<float>& sky, uint32_t w, uint32_t h) {
    double sumImage = 0.0, sumTruth = 0.0, sumSquares = 0.0, sumTruthSquares = 0.0;
    for (size_t p = 0; p < size_t(w) * h; ++p) {
        const double y = luminance(&image[p * 4]), yt = luminance(&truth[p * 4]), ys = luminance(&sky[p * 4]);
        if (!(std::abs(yt - ys) > 0.01 * ys)) continue;
        sumImage += y;
        sumTruth += yt;
        sumSquares += (y - yt) * (y - yt);
        sumTruthSquares += yt * yt;
    }
    CloudsTruthError e;
    if (sumTruth > 0.0) {
        e.bias = sumImage / sumTruth - 1.0;
        e.relativeRmse = std::sqrt(sumSquares / sumTruthSquares);
    }
    return e;
}

// The mean of the standard error's luminance relative to the truth's, over the clouds' pixels.
double meanRelativeStandardError(const std::vector<float>& truth, const std::vector<float>& standardError,
                                 const std::vector<float>& sky) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t p = 0; p < truth.size() / 4; ++p) {
        const double yt = luminance(&truth[p * 4]), ys = luminance(&sky[p * 4]);
        if (!(std::abs(yt - ys) > 0.01 * ys)) continue;
        sum += luminance(&standardError[p * 4]) / yt;
        ++n;
    }
    return n ? sum / double(n) : NAN;
}

// With POSTFX_BENCH_DUMP=DIR: `image` at every stride-th pixel (the error's pixels) as DIR/name.pfm (RGB
// float, bottom row first), to look at where an error comes from.
void dump(const std::string& name, const std::vector<float>& image, uint32_t width, uint32_t height,
          uint32_t stride) {
    const char* dir = std::getenv("POSTFX_BENCH_DUMP");
    if (!dir || !*dir) return;
    std::filesystem::create_directories(dir);
    const uint32_t w = (width + stride - 1) / stride, h = (height + stride - 1) / stride;
    FILE* f = std::fopen((std::string(dir) + "/" + name + ".pfm").c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "PF\n%u %u\n-1.0\n", w, h);
    for (uint32_t j = h; j-- > 0;)
        for (uint32_t i = 0; i < w; ++i)
            std::fwrite(&image[(size_t(j) * stride * width + size_t(i) * stride) * 4], sizeof(float), 3, f);
    std::fclose(f);
}

bool readNoise(FrameGpu& gpu, const char* name, std::vector<float>& out, std::string& error) {
    std::vector<uint8_t> bytes;
    VkExtent3D extent{};
    if (!gpu.readHeld(name, bytes, extent, error)) return false;
    out.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i)
        out[i] = float(bytes[i]) / 255.0f;
    return true;
}

}  // namespace

int runClouds(const CloudsRunArgs& args, const std::string& commandLine, const std::string& date) {
    std::string error;
    std::vector<CloudsView> views;
    for (const CloudsView& v : cloudsViews())
        if (args.views.empty() || std::count(args.views.begin(), args.views.end(), v.name))
            views.push_back(v);
    for (const std::string& name : args.views)
        if (std::none_of(views.begin(), views.end(), [&](const CloudsView& v) { return v.name == name; }))
            return fail("--clouds-views: unknown view '" + name + "'");
    std::vector<CloudsPoint> points;
    if (!cloudsSweep(args.sweep, points, error)) return fail("--clouds-sweep: " + error);
    if (args.shadowMapSize)
        for (CloudsPoint& p : points)
            p.settings.shadowMap.size = args.shadowMapSize;
    auto sweeps = [&](const std::string& view) {
        return args.sweepViews.empty() ||
               std::count(args.sweepViews.begin(), args.sweepViews.end(), view) > 0;
    };

    const uint32_t truthStride = args.truthStride ? args.truthStride : 4 * args.errorStride;
    if (truthStride % args.errorStride != 0)
        return fail("--clouds-truth-stride " + std::to_string(truthStride) +
                    " is not a multiple of --error-stride " + std::to_string(args.errorStride));
    FrameGpu gpu;
    if (!gpu.create(args.runner, error)) return fail(error);
    CloudsInfo info;
    fillRunHeader(info.run, *gpu.host, args.runner, args.errorStride, args.referenceSteps, date, commandLine);
    if (!gpu.calibrate(info.run.calibration, error)) return fail(error);
    info.referenceLightSteps = args.referenceLightSteps;
    info.convergedFrames = args.convergedFrames;
    info.motionFrames = args.motionFrames;
    info.truthPaths = args.truthPaths;
    info.truthStride = truthStride;

    size_t total = 0;
    for (const CloudsView& v : views)
        total += sweeps(v.name) ? points.size() : 1;
    std::fprintf(stderr, "postfx-bench --clouds on %s, %ux%u, %zu measurements\n", info.run.device.c_str(),
                 info.run.width, info.run.height, total);

    const uint32_t W = args.runner.width, H = args.runner.height;
    const uint32_t M = std::max(1u, args.motionFrames);
    std::vector<CloudsRow> rows;
    {
        // No geometry: the atmosphere draws the sky (and the planet's ground below the horizon).
        std::vector<float> color(size_t(W) * H * 4, 0.0f), depth(size_t(W) * H, 0.0f);
        for (size_t i = 3; i < color.size(); i += 4)
            color[i] = 1.0f;
        if (!gpu.upload(color, depth, error)) return fail(error);
        Progress progress(total);
        for (const CloudsView& view : views) {
            // The GPU's atmosphere alone, still and at the pan's last frame: the references' background.
            std::vector<float> skyStill, skyMoved;
            if (!gpu.render(frameOf(view, nullptr, 0.0, true, W, H), skyStill, error) ||
                !gpu.render(frameOf(view, nullptr, panYaw(M - 1), true, W, H), skyMoved, error))
                return fail(view.name + " atmosphere: " + error);
            struct References {
                std::vector<float> still, motion;
            };
            // The model's references by noise sizes and model; the truth by noise sizes.
            std::map<std::tuple<uint32_t, uint32_t, uint32_t>, References> references;
            std::map<std::pair<uint32_t, uint32_t>, std::vector<float>> truths;
            const uint32_t truthFactor = truthStride / args.errorStride;
            const uint32_t tw = (W + truthStride - 1) / truthStride, th = (H + truthStride - 1) / truthStride;
            const std::vector<float> skyTruth = subsample(skyStill, W, H, truthStride);
            for (const CloudsPoint& point : points) {
                if (point.knob != "default" && !sweeps(view.name)) continue;
                const std::string label =
                    view.name + " " +
                    (point.knob == "default" ? std::string("default") : point.knob + "=" + point.value);
                CloudsRow row;
                row.view = view.name;
                row.point = point;
                const postfx::CloudSettings& s = point.settings;
                // Still: converged (temporal) or one frame.
                progress.show(label + " still");
                row.stillFrames = s.temporal.enabled ? std::max(1u, args.convergedFrames) : 1;
                std::vector<float> image;
                for (uint32_t n = 0; n < row.stillFrames; ++n)
                    if (!gpu.render(frameOf(view, &s, 0.0, n == 0, W, H), image, error))
                        return fail(label + ": " + error);
                const std::pair<uint32_t, uint32_t> noiseKey{s.noise.baseSize, s.noise.detailSize};
                const std::tuple<uint32_t, uint32_t, uint32_t> key{s.noise.baseSize, s.noise.detailSize,
                                                                   uint32_t(s.multipleScattering.model)};
                const std::string noise =
                    std::to_string(noiseKey.first) + "/" + std::to_string(noiseKey.second);
                if (!references.count(key) || (args.truthPaths && !truths.count(noiseKey))) {
                    std::vector<float> base, detail;
                    if (!readNoise(gpu, "clouds.base_noise", base, error) ||
                        !readNoise(gpu, "clouds.detail_noise", detail, error))
                        return fail(label + ": " + error);
                    if (!references.count(key)) {
                        References& r = references[key];
                        progress.show(view.name + " reference, noise " + noise + " (" +
                                      std::to_string(args.referenceSteps) + " steps)");
                        const auto start = std::chrono::steady_clock::now();
                        if (!reference(frameOf(view, &s, 0.0, false, W, H), args, skyStill, base, detail,
                                       r.still, error, args.errorStride) ||
                            !reference(frameOf(view, &s, panYaw(M - 1), false, W, H), args, skyMoved, base,
                                       detail, r.motion, error, args.errorStride))
                            return fail(label + ": " + error);
                        info.referenceSeconds.emplace_back(
                            view.name + " noise " + noise + " " + cloudsKnobValue(s, "model"),
                            secondsSince(start));
                    }
                    if (args.truthPaths && !truths.count(noiseKey)) {
                        progress.show(view.name + " path-traced truth, noise " + noise + " (" +
                                      std::to_string(args.truthPaths) + " paths)");
                        const auto start = std::chrono::steady_clock::now();
                        std::vector<float> standardError;
                        if (!reference(frameOf(view, &s, 0.0, false, W, H), args, skyStill, base, detail,
                                       truths[noiseKey], error, truthStride, args.truthPaths, &standardError))
                            return fail(label + " truth: " + error);
                        info.truthSeconds.emplace_back(view.name + " noise " + noise, secondsSince(start));
                        info.truthStandardError.emplace_back(
                            view.name + " noise " + noise,
                            meanRelativeStandardError(truths[noiseKey], standardError, skyTruth));
                    }
                    gpu.idle = true;
                }
                const References& ref = references[key];
                row.still = compare(image, ref.still, W, H, args.errorStride);
                if (args.truthPaths) {
                    const std::vector<float>& truth = truths[noiseKey];
                    const uint32_t rw = (W + args.errorStride - 1) / args.errorStride;
                    const uint32_t rh = (H + args.errorStride - 1) / args.errorStride;
                    row.model =
                        compareTruth(subsample(ref.still, rw, rh, truthFactor), truth, skyTruth, tw, th);
                    row.total = compareTruth(subsample(image, W, H, truthStride), truth, skyTruth, tw, th);
                }
                const std::string dumpName =
                    view.name + "_" + (point.knob == "default" ? "default" : point.knob + "_" + point.value);
                dump(dumpName + "_still_gpu", image, W, H, args.errorStride);
                dump(dumpName + "_still_reference", ref.still, (W + args.errorStride - 1) / args.errorStride,
                     (H + args.errorStride - 1) / args.errorStride, 1);
                // In motion: the camera panning, the last frame against its own view's reference.
                progress.show(label + " motion");
                row.motionFrames = M;
                for (uint32_t n = 0; n < M; ++n)
                    if (!gpu.render(frameOf(view, &s, panYaw(n), n == 0, W, H), image, error))
                        return fail(label + ": " + error);
                row.motion = compare(image, ref.motion, W, H, args.errorStride);
                dump(dumpName + "_motion_gpu", image, W, H, args.errorStride);
                dump(dumpName + "_motion_reference", ref.motion,
                     (W + args.errorStride - 1) / args.errorStride,
                     (H + args.errorStride - 1) / args.errorStride, 1);
                // Timing: camera and sun still.
                progress.show(label + " timing");
                if (!gpu.measure([&](uint32_t n) { return frameOf(view, &s, 0.0, n == 0, W, H); }, row.timing,
                                 row.passFrames, error, isCloudsPass))
                    return fail(label + ": " + error);
                rows.push_back(std::move(row));
                progress.advance();
            }
        }
        progress.show("writing the report");
    }

    const std::vector<std::string> messages = gpu.host->validationMessages();
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) return fail("cannot create '" + args.out + "': " + ec.message());
    const std::string csv = args.out + "/results.csv", md = args.out + "/results.md";
    if (!writeCloudsCsv(csv, info, rows, error) || !writeCloudsMarkdown(md, info, rows, error))
        return fail(error);

    std::printf("postfx-bench --clouds: %s, %ux%u, error stride %u, reference %u x %u steps\n",
                info.run.device.c_str(), W, H, args.errorStride, args.referenceSteps,
                args.referenceLightSteps);
    std::printf("%-14s %-24s %9s %9s %9s %9s %9s %10s %10s %10s %8s %3s\n", "view", "setting", "GPU ms",
                "shadow", "march", "temporal", "upsample", "still RMSE", "moving", "still TM", "calib ms",
                "re");
    for (const CloudsRow& r : rows) {
        const std::string setting =
            r.point.knob == "default" ? "default" : r.point.knob + "=" + r.point.value;
        std::printf("%-14s %-24s %9s", r.view.c_str(), setting.c_str(),
                    orDash(formatNumber(r.timing.median, 4)).c_str());
        for (const char* pass : {"clouds.shadow", "clouds.march", "clouds.temporal", "clouds.upsample"})
            std::printf(" %9s", orDash(formatNumber(cloudsPassMs(r, pass), 3)).c_str());
        std::printf(
            " %10s %10s %10s %8s %3s\n", percent(r.still.stats.relativeRmse).c_str(),
            percent(r.motion.stats.relativeRmse).c_str(), percent(r.still.stats.tonemappedRmse).c_str(),
            calibrationMsText(r.timing.calibration).c_str(), remeasuredText(r.timing.calibration).c_str());
    }
    std::printf("%s", cloudsSummary(info, rows).c_str());
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
