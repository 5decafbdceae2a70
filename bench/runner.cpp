#include "runner.h"

#include "calibration.h"
#include "image_compare.h"
#include "stats.h"

#include "host/camera_math.h"
#include "host/gpu_resources.h"
#include "postfx-bench_spirv.h"

#include <postfx/context.h>

#if POSTFX_BENCH_BASELINES
#include "baseline.h"
#endif

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <chrono>
#include <functional>

namespace bench {
namespace {

constexpr uint32_t kFramesInFlight = demo::Renderer::kFramesInFlight;
constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
// Error frames start at a multiple of this, so every setting averages the same jitter offsets: the
// ray-marched fog's IGN pattern repeats every 64 frames, the froxel fog's Halton (2, 3, 5) samples every
// 1024 (a multiple of 64: the ray-marched fog's frames are those of a period of 64).
constexpr uint64_t kJitterPeriod = 1024;
// Before the error frames: a camera cut, then this many frames unread, so that the temporal histories the
// error frames start from are the same in every run (the timed frames before them end wherever the
// wall-clock warm-up left them). 64: the ray-marched fog's IGN period; after the cut a history is the
// running mean of its first 1/blendWeight frames, then blends exponentially (temporal.h), and 64 frames
// are past the mean's 10 and 20 frames at the fogs' default weights (0.1, the froxel fog's 0.05).
constexpr uint64_t kErrorWarmupFrames = 64;
// A pixel is "off" when a channel differs by more than this fraction of the pixel's magnitude
// max(max_c |reference_c|, kMagnitudeFloor) [radiance; the scenes' values are in the thousands].
constexpr double kPixelTolerance = 0.01;
constexpr double kMagnitudeFloor = 1.0;

demo::GpuImage colorImage(const demo::ImageInfo& info) {
    demo::GpuImage image;  // a non-owning stand-in for the barrier helper
    image.image = info.image;
    image.format = info.format;
    image.extent = info.extent;
    image.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    return image;
}

}  // namespace

struct Runner::Impl {
    RunnerOptions options;
    std::unique_ptr<demo::VulkanHost> host;
    std::unique_ptr<demo::Renderer> renderer;
#if POSTFX_BENCH_BASELINES
    std::unique_ptr<BaselinePass> baseline;
#endif
    std::unique_ptr<Calibration> calibration;  // brackets each row's timed frames (Runner::calibrate)
    std::array<VkCommandBuffer, kFramesInFlight> commandBuffers{};
    std::array<VkFence, kFramesInFlight> fences{};
    VkQueryPool queries = VK_NULL_HANDLE;  // the baselines' timestamps: 2 per frame slot
    double timestampPeriodNs = 1.0;
    uint64_t timestampMask = 0;  // 0: the queue has no timestamps
    bool forwardLookup = true;   // Runner::setForwardLookup
    demo::GpuBuffer readback;    // the HDR image, RGBA16F
    demo::GpuImage fogScratch;  // baselines' frames: where postfx's (cheap) fog goes, keeping its noise alive
    uint64_t nextFrame = kJitterPeriod;  // above renderReference()'s frame index 0
    bool idleSince = true;  // the GPU sat idle (start, setScene, reference): next warm-up is coldWarmupMs
    bool broken = false;

