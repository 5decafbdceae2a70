// FogQuality::Auto: measures the presets on the running device from real frames and picks the most
// accurate one within the budget, cached per (color extent, noise on, shadow map present).
#pragma once

#include <postfx/context.h>
#include <postfx/fog.h>
#include <postfx/result.h>

#include "core/pass_timer.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace postfx::fog {

struct AutoQualityKey {
    uint32_t width = 0, height = 0;  // color extent
    bool noise = false;
    bool shadowMap = false;
    bool operator==(const AutoQualityKey&) const = default;
    static AutoQualityKey of(const FrameInfo& frame) {
        return {frame.color.extent.width, frame.color.extent.height, frame.fog.noise.enabled,
                frame.shadowMap.image.present()};
    }
};

class AutoQuality {
public:
    static constexpr std::array<FogQuality, 4> kPresets = {FogQuality::Low, FogQuality::Medium,
                                                           FogQuality::High, FogQuality::Ultra};
    // Frames measured per preset; a preset's time is their median. The presets take turns (Low, Medium,
    // High, Ultra, Low, ...), so a clock ramp or a first-use cost after a resize falls on all of them.
    static constexpr size_t kSamples = 3;

    // The preset frame `frameIndex` with `key` uses. First collects the timings of pending measured
    // frames that have finished (does not wait); call before the timer starts `frameIndex`. While
    // `key` has presets with fewer than kSamples times, returns the next one to measure; then the
    // highest preset whose median time <= budgetMs, or Low if none fits. Without timings (`timer`
    // disabled): Medium. Context::plan asks a copy, so the plan is what record() would choose now.
    FogQuality select(const AutoQualityKey& key, float budgetMs, const core::PassTimer& timer);
    // After `frameIndex` was recorded with `preset` (as select returned): measure it if still needed.
    void recorded(uint64_t frameIndex, const AutoQualityKey& key, FogQuality preset);
    // The choice for the key of the last select(); NotReady while its presets are being measured.
    Status chosen(FogQuality& out) const;
    // Every fully measured key, with each preset's median time.
    std::vector<FogAutoTimings> timings() const;
    // Sets the keys of `given` as measured, with those times (checked first: nothing changes on error).
    Status give(const std::vector<FogAutoTimings>& given);

private:
    struct Entry {
        AutoQualityKey key;
        std::array<std::array<double, kSamples>, 4> ms{};  // per kPresets: the measured frames' times [ms]
        std::array<size_t, 4> count{};                     // per kPresets: how many of ms are measured
        bool measured() const;
        double medianMs(size_t preset) const;  // of a measured preset
    };
    struct Pending {
        uint64_t frameIndex;
        AutoQualityKey key;
        size_t preset;  // index into kPresets
    };
    Entry& entry(const AutoQualityKey& key);
    void collect(const core::PassTimer& timer);

    std::vector<Entry> cache_;
    std::vector<Pending> pending_;
    std::optional<FogQuality> last_;  // choice for the last select()'s key; empty while measuring
};

}  // namespace postfx::fog
