// Deferred destruction of GPU objects that frames still in flight may use.
//
// An object retired while recording frame f was last used by frame f - 1 at the latest; the host
// guarantees that frame N - framesInFlight has completed when it records frame N, so the object is
// destroyed by collect() at the first frame N >= f - 1 + framesInFlight.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace postfx::core {

class Retirement {
public:
    template <class T>
    void retire(uint64_t frameIndex, std::unique_ptr<T> object) {
        if (!object) return;
        uint64_t bytes = 0;  // device memory it holds (images and buffers), for Context::memoryUsage
        if constexpr (requires(const T& t) { t.bytes(); }) bytes = object->bytes();
        entries_.push_back({frameIndex, bytes, std::shared_ptr<void>(std::move(object))});
    }
    // Destroys what frames up to `frameIndex` - framesInFlight no longer need.
    void collect(uint64_t frameIndex, uint32_t framesInFlight) {
        std::erase_if(entries_, [&](const Entry& e) { return frameIndex + 1 >= e.frame + framesInFlight; });
    }
    size_t pending() const { return entries_.size(); }
    uint64_t pendingBytes() const {
        uint64_t sum = 0;
        for (const Entry& e : entries_)
            sum += e.bytes;
        return sum;
    }

private:
    struct Entry {
        uint64_t frame;
        uint64_t bytes;
        std::shared_ptr<void> object;  // its deleter destroys the object with its own type
    };
    std::vector<Entry> entries_;
};

}  // namespace postfx::core