    ~Impl();
    bool create(std::string& error);
    bool recordFrame(VkCommandBuffer cmd, const demo::Scene& scene, Method method, float stepLength,
                     uint64_t frameIndex, size_t slot, bool withReadback, std::string& error);
    bool submit(size_t slot, const std::function<bool(VkCommandBuffer)>& record, std::string& error);
    bool wait(size_t slot, std::string& error);
    void recordReadback(VkCommandBuffer cmd);
    // The read-back frame's pixels (i · stride, j · stride) as RGBA floats, w × h of them.
    void readStrided(uint32_t stride, uint32_t w, uint32_t h, std::vector<float>& out) const;
};

void Runner::Impl::readStrided(uint32_t stride, uint32_t w, uint32_t h, std::vector<float>& out) const {
    const uint32_t width = options.width;
    const auto* half = static_cast<const uint16_t*>(readback.mapped);
    out.resize(size_t(w) * h * 4);
    for (uint32_t j = 0; j < h; ++j) {
        for (uint32_t i = 0; i < w; ++i) {
            const size_t src = (size_t(j) * stride * width + size_t(i) * stride) * 4;
            const size_t dst = (size_t(j) * w + i) * 4;
            for (size_t c = 0; c < 4; ++c)
                out[dst + c] = glm::unpackHalf1x16(half[src + c]);
        }
    }
    demo::unexpose(out, renderer->preExposure());  // errors in physical units
}

Runner::Impl::~Impl() {
    if (!host) return;
    const VkDevice device = host->device;
    vkDeviceWaitIdle(device);
    calibration.reset();
#if POSTFX_BENCH_BASELINES
    baseline.reset();
#endif
    renderer.reset();
    for (VkFence f : fences)
        if (f) vkDestroyFence(device, f, nullptr);
    for (VkCommandBuffer c : commandBuffers)
        if (c) vkFreeCommandBuffers(device, host->commandPool, 1, &c);
    if (queries) vkDestroyQueryPool(device, queries, nullptr);
    demo::destroyBuffer(device, readback);
    demo::destroyImage(device, fogScratch);
}

bool Runner::Impl::create(std::string& error) {
    demo::HostOptions hostOptions;
    hostOptions.validation = options.validation;
    host = demo::VulkanHost::create(hostOptions, error);
    if (!host) {
        error = "Vulkan: " + error;
        return false;
    }
    demo::RenderOptions render;
    render.width = options.width;
    render.height = options.height;
    render.frames = 1;
    render.fixedTimeSeconds = 0.0;  // frames differ only in their jitter
    renderer = demo::Renderer::create(*host, render, error);
    if (!renderer) return false;
#if POSTFX_BENCH_BASELINES
    baseline = BaselinePass::create(*host, kFramesInFlight, error);
    if (!baseline) return false;
#endif
    const VkDevice device = host->device;
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
        if (!demo::vkCheck(vkCreateFence(device, &fci, nullptr, &f), "vkCreateFence", error)) return false;

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(host->physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(host->physicalDevice, &familyCount, families.data());
    const uint32_t validBits = families[host->queueFamily].timestampValidBits;
    timestampMask = validBits >= 64 ? ~0ull : validBits == 0 ? 0 : (1ull << validBits) - 1;
    timestampPeriodNs = host->properties.limits.timestampPeriod;
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qci.queryCount = 2 * kFramesInFlight;
    if (!demo::vkCheck(vkCreateQueryPool(device, &qci, nullptr, &queries), "vkCreateQueryPool", error))
        return false;

    const VkExtent2D extent{options.width, options.height};
    return demo::createBuffer(*host, VkDeviceSize(extent.width) * extent.height * 8,
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, readback, error) &&
           demo::createImage(*host, renderer->hdrImage().format, extent, VK_IMAGE_USAGE_STORAGE_BIT,
                             fogScratch, error);
}

std::unique_ptr<Runner> Runner::create(const RunnerOptions& options, std::string& error) {
    auto impl = std::make_unique<Impl>();
    impl->options = options;
    if (!impl->create(error)) return nullptr;
    return std::unique_ptr<Runner>(new Runner(std::move(impl)));
}

Runner::Runner(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Runner::~Runner() = default;

const demo::VulkanHost& Runner::host() const {
    return *impl_->host;
}

const postfx::Context& Runner::postfxContext() const {
    return impl_->renderer->postfxContext();
}

bool Runner::hasBaselines() {
    return POSTFX_BENCH_BASELINES != 0;
}

bool Runner::calibrate(CalibrationLog& log, std::string& error) {
    Impl& m = *impl_;
    m.calibration = Calibration::create(*m.host, m.options.calibration, log, error);
    m.idleSince = true;
    return m.calibration &&
           m.calibration->reference(std::max(m.options.warmupMs, m.options.coldWarmupMs), error);
}

std::vector<std::string> Runner::validationMessages() const {
    return impl_->host->validationMessages();
}

bool Runner::setScene(const demo::Scene& scene, std::string& error) {
    impl_->idleSince = true;
    return impl_->renderer->setScene(scene, error);
}

void Runner::setForwardLookup(bool lookup) {
    impl_->forwardLookup = lookup;
}

bool Runner::hasShadowMap(const demo::Scene& scene) const {
    return impl_->renderer->frameInputs(VK_NULL_HANDLE, scene, 0).shadowMap.image.present();
}

bool Runner::reference(const demo::Scene& scene, uint32_t steps, uint32_t stride, demo::ImageF& out,
                       std::string& error) {
    // renderReference waits for the device to be idle first (setScene), so none of our frames is in flight.
    impl_->idleSince = true;
    return impl_->renderer->renderReference(scene, out, error, steps, stride);
}

// HDR image (GENERAL, compute writes) -> readback buffer -> host; left in TRANSFER_SRC_OPTIMAL (the next
// frame discards it).
void Runner::Impl::recordReadback(VkCommandBuffer cmd) {
    const demo::ImageInfo& info = renderer->hdrImage();
    const demo::GpuImage hdr = colorImage(info);
    demo::imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute,
                       VK_ACCESS_SHADER_WRITE_BIT, kTransfer, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {info.extent.width, info.extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, info.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1,
                           &region);
    demo::bufferBarrier(cmd, readback, kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                        VK_ACCESS_HOST_READ_BIT);
}

bool Runner::Impl::recordFrame(VkCommandBuffer cmd, const demo::Scene& scene, Method method, float stepLength,
                               uint64_t frameIndex, size_t slot, bool withReadback, std::string& error) {
    if (isPostfx(method)) {
        // The demo's forward pass (transparent surfaces through postfx's lookup), timed when drawn.
        if (queries && demo::hasForwardDraws(scene)) {
            vkCmdResetQueryPool(cmd, queries, uint32_t(slot) * 2, 2);
            renderer->timeForwardPass(queries, uint32_t(slot) * 2, forwardLookup);
        }
        if (!renderer->recordFrame(cmd, scene, frameIndex, error)) return false;
    } else {
#if POSTFX_BENCH_BASELINES
        // postfx's fog runs too, cheaply (one step) and into a scratch image: it keeps the noise texture
        // (Context::fogNoiseView) alive, which disabling the fog would retire, and leaves the HDR image
        // un-fogged. Only the baseline's dispatch is timed.
        demo::Scene cheap = scene;
        cheap.fog.steps = 1;
        cheap.fog.jitter = false;
        cheap.fog.shadowKernel = 1;
        demo::imageBarrier(cmd, fogScratch, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kCompute, 0,
                           kCompute, VK_ACCESS_SHADER_WRITE_BIT);
        const postfx::ImageInput scratch{fogScratch.image,  fogScratch.view,         fogScratch.format,
                                         fogScratch.extent, VK_IMAGE_LAYOUT_GENERAL, fogScratch.usage};
        if (!renderer->recordFrame(cmd, cheap, frameIndex, scratch, error)) return false;
        // The lighting's writes (and postfx's reads) before the baseline reads and writes in place.
        demo::imageBarrier(cmd, colorImage(renderer->hdrImage()), VK_IMAGE_LAYOUT_GENERAL,
                           VK_IMAGE_LAYOUT_GENERAL, kCompute, VK_ACCESS_SHADER_WRITE_BIT, kCompute,
                           VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
        const uint32_t query = uint32_t(slot) * 2;
        vkCmdResetQueryPool(cmd, queries, query, 2);
        const postfx::FrameInfo frame = renderer->frameInputs(cmd, scene, frameIndex);
        const VkImageView noise =
            scene.fog.noise.enabled ? postfx::fogNoiseView(renderer->postfxContext()) : VK_NULL_HANDLE;
        if (scene.fog.noise.enabled && !noise) {
            error = "postfx holds no fog noise texture for the baseline";
            return false;
        }
        const Baseline which =
            method == Method::SeedAsWritten ? Baseline::SeedAsWritten : Baseline::SeedFixedRiemann;
        if (!baseline->record(cmd, frame, renderer->postfxContext().createInfo().depth, which, stepLength,
                              noise, queries, query, error))
            return false;
#else
        (void)stepLength;
        (void)slot;
        error = "postfx-bench was built without the baselines (bench/baseline.cmake)";
        return false;
#endif
    }
    if (withReadback) recordReadback(cmd);
    return true;
}

bool Runner::Impl::wait(size_t slot, std::string& error) {
    return demo::vkCheck(vkWaitForFences(host->device, 1, &fences[slot], VK_TRUE, UINT64_MAX),
                         "vkWaitForFences", error);
}

// Records into the slot's command buffer and submits with its fence; the caller has waited for the slot.
bool Runner::Impl::submit(size_t slot, const std::function<bool(VkCommandBuffer)>& record,
                          std::string& error) {
    if (broken) {
        error = "a submission failed earlier";
        return false;
    }
    VkCommandBuffer cmd = commandBuffers[slot];
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &bi);
    const bool recorded = record(cmd);
    if (!demo::vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) || !recorded) return false;
    vkResetFences(host->device, 1, &fences[slot]);
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    if (!demo::vkCheck(vkQueueSubmit(host->queue, 1, &si, fences[slot]), "vkQueueSubmit", error)) {
        broken = true;
        return false;
    }
    return true;
}

bool Runner::measure(const demo::Scene& scene, Method method, float stepLength, const demo::ImageF& reference,
                     uint32_t stride, Timing& timing, std::array<ErrorStats, 3>& errors, std::string& error) {
    Impl& m = *impl_;
    const VkDevice device = m.host->device;
    const postfx::Context& context = m.renderer->postfxContext();

    // --- Timing: warm-up, then the timed frames, two in flight. A frame's timings are read after its
    // fence, before its slot is recorded again.
    std::vector<double> totals;
    std::vector<std::pair<std::string, std::vector<double>>> passes;
    auto addPass = [&](const std::string& name, double ms) {
        auto it = std::find_if(passes.begin(), passes.end(), [&](const auto& p) { return p.first == name; });
        if (it == passes.end()) it = passes.insert(passes.end(), {name, {}});
        it->second.push_back(ms);
    };
    auto collect = [&](uint64_t frameIndex, size_t slot) -> bool {
        if (isPostfx(method)) {
            std::vector<postfx::PassTiming> timings;
            const postfx::Status s = context.readPassTimings(frameIndex, timings);
            if (s.code == postfx::Result::Unsupported) return true;  // no timestamps on this queue
            if (!s.ok()) {
                error = "readPassTimings(" + std::to_string(frameIndex) + "): " + s.message;
                return false;
            }
            double total = 0.0;
            for (const postfx::PassTiming& t : timings) {
                addPass(t.name, t.milliseconds);
                total += t.milliseconds;
            }
            totals.push_back(total);
            // The host's forward pass, not postfx's: listed as "host.forward", not in the total.
            uint64_t stamps[2] = {0, 0};
            if (m.queries && m.timestampMask != 0 && demo::hasForwardDraws(scene) &&
                vkGetQueryPoolResults(device, m.queries, uint32_t(slot) * 2, 2, sizeof stamps, stamps,
                                      sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
                addPass("host.forward",
                        double((stamps[1] - stamps[0]) & m.timestampMask) * m.timestampPeriodNs * 1e-6);
            return true;
        }
        if (m.timestampMask == 0) return true;
        uint64_t stamps[2] = {0, 0};
        if (!demo::vkCheck(
                vkGetQueryPoolResults(device, m.queries, uint32_t(slot) * 2, 2, sizeof stamps, stamps,
                                      sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                "vkGetQueryPoolResults", error))
            return false;
        const double ms = double((stamps[1] - stamps[0]) & m.timestampMask) * m.timestampPeriodNs * 1e-6;
        addPass(methodName(method), ms);
        totals.push_back(ms);
        return true;
    };
    struct InFlight {
        bool active = false;
        bool timed = false;
        uint64_t frame = 0;
    };
    std::array<InFlight, kFramesInFlight> inFlight{};
    auto retire = [&](size_t slot) -> bool {
        if (!m.wait(slot, error)) return false;
        InFlight& f = inFlight[slot];
        const bool ok = !f.active || !f.timed || collect(f.frame, slot);
        f.active = false;
        return ok;
    };
    auto submitFrame = [&](bool timed) -> bool {
        const uint64_t frameIndex = m.nextFrame++;
        const size_t slot = frameIndex % kFramesInFlight;
        if (!retire(slot) || !m.submit(
                                 slot,
                                 [&](VkCommandBuffer cmd) {
                                     return m.recordFrame(cmd, scene, method, stepLength, frameIndex, slot,
                                                          false, error);
                                 },
                                 error))
            return false;
        inFlight[slot] = {true, timed, frameIndex};
        return true;
    };
    auto retireAll = [&]() -> bool {
        for (uint64_t f = m.nextFrame - kFramesInFlight; f < m.nextFrame; ++f)  // oldest first
            if (!retire(f % kFramesInFlight)) return false;
        return true;
    };
    // One attempt: the warm-up (at least options.warmup frames and warmupMs), the calibration, the timed
    // frames, the calibration again (bench/calibration.h).
    CalibratedRow calibrated(m.calibration.get());
    double warmupMs = m.idleSince ? std::max(m.options.warmupMs, m.options.coldWarmupMs) : m.options.warmupMs;
    m.idleSince = false;
    do {
        totals.clear();
        passes.clear();
        const auto start = std::chrono::steady_clock::now();
        for (uint32_t warmupFrames = 0;
             warmupFrames < m.options.warmup ||
             std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() <
                 warmupMs;
             ++warmupFrames)
            if (!submitFrame(false)) return false;
        if (!retireAll() || !calibrated.before(error)) return false;
        for (uint32_t timedFrames = 0; timedFrames < m.options.frames; ++timedFrames)
            if (!submitFrame(true)) return false;
        if (!retireAll() || !calibrated.after(error)) return false;
        if (calibrated.kept()) timing = summarize(totals, passes);
        warmupMs = m.options.warmupMs;
    } while (calibrated.again());
    timing.calibration = calibrated.finish();
    if (reference.width == 0) return true;  // timing only

    // --- Error: one frame at a time, read back; the reference's pixel (i, j) is the frame's
    // (i·stride, j·stride).
    const uint32_t width = m.options.width, height = m.options.height;
    const uint32_t w = reference.width, h = reference.height;
    if (stride == 0 || w != (width + stride - 1) / stride || h != (height + stride - 1) / stride) {
        error = "the reference's size " + std::to_string(w) + "x" + std::to_string(h) +
                " does not match stride " + std::to_string(stride);
        return false;
    }
    const uint64_t firstRead =
        (m.nextFrame + kErrorWarmupFrames + kJitterPeriod - 1) / kJitterPeriod * kJitterPeriod;
    m.nextFrame = firstRead - kErrorWarmupFrames;
    m.renderer->requestCameraCut();
    std::vector<double> sum(size_t(w) * h * 4, 0.0);
    std::vector<float> image(sum.size()), frame;
    const uint32_t frames = kAveragedFrames.back();
    // The warm-up's frames, then the read ones (k = 0 is firstRead).
    for (int64_t k = -int64_t(kErrorWarmupFrames); k < int64_t(frames); ++k) {
        const bool read = k >= 0;
        const uint64_t frameIndex = m.nextFrame++;
        const size_t slot = frameIndex % kFramesInFlight;
        if (!m.wait(slot, error) || !m.submit(
                                        slot,
                                        [&](VkCommandBuffer cmd) {
                                            return m.recordFrame(cmd, scene, method, stepLength, frameIndex,
                                                                 slot, read, error);
                                        },
                                        error))
            return false;
        if (!read) continue;
        if (!m.wait(slot, error)) return false;
        m.readStrided(stride, w, h, frame);
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += double(frame[i]);
        for (size_t a = 0; a < kAveragedFrames.size(); ++a) {
            if (uint64_t(k) + 1 != kAveragedFrames[a]) continue;
            for (size_t i = 0; i < sum.size(); ++i)
                image[i] = float(sum[i] / double(k + 1));
            errors[a] = compare(image, reference);
        }
    }
    return true;
}

uint32_t Runner::shadowMatrixChanges(const std::function<demo::Scene(uint32_t)>& sceneAt,
                                     uint32_t frames) const {
    auto changed = [](const glm::mat4& a, const glm::mat4& b) {
        double scale = 0.0, difference = 0.0;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                scale = std::max({scale, std::abs(double(a[c][r])), std::abs(double(b[c][r]))});
                difference = std::max(difference, std::abs(double(a[c][r]) - double(b[c][r])));
            }
        return difference > 1e-6 * scale;
    };
    uint32_t changes = 0;
    glm::mat4 last{1.0f};
    for (uint32_t n = 0; n < frames; ++n) {
        const demo::Scene scene = sceneAt(n);
        if (!hasShadowMap(scene)) return 0;
        const demo::ShadowFit fit =
            demo::fitShadowMap(scene, impl_->renderer->shadowMap().image.extent.width);
        if (n > 0 && changed(last, fit.viewProj)) ++changes;
        if (n == 0 || changed(last, fit.viewProj)) last = fit.viewProj;
    }
    return changes;
}

ErrorStats Runner::compare(const std::vector<float>& image, const demo::ImageF& reference) {
    const test::ImageStats s = test::compareImages(image, reference.rgba, reference.width, reference.height,
                                                   kPixelTolerance, kMagnitudeFloor);
    return {s.relativeRmse, s.maxAbsError, s.fractionOff, s.nonFinite, tonemappedRmse(image, reference.rgba)};
}

bool Runner::sequence(uint32_t frames, const std::function<demo::Scene(uint32_t)>& sceneAt,
                      const std::vector<uint32_t>& readback, uint32_t stride,
                      const std::function<bool(uint32_t, const std::vector<float>&)>& onFrame,
                      std::string& error) {
    Impl& m = *impl_;
    if (stride == 0) {
        error = "stride 0";
        return false;
    }
    const uint32_t w = (m.options.width + stride - 1) / stride, h = (m.options.height + stride - 1) / stride;
    // Every frame in flight done: the sequence's indices start again at 0 (each slot's fence is the frame
    // that last used the slot's command buffer and postfx's per-slot resources).
    for (size_t slot = 0; slot < kFramesInFlight; ++slot)
        if (!m.wait(slot, error)) return false;
    std::vector<float> image;
    size_t next = 0;  // into readback
    for (uint32_t n = 0; n < frames; ++n) {
        const size_t slot = n % kFramesInFlight;
        const bool read = next < readback.size() && readback[next] == n;
        const demo::Scene scene = sceneAt(n);
        if (!m.wait(slot, error) || !m.submit(
                                        slot,
                                        [&](VkCommandBuffer cmd) {
                                            return m.recordFrame(cmd, scene, Method::Ours, 0.0f, n, slot,
                                                                 read, error);
                                        },
                                        error))
            return false;
        if (!read) continue;
        ++next;
        if (!m.wait(slot, error)) return false;
        m.readStrided(stride, w, h, image);
        if (!onFrame(n, image)) return false;
    }
    if (next != readback.size()) {
        error = "sequence: a read-back frame is not below " + std::to_string(frames) + " or not ascending";
        return false;
    }
    for (size_t slot = 0; slot < kFramesInFlight; ++slot)
        if (!m.wait(slot, error)) return false;
    // Later frames continue above every index used so far, from a multiple of the jitter period.
    m.nextFrame = (m.nextFrame + kJitterPeriod) / kJitterPeriod * kJitterPeriod;
    m.idleSince = true;
    return true;
}

bool Runner::copyBandwidth(uint64_t bytes, uint32_t repeats, double& transfer, double& compute,
                           std::string& error) {
    Impl& m = *impl_;
    transfer = compute = NAN;
    if (m.timestampMask == 0) return true;
    const VkDevice device = m.host->device;
    bytes &= ~uint64_t(15);  // whole 16-byte words
    const uint32_t words = uint32_t(std::min<uint64_t>(bytes / 16, UINT32_MAX));
    demo::GpuBuffer source, target;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    bool ok = demo::createBuffer(*m.host, bytes, usage, false, source, error) &&
              demo::createBuffer(*m.host, bytes, usage, false, target, error);
    if (ok) {
        VkDescriptorSetLayoutBinding bindings[2]{};
        for (uint32_t b = 0; b < 2; ++b)
            bindings[b] = {b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        VkDescriptorSetLayoutCreateInfo dl{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        dl.bindingCount = 2;
        dl.pBindings = bindings;
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t)};
        VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        pl.setLayoutCount = 1;
        pl.pSetLayouts = &setLayout;
        pl.pushConstantRangeCount = 1;
        pl.pPushConstantRanges = &push;
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
        VkDescriptorPoolCreateInfo dp{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dp.maxSets = 1;
        dp.poolSizeCount = 1;
        dp.pPoolSizes = &size;
        ok = demo::vkCheck(vkCreateDescriptorSetLayout(device, &dl, nullptr, &setLayout),
                           "vkCreateDescriptorSetLayout", error) &&
             demo::vkCheck(vkCreatePipelineLayout(device, &pl, nullptr, &layout), "vkCreatePipelineLayout",
                           error) &&
             demo::createComputePipeline(device, spirv::bench_shaders_copy_bandwidth_comp, layout,
                                         "copy_bandwidth.comp", pipeline, error) &&
             demo::vkCheck(vkCreateDescriptorPool(device, &dp, nullptr, &pool), "vkCreateDescriptorPool",
                           error);
        if (ok) {
            VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
            ai.descriptorPool = pool;
            ai.descriptorSetCount = 1;
            ai.pSetLayouts = &setLayout;
            ok =
                demo::vkCheck(vkAllocateDescriptorSets(device, &ai, &set), "vkAllocateDescriptorSets", error);
        }
        if (ok) {
            const VkDescriptorBufferInfo infos[2] = {{source.buffer, 0, VK_WHOLE_SIZE},
                                                     {target.buffer, 0, VK_WHOLE_SIZE}};
            VkWriteDescriptorSet writes[2]{};
            for (uint32_t b = 0; b < 2; ++b) {
                writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
                writes[b].dstSet = set;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                writes[b].pBufferInfo = &infos[b];
            }
            vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
        }
    }
    const uint32_t groups =
        std::max(1u, std::min((words + 255) / 256, m.host->properties.limits.maxComputeWorkGroupCount[0]));
    // One copy between timestamps; the next waits for this one's writes (its reads of the target).
    auto timed = [&](bool useCompute, double& ms) -> bool {
        const size_t slot = 0;
        const bool recorded =
            m.wait(slot, error) &&
            m.submit(
                slot,
                [&](VkCommandBuffer cmd) {
                    vkCmdResetQueryPool(cmd, m.queries, 0, 2);
                    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
                    barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
                    barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
                    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0,
                                         nullptr);
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, m.queries, 0);
                    if (useCompute) {
                        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
                        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0,
                                                nullptr);
                        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof words, &words);
                        vkCmdDispatch(cmd, groups, 1, 1);
                    } else {
                        const VkBufferCopy region{0, 0, bytes};
                        vkCmdCopyBuffer(cmd, source.buffer, target.buffer, 1, &region);
                    }
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m.queries, 1);
                    return true;
                },
                error) &&
            m.wait(slot, error);
        uint64_t stamps[2] = {0, 0};
        if (!recorded || !demo::vkCheck(vkGetQueryPoolResults(
                                            device, m.queries, 0, 2, sizeof stamps, stamps, sizeof(uint64_t),
                                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                                        "vkGetQueryPoolResults", error))
            return false;
        ms = double((stamps[1] - stamps[0]) & m.timestampMask) * m.timestampPeriodNs * 1e-6;
        return true;
    };
    for (bool useCompute : {false, true}) {
        // Warm-up: copies for coldWarmupMs (at least two), then the timed ones.
        const auto start = std::chrono::steady_clock::now();
        double ms = 0;
        for (uint32_t k = 0;
             ok &&
             (k < 2 ||
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() <
                  m.options.coldWarmupMs);
             ++k)
            ok = timed(useCompute, ms);
        std::vector<double> times;
        for (uint32_t k = 0; ok && k < repeats; ++k) {
            ok = timed(useCompute, ms);
            times.push_back(ms);
        }
        if (ok)
            (useCompute ? compute : transfer) = 2.0 * double(bytes) / (percentile(times, 0.5) * 1e-3) * 1e-9;
    }
    vkDeviceWaitIdle(device);
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
    if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    demo::destroyBuffer(device, source);
    demo::destroyBuffer(device, target);
    m.idleSince = true;
    return ok;
}

void fillRunHeader(RunInfo& info, const demo::VulkanHost& host, const RunnerOptions& options,
                   uint32_t errorStride, uint32_t referenceSteps, const std::string& date,
                   const std::string& commandLine) {
    info.device = host.deviceDescription();
    const uint32_t api = host.properties.apiVersion;
    info.vulkanApi = std::to_string(VK_API_VERSION_MAJOR(api)) + "." +
                     std::to_string(VK_API_VERSION_MINOR(api)) + "." +
                     std::to_string(VK_API_VERSION_PATCH(api));
    info.date = date;
    info.commandLine = commandLine;
    info.width = options.width;
    info.height = options.height;
    info.errorStride = errorStride;
    info.referenceSteps = referenceSteps;
    info.warmup = options.warmup;
    info.warmupMs = options.warmupMs;
    info.coldWarmupMs = options.coldWarmupMs;
    info.frames = options.frames;
}

}  // namespace bench
