#include "calibration.h"

#include "stats.h"

#include "host/gpu_resources.h"
#include "postfx-bench_spirv.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace bench {

struct Calibration::Impl {
    const demo::VulkanHost* host = nullptr;
    CalibrationOptions options;
    uint32_t iterations = 0;  // the dispatch's loop steps
    CalibrationLog* log = nullptr;
    bool enabled = false;
    double timestampPeriodNs = 1.0;
    uint64_t timestampMask = 0;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkQueryPool queries = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    demo::GpuBuffer sink;

    ~Impl();
    bool create(std::string& error);
    // `repeats` timed dispatches in one submission, waited for; their times [ms].
    bool dispatch(uint32_t repeats, std::vector<double>& ms, std::string& error);
    // Sets `iterations` to the power of two nearest to take options.targetMs: doubled from 64 until a
    // dispatch takes an eighth of it, then scaled.
    bool size(std::string& error);
};

Calibration::Impl::~Impl() {
    if (!host) return;
    const VkDevice device = host->device;
    vkDeviceWaitIdle(device);
    if (fence) vkDestroyFence(device, fence, nullptr);
    if (cmd) vkFreeCommandBuffers(device, host->commandPool, 1, &cmd);
    if (queries) vkDestroyQueryPool(device, queries, nullptr);
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
    if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    demo::destroyBuffer(device, sink);
}

bool Calibration::Impl::create(std::string& error) {
    const VkDevice device = host->device;
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(host->physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(host->physicalDevice, &familyCount, families.data());
    const uint32_t validBits = families[host->queueFamily].timestampValidBits;
    timestampMask = validBits >= 64 ? ~0ull : validBits == 0 ? 0 : (1ull << validBits) - 1;
    timestampPeriodNs = host->properties.limits.timestampPeriod;
    enabled = options.enabled && timestampMask != 0 && options.repeats > 0;
    if (!enabled) return true;

    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                               VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t)};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &setLayout;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &push;
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qci.queryCount = 2 * options.repeats;
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = host->commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (!demo::createBuffer(*host, 64 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, sink,
                            error) ||
        !demo::createDescriptorSet(device, {&binding, 1}, setLayout, pool, set, error) ||
        !demo::vkCheck(vkCreatePipelineLayout(device, &pl, nullptr, &layout), "vkCreatePipelineLayout",
                       error) ||
        !demo::createComputePipeline(device, spirv::bench_shaders_calibration_comp, layout,
                                     "calibration.comp", pipeline, error) ||
        !demo::vkCheck(vkCreateQueryPool(device, &qci, nullptr, &queries), "vkCreateQueryPool", error) ||
        !demo::vkCheck(vkAllocateCommandBuffers(device, &ai, &cmd), "vkAllocateCommandBuffers", error) ||
        !demo::vkCheck(vkCreateFence(device, &fci, nullptr, &fence), "vkCreateFence", error))
        return false;
    const VkDescriptorBufferInfo info{sink.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    return true;
}

bool Calibration::Impl::dispatch(uint32_t repeats, std::vector<double>& ms, std::string& error) {
    const VkDevice device = host->device;
    // The work before it done: its timestamps time the dispatch alone.
    if (!demo::vkCheck(vkQueueWaitIdle(host->queue), "vkQueueWaitIdle", error)) return false;
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &bi);
    vkCmdResetQueryPool(cmd, queries, 0, 2 * repeats);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t), &iterations);
    // Each dispatch after the work before it (the previous dispatch, the previous submission's) and before
    // the next; a barrier between each timestamp and the dispatch, which lavapipe needs: it takes a
    // timestamp at the next flush (a barrier) after the command, not at the command.
    auto barrier = [&] {
        demo::bufferBarrier(cmd, sink, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
    };
    for (uint32_t r = 0; r < repeats; ++r) {
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 2 * r);
        barrier();
        vkCmdDispatch(cmd, options.groups, 1, 1);
        barrier();
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 2 * r + 1);
    }
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    std::vector<uint64_t> stamps(2 * repeats);
    if (!demo::vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) ||
        !demo::vkCheck(vkResetFences(device, 1, &fence), "vkResetFences", error) ||
        !demo::vkCheck(vkQueueSubmit(host->queue, 1, &si, fence), "vkQueueSubmit", error) ||
        !demo::vkCheck(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", error) ||
        !demo::vkCheck(vkGetQueryPoolResults(
                           device, queries, 0, 2 * repeats, stamps.size() * sizeof(uint64_t), stamps.data(),
                           sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                       "vkGetQueryPoolResults", error))
        return false;
    ms.clear();
    for (uint32_t r = 0; r < repeats; ++r)
        ms.push_back(double((stamps[2 * r + 1] - stamps[2 * r]) & timestampMask) * timestampPeriodNs * 1e-6);
    return true;
}

