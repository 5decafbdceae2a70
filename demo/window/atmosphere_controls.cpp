#include "window/atmosphere_controls.h"

#include "window/medium_controls.h"
#include "window/settings_controls.h"

#include <postfx/settings_table.h>

#include <imgui.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace demo::window {
namespace {

using widgets::clampOrLow;
using widgets::tooltip;

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// The sliders' ranges of the hand-written controls (the others: the settings table's editor ranges).
constexpr float kMaxScale = 20.0f;             // Rayleigh and ozone, times the file's
constexpr float kMaxCameraAltitude = 1e7f;     // [m] scene files' coordinate bound (limits::kMaxCoordinate)
constexpr float kMinSunElevationDeg = -20.0f;  // night, below the twilight

postfx::Vec3 scaled(const postfx::Vec3& v, float k) {
    postfx::Vec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] = clampOrLow(v[c] * k, 0.0f, 1.0f);
    return out;
}

bool buildMedia(postfx::AtmosphereSettings& a, const postfx::AtmosphereSettings& file, float& rayleighScale,
                float& ozoneScale) {
    bool changed = false;
    // Rayleigh scattering and ozone absorption: one scale of the file's spectrum each (their channels are
    // ~1e-6 /m apart in a fixed ratio: three sliders of such numbers would only break the colour).
    if (ImGui::SliderFloat("Rayleigh scale", &rayleighScale, 0.0f, kMaxScale, "%.3g", kLog)) {
        rayleighScale = clampOrLow(rayleighScale, 0.0f, kMaxScale);
        a.rayleighScattering = scaled(file.rayleighScattering, rayleighScale);
        changed = true;
    }
    tooltip("air's scattering, times the scene file's (5.8, 13.6, 33.1)e-6 /m on Earth): the blue sky");
    if (ImGui::SliderFloat("ozone scale", &ozoneScale, 0.0f, kMaxScale, "%.3g", kLog)) {
        ozoneScale = clampOrLow(ozoneScale, 0.0f, kMaxScale);
        a.ozoneAbsorption = scaled(file.ozoneAbsorption, ozoneScale);
        changed = true;
    }
    tooltip("ozone's absorption, times the scene file's: the blue of the sky at twilight");
    const std::span<const postfx::SettingField> table = postfx::atmosphereSettingsTable();
    // The direction counts must be perfect squares, which a slider would mostly miss: the scene file sets
    // them.
    changed |= settingControls(table, &a, "",
                               {"enabled", "rayleighScattering", "ozoneAbsorption",
                                "multipleScatteringDirections", "scatteringOrdersDirections"});
    return changed;
}

}  // namespace

AtmosphereControls::AtmosphereControls(const Scene& sceneFile) : fileAtmosphere_(sceneFile.atmosphere) {}

bool AtmosphereControls::build(Scene& scene) {
    bool changed = false;
    ImGui::PushID("atmosphere");
    ImGui::SetNextItemOpen(scene.atmosphere.enabled, ImGuiCond_Once);
    if (!ImGui::CollapsingHeader("Atmosphere")) {
        ImGui::PopID();
        return false;
    }
    if (ImGui::Button("Reset atmosphere")) {
        scene.atmosphere = fileAtmosphere_;
        rayleighScale_ = ozoneScale_ = 1.0f;
        changed = true;
    }
    tooltip("the atmosphere as the scene file has it (the sun and camera stay)");

    postfx::AtmosphereSettings edited = scene.atmosphere;
    bool edit = settingControl(postfx::atmosphereSettingsTable(), "enabled", &edited);
    tooltip("sun.illuminance is then the sun's outside the atmosphere; the sky is drawn by postfx");

    // The sun, from the scene's direction every frame (the Fog panel's "Sun" edits it too).
    const glm::vec3 d = glm::dot(scene.sun.direction, scene.sun.direction) > 0.0f
                            ? glm::normalize(scene.sun.direction)
                            : glm::vec3(0.0f, 1.0f, 0.0f);
    float elevationDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    if (std::hypot(d.x, d.z) > 1e-6f) azimuthDeg_ = glm::degrees(std::atan2(d.x, -d.z));
    bool sun =
        ImGui::SliderFloat("sun elevation [deg]", &elevationDeg, kMinSunElevationDeg, 90.0f, "%.2f", kClamp);
    tooltip("angle above the horizon; below it the planet hides the sun (twilight, then night)");
    sun |= ImGui::SliderFloat("sun azimuth [deg]", &azimuthDeg_, -180.0f, 180.0f, "%.1f", kClamp);
    tooltip("about +y: 0 toward -z, 90 toward +x");
    if (sun) {
        const float el = glm::radians(clampOrLow(elevationDeg, -90.0f, 90.0f));
        const float az = glm::radians(clampOrLow(azimuthDeg_, -360.0f, 360.0f));
        scene.sun.direction = {std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el)};
        changed = true;
    }

    float altitude = clampOrLow(scene.camera.position.y, 0.0f, kMaxCameraAltitude);
    if (ImGui::SliderFloat("camera altitude [m]", &altitude, 0.0f, kMaxCameraAltitude, "%.0f", kLog)) {
        altitude = clampOrLow(altitude, 0.0f, kMaxCameraAltitude);
        const float dy = altitude - scene.camera.position.y;
        scene.camera.position.y = altitude;
        scene.camera.lookAt.y += dy;  // the view direction stays
        changed = true;
    }
    tooltip(
        "the camera's y (the ground is y = 0; the atmosphere's top 100 km up on Earth); the camera's far "
        "plane limits what geometry is seen");

    ImGui::Separator();
    ImGui::TextUnformatted("media");
    edit |= buildMedia(edited, fileAtmosphere_, rayleighScale_, ozoneScale_);
    if (edit) {
        sanitizeSettings(postfx::atmosphereSettingsTable(), &edited);
        // sanitize makes every edited field valid; should a check ever disagree, keep the last settings.
        if (postfx::validateAtmosphereSettings(edited).ok()) {
            scene.atmosphere = edited;
            changed = true;
        }
    }
    ImGui::PopID();
    return changed;
}

}  // namespace demo::window
