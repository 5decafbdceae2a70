#include "window/medium_controls.h"

#include "window/settings_controls.h"

#include <postfx/settings_table.h>

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

using widgets::tooltip;

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

// The noise texture's size: a combo of the powers of two postfx accepts (a slider would offer sizes it
// refuses).
bool textureSizeCombo(postfx::FogNoiseSettings& n) {
    int size = textureSizeIndex(n.textureSize);
    if (!ImGui::Combo("texture size [texels]", &size, kTextureSizeNames.data(),
                      int(kTextureSizeNames.size())))
        return false;
    n.textureSize = kTextureSizes[size_t(std::clamp(size, 0, int(kTextureSizes.size()) - 1))];
    return true;
}

}  // namespace

bool buildMediumControls(postfx::FogMedium& m) {
    const std::span<const postfx::SettingField> table = postfx::fogMediumSettingsTable();
    bool changed = settingControls(table, &m, "");
    if (ImGui::TreeNode("Noise")) {
        changed |= settingControls(table, &m, "noise", {"noise.textureSize"});
        if (!m.noise.enabled) ImGui::BeginDisabled();
        changed |= textureSizeCombo(m.noise);
        tooltip("edge of the cubic texture postfx generates (again when the size or seed changes)");
        if (!m.noise.enabled) ImGui::EndDisabled();
        ImGui::TreePop();
    }
    return changed;
}

void sanitizeMedium(postfx::FogMedium& m) {
    sanitizeSettings(postfx::fogMediumSettingsTable(), &m);
    m.noise.textureSize = kTextureSizes[size_t(textureSizeIndex(m.noise.textureSize))];
}

}  // namespace demo::window