bool Calibration::Impl::size(std::string& error) {
    constexpr uint32_t kMost = 1u << 26;
    std::vector<double> ms;
    for (iterations = 64;; iterations *= 2) {
        if (!dispatch(3, ms, error)) return false;
        const double t = percentile(ms, 0.5);
        if (t >= options.targetMs / 8.0 || iterations >= kMost) {
            const double wanted = t > 0.0 ? double(iterations) * options.targetMs / t : double(kMost);
            iterations = uint32_t(std::exp2(std::round(std::log2(std::clamp(wanted, 16.0, double(kMost))))));
            return true;
        }
    }
}

std::unique_ptr<Calibration> Calibration::create(const demo::VulkanHost& host,
                                                 const CalibrationOptions& options, CalibrationLog& log,
                                                 std::string& error) {
    auto impl = std::make_unique<Impl>();
    impl->host = &host;
    impl->options = options;
    impl->options.repeats = std::max(options.repeats, 1u);
    impl->log = &log;
    // A later device of the run (--frame's sizes) does the reference's work.
    impl->iterations = log.iterations ? log.iterations : options.iterations;
    if (!impl->create(error)) {
        error = "calibration: " + error;
        return nullptr;
    }
    log.enabled = impl->enabled;
    log.groups = options.groups;
    log.repeats = impl->options.repeats;
    log.tolerance = options.tolerance;
    log.retries = options.retries;
    return std::unique_ptr<Calibration>(new Calibration(std::move(impl)));
}

Calibration::Calibration(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Calibration::~Calibration() = default;

bool Calibration::enabled() const {
    return impl_->enabled;
}

CalibrationLog& Calibration::log() {
    return *impl_->log;
}

bool Calibration::reference(double warmupMs, std::string& error) {
    if (!impl_->enabled || std::isfinite(impl_->log->referenceMs)) return true;
    if (impl_->iterations == 0 && !impl_->size(error)) return false;
    impl_->log->iterations = impl_->iterations;
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> ms;
    for (uint32_t k = 0;
         k < 2 ||
         std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() <
             warmupMs;
         ++k)
        if (!impl_->dispatch(1, ms, error)) return false;
    // The median of three measurements: not one moment's (lavapipe's times halve while it has a core to
    // itself).
    std::vector<double> references(3);
    for (double& r : references)
        if (!measure(r, error)) return false;
    impl_->log->referenceMs = percentile(references, 0.5);
    return true;
}

bool Calibration::measure(double& ms, std::string& error) {
    ms = NAN;
    if (!impl_->enabled) return true;
    std::vector<double> times;
    if (!impl_->dispatch(impl_->options.repeats, times, error)) {
        error = "calibration: " + error;
        return false;
    }
    ms = percentile(times, 0.5);
    impl_->log->measurements.push_back(ms);
    return true;
}

CalibratedRow::CalibratedRow(Calibration* calibration)
    : calibration_(calibration && calibration->enabled() ? calibration : nullptr) {}

bool CalibratedRow::before(std::string& error) {
    return !calibration_ || calibration_->measure(before_, error);
}

bool CalibratedRow::after(std::string& error) {
    double after = NAN;
    if (calibration_ && !calibration_->measure(after, error)) return false;
    RowCalibration attempt;
    attempt.beforeMs = before_;
    attempt.afterMs = after;
    attempt.drift = calibrationDrift(before_, after, calibration_ ? calibration_->log().referenceMs : NAN);
    // The first attempt, or one that drifted less than every one before it.
    keptThis_ = attempts_ == 0 || attempt.drift < best_.drift;
    if (keptThis_) best_ = attempt;
    ++attempts_;
    return true;
}

bool CalibratedRow::again() const {
    return calibration_ && attempts_ <= calibration_->log().retries &&
           best_.drift > calibration_->log().tolerance;
}

RowCalibration CalibratedRow::finish() {
    RowCalibration result = best_;
    result.remeasured = attempts_ > 0 ? attempts_ - 1 : 0;
    result.flagged = calibration_ && best_.drift > calibration_->log().tolerance;
    if (calibration_ && !finished_) {
        CalibrationLog& log = calibration_->log();
        ++log.rows;
        log.remeasuredRows += result.remeasured > 0;
        log.remeasurements += result.remeasured;
        log.flaggedRows += result.flagged;
    }
    finished_ = true;
    return result;
}

}  // namespace bench
