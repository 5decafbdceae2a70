#include "atmosphere_run.h"

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

constexpr uint32_t kFramesInFlight = 2;
constexpr VkPipelineStageFlags kAll = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkImageLayout kDepthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The bench's own host for postfx's atmosphere (the demo renderer has no atmosphere): the view's colour
// (RGBA16F, only read) and depth (D32) uploaded once, postfx's result in a separate output image, frames
// recorded two in flight into the bench's command buffers and timed by Context::readPassTimings as
// bench/runner.h does for the fogs.
class AtmosphereGpu {
public:
    ~AtmosphereGpu() {
        if (!host) return;
        const VkDevice device = host->device;
        vkDeviceWaitIdle(device);
        context.reset();
        for (VkFence f : fences)
            if (f) vkDestroyFence(device, f, nullptr);
        for (VkCommandBuffer c : commandBuffers)
            if (c) vkFreeCommandBuffers(device, host->commandPool, 1, &c);
        demo::destroyImage(device, color);
        demo::destroyImage(device, depth);
        demo::destroyImage(device, output);
        demo::destroyBuffer(device, staging);
    }

    bool create(const RunnerOptions& opts, std::string& error) {
        options = opts;
        demo::HostOptions hostOptions;
        hostOptions.validation = options.validation;
        host = demo::VulkanHost::create(hostOptions, error);
        if (!host) {
            error = "Vulkan: " + error;
            return false;
        }
        const VkDevice device = host->device;
        const VkExtent2D extent{options.width, options.height};
        postfx::ContextCreateInfo ci;
        ci.instance = host->instance;
        ci.physicalDevice = host->physicalDevice;
        ci.device = host->device;
        ci.getInstanceProcAddr = vkGetInstanceProcAddr;
        ci.getDeviceProcAddr = vkGetDeviceProcAddr;
        ci.queueFamilyIndex = host->queueFamily;
        ci.maxExtent = extent;
        ci.depth.reversedZ = true;
        ci.framesInFlight = kFramesInFlight;
        ci.debugLabels = host->debugUtilsEnabled;
        if (const postfx::Status s = postfx::Context::create(ci, context); !s.ok()) {
            error = "postfx context: " + s.message;
            return false;
        }
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = host->commandPool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = kFramesInFlight;
        if (!demo::vkCheck(vkAllocateCommandBuffers(device, &ai, commandBuffers.data()),
                           "vkAllocateCommandBuffers", error))
            return false;
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fci.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        for (VkFence& f : fences)
            if (!demo::vkCheck(vkCreateFence(device, &fci, nullptr, &f), "vkCreateFence", error))
                return false;
        const VkImageUsageFlags colorUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        const VkImageUsageFlags outputUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        const VkImageUsageFlags depthUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        const size_t pixels = size_t(extent.width) * extent.height;
        return demo::createImage(*host, VK_FORMAT_R16G16B16A16_SFLOAT, extent, colorUsage, color, error) &&
               demo::createImage(*host, VK_FORMAT_R16G16B16A16_SFLOAT, extent, outputUsage, output, error) &&
               demo::createImage(*host, VK_FORMAT_D32_SFLOAT, extent, depthUsage, depth, error) &&
               demo::createBuffer(*host, VkDeviceSize(pixels) * 12,
                                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                                  staging, error);
    }

