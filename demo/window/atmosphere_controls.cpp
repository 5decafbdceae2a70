#include "window/atmosphere_controls.h"

#include "window/medium_controls.h"

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

// The sliders' ranges: within postfx's (validateAtmosphereSettings), narrower where a wider one is useless.
constexpr float kMaxScale = 20.0f;             // Rayleigh and ozone, times the file's
constexpr float kMinHeight = 10.0f;            // scale heights [m]
constexpr float kMaxHeight = 1e5f;             // (postfx: 1e7)
constexpr float kMaxMieCoefficient = 1e-3f;    // [1/m] (postfx: 1); 250× Earth's
constexpr float kMaxAnisotropy = 0.99f;        // |g| (postfx: < 1)
constexpr float kMaxSunRadiusDeg = 45.0f;      // postfx's bound
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
    if (ImGui::SliderFloat("Rayleigh scale", &rayleighScale, 0.0f, kMaxScale, "%.3g", kLog)) {
        rayleighScale = clampOrLow(rayleighScale, 0.0f, kMaxScale);
        a.rayleighScattering = scaled(file.rayleighScattering, rayleighScale);
        changed = true;
    }
    tooltip("air's scattering, times the scene file's (5.8, 13.6, 33.1)e-6 /m on Earth): the blue sky");
    changed |= ImGui::SliderFloat("Rayleigh height [m]", &a.rayleighScaleHeight, kMinHeight, kMaxHeight,
                                  "%.0f", kLog);
    tooltip("scale height: the air's density falls as exp(-altitude / this)");
    changed |=
        ImGui::SliderFloat("Mie scattering [1/m]", &a.mieScattering, 0.0f, kMaxMieCoefficient, "%.3g", kLog);
    tooltip("aerosols' scattering at the ground (Earth: 4e-6): haze, the glow around the sun");
    changed |=
        ImGui::SliderFloat("Mie absorption [1/m]", &a.mieAbsorption, 0.0f, kMaxMieCoefficient, "%.3g", kLog);
    changed |= ImGui::SliderFloat("Mie height [m]", &a.mieScaleHeight, kMinHeight, kMaxHeight, "%.0f", kLog);
    changed |= ImGui::SliderFloat("Mie anisotropy g", &a.mieAnisotropy, -kMaxAnisotropy, kMaxAnisotropy,
                                  "%.3f", kClamp);
    tooltip("Cornette-Shanks g: > 0 scatters forward (bright toward the sun)");
    if (ImGui::SliderFloat("ozone scale", &ozoneScale, 0.0f, kMaxScale, "%.3g", kLog)) {
        ozoneScale = clampOrLow(ozoneScale, 0.0f, kMaxScale);
        a.ozoneAbsorption = scaled(file.ozoneAbsorption, ozoneScale);
        changed = true;
    }
    tooltip("ozone's absorption, times the scene file's: the blue of the sky at twilight");
    changed |= ImGui::ColorEdit3("ground albedo", &a.groundAlbedo.x, ImGuiColorEditFlags_Float);
    tooltip("the planet's ground as the atmosphere's multiple scattering sees it (not the scene's objects)");
    int model = int(a.multipleScattering);
    if (ImGui::Combo("multiple scattering", &model, "off\0hillaire\0orders\0")) {
        a.multipleScattering = postfx::AtmosphereMultipleScattering(model);
        changed = true;
    }
    tooltip(
        "orders: every order of scattering, within 2% of a path tracer (its LUT rebuilt when the media "
        "change); hillaire: the paper's isotropic approximation, too dark at the horizon");
    changed |= ImGui::Checkbox("ambient from sky", &a.ambientFromSky);
    tooltip(
        "the surfaces' ambient is the sky's irradiance / pi instead of the scene's (recomputed on the CPU, "
        "tens of ms, when the sun or the media change)");
    changed |=
        ImGui::SliderFloat("sun radius [deg]", &a.sunAngularRadiusDeg, 0.0f, kMaxSunRadiusDeg, "%.3f", kLog);
    tooltip("the sun disk's angular radius (Earth: 0.2678); 0: no disk");
    return changed;
}

void sanitize(postfx::AtmosphereSettings& a) {
    a.rayleighScaleHeight = clampOrLow(a.rayleighScaleHeight, kMinHeight, kMaxHeight);
    a.mieScaleHeight = clampOrLow(a.mieScaleHeight, kMinHeight, kMaxHeight);
    a.mieScattering = clampOrLow(a.mieScattering, 0.0f, kMaxMieCoefficient);
    a.mieAbsorption = clampOrLow(a.mieAbsorption, 0.0f, kMaxMieCoefficient);
    a.mieAnisotropy = clampOrLow(a.mieAnisotropy, -kMaxAnisotropy, kMaxAnisotropy);
    a.sunAngularRadiusDeg = clampOrLow(a.sunAngularRadiusDeg, 0.0f, kMaxSunRadiusDeg);
    for (int c = 0; c < 3; ++c)
        a.groundAlbedo[c] = clampOrLow(a.groundAlbedo[c], 0.0f, 1.0f);
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
    bool edit = ImGui::Checkbox("enabled", &edited.enabled);
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
        sanitize(edited);
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
