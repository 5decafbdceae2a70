#include "core/auto_quality.h"

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

void AutoQuality::setEffects(std::vector<uint32_t> presetCount, std::vector<uint32_t> fallback) {
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

Status AutoQuality::collect(const PassTimer& timer) {
    std::vector<PassTimer::TaggedTiming> timings;
    for (auto it = pending_.begin(); it != pending_.end();) {
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
        // The preset with the fewest times, counting frames still waiting for theirs (ties: the lower
        // preset), so the presets take turns; once every missing time is waited for, the one with the
        // fewest times again.
        size_t next = 0, fewest = SIZE_MAX;
        for (size_t i = 0; i < e.presets; ++i) {
            const size_t waiting =
                size_t(std::count_if(pending_.begin(), pending_.end(),
                                     [&](const Pending& p) { return p.key == key && p.preset == i; }));
            const size_t count = e.count[i] + waiting;
            if (e.count[i] < kSamples && count < kSamples && count < fewest) next = i, fewest = count;
        }
        if (fewest == SIZE_MAX)
            for (size_t i = 0; i < e.presets; ++i)
                if (e.count[i] < kSamples && e.count[i] < fewest) next = i, fewest = e.count[i];
        preset = uint32_t(next);
        return Status::success();
    }
    uint32_t choice = 0;
    for (size_t i = 0; i < e.presets; ++i)
        if (e.medianMs(i) <= double(budgetMs)) choice = uint32_t(i);
    last = choice;
    preset = choice;
    return Status::success();
}

void AutoQuality::recorded(uint64_t frameIndex, const AutoQualityKey& key, uint32_t preset) {
    if (last_[size_t(key.effect)]) return;  // a choice exists (or no timings): nothing to measure
    if (preset >= presetCount_[size_t(key.effect)]) return;
    std::erase_if(pending_,
                  [&](const Pending& p) { return p.frameIndex == frameIndex && p.key.effect == key.effect; });
    pending_.push_back({frameIndex, key, preset});
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
