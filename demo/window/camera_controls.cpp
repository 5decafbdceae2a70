#include "window/camera_controls.h"

#include "window/medium_controls.h"

#include <imgui.h>

#include <cmath>

namespace demo::window {

bool CameraControls::build(Scene& scene, float preExposure) {
    if (!ImGui::CollapsingHeader("Camera exposure")) return false;
    float ev100 = scene.camera.ev100;
    const bool changed =
        ImGui::SliderFloat("ev100", &ev100, -6.0f, 20.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
    widgets::tooltip("exposure value at ISO 100: 15 for direct sun, 12 overcast, 0 a lit room at night");
    if (changed && std::isfinite(ev100)) scene.camera.ev100 = ev100;
    ImGui::Text("pre-exposure 2^%d (HDR image = radiance x it)", int(std::lround(std::log2(preExposure))));
    widgets::tooltip(
        "postfx::FrameInfo::preExposure: a power of two metered from what the camera sees every 4th "
        "frame (the exposure's, lowered so that the brightest pixel fits RGBA16F, raised so that the "
        "median keeps half precision's digits)");
    return changed;
}

}  // namespace demo::window
