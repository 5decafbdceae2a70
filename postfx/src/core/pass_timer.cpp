#include "core/pass_timer.h"

namespace postfx::core {

Status PassTimer::create(const Gpu& gpu, uint32_t framesInFlight, uint32_t timestampValidBits) {
    reset();
    gpu_ = &gpu;
    slots_.assign(framesInFlight, Slot{});
    if (timestampValidBits == 0) return Status::success();  // timing unsupported on this queue
    validMask_ = timestampValidBits >= 64 ? ~0ull : ((1ull << timestampValidBits) - 1);
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = framesInFlight * kMaxPassesPerFrame * 2;
    VkQueryPool pool = VK_NULL_HANDLE;  // kept only on success (a failed call's output is undefined)
    Status s =
        vulkanStatus(gpu.fn.vkCreateQueryPool(gpu.device, &info, gpu.allocator, &pool), "vkCreateQueryPool");
    if (s) pool_ = pool;
    return s;
}

void PassTimer::reset() {
    if (gpu_ && pool_) gpu_->fn.vkDestroyQueryPool(gpu_->device, pool_, gpu_->allocator);
    pool_ = VK_NULL_HANDLE;
    gpu_ = nullptr;
    slots_.clear();
}

void PassTimer::beginFrame(VkCommandBuffer cmd, uint64_t frameIndex) {
    if (slots_.empty()) return;
    current_ = static_cast<uint32_t>(frameIndex % slots_.size());
    Slot& slot = slots_[current_];
    slot.frameIndex = frameIndex;
    slot.passes.clear();
    if (enabled())
        gpu_->fn.vkCmdResetQueryPool(cmd, pool_, current_ * kMaxPassesPerFrame * 2, kMaxPassesPerFrame * 2);
}

void PassTimer::beginPass(VkCommandBuffer cmd, const std::string& name, int effect, bool autoTimed) {
    if (!enabled()) return;
    Slot& slot = slots_[current_];
    if (slot.passes.size() >= kMaxPassesPerFrame) return;  // untimed beyond the range
    uint32_t query = (current_ * kMaxPassesPerFrame + static_cast<uint32_t>(slot.passes.size())) * 2;
    slot.passes.push_back({name, effect, autoTimed});
    gpu_->fn.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, query);
}

void PassTimer::endPass(VkCommandBuffer cmd) {
    if (!enabled()) return;
    const Slot& slot = slots_[current_];
    if (slot.passes.empty() || slot.passes.size() > kMaxPassesPerFrame) return;
    uint32_t query = (current_ * kMaxPassesPerFrame + static_cast<uint32_t>(slot.passes.size()) - 1) * 2 + 1;
    gpu_->fn.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, query);
}

Status PassTimer::readMs(uint64_t frameIndex, std::vector<double>& ms) const {
    ms.clear();
    if (!enabled())
        return {Result::Unsupported, "GPU timings are off (gpuTimings) or the queue has no timestamps"};
    const uint32_t slotIndex = static_cast<uint32_t>(frameIndex % slots_.size());
    const Slot& slot = slots_[slotIndex];
    if (slot.frameIndex != frameIndex)
        return {Result::InvalidArgument,
                "frameIndex " + std::to_string(frameIndex) +
                    ": no timings recorded (never recorded, or overwritten by a newer frame)"};
    if (slot.passes.empty()) return Status::success();
    const uint32_t count = static_cast<uint32_t>(slot.passes.size()) * 2;
    std::vector<uint64_t> values(count * 2);  // (value, availability) pairs
    VkResult r = gpu_->fn.vkGetQueryPoolResults(
        gpu_->device, pool_, slotIndex * kMaxPassesPerFrame * 2, count, values.size() * sizeof(uint64_t),
        values.data(), 2 * sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (r != VK_SUCCESS && r != VK_NOT_READY) return vulkanStatus(r, "vkGetQueryPoolResults");
    const double nsPerTick = gpu_->properties.limits.timestampPeriod;
    for (uint32_t i = 0; i < count; ++i)
        if (values[i * 2 + 1] == 0)
            return {Result::NotReady, "frame " + std::to_string(frameIndex) + " not finished"};
    for (size_t p = 0; p < slot.passes.size(); ++p) {
        const uint64_t begin = values[p * 4] & validMask_;
        const uint64_t end = values[p * 4 + 2] & validMask_;
        const uint64_t ticks = (end - begin) & validMask_;  // wraps within the valid bits
        ms.push_back(double(ticks) * nsPerTick * 1e-6);
    }
    return Status::success();
}

Status PassTimer::read(uint64_t frameIndex, std::vector<PassTiming>& out) const {
    out.clear();
    std::vector<double> ms;
    if (Status s = readMs(frameIndex, ms); !s) return s;
    const Slot& slot = slots_[frameIndex % slots_.size()];
    for (size_t p = 0; p < ms.size(); ++p)
        out.push_back({slot.passes[p].name, ms[p]});
    return Status::success();
}

Status PassTimer::readTagged(uint64_t frameIndex, std::vector<TaggedTiming>& out) const {
    out.clear();
    std::vector<double> ms;
    if (Status s = readMs(frameIndex, ms); !s) return s;
    const Slot& slot = slots_[frameIndex % slots_.size()];
    for (size_t p = 0; p < ms.size(); ++p)
        out.push_back({slot.passes[p].effect, slot.passes[p].autoTimed, ms[p]});
    return Status::success();
}

}  // namespace postfx::core
