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
#include <string>
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
    // `framesInFlight`: the context's; only frames at least that old are read (below).
    void setEffects(std::vector<uint32_t> presetCount, std::vector<uint32_t> fallback,
                    uint32_t framesInFlight);

    // The preset frame `frameIndex` with `key` uses. First collects the timings of pending measured
    // frames that have finished (does not wait); call before the timer starts `frameIndex`. While `key`
    // has presets with fewer than kSamples times, returns the next one to measure; then the highest
    // preset whose median time <= budgetMs, or the lowest if none fits. Without timings (`timer`
    // disabled): the effect's fallback. Context::plan asks a copy, so the plan is what record() would
    // choose now. Fails only when reading the timings failed (VK_ERROR_DEVICE_LOST, out of memory);
    // the frames read are then read again next time.
    Status select(const AutoQualityKey& key, float budgetMs, const PassTimer& timer, uint32_t& preset);
    // One budget for several effects (FrameInfo::budgetMs): each request is an effect on Auto with its
    // presets' errors. While a request's presets are not all measured, each unmeasured one measures (as
    // select) and the others use their fallback; then the presets of chooseWithinBudget (core/budget.h)
    // over the measured times and the errors, within `budgetMs` less the other work's time: the
    // autoTimed passes of the effects in `others` (this frame's other active effects; -1: the context's
    // own passes, postfx.view_distance, when this frame has them), in the newest frame the host has waited
    // for (collect; the last value read when none is readable). `presets` gets one per request. Fails only as
    // select does.
    struct JointRequest {
        AutoQualityKey key;
        std::vector<double> errors;  // per preset, lowest first
    };
    struct JointChoice {
        std::vector<int> effects;  // the requests' effects
        std::vector<uint32_t> presets;
        std::vector<double> ms, errors;  // each chosen preset's median time and error
        double budgetMs = 0.0, otherMs = 0.0, chosenMs = 0.0, error = 0.0;
        bool fits = false;
    };
    Status selectJoint(const std::vector<JointRequest>& requests, const std::vector<int>& others,
                       double budgetMs, const PassTimer& timer, std::vector<uint32_t>& presets);
    // The last selectJoint's choice; NotReady while it measured, or when the last frame had no budget.
    Status jointChoice(JointChoice& out) const;
    // A frame chose each Auto effect on its own (no budget): jointChoice has nothing.
    void clearJoint() { joint_.reset(); }

    // After a frame was recorded (and every recorded() of it): its index joins the recording order.
    void frameRecorded(uint64_t frameIndex);

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
        uint64_t sequence;  // its place in recording order (frameRecorded's count when it was recorded)
        AutoQualityKey key;
        uint32_t preset;
    };
    Entry& entry(const AutoQualityKey& key);
    // The preset of an unmeasured entry to measure next (the presets take turns).
    uint32_t nextToMeasure(const Entry& e) const;
    // Reads the pending frames the host has waited for: recorded at least framesInFlight frames before the
    // one being prepared (in recording order; frame indices may jump). A younger frame may be recorded and
    // submitted but not yet started on the GPU: its query slot still holds the results of the frame that
    // used it framesInFlight frames earlier (the slot's reset is a command of the frame itself), which
    // read as its own would be another preset's time (seen on the H100; lavapipe runs a submission at
    // once).
    Status collect(const PassTimer& timer);

    std::vector<uint32_t> presetCount_, fallback_;
    uint32_t framesInFlight_ = 1;
    uint64_t sequence_ = 0;                         // frames recorded so far
    static constexpr size_t kRecentFrames = 16;     // >= 2 × the largest framesInFlight (8)
    std::array<uint64_t, kRecentFrames> recent_{};  // frame index of recorded frame n at n % kRecentFrames
    std::vector<Entry> cache_;
    std::vector<Pending> pending_;
    std::vector<std::optional<uint32_t>> last_;  // per effect: choice for its last select()'s key
    std::optional<JointChoice> joint_;           // the last selectJoint's choice
    double otherMs_ = 0.0;                       // the other work's time, last read
};

}  // namespace postfx::core
