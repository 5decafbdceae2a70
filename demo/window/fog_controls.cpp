#include "window/fog_controls.h"

#include "window/medium_controls.h"
#include "window/settings_controls.h"

#include <postfx/settings_table.h>

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace demo::window {
namespace {

using widgets::clampOrLow;
using widgets::tooltip;

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// The choices of the shadow kernel combo (all values postfx accepts).
constexpr std::array<uint32_t, 4> kShadowKernels{1, 3, 5, 7};
constexpr std::array<const char*, 4> kShadowKernelNames{"1 x 1", "3 x 3", "5 x 5", "7 x 7"};
// The fields a quality preset sets (besides shadowKernel, a combo of the odd sizes postfx accepts): shown
// with the preset's values, greyed, unless the quality is Custom.
constexpr const char* kPresetKnobs[] = {"steps", "resolutionScale", "jitter"};

// Limits postfx puts on the sun (SunInput): each illuminance channel in [0, 1e7] lux.
constexpr float kMaxIlluminance = 1e7f;

// Index of `value` in `choices`, or of the nearest one (by ratio: the choices are odd sizes).
template <size_t N>
int choiceIndex(const std::array<uint32_t, N>& choices, uint32_t value) {
    int best = 0;
    for (int i = 1; i < int(N); ++i) {
        const double d = std::abs(std::log2(double(std::max(value, 1u)) / double(choices[i])));
        const double dBest = std::abs(std::log2(double(std::max(value, 1u)) / double(choices[best])));
        if (d < dBest) best = i;
    }
    return best;
}

template <size_t N>
bool combo(const char* label, uint32_t& value, const std::array<uint32_t, N>& choices,
           const std::array<const char*, N>& names) {
    int index = choiceIndex(choices, value);
    if (!ImGui::Combo(label, &index, names.data(), int(N))) return false;
    value = choices[size_t(std::clamp(index, 0, int(N) - 1))];
    return true;
}

// The quality combo and the four knobs a preset sets. With a preset they show the preset's values and
// cannot be edited (Auto: the custom values, greyed; the overlay shows the preset Auto picked).
bool buildQuality(postfx::FogSettings& f) {
    bool changed = false;
    const std::span<const postfx::SettingField> fogTable = postfx::fogSettingsTable();
    changed |= settingControl(fogTable, "quality", &f);
    if (f.quality == postfx::FogQuality::Auto) changed |= settingControl(fogTable, "autoBudgetMs", &f);
    const bool custom = f.quality == postfx::FogQuality::Custom;
    postfx::FogSettings preset = postfx::applyFogQuality(f, f.quality);
    postfx::FogSettings& k = custom ? f : preset;  // what the knobs show and edit
    if (!custom) ImGui::BeginDisabled();
    const std::span<const postfx::SettingField> table = postfx::fogSettingsTable();
    bool knobs = false;
    for (const char* member : kPresetKnobs)
        knobs |= settingControl(table, member, &k);
    knobs |= combo("shadow kernel [texels]", k.shadowKernel, kShadowKernels, kShadowKernelNames);
    if (!custom) ImGui::EndDisabled();
    return changed || (custom && knobs);
}

bool buildFog(postfx::FogSettings& f) {
    const std::span<const postfx::SettingField> table = postfx::fogSettingsTable();
    bool changed = settingControl(table, "enabled", &f);
    tooltip("the ray-marched fog; turning it on turns the froxel fog off (postfx draws one of them)");
    changed |= buildMediumControls(f);  // the medium, its noise included
    changed |= buildQuality(f);
    // The fog's other fields: generic controls.
    changed |= settingControls(
        table, &f, "",
        {"enabled", "quality", "autoBudgetMs", "shadowKernel", "steps", "resolutionScale", "jitter"},
        postfx::fogMediumSettingsTable());
    if (ImGui::TreeNode("Temporal")) {
        changed |= settingControls(table, &f, "temporal");
        ImGui::TreePop();
    }
    return changed;
}

}  // namespace

FogControls::FogControls(const Scene& sceneFile)
    : fileFog_(sceneFile.fog),
      fileFroxelFog_(sceneFile.froxelFog),
      fileVolumes_(sceneFile.froxelVolumes),
      fileSun_(sceneFile.sun) {
    takeSun(fileSun_);
}

void FogControls::takeSun(const Sun& sun) {
    const glm::vec3 d = glm::dot(sun.direction, sun.direction) > 0.0f ? glm::normalize(sun.direction)
                                                                      : glm::vec3(0.0f, 1.0f, 0.0f);
    elevationDeg_ = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    azimuthDeg_ = std::hypot(d.x, d.z) > 1e-6f ? glm::degrees(std::atan2(d.x, -d.z)) : 0.0f;
    const float brightest = std::max({sun.illuminance.x, sun.illuminance.y, sun.illuminance.z});
    if (brightest > 0.0f) {
        illuminanceLux_ = brightest;
        illuminanceColor_ = sun.illuminance / brightest;
    } else {
        illuminanceLux_ = 0.0f;
        illuminanceColor_ = glm::vec3(1.0f);
    }
}

glm::vec3 FogControls::sunDirection() const {
    const float el = glm::radians(elevationDeg_), az = glm::radians(azimuthDeg_);
    return {std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el)};
}

