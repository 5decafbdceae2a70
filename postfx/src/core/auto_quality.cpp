#include "core/auto_quality.h"

#include "core/budget.h"

#include <algorithm>
#include <cstdint>

namespace postfx::core {

bool AutoQuality::Entry::measured() const {
    return std::all_of(count.begin(), count.begin() + presets, [](size_t n) { return n >= kSamples; });
}

double AutoQuality::Entry::medianMs(size_t preset) const {
    std::array<double, kSamples> t = ms[preset];
    std::nth_element(t.begin(), t.begin() + kSamples / 2, t.end());
    return t[kSamples / 2];
}

void AutoQuality::setEffects(std::vector<uint32_t> presetCount, std::vector<uint32_t> fallback,
                             uint32_t framesInFlight) {
    framesInFlight_ = std::max(framesInFlight, 1u);
    presetCount_ = std::move(presetCount);
    fallback_ = std::move(fallback);
    last_.assign(presetCount_.size(), std::nullopt);
}

AutoQuality::Entry& AutoQuality::entry(const AutoQualityKey& key) {
    for (Entry& e : cache_)
        if (e.key == key) return e;
    Entry e;
    e.key = key;
    e.presets = std::min<uint32_t>(presetCount_[size_t(key.effect)], kMaxPresets);
    cache_.push_back(e);
    return cache_.back();
}

void AutoQuality::frameRecorded(uint64_t frameIndex) {
    recent_[sequence_ % kRecentFrames] = frameIndex;
    ++sequence_;
}

Status AutoQuality::collect(const PassTimer& timer) {
    std::vector<PassTimer::TaggedTiming> timings;
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (it->sequence + framesInFlight_ > sequence_) {  // not yet known to be finished
            ++it;
            continue;
        }
        const Status s = timer.readTagged(it->frameIndex, timings);
        if (s.code == Result::NotReady) {
            ++it;
            continue;
        }
        // The query read itself failed (device lost, out of memory): the host hears of it; the frame
        // stays pending.
        if (s.code == Result::VulkanError || s.code == Result::OutOfMemory) return s;
        if (s.ok()) {
            // The effect's passes, without work on slow inputs (a noise texture or LUT being rebuilt).
            double ms = 0.0;
            for (const PassTimer::TaggedTiming& t : timings)
                if (t.effect == it->key.effect && t.autoTimed) ms += t.milliseconds;
            Entry& e = entry(it->key);
            if (e.count[it->preset] < kSamples) e.ms[it->preset][e.count[it->preset]++] = ms;
        }  // any other status: the frame's queries are gone; its preset is measured again later
        it = pending_.erase(it);
    }
    return Status::success();
}

Status AutoQuality::select(const AutoQualityKey& key, float budgetMs, const PassTimer& timer,
                           uint32_t& preset) {
    std::optional<uint32_t>& last = last_[size_t(key.effect)];
    if (!timer.enabled()) {
        last = fallback_[size_t(key.effect)];
        preset = *last;
        return Status::success();
    }
    if (Status s = collect(timer); !s) return s;
    const Entry& e = entry(key);
    if (!e.measured()) {
        last.reset();
        preset = nextToMeasure(e);
        return Status::success();
    }
    uint32_t choice = 0;
    for (size_t i = 0; i < e.presets; ++i)
        if (e.medianMs(i) <= double(budgetMs)) choice = uint32_t(i);
    last = choice;
    preset = choice;
    return Status::success();
}

uint32_t AutoQuality::nextToMeasure(const Entry& e) const {
    // The preset with the fewest times, counting frames still waiting for theirs (ties: the lower
    // preset), so the presets take turns; once every missing time is waited for, the one with the
    // fewest times again.
    size_t next = 0, fewest = SIZE_MAX;
    for (size_t i = 0; i < e.presets; ++i) {
        const size_t waiting = size_t(std::count_if(pending_.begin(), pending_.end(), [&](const Pending& p) {
            return p.key == e.key && p.preset == i;
        }));
        const size_t count = e.count[i] + waiting;
        if (e.count[i] < kSamples && count < kSamples && count < fewest) next = i, fewest = count;
    }
    if (fewest == SIZE_MAX)
        for (size_t i = 0; i < e.presets; ++i)
            if (e.count[i] < kSamples && e.count[i] < fewest) next = i, fewest = e.count[i];
    return uint32_t(next);
}

