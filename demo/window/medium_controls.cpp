#include "window/medium_controls.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace demo::window {

namespace widgets {

float clampOrLow(float v, float lo, float hi) {
    return v >= lo ? (v <= hi ? v : hi) : lo;
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool sliderUint(const char* label, uint32_t& value, int lo, int hi) {
    int v = int(std::min<uint32_t>(value, uint32_t(INT32_MAX)));
    if (!ImGui::SliderInt(label, &v, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp)) return false;
    value = uint32_t(std::clamp(v, lo, hi));
    return true;
}

}  // namespace widgets

namespace {

using widgets::clampOrLow;
using widgets::tooltip;

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// The texture sizes postfx accepts.
constexpr std::array<uint32_t, 5> kTextureSizes{16, 32, 64, 128, 256};
constexpr std::array<const char*, 5> kTextureSizeNames{"16", "32", "64", "128", "256"};

// Index of the texture size nearest to `size` (by ratio: they are powers of two).
int textureSizeIndex(uint32_t size) {
    int best = 0;
    for (int i = 1; i < int(kTextureSizes.size()); ++i) {
        const double d = std::abs(std::log2(double(std::max(size, 1u)) / double(kTextureSizes[size_t(i)])));
        const double dBest =
            std::abs(std::log2(double(std::max(size, 1u)) / double(kTextureSizes[size_t(best)])));
        if (d < dBest) best = i;
    }
    return best;
}

bool buildNoise(postfx::FogNoiseSettings& n) {
    bool changed = false;
    changed |= ImGui::Checkbox("enabled", &n.enabled);
    tooltip("modulate the extinction by a tileable Perlin-Worley noise texture");
    int size = textureSizeIndex(n.textureSize);
    if (ImGui::Combo("texture size [texels]", &size, kTextureSizeNames.data(),
                     int(kTextureSizeNames.size()))) {
        n.textureSize = kTextureSizes[size_t(std::clamp(size, 0, int(kTextureSizes.size()) - 1))];
        changed = true;
    }
    tooltip("edge of the cubic texture postfx generates (again when the size or seed changes)");
    const uint32_t step = 1;
    changed |= ImGui::InputScalar("seed", ImGuiDataType_U32, &n.seed, &step, nullptr, "%u");
    changed |= ImGui::SliderFloat("tiling [1/(100 m)]", &n.tiling, 0.1f, 50.0f, "%.3g", kLog);
    tooltip("the texture repeats every 100/tiling metres");
    changed |= ImGui::SliderFloat("threshold", &n.threshold, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("noise = clamp(texel - threshold, 0, 1) * multiplier");
    changed |= ImGui::SliderFloat("multiplier", &n.multiplier, 0.0f, 10.0f, "%.2f", kClamp);
    changed |= ImGui::DragFloat3("wind [m/s]", &n.wind.x, 0.05f, -100.0f, 100.0f, "%.2f", kClamp);
    tooltip("velocity of the noise field");
    return changed;
}

}  // namespace

bool buildMediumControls(postfx::FogMedium& m) {
    bool changed = false;
    changed |= ImGui::SliderFloat("density [1/m]", &m.density, 1e-4f, 1.0f, "%.4g", kLog);
    tooltip("extinction at the base height where noise = 1; 0.02/m: ~150 m visibility");
    changed |= ImGui::ColorEdit3("albedo", &m.albedo.x, ImGuiColorEditFlags_Float);
    tooltip("single-scattering albedo per RGB channel, plain numbers in [0, 1]");
    changed |= ImGui::SliderFloat("anisotropy g", &m.anisotropy, -0.99f, 0.99f, "%.2f", kClamp);
    tooltip("Henyey-Greenstein g; > 0 scatters forward (brightest toward the sun and the lights)");
    changed |= ImGui::SliderFloat("height falloff [1/m]", &m.heightFalloff, 0.0f, 1.0f, "%.3g", kLog);
    tooltip("density ~ exp(-falloff * (y - base height)); 0: homogeneous");
    changed |= ImGui::SliderFloat("base height [m]", &m.baseHeight, -50.0f, 50.0f, "%.2f", kClamp);
    changed |= ImGui::SliderFloat("max distance [m]", &m.maxDistance, 1.0f, 2000.0f, "%.1f", kLog);
    tooltip("how far the fog is evaluated (then the analytic tail)");
    changed |= ImGui::Checkbox("self shadow", &m.selfShadow);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("analytic tail", &m.analyticTail);
    if (ImGui::TreeNode("Noise")) {
        changed |= buildNoise(m.noise);
        ImGui::TreePop();
    }
    return changed;
}

bool buildTemporalControls(postfx::TemporalSettings& t) {
    bool changed = ImGui::Checkbox("temporal", &t.enabled);
    tooltip(
        "blend each frame with the previous frames' result, reprojected into this view: the jitter's noise "
        "averages out; history that no longer fits (disocclusion, a light that changed) is dropped");
    if (!t.enabled) ImGui::BeginDisabled();
    changed |= ImGui::SliderFloat("blend weight", &t.blendWeight, kMinBlendWeight, 1.0f, "%.3f", kLog);
    tooltip(
        "weight of the current frame: lower is smoother and slower to follow changes (the history "
        "decays as (1 - weight)^frames); 1 keeps no history");
    if (!t.enabled) ImGui::EndDisabled();
    return changed;
}

void sanitizeTemporal(postfx::TemporalSettings& t) {
    if (!(t.blendWeight > 0.0f)) t.blendWeight = kMinBlendWeight;  // also NaN
    t.blendWeight = std::min(t.blendWeight, 1.0f);
}

void sanitizeMedium(postfx::FogMedium& m) {
    m.density = clampOrLow(m.density, 0.0f, 1e6f);
    for (int c = 0; c < 3; ++c)
        m.albedo[c] = clampOrLow(m.albedo[c], 0.0f, 1.0f);
    m.anisotropy = clampOrLow(m.anisotropy, -1.0f, 1.0f);
    m.heightFalloff = clampOrLow(m.heightFalloff, 0.0f, 10.0f);
    if (!std::isfinite(m.baseHeight))
        m.baseHeight = std::isnan(m.baseHeight) ? 0.0f : std::clamp(m.baseHeight, -1e6f, 1e6f);
    if (!(m.maxDistance > 0.0f)) m.maxDistance = 1.0f;  // also NaN
    m.maxDistance = std::min(m.maxDistance, 1e7f);
    postfx::FogNoiseSettings& n = m.noise;
    n.textureSize = kTextureSizes[size_t(textureSizeIndex(n.textureSize))];
    if (!(n.tiling > 0.0f)) n.tiling = 0.1f;  // also NaN
    n.tiling = std::min(n.tiling, 1000.0f);
    n.threshold = clampOrLow(n.threshold, 0.0f, 1.0f);
    n.multiplier = clampOrLow(n.multiplier, 0.0f, 1e3f);
    for (int c = 0; c < 3; ++c)
        n.wind[c] = clampOrLow(n.wind[c], -1e3f, 1e3f);
}

}  // namespace demo::window
