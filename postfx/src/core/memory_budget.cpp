#include "core/memory_budget.h"

#include "core/checks.h"
#include "core/frame_graph_internal.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace postfx::core {
namespace {

// "512x512x512", "256x64", "64x64, 2 layers".
std::string extentText(const ImageDesc& d) {
    std::string s = std::to_string(d.extent.width) + "x" + std::to_string(d.extent.height);
    if (d.type == VK_IMAGE_TYPE_3D) s += "x" + std::to_string(d.extent.depth);
    if (d.layers > 1) s += ", " + std::to_string(d.layers) + " layers";
    return s;
}

// The bytes of the frame's resources sized by one setting (or of one resource without a key).
struct KeyBytes {
    std::string key;
    std::string extent;  // of its largest image
    uint64_t largest = 0;
    uint64_t bytes = 0;
};

}  // namespace

uint64_t resourceBytes(const ResourceDecl& r, uint32_t framesInFlight) {
    if (r.kind == ResourceDecl::Kind::Uniform) return slotBytes(r.uniformBytes) * framesInFlight;
    const VkExtent3D& e = r.desc.extent;
    return uint64_t(e.width) * e.height * e.depth * r.desc.layers * texelBytes(r.desc.format);
}

std::string bytesText(uint64_t bytes) {
    static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    double value = double(bytes) / 1024.0;
    size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(kUnits)) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    const double tenths = double(uint64_t(value * 10.0 + 0.5)) / 10.0;
    if (tenths == double(uint64_t(tenths)))
        std::snprintf(text, sizeof text, "%.0f %s", tenths, kUnits[unit]);
    else
        std::snprintf(text, sizeof text, "%.1f %s", tenths, kUnits[unit]);
    return text;
}

Status checkMemoryBudget(const Frame& frame, uint32_t framesInFlight, uint64_t budget) {
    if (budget == 0) return Status::success();
    uint64_t total = 0;
    for (const ResourceDecl& r : frame.resources)
        if (r.held && (owned(r) || r.kind == ResourceDecl::Kind::Uniform))
            total += resourceBytes(r, framesInFlight);
    if (total <= budget) return Status::success();

    std::vector<KeyBytes> keys;
    for (const ResourceDecl& r : frame.resources) {
        if (!r.held || !(owned(r) || r.kind == ResourceDecl::Kind::Uniform)) continue;
        const bool image = r.kind != ResourceDecl::Kind::Uniform;
        const std::string key = image && r.desc.sizedBy ? r.desc.sizedBy : r.name;
        auto it = std::find_if(keys.begin(), keys.end(), [&](const KeyBytes& k) { return k.key == key; });
        if (it == keys.end()) it = keys.insert(keys.end(), KeyBytes{key, "", 0, 0});
        const uint64_t bytes = resourceBytes(r, framesInFlight);
        it->bytes += bytes;
        if (bytes > it->largest) {
            it->largest = bytes;
            it->extent = image ? extentText(r.desc) : std::to_string(bytes) + " bytes";
        }
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const KeyBytes& a, const KeyBytes& b) { return a.bytes > b.bytes; });
    // The largest keys, until the frame without them fits.
    std::string named;
    uint64_t rest = total;
    for (const KeyBytes& k : keys) {
        named += (named.empty() ? "" : ", ") + k.key + ": " + k.extent + " needs " + bytesText(k.bytes);
        rest -= k.bytes;
        if (rest <= budget) break;
    }
    const bool alone = keys.front().bytes == total;
    return invalid(named + " of images" + (alone ? "" : " (the frame " + bytesText(total) + ")") +
                   "; the memory budget is " + bytesText(budget) + " (ContextCreateInfo.memoryBudgetBytes)");
}

}  // namespace postfx::core