    // Uploads a view's images (full size): colour RGBA, depth one float a pixel.
    bool upload(const std::vector<float>& rgba, const std::vector<float>& depthValues, std::string& error) {
        if (!waitAll(error)) return false;
        const size_t pixels = depthValues.size();
        auto* half = static_cast<uint16_t*>(staging.mapped);
        for (size_t i = 0; i < rgba.size(); ++i)
            half[i] = glm::packHalf1x16(rgba[i]);
        std::memcpy(static_cast<char*>(staging.mapped) + pixels * 8, depthValues.data(), pixels * 4);
        idle = true;
        return host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                for (const demo::GpuImage* image : {&color, &depth})
                    demo::imageBarrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED,
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kAll,
                                       VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT, kTransfer,
                                       VK_ACCESS_TRANSFER_WRITE_BIT);
                VkBufferImageCopy region{};
                region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                region.imageExtent = {options.width, options.height, 1};
                vkCmdCopyBufferToImage(cmd, staging.buffer, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                       1, &region);
                region.bufferOffset = pixels * 8;
                region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
                vkCmdCopyBufferToImage(cmd, staging.buffer, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                       1, &region);
                const VkAccessFlags any = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
                demo::imageBarrier(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                                   kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, kAll, any);
                demo::imageBarrier(cmd, depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kDepthLayout, kTransfer,
                                   VK_ACCESS_TRANSFER_WRITE_BIT, kAll, any);
                demo::imageBarrier(cmd, output, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kAll, any,
                                   kAll, any);
            },
            error);
    }

    // Times frames n = 0, 1, ... of frameAt (warm-up, then options.frames timed), two in flight.
    bool measure(const std::function<postfx::FrameInfo(uint32_t)>& frameAt, Timing& timing,
                 std::vector<std::pair<std::string, uint32_t>>& passFrames, std::string& error) {
        std::vector<double> totals;
        std::vector<std::pair<std::string, std::vector<double>>> passes;
        auto collect = [&](uint64_t frameIndex) -> bool {
            std::vector<postfx::PassTiming> timings;
            const postfx::Status s = context->readPassTimings(frameIndex, timings);
            if (s.code == postfx::Result::Unsupported) return true;  // no timestamps on this queue
            if (!s.ok()) {
                error = "readPassTimings(" + std::to_string(frameIndex) + "): " + s.message;
                return false;
            }
            double total = 0.0;
            for (const postfx::PassTiming& t : timings) {
                auto it = std::find_if(passes.begin(), passes.end(),
                                       [&](const auto& p) { return p.first == t.name; });
                if (it == passes.end()) it = passes.insert(passes.end(), {t.name, {}});
                it->second.push_back(t.milliseconds);
                total += t.milliseconds;
            }
            totals.push_back(total);
            return true;
        };
        struct InFlight {
            bool active = false, timed = false;
            uint64_t frame = 0;
        };
        std::array<InFlight, kFramesInFlight> inFlight{};
        auto retire = [&](size_t slot) -> bool {
            if (!wait(slot, error)) return false;
            InFlight& f = inFlight[slot];
            const bool ok = !f.active || !f.timed || collect(f.frame);
            f.active = false;
            return ok;
        };
        const auto start = std::chrono::steady_clock::now();
        const double warmupMs = idle ? std::max(options.warmupMs, options.coldWarmupMs) : options.warmupMs;
        idle = false;
        uint32_t warmupFrames = 0, timedFrames = 0;
        for (uint32_t n = 0; timedFrames < options.frames; ++n) {
            const bool timed =
                timedFrames > 0 || (warmupFrames >= options.warmup && secondsSince(start) * 1e3 >= warmupMs);
            ++(timed ? timedFrames : warmupFrames);
            const uint64_t frameIndex = nextFrame++;
            const size_t slot = frameIndex % kFramesInFlight;
            if (!retire(slot) || !submit(slot, frameAt(n), frameIndex, false, error)) return false;
            inFlight[slot] = {true, timed, frameIndex};
        }
        for (uint64_t f = nextFrame - kFramesInFlight; f < nextFrame; ++f)
            if (!retire(f % kFramesInFlight)) return false;
        timing = summarize(totals, passes);
        passFrames.clear();
        for (const auto& [name, values] : passes)
            passFrames.emplace_back(name, uint32_t(values.size()));
        return true;
    }

    // Records `frame` once and reads its output back: RGBA floats, full size.
    bool render(const postfx::FrameInfo& frame, std::vector<float>& rgba, std::string& error) {
        if (!waitAll(error)) return false;
        const uint64_t frameIndex = nextFrame++;
        const size_t slot = frameIndex % kFramesInFlight;
        if (!submit(slot, frame, frameIndex, true, error) || !wait(slot, error)) return false;
        const auto* half = static_cast<const uint16_t*>(staging.mapped);
        rgba.resize(size_t(options.width) * options.height * 4);
        for (size_t i = 0; i < rgba.size(); ++i)
            rgba[i] = glm::unpackHalf1x16(half[i]);
        return true;
    }

    std::unique_ptr<demo::VulkanHost> host;
    RunnerOptions options;
    bool idle = true;  // the GPU sat idle (a CPU reference): the next warm-up is coldWarmupMs