glm::vec3 FogControls::sunIlluminance() const {
    glm::vec3 e = illuminanceColor_ * illuminanceLux_;
    for (int c = 0; c < 3; ++c)
        e[c] = clampOrLow(e[c], 0.0f, kMaxIlluminance);
    return e;
}

void FogControls::sanitize(postfx::FogSettings& f) {
    sanitizeSettings(postfx::fogSettingsTable(), &f);
    sanitizeMedium(f);                                                 // the texture size
    f.shadowKernel = std::clamp<uint32_t>(f.shadowKernel | 1u, 1, 7);  // odd: even sizes round up
}

bool FogControls::build(Scene& scene) {
    bool changed = false;
    if (ImGui::Button("Reset to scene file")) {
        scene.fog = fileFog_;
        scene.froxelFog = fileFroxelFog_;
        scene.froxelVolumes = fileVolumes_;
        scene.sun.direction = fileSun_.direction;
        scene.sun.illuminance = fileSun_.illuminance;
        takeSun(fileSun_);
        changed = true;
    }
    tooltip("both fogs, the fog volumes and the sun as the scene file has them (the camera and lights stay)");

    ImGui::PushID("fog");
    // Open at first when the scene shows this fog, or no effect at all (once: later the user decides).
    ImGui::SetNextItemOpen(scene.fog.enabled || (!scene.froxelFog.enabled && !scene.atmosphere.enabled),
                           ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Fog")) {
        postfx::FogSettings edited = scene.fog;
        if (buildFog(edited)) {
            sanitize(edited);
            // sanitize makes every field valid; should a check ever disagree, keep the last settings.
            if (postfx::validateFogSettings(edited).ok()) {
                // postfx draws one fog per frame: turning this one on turns the froxel fog off.
                if (edited.enabled && !scene.fog.enabled) scene.froxelFog.enabled = false;
                scene.fog = edited;
                changed = true;
            }
        }
    }
    ImGui::PopID();

    ImGui::PushID("sun");
    if (ImGui::CollapsingHeader("Sun")) {
        // The Atmosphere panel moves the sun too: follow the scene's direction when it differs.
        if (glm::dot(scene.sun.direction, scene.sun.direction) > 0.0f &&
            glm::length(glm::normalize(scene.sun.direction) - sunDirection()) > 1e-4f) {
            Sun current = fileSun_;
            current.direction = scene.sun.direction;
            current.illuminance = scene.sun.illuminance;
            takeSun(current);
        }
        bool direction = false;
        direction |= ImGui::SliderFloat("elevation [deg]", &elevationDeg_, 0.0f, 90.0f, "%.1f", kClamp);
        tooltip("angle above the horizon");
        direction |= ImGui::SliderFloat("azimuth [deg]", &azimuthDeg_, -180.0f, 180.0f, "%.1f", kClamp);
        tooltip("about +y: 0 toward -z, 90 toward +x");
        elevationDeg_ = clampOrLow(elevationDeg_, -90.0f, 90.0f);
        azimuthDeg_ = clampOrLow(azimuthDeg_, -360.0f, 360.0f);
        if (direction) {
            scene.sun.direction = sunDirection();
            changed = true;
        }
        if (ImGui::SliderFloat("illuminance [lux]", &illuminanceLux_, 0.0f, 1e6f, "%.0f", kLog)) {
            illuminanceLux_ = clampOrLow(illuminanceLux_, 0.0f, kMaxIlluminance);
            scene.sun.illuminance = sunIlluminance();
            changed = true;
        }
        tooltip("the brightest channel; the scene file's colour is kept");
    }
    ImGui::PopID();
    return changed;
}

}  // namespace demo::window
