// postfx-render: renders a demo scene headless (G-buffer, sun + shadow map, lighting, postfx) and
// writes the HDR result as .exr (linear, 32-bit float) or .png (tonemapped). With --reference the
// atmosphere, the clouds and the fog (ray-marched or froxel) come from postfx's CPU references
// (Renderer::renderReference) instead of the GPU passes; with --reference=path the clouds are path-traced
// and their standard error written beside the output.
#include "program.h"

#include <nlohmann/json.hpp>
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/motion.h"
#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

namespace cli = demo::cli;

namespace {

constexpr uint32_t kMaxFrames = 100000;
constexpr uint32_t kDefaultReferenceSteps = 4096;
constexpr uint32_t kMaxReferenceSteps = 1u << 20;
constexpr uint32_t kDefaultPathSamples = 64;
constexpr uint32_t kMaxPathSamples = 1u << 24;

const char* kUsage =
    "usage: postfx-render [SCENE.json] -o OUT.exr|OUT.png [--size WxH] [--frames N] [--standard-z]\n"
    "                     [--infinite-far] [--validation]\n"
    "                     [--reference|--reference=path [--reference-steps N] [--path-samples N]]\n"
    "       postfx-render [SCENE.json] --print-plan [--size WxH] [--frames N] [--standard-z] ...\n"
    "Renders SCENE.json (the built-in default scene when omitted) headless and writes OUT:\n"
    "  .exr  linear radiance [cd/m^2], 32-bit float RGBA\n"
    "  .png  tonemapped with the camera's ev100 (ACES fitted, sRGB)\n"
    "options:\n"
    "  -o, --output PATH  output image (required)\n"
    "  --size WxH         image size in pixels (default 1280x720), each side 1..16384, at most\n"
    "                     67108864 pixels (8192x8192: about 128 bytes per pixel within 8 GiB)\n"
    "  --frames N         render frames 0..N-1, each in its state of the scene's motion (camera\n"
    "                     and light velocities, intensity changes, camera cut; docs/scene-format.md),\n"
    "                     and write the last (default 1)\n"
    "  --standard-z       standard depth (near 0, far 1) instead of reversed Z\n"
    "  --infinite-far     projection without a far plane\n"
    "  --validation       Vulkan validation layer with synchronization validation (also\n"
    "                     POSTFX_VALIDATION=1); any validation message fails the run, one\n"
    "                     at the device's destruction (an object left alive) included\n"
    "  --reference        the atmosphere (its model without LUTs) and the fog (ray-marched or froxel)\n"
    "                     from postfx's CPU references (double precision, no jitter, all CPU\n"
    "                     threads) instead of the GPU passes, over the same GPU frame (the last,\n"
    "                     N-1, in its state: a single frame, no history)\n"
    "  --reference=path   as --reference, with the clouds from a Monte Carlo volumetric path tracer\n"
    "                     (every scattering order; docs/effects/clouds.md, \"Path-traced truth\")\n"
    "                     instead of the model's march; writes the clouds' standard error per pixel\n"
    "                     to OUT's stem + .stderr.exr and prints its mean relative to the pixels\n"
    "  --reference-steps N  march steps per pixel of --reference (default 4096), 1..1048576\n"
    "  --path-samples N   paths per pixel of --reference=path (default 64), 2..16777216\n"
    "  --print-plan       print postfx's frame plan of the last frame (docs/frame-plan.md) as JSON on\n"
    "                     stdout instead of writing an image: the frames before it are rendered\n"
    "                     (so --frames 2 shows the steady state, without one-time work)\n"
    "environment: POSTFX_DEVICE=<substring of the device name> picks the Vulkan device\n";

const cli::Program kProgram("postfx-render", kUsage, 2);

struct Args {
    cli::CommonArgs common;  // scene, --size, --frames, --validation
    std::string output;
    demo::RenderOptions render;  // --size and --frames copied in
    bool reference = false;
    uint32_t referenceSteps = kDefaultReferenceSteps;
    bool referenceStepsGiven = false;
    bool pathTraced = false;  // --reference=path
    uint32_t pathSamples = kDefaultPathSamples;
    bool pathSamplesGiven = false;
    bool printPlan = false;
};

Args parseArgs(int argc, char** argv) {
    Args args;
    args.common.frames = args.render.frames;
    cli::parseArgs(argc, argv, kMaxFrames, args.common, [&](const std::string& a, const auto& next) {
        if (a == "-o" || a == "--output") {
            args.output = next();
        } else if (a == "--standard-z") {
            args.render.reversedZ = false;
        } else if (a == "--infinite-far") {
            args.render.infiniteFar = true;
        } else if (a == "--print-plan") {
            args.printPlan = true;
        } else if (a == "--reference" || a == "--reference=path") {
            args.reference = true;
            args.pathTraced = a == "--reference=path";
        } else if (a.rfind("--reference=", 0) == 0) {
            throw cli::UsageError{"'" + a + "': expected --reference or --reference=path"};
        } else if (a == "--path-samples") {
            cli::uintOption(a, next(), 2, kMaxPathSamples, args.pathSamples);
            args.pathSamplesGiven = true;
        } else if (a == "--reference-steps") {
            cli::uintOption(a, next(), 1, kMaxReferenceSteps, args.referenceSteps);
            args.referenceStepsGiven = true;
        } else {
            return false;
        }
        return true;
    });
    args.render.width = args.common.width;
    args.render.height = args.common.height;
    args.render.frames = args.common.frames;
    if (args.printPlan) {
        if (!args.output.empty() || args.reference)
            throw cli::UsageError{"--print-plan writes no image: leave out -o and --reference"};
        return args;
    }
    if (args.output.empty())
        throw cli::UsageError{"no output file given (-o OUT.exr or -o OUT.png; see --help)"};
    if (args.referenceStepsGiven && !args.reference)
        throw cli::UsageError{"--reference-steps needs --reference"};
    if (args.pathSamplesGiven && !args.pathTraced)
        throw cli::UsageError{"--path-samples needs --reference=path"};
    std::string ext = std::filesystem::path(args.output).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".exr" && ext != ".png")
        throw cli::UsageError{"output '" + args.output + "': unsupported extension '" +
                              (ext.empty() ? "(none)" : ext) + "' (expected .exr or .png)"};
    return args;
}

