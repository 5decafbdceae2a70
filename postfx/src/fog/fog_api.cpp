// The fog's typed view of the context's generic calls (postfx/fog.h).
#include <postfx/context.h>
#include <postfx/fog.h>

namespace postfx {
namespace {
constexpr const char* kFog = "fog";
constexpr uint32_t kPresets = 4;  // Low, Medium, High, Ultra
}  // namespace

Status fogAutoQuality(const Context& context, FogQuality& chosen) {
    uint32_t preset = 0;
    Status s = context.autoQuality(kFog, preset);
    if (s) chosen = FogQuality(uint32_t(FogQuality::Low) + preset);
    return s;
}

std::vector<FogAutoTimings> fogAutoTimings(const Context& context) {
    std::vector<FogAutoTimings> out;
    for (const AutoQualityTimings& t : context.autoQualityTimings()) {
        if (t.effect != kFog || t.presetMs.size() != kPresets) continue;
        FogAutoTimings f;
        f.width = t.width;
        f.height = t.height;
        f.noise = (t.features & kFogAutoFeatureNoise) != 0;
        f.shadowMap = (t.features & kFogAutoFeatureShadowMap) != 0;
        for (uint32_t i = 0; i < kPresets; ++i)
            f.presetMs[i] = t.presetMs[i];
        f.origin = t.origin;
        out.push_back(f);
    }
    return out;
}

Status setFogAutoTimings(Context& context, const std::vector<FogAutoTimings>& timings) {
    std::vector<AutoQualityTimings> generic;
    for (const FogAutoTimings& f : timings) {
        AutoQualityTimings t;
        t.effect = kFog;
        t.width = f.width;
        t.height = f.height;
        t.features = (f.noise ? kFogAutoFeatureNoise : 0u) | (f.shadowMap ? kFogAutoFeatureShadowMap : 0u);
        t.presetMs.assign(std::begin(f.presetMs), std::end(f.presetMs));
        t.origin = f.origin;
        generic.push_back(std::move(t));
    }
    return context.setAutoQualityTimings(generic);
}

Status recordFogNoiseReadback(const Context& context, VkCommandBuffer commandBuffer, VkBuffer buffer,
                              VkDeviceSize offset, uint32_t& size) {
    VkExtent3D extent{};
    VkDeviceSize bytes = 0;
    Status s = context.recordImageReadback(kFogNoiseTexture, commandBuffer, buffer, offset, extent, bytes);
    if (s) size = extent.width;
    return s;
}

VkImageView fogNoiseView(const Context& context) {
    return context.imageView(kFogNoiseTexture);
}

}  // namespace postfx
