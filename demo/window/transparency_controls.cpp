#include "window/transparency_controls.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace demo::window {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;

const char* typeName(ObjectType type) {
    switch (type) {
        case ObjectType::Plane:
            return "plane";
        case ObjectType::Box:
            return "box";
        case ObjectType::Sphere:
            return "sphere";
    }
    return "object";
}

bool buildEmitter(ParticleEmitter& e) {
    bool changed = ImGui::Checkbox("on", &e.enabled);
    int count = int(e.count);
    if (ImGui::SliderInt("count", &count, 0, int(kMaxParticlesPerEmitter), "%d", kClamp)) {
        e.count = uint32_t(std::clamp(count, 0, int(kMaxParticlesPerEmitter)));
        changed = true;
    }
    changed |= ImGui::SliderFloat("opacity", &e.opacity, 0.0f, 1.0f, "%.2f", kClamp);
    changed |= ImGui::SliderFloat("rise speed [m/s]", &e.riseSpeed, -5.0f, 5.0f, "%.2f", kClamp);
    e.opacity = std::clamp(e.opacity, 0.0f, 1.0f);
    e.riseSpeed = std::clamp(e.riseSpeed, -5.0f, 5.0f);
    return changed;
}

}  // namespace

bool TransparencyControls::build(Scene& scene) {
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (drawnForward(scene.objects[i])) listed_.insert(i);
    if (!ImGui::CollapsingHeader("Transparency")) return false;
    bool changed = false;
    if (listed_.empty() && scene.particles.empty())
        ImGui::TextUnformatted("no transparent objects or particles");
    for (size_t i : listed_) {
        if (i >= scene.objects.size()) continue;
        Object& o = scene.objects[i];
        ImGui::PushID(int(i));
        const std::string label = std::string(typeName(o.type)) + " " + std::to_string(i) + " opacity";
        changed |= ImGui::SliderFloat(label.c_str(), &o.opacity, 0.0f, 1.0f, "%.2f", kClamp);
        o.opacity = std::clamp(o.opacity, 0.0f, 1.0f);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("1: opaque (G-buffer, unless forced forward)");
        ImGui::PopID();
    }
    for (size_t i = 0; i < scene.particles.size(); ++i) {
        ImGui::PushID(int(1000000 + i));
        const std::string label = "particles " + std::to_string(i);
        if (ImGui::TreeNode(label.c_str())) {
            changed |= buildEmitter(scene.particles[i]);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    return changed;
}

}  // namespace demo::window