int fail(const std::string& message) {
    return kProgram.fail(message);
}

// {"passes":[{"name", "effect", "reads", "writes", "groups"}], "resources":[{"name", "effect", "bytes",
// "sized_by" (when a setting sizes it)}], "total_bytes", "adjusted" (when postfx uses an input other
// than as given: one line each)}: postfx's own passes and memory only.
nlohmann::ordered_json planJson(const postfx::FramePlan& plan) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array(),
                           resources = nlohmann::ordered_json::array();
    for (const postfx::PlannedPass& p : plan.passes)
        passes.push_back({{"name", p.name},
                          {"effect", p.effect},
                          {"reads", p.reads},
                          {"writes", p.writes},
                          {"groups", {p.groups[0], p.groups[1], p.groups[2]}}});
    for (const postfx::PlannedResource& r : plan.resources) {
        resources.push_back({{"name", r.name}, {"effect", r.effect}, {"bytes", r.bytes}});
        if (!r.sizedBy.empty()) resources.back()["sized_by"] = r.sizedBy;
    }
    nlohmann::ordered_json json = {
        {"passes", passes}, {"resources", resources}, {"total_bytes", plan.totalBytes()}};
    if (!plan.adjusted.empty()) json["adjusted"] = plan.adjusted;
    return json;
}

// --print-plan: renders frames 0..frames-2, then prints the plan of frame frames-1.
int printPlan(demo::VulkanHost& host, const Args& args, const demo::Scene& scene) {
    std::string error;
    demo::RenderOptions options = args.render;
    const uint32_t before = options.frames - 1;
    options.frames = std::max(before, 1u);
    auto renderer = demo::Renderer::create(host, options, error);
    if (!renderer) return fail(error);
    if (!renderer->setScene(scene, error)) return fail(error);
    demo::ImageF unused;
    if (before > 0 && !renderer->render(scene, unused, error)) return fail(error);
    postfx::FramePlan plan;
    if (!renderer->plan(demo::sceneAtFrame(scene, before), before, plan, error)) return fail(error);
    std::printf("%s\n", planJson(plan).dump(2).c_str());
    return 0;
}

