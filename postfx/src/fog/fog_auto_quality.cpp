#include "fog/fog_auto_quality.h"

#include <algorithm>
#include <string>

namespace postfx::fog {

bool AutoQuality::Entry::measured() const {
    return std::all_of(ms.begin(), ms.end(), [](const std::optional<double>& t) { return t.has_value(); });
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
            entry(it->key).ms[it->preset] = ms;
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
        // The next preset neither measured nor waiting for its timings; when all are waiting, the first
        // unmeasured one again.
        std::optional<size_t> next;
        for (size_t i = 0; i < kPresets.size() && !next; ++i) {
            const bool waiting = std::any_of(pending_.begin(), pending_.end(),
                                             [&](const Pending& p) { return p.key == key && p.preset == i; });
            if (!e.ms[i] && !waiting) next = i;
        }
        for (size_t i = 0; i < kPresets.size() && !next; ++i)
            if (!e.ms[i]) next = i;
        return kPresets[*next];
    }
    FogQuality choice = FogQuality::Low;
    for (size_t i = 0; i < kPresets.size(); ++i)
        if (*e.ms[i] <= double(budgetMs)) choice = kPresets[i];
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

Status AutoQuality::chosen(FogQuality& out) const {
    if (!last_)
        return {Result::NotReady,
                "fog auto quality: no choice yet for the last recorded frame's "
                "(color extent, noise, shadow map); its presets are being measured"};
    out = *last_;
    return Status::success();
}

}  // namespace postfx::fog
