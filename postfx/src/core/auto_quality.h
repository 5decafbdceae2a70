// Quality Auto, for every effect that declares presets (Effect::presetCount): measures the presets on the
// running device from real frames and picks the most accurate one within the effect's budget, cached per
// (effect, color extent, the effect's cost-relevant features).
#pragma once

#include <postfx/context.h>
#include <postfx/result.h>

#include "core/pass_timer.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace postfx::core {

struct AutoQualityKey {
    int effect = 0;                  // index of the effect in the context
    uint32_t width = 0, height = 0;  // color extent
    uint32_t features = 0;           // Effect::autoFeatures
    bool operator==(const AutoQualityKey&) const = default;
};

class AutoQuality {
public:
    static constexpr size_t kMaxPresets = 8;
    // Frames measured per preset; a preset's time is their median. The presets take turns (lowest first,
    // then the next, ...), so a clock ramp or a first-use cost after a resize falls on all of them.
    static constexpr size_t kSamples = 3;

    // `presetCount[e]`, `fallback[e]`: effect e's number of presets (0: none) and the preset it uses
    // without GPU timings.
    void setEffects(std::vector<uint32_t> presetCount, std::vector<uint32_t> fallback);

    // The preset frame `frameIndex` with `key` uses. First collects the timings of pending measured
    // frames that have finished (does not wait); call before the timer starts `frameIndex`. While `key`
    // has presets with fewer than kSamples times, returns the next one to measure; then the highest
    // preset whose median time <= budgetMs, or the lowest if none fits. Without timings (`timer`
    // disabled): the effect's fallback. Context::plan asks a copy, so the plan is what record() would
    // choose now. Fails only when reading the timings failed (VK_ERROR_DEVICE_LOST, out of memory);
    // the frames read are then read again next time.
    Status select(const AutoQualityKey& key, float budgetMs, const PassTimer& timer, uint32_t& preset);
    // After `frameIndex` was recorded with `preset` (as select returned): measure it if still needed.
    void recorded(uint64_t frameIndex, const AutoQualityKey& key, uint32_t preset);
    // The choice for effect `effect`'s key of its last select(); NotReady while its presets are measured.
    Status chosen(int effect, uint32_t& out) const;
    // Every fully measured key, with each preset's median time (effect name filled by the caller).
    std::vector<std::pair<AutoQualityKey, std::vector<float>>> timings() const;
    // Sets `given` keys as measured with those times: each the effect's preset count, checked by the
    // caller.
    void give(const std::vector<std::pair<AutoQualityKey, std::vector<float>>>& given);

private:
    struct Entry {
        AutoQualityKey key;
        uint32_t presets = 0;
        std::array<std::array<double, kSamples>, kMaxPresets> ms{};  // per preset: measured times [ms]
        std::array<size_t, kMaxPresets> count{};                     // per preset: how many are measured
        bool measured() const;
        double medianMs(size_t preset) const;  // of a measured preset
    };
    struct Pending {
        uint64_t frameIndex;
        AutoQualityKey key;
        uint32_t preset;
    };
    Entry& entry(const AutoQualityKey& key);
    Status collect(const PassTimer& timer);

    std::vector<uint32_t> presetCount_, fallback_;
    std::vector<Entry> cache_;
    std::vector<Pending> pending_;
    std::vector<std::optional<uint32_t>> last_;  // per effect: choice for its last select()'s key
};

}  // namespace postfx::core