double luminance(const float* rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

// --reference=path: writes the clouds' standard error to OUT's stem + .stderr.exr and prints its mean
// relative to the pixels' values (luminance) over the pixels the paths reached, and the time.
bool reportPathTracing(const Args& args, const demo::CloudsPathTracing& paths, const demo::ImageF& image,
                       double seconds) {
    const uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
    if (paths.standardError.empty()) {
        std::printf("reference=path: the scene has no clouds, %.1f s on %u threads\n", seconds, threads);
        return true;
    }
    double sum = 0.0;
    size_t pixels = 0;
    for (size_t p = 0; p * 4 < paths.standardError.size(); ++p) {
        const double e = luminance(&paths.standardError[p * 4]), value = luminance(&image.rgba[p * 4]);
        if (!(e > 0.0) || !(value > 0.0)) continue;
        sum += e / value;
        ++pixels;
    }
    const std::filesystem::path out(args.output);
    const std::string errorPath = (out.parent_path() / (out.stem().string() + ".stderr.exr")).string();
    demo::ImageF errorImage;
    errorImage.width = image.width;
    errorImage.height = image.height;
    errorImage.rgba = paths.standardError;
    std::string error;
    if (!demo::writeImage(errorPath, errorImage, 0.0f, error)) {
        fail(error);
        return false;
    }
    std::printf(
        "reference=path: clouds path-traced, %u paths/pixel, mean relative standard error %.3f%% "
        "over %zu cloud pixels (%s), %.1f s on %u threads\n",
        paths.samples, pixels ? 100.0 * sum / double(pixels) : 0.0, pixels, errorPath.c_str(), seconds,
        threads);
    return true;
}

int run(const Args& args) {
    demo::Scene scene;
    if (!kProgram.loadScene(args.common.scene, scene)) return 1;
    auto host = kProgram.createHost(args.common.validation);
    if (!host) return 1;
    if (args.printPlan) return kProgram.validationStatus(*host, printPlan(*host, args, scene));
    std::string error;
    {
        auto renderer = demo::Renderer::create(*host, args.render, error);
        if (!renderer) return fail(error);
        demo::ImageF image;
        if (args.reference) {
            demo::CloudsPathTracing paths;
            paths.samples = args.pathSamples;
            const auto start = std::chrono::steady_clock::now();
            if (!renderer->renderReference(scene, image, error, args.referenceSteps, 1,
                                           args.pathTraced ? &paths : nullptr))
                return fail(error);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (args.pathTraced && !reportPathTracing(args, paths, image, seconds)) return 1;
            if (scene.fog.enabled || scene.froxelFog.enabled) {
                std::printf("reference: %s, %u steps/pixel, %.1f s on %u threads\n",
                            scene.froxelFog.enabled ? "froxel fog" : "fog", args.referenceSteps, seconds,
                            std::max(1u, std::thread::hardware_concurrency()));
            } else {
                std::printf("reference: the scene has no fog (the un-fogged frame), %.1f s\n", seconds);
            }
        } else if (!renderer->render(scene, image, error)) {
            return fail(error);
        }
        if (!demo::writeImage(args.output, image, scene.camera.ev100, error)) return fail(error);
    }
    const std::string device = host->deviceDescription();
    if (int status = kProgram.validationStatus(*host)) return status;
    if (args.reference) {
        std::printf("postfx-render: wrote %s (%ux%u, frame %u with the CPU references) on %s\n",
                    args.output.c_str(), args.render.width, args.render.height, args.render.frames - 1,
                    device.c_str());
    } else {
        std::printf("postfx-render: wrote %s (%ux%u, %u frame%s) on %s\n", args.output.c_str(),
                    args.render.width, args.render.height, args.render.frames,
                    args.render.frames == 1 ? "" : "s", device.c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return kProgram.main(argc, argv, [&] { return run(parseArgs(argc, argv)); });
}
