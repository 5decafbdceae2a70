#include "first_frame.h"

#include "frame_run.h"

#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <postfx/postfx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

namespace bench {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

// vkCreateComputePipelines counted: the contexts' device functions come through this vkGetDeviceProcAddr.
PFN_vkCreateComputePipelines gCreatePipelines = nullptr;
uint64_t gPipelines = 0;

VKAPI_ATTR VkResult VKAPI_CALL countCreatePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                    const VkComputePipelineCreateInfo* infos,
                                                    const VkAllocationCallbacks* allocator, VkPipeline* out) {
    gPipelines += count;
    return gCreatePipelines(device, cache, count, infos, allocator, out);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingGetDeviceProcAddr(VkDevice device, const char* name) {
    if (std::strcmp(name, "vkCreateComputePipelines")) return vkGetDeviceProcAddr(device, name);
    gCreatePipelines = reinterpret_cast<PFN_vkCreateComputePipelines>(vkGetDeviceProcAddr(device, name));
    return reinterpret_cast<PFN_vkVoidFunction>(&countCreatePipelines);
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

struct Row {
    std::string scene, setup;
    double prewarmMs = NAN;
    uint64_t prewarmPipelines = 0;
    double firstMs = 0.0;
    uint64_t firstPipelines = 0;
    // The first frame's submission until the queue is idle: its GPU work (every build of a persistent
    // image) and what a driver compiles only when a pipeline first runs (llvmpipe: its LLVM code).
    double firstWaitMs = 0.0;
    double laterWorstMs = 0.0, laterMedianMs = 0.0;
    uint64_t laterPipelines = 0;
    postfx::MemoryUsage memory;  // after the first frame
};

// The host's side: the demo renderer's images (drawn once with postfx off), a command buffer, and a
// context per row on the renderer's device.
struct Bench {
    std::unique_ptr<demo::VulkanHost> host;
    std::unique_ptr<demo::Renderer> renderer;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    uint32_t frames = 0;

    bool submit(std::string& error) {
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        if (vkQueueSubmit(host->queue, 1, &si, VK_NULL_HANDLE) != VK_SUCCESS ||
            vkQueueWaitIdle(host->queue) != VK_SUCCESS) {
            error = "vkQueueSubmit or vkQueueWaitIdle failed";
            return false;
        }
        return true;
    }
    bool begin(std::string& error) {
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        if (vkBeginCommandBuffer(cmd, &bi) != VK_SUCCESS) {
            error = "vkBeginCommandBuffer failed";
            return false;
        }
        return true;
    }

    // One row: a new context (on `cache` when given), prewarmed or not, recording frames 0 .. frames of
    // `scene` (0 and the middle one camera cuts), each submitted and waited for.
    bool row(const demo::Scene& scene, VkPipelineCache cache, bool prewarm, Row& out, std::string& error) {
        postfx::ContextCreateInfo info = renderer->postfxContext().createInfo();
        info.getDeviceProcAddr = &countingGetDeviceProcAddr;
        info.pipelineCache = cache;
        info.messageCallback = nullptr;
        std::unique_ptr<postfx::Context> context;
        if (const postfx::Status s = postfx::Context::create(info, context); !s) {
            error = "postfx create: " + s.message;
            return false;
        }
        std::vector<double> later;
        for (uint32_t n = 0; n <= frames; ++n) {
            if (!begin(error)) return false;
            postfx::FrameInfo f = renderer->frameInputs(cmd, scene, n);
            f.cameraCut = n == 0 || n == frames / 2 + 1;
            if (n == 0 && prewarm) {
                const uint64_t before = gPipelines;
                const auto start = std::chrono::steady_clock::now();
                const postfx::Status s = context->prewarm(f);
                out.prewarmMs = msSince(start);
                out.prewarmPipelines = gPipelines - before;
                if (!s) {
                    error = "postfx prewarm: " + s.message;
                    return false;
                }
            }
            const uint64_t before = gPipelines;
            const auto start = std::chrono::steady_clock::now();
            const postfx::Status s = context->record(f);
            const double ms = msSince(start);
            if (!s) {
                error = "postfx record: " + s.message;
                return false;
            }
            if (n == 0) {
                out.firstMs = ms;
                out.firstPipelines = gPipelines - before;
                (void)context->memoryUsage(out.memory);
            } else {
                later.push_back(ms);
                out.laterPipelines += gPipelines - before;
            }
            if (vkEndCommandBuffer(cmd) != VK_SUCCESS) {
                error = "vkEndCommandBuffer failed";
                return false;
            }
            const auto submitted = std::chrono::steady_clock::now();
            if (!submit(error)) return false;
            if (n == 0) out.firstWaitMs = msSince(submitted);
        }
        if (!later.empty()) {
            std::sort(later.begin(), later.end());
            out.laterWorstMs = later.back();
            out.laterMedianMs = later[later.size() / 2];
        }
        vkDeviceWaitIdle(host->device);
        return true;
    }
};

VkPipelineCache newCache(VkDevice device, const std::vector<char>& data) {
    VkPipelineCacheCreateInfo ci{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    ci.initialDataSize = data.size();
    ci.pInitialData = data.empty() ? nullptr : data.data();
    VkPipelineCache cache = VK_NULL_HANDLE;
    return vkCreatePipelineCache(device, &ci, nullptr, &cache) == VK_SUCCESS ? cache : VK_NULL_HANDLE;
}

std::string fixed(double v, int digits = 1) {
    if (!std::isfinite(v)) return "–";
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

void printTable(const std::vector<Row>& rows) {
    std::printf(
        "\n| scene | setup | prewarm ms (pipelines) | first record ms (pipelines) | first submit to idle ms "
        "| "
        "later record ms: worst, median (pipelines) |\n|---|---|---|---|---|---|\n");
    for (const Row& r : rows) {
        const std::string prewarm = std::isfinite(r.prewarmMs)
                                        ? fixed(r.prewarmMs) + " (" + std::to_string(r.prewarmPipelines) + ")"
                                        : "–";
        std::printf("| %s | %s | %s | %s (%llu) | %s | %s, %s (%llu) |\n", r.scene.c_str(), r.setup.c_str(),
                    prewarm.c_str(), fixed(r.firstMs).c_str(), (unsigned long long)r.firstPipelines,
                    fixed(r.firstWaitMs).c_str(), fixed(r.laterWorstMs).c_str(),
                    fixed(r.laterMedianMs, 2).c_str(), (unsigned long long)r.laterPipelines);
    }
    std::printf("\nDevice memory after the first frame (Context::memoryUsage) [MiB]:\n");
    for (const Row& r : rows) {
        if (r.setup != "none") continue;
        std::printf("  %-18s total %.1f:", r.scene.c_str(), double(r.memory.totalBytes) / 1048576.0);
        for (const postfx::MemoryUsage::Owner& o : r.memory.owners)
            if (o.bytes) std::printf(" %s %.1f", o.name.c_str(), double(o.bytes) / 1048576.0);
        std::printf("\n");
    }
}

// Every size the GPU's work follows made small; no pipeline depends on them.
void shrink(demo::Scene& scene) {
    postfx::AtmosphereSettings& a = scene.atmosphere;
    a.transmittanceLutSize = {64, 16};
    a.multipleScatteringLutSize = {8, 8};
    a.scatteringOrdersLutSize = {4, 8, 4};
    a.scatteringOrdersAzimuthSize = 2;
    a.scatteringOrdersDirections = 16;
    a.skyViewLutSize = {32, 16};
    a.aerialPerspectiveLutSize = {8, 8, 8};
    scene.clouds.noise.baseSize = 32;
    scene.clouds.noise.detailSize = 16;
    scene.clouds.shadowMap.size = 64;
    scene.froxelFog.grid = {16, 9, 16};
    for (demo::Light& l : scene.lights)
        l.shadowResolution = 16;
}

}  // namespace

int runFirstFrame(const FirstFrameArgs& args, const std::string& commandLine) {
    // The drivers' own disk caches would turn a "cold" first frame into a warm one on a second run.
    if (!args.driverCache) {
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
        setenv("MESA_GLSL_CACHE_DISABLE", "true", 0);
        setenv("__GL_SHADER_DISK_CACHE", "0", 0);
    }
    demo::Scene showcase;
    std::string error;
    const std::string path = args.sceneDir + "/showcase.json";
    if (!demo::loadSceneFile(path, showcase, error)) return fail(error);
    if (args.small) shrink(showcase);

    Bench b;
    b.frames = args.frames;
    demo::HostOptions hostOptions;
    hostOptions.validation = args.validation;
    b.host = demo::VulkanHost::create(hostOptions, error);
    if (!b.host) return fail("Vulkan: " + error);
    demo::RenderOptions render;
    render.width = args.width;
    render.height = args.height;
    if (args.small) render.shadowMapSize = 256;
    b.renderer = demo::Renderer::create(*b.host, render, error);
    if (!b.renderer) return fail(error);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = b.host->commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    if (vkAllocateCommandBuffers(b.host->device, &ai, &b.cmd) != VK_SUCCESS)
        return fail("vkAllocateCommandBuffers failed");
    std::printf(
        "postfx-bench --first-frame: %s, %ux%u, %u frames after the first; drivers' disk caches %s\n",
        b.host->deviceDescription().c_str(), args.width, args.height, args.frames,
        args.driverCache ? "as configured" : "off (MESA_SHADER_CACHE_DISABLE, __GL_SHADER_DISK_CACHE)");
    std::printf("command: %s\n", commandLine.c_str());

    struct Variant {
        const char* name;
        demo::Scene scene;
    };
    const demo::Scene raymarched = withPreset(frameVariant(showcase, "raymarched"), "medium");
    const Variant variants[] = {{"froxel", withPreset(frameVariant(showcase, "froxel"), "medium")},
                                {"raymarched", raymarched},
                                {"auto", withPreset(raymarched, "budget")}};
    std::vector<Row> rows;
    for (const Variant& v : variants) {
        if (std::find(args.scenes.begin(), args.scenes.end(), v.name) == args.scenes.end()) continue;
        // The host's images as a frame leaves them: drawn once with postfx off (its context compiles
        // nothing that could warm a driver's cache for the rows).
        demo::Scene off = v.scene;
        off.atmosphere.enabled = off.clouds.enabled = off.fog.enabled = off.froxelFog.enabled = false;
        bool drawn = false;
        if (!b.renderer->setScene(v.scene, error) ||
            !b.host->submitAndWait(
                [&](VkCommandBuffer c) { drawn = b.renderer->recordFrame(c, off, 0, error); }, error) ||
            !drawn)
            return fail(error);
        // The cache a host saved from an earlier run: filled by a prewarmed context, read back as data.
        std::vector<char> saved;
        {
            const VkPipelineCache cache = newCache(b.host->device, {});
            Row scratch;
            if (!cache || !b.row(v.scene, cache, true, scratch, error)) return fail("cache: " + error);
            size_t size = 0;
            vkGetPipelineCacheData(b.host->device, cache, &size, nullptr);
            saved.resize(size);
            vkGetPipelineCacheData(b.host->device, cache, &size, saved.data());
            vkDestroyPipelineCache(b.host->device, cache, nullptr);
        }
        struct Setup {
            const char* name;
            bool cache, prewarm;
        };
        const Setup setups[] = {{"none", false, false},
                                {"prewarm", false, true},
                                {"cache", true, false},
                                {"cache + prewarm", true, true},
                                {"none, again", false, false}};
        for (const Setup& s : setups) {
            Row row;
            row.scene = v.name;
            row.setup = s.name;
            const VkPipelineCache cache = s.cache ? newCache(b.host->device, saved) : VK_NULL_HANDLE;
            const bool ok = b.row(v.scene, cache, s.prewarm, row, error);
            if (cache) vkDestroyPipelineCache(b.host->device, cache, nullptr);
            if (!ok) return fail(std::string(v.name) + ", " + s.name + ": " + error);
            std::printf(
                "%-10s %-16s prewarm %8s ms, first record %8.1f ms (%llu pipelines), later worst %.1f ms\n",
                row.scene.c_str(), row.setup.c_str(), fixed(row.prewarmMs).c_str(), row.firstMs,
                (unsigned long long)row.firstPipelines, row.laterWorstMs);
            std::fflush(stdout);
            rows.push_back(row);
        }
        std::printf("%-18s pipeline cache data: %zu bytes\n", v.name, saved.size());
    }
    printTable(rows);
    for (const std::string& m : b.host->validationMessages())
        return fail("validation: " + m);
    vkDeviceWaitIdle(b.host->device);
    vkFreeCommandBuffers(b.host->device, b.host->commandPool, 1, &b.cmd);
    return 0;
}

}  // namespace bench