private:
    bool wait(size_t slot, std::string& error) {
        return demo::vkCheck(vkWaitForFences(host->device, 1, &fences[slot], VK_TRUE, UINT64_MAX),
                             "vkWaitForFences", error);
    }
    bool waitAll(std::string& error) {
        for (size_t slot = 0; slot < kFramesInFlight; ++slot)
            if (!wait(slot, error)) return false;
        return true;
    }

    bool submit(size_t slot, postfx::FrameInfo frame, uint64_t frameIndex, bool readback,
                std::string& error) {
        VkCommandBuffer cmd = commandBuffers[slot];
        vkResetCommandBuffer(cmd, 0);
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &bi);
        // The previous frame's work on the output (postfx's writes, a read-back) before this frame's.
        VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_MEMORY_READ_BIT;
        barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, kAll, kAll, 0, 1, &barrier, 0, nullptr, 0, nullptr);
        const VkExtent2D extent{options.width, options.height};
        frame.commandBuffer = cmd;
        frame.frameIndex = frameIndex;
        frame.color = {color.image, color.view, color.format, extent, VK_IMAGE_LAYOUT_GENERAL, color.usage};
        frame.depth = {depth.image, depth.view, depth.format, extent, kDepthLayout, depth.usage};
        frame.output = {output.image, output.view, output.format, extent, VK_IMAGE_LAYOUT_GENERAL,
                        output.usage};
        const postfx::Status status = context->record(frame);
        if (readback && status.ok()) {
            demo::imageBarrier(cmd, output, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               kAll, VK_ACCESS_MEMORY_WRITE_BIT, kTransfer, VK_ACCESS_TRANSFER_READ_BIT);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {extent.width, extent.height, 1};
            vkCmdCopyImageToBuffer(cmd, output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1,
                                   &region);
            demo::imageBarrier(cmd, output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                               kTransfer, VK_ACCESS_TRANSFER_READ_BIT, kAll,
                               VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
            demo::bufferBarrier(cmd, staging, kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT,
                                VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
        }
        if (!demo::vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error)) return false;
        if (!status.ok()) {
            error = "Context::record: " + status.message;
            return false;
        }
        vkResetFences(host->device, 1, &fences[slot]);
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        return demo::vkCheck(vkQueueSubmit(host->queue, 1, &si, fences[slot]), "vkQueueSubmit", error);
    }

    std::unique_ptr<postfx::Context> context;
    std::array<VkCommandBuffer, kFramesInFlight> commandBuffers{};
    std::array<VkFence, kFramesInFlight> fences{};
    demo::GpuImage color, depth, output;
    demo::GpuBuffer staging;  // upload (colour RGBA16F, depth D32) and read-back (output RGBA16F)
    uint64_t nextFrame = 0;
};

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
        return ErrorStats{s.relativeRmse, s.maxAbsError, s.fractionOff, s.nonFinite};
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

    AtmosphereGpu gpu;
    if (!gpu.create(args.runner, error)) return fail(error);
    AtmosphereInfo info;
    fillRunHeader(info.run, *gpu.host, args.runner, args.errorStride, args.referenceSteps, date, commandLine);
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
    std::printf("%-14s %-7s %-26s %9s %9s %9s %9s %9s %9s %9s %9s\n", "view", "frame", "setting", "GPU ms",
                "trans", "ms", "sky_view", "ap", "apply", "sky RMSE", "geo RMSE");
    for (const AtmosphereRow& r : rows) {
        const std::string setting =
            r.point.knob == "default" ? "defaults" : r.point.knob + "=" + r.point.value;
        std::printf("%-14s %-7s %-26s %9s", r.view.c_str(), situationName(r.situation), setting.c_str(),
                    formatNumber(r.timing.median, 4).c_str());
        for (const char* pass : kAtmospherePasses)
            std::printf(" %9s", orDash(formatNumber(atmospherePassMs(r, pass), 3)).c_str());
        std::printf(" %9s %9s\n", percent(r.sky.relativeRmse).c_str(),
                    r.geometryPixels ? percent(r.geometry.relativeRmse).c_str() : "–");
    }
    std::printf("%s", atmosphereSummary(info, rows).c_str());
    std::printf("wrote %s, %s\n", csv.c_str(), md.c_str());
    if (!messages.empty()) {
        for (const std::string& m : messages)
            std::fprintf(stderr, "validation: %s\n", m.c_str());
        return fail(std::to_string(messages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace bench
