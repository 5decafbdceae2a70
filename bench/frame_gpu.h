// The bench's own Vulkan host for --atmosphere and --clouds, whose views are the bench's own (made up in
// code, not scene files the demo renderer loads): the view's colour and depth, built by the bench, uploaded
// once; postfx's output and images postfx holds (the clouds' noise, for the CPU reference) read back;
// frames timed two in flight by Context::readPassTimings.
#pragma once

#include "bench_types.h"
#include "calibration.h"
#include "runner.h"
#include "stats.h"

#include "host/gpu_resources.h"
#include "host/vulkan_host.h"

#include <postfx/context.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bench {
namespace frame_gpu {

constexpr uint32_t kFramesInFlight = 2;
constexpr VkPipelineStageFlags kAll = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkImageLayout kDepthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The bench's own host for postfx's atmosphere and clouds on the bench's views: the view's colour
// (RGBA16F, only read) and depth (D32) uploaded once, postfx's result in a separate output image, frames
// recorded two in flight into the bench's command buffers and timed by Context::readPassTimings as
// bench/runner.h does for the scene files.
class FrameGpu {
public:
    ~FrameGpu() {
        if (!host) return;
        const VkDevice device = host->device;
        vkDeviceWaitIdle(device);
        calibration.reset();
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

    // Brackets every measure() from now on with the calibration (bench/calibration.h), recording into
    // `log`; takes the run's reference first unless `log` has one.
    bool calibrate(CalibrationLog& log, std::string& error) {
        calibration = Calibration::create(*host, options.calibration, log, error);
        idle = true;
        return calibration && calibration->reference(std::max(options.warmupMs, options.coldWarmupMs), error);
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

    // Times frames n = 0, 1, ... of frameAt (warm-up, then options.frames timed), two in flight,
    // bracketed by the calibration and timed again from n = 0 while it drifts (Timing::calibration).
    // `include`: the passes counted (all when empty).
    bool measure(const std::function<postfx::FrameInfo(uint32_t)>& frameAt, Timing& timing,
                 std::vector<std::pair<std::string, uint32_t>>& passFrames, std::string& error,
                 const std::function<bool(const std::string&)>& include = {}) {
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
            // A pass recorded several times in a frame (one per scattering order) counts once, summed.
            double total = 0.0;
            std::vector<std::pair<std::string, double>> frameSums;
            for (const postfx::PassTiming& t : timings) {
                if (include && !include(t.name)) continue;
                auto it = std::find_if(frameSums.begin(), frameSums.end(),
                                       [&](const auto& p) { return p.first == t.name; });
                if (it == frameSums.end()) it = frameSums.insert(frameSums.end(), {t.name, 0.0});
                it->second += t.milliseconds;
                total += t.milliseconds;
            }
            for (const auto& [name, ms] : frameSums) {
                auto it = std::find_if(passes.begin(), passes.end(),
                                       [&](const auto& p) { return p.first == name; });
                if (it == passes.end()) it = passes.insert(passes.end(), {name, {}});
                it->second.push_back(ms);
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
        uint32_t n = 0;  // frameAt's frame
        auto submitFrame = [&](bool timed) -> bool {
            const uint64_t frameIndex = nextFrame++;
            const size_t slot = frameIndex % kFramesInFlight;
            if (!retire(slot) || !submit(slot, frameAt(n++), frameIndex, false, error)) return false;
            inFlight[slot] = {true, timed, frameIndex};
            return true;
        };
        auto retireAll = [&]() -> bool {
            for (uint64_t age = kFramesInFlight; age > 0; --age)  // oldest first
                if (nextFrame >= age && !retire((nextFrame - age) % kFramesInFlight)) return false;
            return true;
        };
        // One attempt: frames 0, 1, ... of frameAt, the calibration after the warm-up and after the timed
        // frames (bench/calibration.h).
        CalibratedRow calibrated(calibration.get());
        double warmupMs = idle ? std::max(options.warmupMs, options.coldWarmupMs) : options.warmupMs;
        idle = false;
        do {
            totals.clear();
            passes.clear();
            n = 0;
            const auto start = std::chrono::steady_clock::now();
            for (uint32_t warmupFrames = 0;
                 warmupFrames < options.warmup || secondsSince(start) * 1e3 < warmupMs; ++warmupFrames)
                if (!submitFrame(false)) return false;
            if (!retireAll() || !calibrated.before(error)) return false;
            for (uint32_t timedFrames = 0; timedFrames < options.frames; ++timedFrames)
                if (!submitFrame(true)) return false;
            if (!retireAll() || !calibrated.after(error)) return false;
            if (calibrated.kept()) {
                timing = summarize(totals, passes);
                passFrames.clear();
                for (const auto& [name, values] : passes)
                    passFrames.emplace_back(name, uint32_t(values.size()));
            }
            warmupMs = options.warmupMs;
        } while (calibrated.again());
        timing.calibration = calibrated.finish();
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

    // Reads back an image postfx holds between frames (Context::recordImageReadback: "clouds.base_noise"),
    // its texels tightly packed.
    bool readHeld(const char* name, std::vector<uint8_t>& bytes, VkExtent3D& extent, std::string& error) {
        if (!waitAll(error)) return false;
        demo::GpuBuffer buffer;
        if (!demo::createBuffer(*host, VkDeviceSize(64) << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, buffer,
                                error))
            return false;
        VkDeviceSize size = 0;
        postfx::Status status;
        const bool ok = host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                status = context->recordImageReadback({name}, cmd, buffer.buffer, 0, extent, size);
            },
            error);
        if (ok && status.ok()) {
            const auto* p = static_cast<const uint8_t*>(buffer.mapped);
            bytes.assign(p, p + size);
        }
        demo::destroyBuffer(host->device, buffer);
        if (ok && !status.ok()) error = std::string(name) + ": " + status.message;
        return ok && status.ok();
    }

    std::unique_ptr<demo::VulkanHost> host;
    std::unique_ptr<Calibration> calibration;
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

}  // namespace frame_gpu

using frame_gpu::FrameGpu;
using frame_gpu::secondsSince;

}  // namespace bench
