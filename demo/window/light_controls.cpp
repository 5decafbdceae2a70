#include "window/light_controls.h"

#include <imgui.h>
#include <postfx/inputs.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace demo::window {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;
constexpr float kMaxCoordinate = 1e7f;  // limits::kMaxCoordinate
constexpr float kMaxIntensity = 1e9f;   // [cd], postfx's bound
constexpr float kMaxRange = 1e9f;       // [m]
constexpr float kMaxOuterDeg = 89.9f;
constexpr uint32_t kMinShadowResolution = 16;  // texels per face edge, as the scene file's range
constexpr uint32_t kMaxShadowResolution = 4096;

float clampOrLow(float v, float lo, float hi) {
    return v >= lo ? (v <= hi ? v : hi) : lo;
}

// Colour (each channel in [0, 1], the brightest 1) and brightest channel [cd] of an intensity.
void split(const glm::vec3& intensity, glm::vec3& colour, float& candela) {
    candela = std::max({intensity.r, intensity.g, intensity.b});
    colour = candela > 0.0f ? intensity / candela : glm::vec3(1.0f);
}

// The camera's unit view direction (-z when look_at is the camera's position).
glm::vec3 viewDirection(const Camera& camera) {
    const glm::vec3 view = camera.lookAt - camera.position;
    const float length = std::sqrt(glm::dot(view, view));
    return length > 0.0f ? view / length : glm::vec3(0.0f, 0.0f, -1.0f);
}

// A point `distance` metres in front of the camera.
glm::vec3 inFront(const Camera& camera, float distance) {
    return camera.position + distance * viewDirection(camera);
}

bool buildLight(Light& l, const Camera& camera) {
    bool changed = false;
    int kind = l.kind == LightKind::Spot ? 1 : 0;
    if (ImGui::Combo("type", &kind, "point\0spot\0")) {
        l.kind = kind == 1 ? LightKind::Spot : LightKind::Point;
        changed = true;
    }
    changed |= ImGui::DragFloat3("position [m]", &l.position.x, 0.05f, -kMaxCoordinate, kMaxCoordinate,
                                 "%.2f", kClamp);
    if (ImGui::Button("move in front of the camera")) {
        l.position = inFront(camera, 5.0f);
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("5 m ahead along the view");
    glm::vec3 colour;
    float candela;
    split(l.intensity, colour, candela);
    bool intensityChanged = ImGui::ColorEdit3("colour", &colour.x);
    intensityChanged |= ImGui::SliderFloat("intensity [cd]", &candela, 0.0f, 1e6f, "%.4g", kLog);
    if (intensityChanged) {
        l.intensity = colour * candela;
        changed = true;
    }
    changed |= ImGui::SliderFloat("range [m]", &l.range, 0.1f, 1000.0f, "%.3g", kLog);
    changed |= ImGui::SliderFloat("radius [m]", &l.radius, 0.001f, 10.0f, "%.3g", kLog);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("source radius: E = I / (d^2 + radius^2)");
    if (l.kind == LightKind::Spot) {
        if (ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f, "%.2f", kClamp)) {
            const float length = std::sqrt(glm::dot(l.direction, l.direction));
            l.direction = length > 1e-6f ? l.direction / length : glm::vec3(0.0f, -1.0f, 0.0f);
            changed = true;
        }
        if (ImGui::Button("aim along the view")) {
            l.direction = viewDirection(camera);
            changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("the cone's axis becomes the camera's view direction");
        changed |=
            ImGui::SliderFloat("outer angle [deg]", &l.outerAngleDeg, 0.0f, kMaxOuterDeg, "%.1f", kClamp);
        changed |=
            ImGui::SliderFloat("inner angle [deg]", &l.innerAngleDeg, 0.0f, l.outerAngleDeg, "%.1f", kClamp);
    }
    changed |= ImGui::Checkbox("shadows", &l.shadows);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("shadow maps in the local shadow atlas: surfaces and fog");
    if (l.shadows) {
        int resolution = int(l.shadowResolution);
        if (ImGui::SliderInt("shadow resolution [texels]", &resolution, int(kMinShadowResolution),
                             int(kMaxShadowResolution), "%d", kLog)) {
            l.shadowResolution = uint32_t(resolution);
            changed = true;
        }
    }
    return changed;
}

}  // namespace

void LightControls::sanitize(Light& l) {
    if (l.kind != LightKind::Point && l.kind != LightKind::Spot) l.kind = LightKind::Point;
    for (int c = 0; c < 3; ++c) {
        l.position[c] = clampOrLow(l.position[c], -kMaxCoordinate, kMaxCoordinate);
        l.intensity[c] = clampOrLow(l.intensity[c], 0.0f, kMaxIntensity);
    }
    l.range = clampOrLow(l.range, 1e-3f, kMaxRange);
    l.radius = clampOrLow(l.radius, 1e-6f, l.range);
    l.outerAngleDeg = clampOrLow(l.outerAngleDeg, 0.0f, kMaxOuterDeg);
    l.innerAngleDeg = clampOrLow(l.innerAngleDeg, 0.0f, l.outerAngleDeg);
    l.shadowResolution = std::clamp(l.shadowResolution, kMinShadowResolution, kMaxShadowResolution);
    const float length = std::sqrt(glm::dot(l.direction, l.direction));
    l.direction =
        std::isfinite(length) && length > 1e-6f ? l.direction / length : glm::vec3(0.0f, -1.0f, 0.0f);
}

bool LightControls::build(Scene& scene) {
    if (!ImGui::CollapsingHeader("Lights")) return false;
    bool changed = false;
    int remove = -1;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        Light& l = scene.lights[i];
        ImGui::PushID(int(i));
        const std::string label =
            std::string(l.kind == LightKind::Spot ? "spot " : "point ") + std::to_string(i);
        if (ImGui::TreeNode(label.c_str())) {
            changed |= buildLight(l, scene.camera);
            if (ImGui::Button("remove")) remove = int(i);
            ImGui::TreePop();
        }
        sanitize(l);
        ImGui::PopID();
    }
    if (remove >= 0) {
        scene.lights.erase(scene.lights.begin() + remove);
        changed = true;
    }
    if (scene.lights.size() < postfx::kMaxLocalLights && ImGui::Button("add light")) {
        Light l;  // 5 m in front of the camera, white, 100 cd
        l.position = inFront(scene.camera, 5.0f);
        l.intensity = glm::vec3(100.0f);
        l.range = 30.0f;
        l.radius = 0.1f;
        scene.lights.push_back(l);
        changed = true;
    }
    return changed;
}

}  // namespace demo::window
