#include "window/clouds_controls.h"

#include "window/medium_controls.h"
#include "window/settings_controls.h"

#include <postfx/settings_table.h>

#include <imgui.h>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace demo::window {
namespace {

using widgets::tooltip;

// The noise textures' sizes postfx accepts (powers of two): combos, as a slider would offer sizes it refuses.
constexpr std::array<uint32_t, 5> kBaseSizes{16, 32, 64, 128, 256};
constexpr std::array<const char*, 5> kBaseSizeNames{"16", "32", "64", "128", "256"};
constexpr std::array<uint32_t, 5> kDetailSizes{8, 16, 32, 64, 128};
constexpr std::array<const char*, 5> kDetailSizeNames{"8", "16", "32", "64", "128"};

// Index of the size in `sizes` nearest to `size` (by ratio: they are powers of two).
template <size_t N>
int sizeIndex(const std::array<uint32_t, N>& sizes, uint32_t size) {
    int best = 0;
    for (int i = 1; i < int(N); ++i) {
        const double d = std::abs(std::log2(double(std::max(size, 1u)) / double(sizes[size_t(i)])));
        const double dBest = std::abs(std::log2(double(std::max(size, 1u)) / double(sizes[size_t(best)])));
        if (d < dBest) best = i;
    }
    return best;
}

template <size_t N>
bool sizeCombo(const char* label, uint32_t& value, const std::array<uint32_t, N>& sizes,
               const std::array<const char*, N>& names) {
    int index = sizeIndex(sizes, value);
    if (!ImGui::Combo(label, &index, names.data(), int(N))) return false;
    value = sizes[size_t(std::clamp(index, 0, int(N) - 1))];
    return true;
}

// The fields a quality preset sets: shown with the preset's values, greyed, unless the quality is Custom.
constexpr const char* kPresetKnobs[] = {"steps", "lightSteps", "resolutionScale", "temporal.enabled"};

bool buildQuality(postfx::CloudSettings& s) {
    const std::span<const postfx::SettingField> table = postfx::cloudSettingsTable();
    bool changed = settingControl(table, "quality", &s);
    if (s.quality == postfx::CloudQuality::Auto) changed |= settingControl(table, "autoBudgetMs", &s);
    const bool custom = s.quality == postfx::CloudQuality::Custom;
    postfx::CloudSettings preset = postfx::applyCloudQuality(s, s.quality);
    postfx::CloudSettings& k = custom ? s : preset;  // what the knobs show and edit
    if (!custom) ImGui::BeginDisabled();
    bool knobs = false;
    for (const char* member : kPresetKnobs)
        knobs |= settingControl(table, member, &k);
    if (!custom) ImGui::EndDisabled();
    return changed || (custom && knobs);
}

// A nested struct's controls in a tree node.
bool group(const char* label, const char* key, postfx::CloudSettings& s,
           std::initializer_list<const char*> skip = {}) {
    if (!ImGui::TreeNode(label)) return false;
    const bool changed = settingControls(postfx::cloudSettingsTable(), &s, key, skip);
    ImGui::TreePop();
    return changed;
}

bool buildNoise(postfx::CloudSettings& s) {
    if (!ImGui::TreeNode("Noise")) return false;
    postfx::CloudNoiseSettings& n = s.noise;
    bool changed =
        settingControls(postfx::cloudSettingsTable(), &s, "noise", {"noise.baseSize", "noise.detailSize"});
    if (!n.enabled) ImGui::BeginDisabled();
    changed |= sizeCombo("base size [texels]", n.baseSize, kBaseSizes, kBaseSizeNames);
    tooltip(
        "edge of the Perlin-Worley base-shape texture postfx generates (again when a size or the seed "
        "changes)");
    changed |= sizeCombo("detail size [texels]", n.detailSize, kDetailSizes, kDetailSizeNames);
    tooltip("edge of the Worley detail texture");
    if (!n.enabled) ImGui::EndDisabled();
    ImGui::TreePop();
    return changed;
}

}  // namespace

CloudsControls::CloudsControls(const Scene& sceneFile) : fileClouds_(sceneFile.clouds) {}

void CloudsControls::sanitize(postfx::CloudSettings& s) {
    sanitizeSettings(postfx::cloudSettingsTable(), &s);
    // The rules beside the table's ranges.
    const double maxHeight = postfx::findSettingByMember(postfx::cloudSettingsTable(), "topHeight")->max;
    s.bottomHeight = std::min(s.bottomHeight, float(maxHeight) - 1.0f);
    if (!(s.topHeight > s.bottomHeight))
        s.topHeight = s.bottomHeight + 1.0f;  // the top follows the bottom up
    postfx::CloudMultipleScattering& m = s.multipleScattering;
    m.contribution = std::min(m.contribution, m.attenuation);
    postfx::CloudNoiseSettings& n = s.noise;
    n.baseSize = kBaseSizes[size_t(sizeIndex(kBaseSizes, n.baseSize))];
    n.detailSize = kDetailSizes[size_t(sizeIndex(kDetailSizes, n.detailSize))];
}

bool CloudsControls::build(Scene& scene) {
    bool changed = false;
    ImGui::PushID("clouds");
    ImGui::SetNextItemOpen(scene.clouds.enabled, ImGuiCond_Once);  // at first: open when they are on
    if (!ImGui::CollapsingHeader("Clouds")) {
        ImGui::PopID();
        return false;
    }
    if (ImGui::Button("Reset clouds")) {
        scene.clouds = fileClouds_;
        changed = true;
    }
    tooltip("the clouds as the scene file has them");

    postfx::CloudSettings edited = scene.clouds;
    const std::span<const postfx::SettingField> table = postfx::cloudSettingsTable();
    bool edit = settingControl(table, "enabled", &edited);
    tooltip("postfx's volumetric clouds: in front of the sky, behind nearer geometry");
    edit |= buildQuality(edited);
    // The shape's fields: the layer's heights or the box.
    const bool box = edited.shape == postfx::CloudShape::Box;
    edit |= settingControls(table, &edited, "",
                            {"enabled", "quality", "autoBudgetMs", "steps", "lightSteps", "resolutionScale",
                             box ? "bottomHeight" : "shape", box ? "topHeight" : "shape"});
    if (box) edit |= group("Box", "box", edited);
    edit |= group("Multiple scattering", "multiple_scattering", edited);
    edit |= group("Temporal", "temporal", edited, {"temporal.enabled"});
    edit |= group("Shadow map", "shadow_map", edited);
    edit |= buildNoise(edited);
    if (edit) {
        sanitize(edited);
        // sanitize makes every field valid; should a check ever disagree, keep the last settings.
        if (postfx::validateCloudSettings(edited).ok()) {
            scene.clouds = edited;
            changed = true;
        }
    }
    ImGui::PopID();
    return changed;
}

}  // namespace demo::window
