#include <postfx/frame_plan.h>

#include <algorithm>

namespace postfx {

uint64_t FramePlan::totalBytes() const {
    uint64_t total = 0;
    for (const PlannedResource& r : resources)
        total += r.bytes;
    return total;
}

bool FramePlan::reads(std::string_view resource) const {
    return std::any_of(passes.begin(), passes.end(), [&](const PlannedPass& p) {
        return std::find(p.reads.begin(), p.reads.end(), resource) != p.reads.end();
    });
}

bool FramePlan::writes(std::string_view resource) const {
    return std::any_of(passes.begin(), passes.end(), [&](const PlannedPass& p) {
        return std::find(p.writes.begin(), p.writes.end(), resource) != p.writes.end();
    });
}

const PlannedPass* FramePlan::pass(std::string_view name) const {
    for (const PlannedPass& p : passes)
        if (p.name == name) return &p;
    return nullptr;
}

}  // namespace postfx