Status AutoQuality::selectJoint(const std::vector<JointRequest>& requests, const std::vector<int>& others,
                                double budgetMs, const PassTimer& timer, std::vector<uint32_t>& presets) {
    presets.assign(requests.size(), 0);
    joint_.reset();
    if (!timer.enabled()) {
        for (size_t r = 0; r < requests.size(); ++r) {
            const int effect = requests[r].key.effect;
            last_[size_t(effect)] = fallback_[size_t(effect)];
            presets[r] = fallback_[size_t(effect)];
        }
        return Status::success();
    }
    if (Status s = collect(timer); !s) return s;

    // The rest of postfx's work, from the newest frame the host has waited for (collect says why not a
    // younger one).
    std::vector<PassTimer::TaggedTiming> timings;
    for (uint64_t back = framesInFlight_; back <= 2 * uint64_t(framesInFlight_) && back <= sequence_;
         ++back) {
        const Status s = timer.readTagged(recent_[(sequence_ - back) % kRecentFrames], timings);
        if (s.code == Result::VulkanError || s.code == Result::OutOfMemory) return s;
        if (!s.ok()) continue;
        double other = 0.0;
        for (const PassTimer::TaggedTiming& t : timings) {
            const bool counted = std::find(others.begin(), others.end(), t.effect) != others.end();
            if (t.autoTimed && counted) other += t.milliseconds;
        }
        otherMs_ = other;
        break;
    }

    bool measured = true;
    for (size_t r = 0; r < requests.size(); ++r) {
        const Entry& e = entry(requests[r].key);
        const int effect = requests[r].key.effect;
        last_[size_t(effect)].reset();
        if (e.measured()) {
            presets[r] = fallback_[size_t(effect)];
        } else {
            measured = false;
            presets[r] = nextToMeasure(e);
        }
    }
    if (!measured) return Status::success();

    std::vector<PresetFront> fronts(requests.size());
    for (size_t r = 0; r < requests.size(); ++r) {
        const Entry& e = entry(requests[r].key);
        for (size_t i = 0; i < e.presets && i < requests[r].errors.size(); ++i) {
            fronts[r].ms.push_back(e.medianMs(i));
            fronts[r].error.push_back(requests[r].errors[i]);
        }
    }
    const BudgetSolution solution = chooseWithinBudget(fronts, budgetMs - otherMs_);
    JointChoice choice;
    choice.budgetMs = budgetMs;
    choice.otherMs = otherMs_;
    choice.chosenMs = solution.ms;
    choice.error = solution.error;
    choice.fits = solution.fits;
    for (size_t r = 0; r < requests.size(); ++r) {
        const uint32_t p = solution.presets[r];
        const int effect = requests[r].key.effect;
        presets[r] = p;
        last_[size_t(effect)] = p;
        choice.effects.push_back(effect);
        choice.presets.push_back(p);
        choice.ms.push_back(fronts[r].ms.empty() ? 0.0 : fronts[r].ms[p]);
        choice.errors.push_back(fronts[r].error.empty() ? 0.0 : fronts[r].error[p]);
    }
    joint_ = std::move(choice);
    return Status::success();
}

Status AutoQuality::jointChoice(JointChoice& out) const {
    if (!joint_)
        return {Result::NotReady,
                "budget: no choice for the last recorded frame (FrameInfo::budgetMs 0, no effect on quality "
                "Auto, or their presets are being measured)"};
    out = *joint_;
    return Status::success();
}

void AutoQuality::recorded(uint64_t frameIndex, const AutoQualityKey& key, uint32_t preset) {
    if (last_[size_t(key.effect)]) return;  // a choice exists (or no timings): nothing to measure
    if (preset >= presetCount_[size_t(key.effect)]) return;
    std::erase_if(pending_,
                  [&](const Pending& p) { return p.frameIndex == frameIndex && p.key.effect == key.effect; });
    pending_.push_back({frameIndex, sequence_, key, preset});
}

std::vector<std::pair<AutoQualityKey, std::vector<float>>> AutoQuality::timings() const {
    std::vector<std::pair<AutoQualityKey, std::vector<float>>> out;
    for (const Entry& e : cache_) {
        if (!e.measured()) continue;
        std::vector<float> ms;
        for (size_t i = 0; i < e.presets; ++i)
            ms.push_back(float(e.medianMs(i)));
        out.emplace_back(e.key, std::move(ms));
    }
    return out;
}

void AutoQuality::give(const std::vector<std::pair<AutoQualityKey, std::vector<float>>>& given) {
    for (const auto& [key, ms] : given) {
        Entry& e = entry(key);
        // A given time stands for all kSamples measurements (its median is that time).
        for (size_t i = 0; i < e.presets && i < ms.size(); ++i) {
            e.ms[i].fill(double(ms[i]));
            e.count[i] = kSamples;
        }
    }
}

Status AutoQuality::chosen(int effect, uint32_t& out) const {
    if (effect < 0 || size_t(effect) >= last_.size() || !last_[size_t(effect)])
        return {Result::NotReady,
                "auto quality: no choice yet for the last recorded frame's key (color extent and the "
                "effect's features); its presets are being measured"};
    out = *last_[size_t(effect)];
    return Status::success();
}

}  // namespace postfx::core
