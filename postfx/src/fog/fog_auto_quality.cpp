#include "fog/fog_auto_quality.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace postfx::fog {

bool AutoQuality::Entry::measured() const {
    return std::all_of(count.begin(), count.end(), [](size_t n) { return n >= kSamples; });
}

double AutoQuality::Entry::medianMs(size_t preset) const {
    std::array<double, kSamples> t = ms[preset];
    std::nth_element(t.begin(), t.begin() + kSamples / 2, t.end());
    return t[kSamples / 2];
}

AutoQuality::Entry& AutoQuality::entry(const AutoQualityKey& key) {
    for (Entry& e : cache_)
        if (e.key == key) return e;
    cache_.push_back({key, {}});
    return cache_.back();
}

void AutoQuality::collect(const core::PassTimer& timer) {
    std::vector<PassTiming> timings;
    for (auto it = pending_.begin(); it != pending_.end();) {
        const Status s = timer.read(it->frameIndex, timings);
        if (s.code == Result::NotReady) {
            ++it;
            continue;
        }
        if (s.ok()) {
            double ms = 0.0;
            for (const PassTiming& t : timings)
                if (t.name.rfind("fog.", 0) == 0 && t.name != "fog.noise") ms += t.milliseconds;
            Entry& e = entry(it->key);
            if (e.count[it->preset] < kSamples) e.ms[it->preset][e.count[it->preset]++] = ms;
        }  // any other status: the frame's queries are gone; its preset is measured again later
        it = pending_.erase(it);
    }
}

FogQuality AutoQuality::select(const AutoQualityKey& key, float budgetMs, const core::PassTimer& timer) {
    if (!timer.enabled()) {
        last_ = FogQuality::Medium;
        return FogQuality::Medium;
    }
    collect(timer);
    const Entry& e = entry(key);
    if (!e.measured()) {
        last_.reset();
        // The preset with the fewest times, counting frames still waiting for theirs (ties: the lower
        // preset), so the presets take turns; once every missing time is waited for, the one with the
        // fewest times again.
        size_t next = 0, fewest = SIZE_MAX;
        for (size_t i = 0; i < kPresets.size(); ++i) {
            const size_t waiting =
                size_t(std::count_if(pending_.begin(), pending_.end(),
                                     [&](const Pending& p) { return p.key == key && p.preset == i; }));
            const size_t count = e.count[i] + waiting;
            if (e.count[i] < kSamples && count < kSamples && count < fewest) next = i, fewest = count;
        }
        if (fewest == SIZE_MAX)
            for (size_t i = 0; i < kPresets.size(); ++i)
                if (e.count[i] < kSamples && e.count[i] < fewest) next = i, fewest = e.count[i];
        return kPresets[next];
    }
    FogQuality choice = FogQuality::Low;
    for (size_t i = 0; i < kPresets.size(); ++i)
        if (e.medianMs(i) <= double(budgetMs)) choice = kPresets[i];
    last_ = choice;
    return choice;
}

void AutoQuality::recorded(uint64_t frameIndex, const AutoQualityKey& key, FogQuality preset) {
    if (last_) return;  // a choice exists (or no timings): nothing to measure
    const auto it = std::find(kPresets.begin(), kPresets.end(), preset);
    if (it == kPresets.end()) return;
    std::erase_if(pending_, [&](const Pending& p) { return p.frameIndex == frameIndex; });
    pending_.push_back({frameIndex, key, size_t(it - kPresets.begin())});
}

std::vector<FogAutoTimings> AutoQuality::timings() const {
    std::vector<FogAutoTimings> out;
    for (const Entry& e : cache_) {
        if (!e.measured()) continue;
        FogAutoTimings t;
        t.width = e.key.width;
        t.height = e.key.height;
        t.noise = e.key.noise;
        t.shadowMap = e.key.shadowMap;
        for (size_t i = 0; i < kPresets.size(); ++i)
            t.presetMs[i] = float(e.medianMs(i));
        out.push_back(t);
    }
    return out;
}

Status AutoQuality::give(const std::vector<FogAutoTimings>& given) {
    for (size_t k = 0; k < given.size(); ++k) {
        const FogAutoTimings& t = given[k];
        const std::string name = "fog auto timings[" + std::to_string(k) + "]";
        if (t.width == 0 || t.height == 0)
            return {Result::InvalidArgument, name + ": extent must be at least 1x1"};
        for (size_t i = 0; i < kPresets.size(); ++i)
            if (!std::isfinite(t.presetMs[i]) || t.presetMs[i] < 0.0f)
                return {Result::InvalidArgument, name + ".presetMs[" + std::to_string(i) +
                                                     "]: " + std::to_string(t.presetMs[i]) +
                                                     " must be finite and >= 0"};
    }
    for (const FogAutoTimings& t : given) {
        Entry& e = entry({t.width, t.height, t.noise, t.shadowMap});
        // A given time stands for all kSamples measurements (its median is that time).
        for (size_t i = 0; i < kPresets.size(); ++i) {
            e.ms[i].fill(double(t.presetMs[i]));
            e.count[i] = kSamples;
        }
    }
    return Status::success();
}

Status AutoQuality::chosen(FogQuality& out) const {
    if (!last_)
        return {Result::NotReady,
                "fog auto quality: no choice yet for the last recorded frame's "
                "(color extent, noise, shadow map); its presets are being measured"};
    out = *last_;
    return Status::success();
}

}  // namespace postfx::fog
