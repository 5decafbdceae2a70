// GPU timestamps around each postfx pass, one query range per frame in flight.
#pragma once

#include <postfx/context.h>

#include "core/gpu.h"

#include <string>
#include <vector>

namespace postfx::core {

class PassTimer {
public:
    static constexpr uint32_t kMaxPassesPerFrame = 32;

    PassTimer() = default;
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;
    ~PassTimer() { reset(); }

    // timestampValidBits of the queue family; 0 disables timing (every read returns Unsupported).
    Status create(const Gpu& gpu, uint32_t framesInFlight, uint32_t timestampValidBits);
    void reset();
    bool enabled() const { return pool_ != VK_NULL_HANDLE; }

    // Starts `frameIndex`: resets its query range in the command buffer and forgets its old passes.
    void beginFrame(VkCommandBuffer cmd, uint64_t frameIndex);
    // Brackets one pass; calls must pair up and must not nest. `effect` (-1: the context's own pass) and
    // `autoTimed` (counts toward the effect's quality Auto measurement) tag it for readTagged().
    void beginPass(VkCommandBuffer cmd, const std::string& name, int effect = -1, bool autoTimed = false);
    void endPass(VkCommandBuffer cmd);

    Status read(uint64_t frameIndex, std::vector<PassTiming>& out) const;

    struct TaggedTiming {
        int effect;
        bool autoTimed;
        double milliseconds;
    };
    // The same timings with their tags.
    Status readTagged(uint64_t frameIndex, std::vector<TaggedTiming>& out) const;

private:
    struct Pass {
        std::string name;
        int effect;
        bool autoTimed;
    };
    struct Slot {
        uint64_t frameIndex = ~0ull;
        std::vector<Pass> passes;
    };
    // Ticks of each pass of `frameIndex` into `ms` [ms].
    Status readMs(uint64_t frameIndex, std::vector<double>& ms) const;
    const Gpu* gpu_ = nullptr;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    std::vector<Slot> slots_;
    uint32_t current_ = 0;
    uint64_t validMask_ = 0;
};

}  // namespace postfx::core
