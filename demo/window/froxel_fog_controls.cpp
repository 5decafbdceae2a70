#include "window/froxel_fog_controls.h"

#include "window/medium_controls.h"
#include "window/settings_controls.h"

#include <postfx/settings_table.h>

#include <imgui.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace demo::window {
namespace {

using widgets::tooltip;

// A volume's controls: its table's (postfx::fogVolumeSettingsTable), those of its shape only.
bool buildVolume(postfx::FogVolume& v) {
    const bool sphere = v.shape == postfx::FogVolumeShape::Sphere;
    return settingControls(postfx::fogVolumeSettingsTable(), &v, "", {sphere ? "halfSize" : "radius"});
}

bool buildVolumes(std::vector<postfx::FogVolume>& volumes, const Camera& camera) {
    bool changed = false;
    int remove = -1;
    for (size_t i = 0; i < volumes.size(); ++i) {
        postfx::FogVolume& v = volumes[i];
        ImGui::PushID(int(i));
        const std::string label =
            std::string(v.shape == postfx::FogVolumeShape::Sphere ? "sphere " : "box ") + std::to_string(i);
        if (ImGui::TreeNode(label.c_str())) {
            changed |= buildVolume(v);
            if (ImGui::Button("remove")) remove = int(i);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0) {
        volumes.erase(volumes.begin() + remove);
        changed = true;
    }
    if (volumes.size() < postfx::kMaxFogVolumes && ImGui::Button("add volume")) {
        postfx::FogVolume v;  // a 4 m sphere 10 m in front of the camera
        v.shape = postfx::FogVolumeShape::Sphere;
        const glm::vec3 view = camera.lookAt - camera.position;
        const float length = glm::length(view);
        const glm::vec3 forward = length > 0.0f ? view / length : glm::vec3(0.0f, 0.0f, -1.0f);
        v.center = postfx::DVec3(glm::dvec3(camera.position) + 10.0 * glm::dvec3(forward));
        v.radius = 4.0f;
        v.halfSize = glm::vec3(4.0f);
        v.density = 0.2f;
        v.edgeFalloff = 1.0f;
        volumes.push_back(v);
        changed = true;
    }
    tooltip("a sphere 10 m in front of the camera");
    return changed;
}

}  // namespace

void FroxelFogControls::sanitize(postfx::FroxelFogSettings& f, std::vector<postfx::FogVolume>& volumes) {
    sanitizeSettings(postfx::froxelFogSettingsTable(), &f);
    sanitizeMedium(f);    // the texture size
    f.volumes = nullptr;  // the scene's volumes are froxelVolumes (froxelFogSettings)
    f.volumeCount = 0;
    if (volumes.size() > postfx::kMaxFogVolumes) volumes.resize(postfx::kMaxFogVolumes);
    for (postfx::FogVolume& v : volumes)
        sanitizeSettings(postfx::fogVolumeSettingsTable(), &v);
}

bool FroxelFogControls::build(Scene& scene) {
    bool changed = false;
    ImGui::PushID("froxel_fog");
    ImGui::SetNextItemOpen(scene.froxelFog.enabled, ImGuiCond_Once);  // at first: open when it is on
    if (ImGui::CollapsingHeader("Froxel fog")) {
        postfx::FroxelFogSettings edited = scene.froxelFog;
        std::vector<postfx::FogVolume> volumes = scene.froxelVolumes;
        const std::span<const postfx::SettingField> table = postfx::froxelFogSettingsTable();
        bool edits = settingControl(table, "enabled", &edited);
        tooltip("the froxel fog; turning it on turns the ray-marched fog off (postfx draws one of them)");
        edits |= buildMediumControls(edited);  // the same widgets as the ray-marched fog's
        // The grid and the froxel fog's other fields.
        edits |= settingControls(table, &edited, "", {"enabled"}, postfx::fogMediumSettingsTable());
        if (ImGui::TreeNode("Temporal")) {
            edits |= settingControls(table, &edited, "temporal");
            ImGui::TreePop();
        }
        if (ImGui::TreeNode("Volumes")) {
            edits |= buildVolumes(volumes, scene.camera);
            ImGui::TreePop();
        }
        if (edits) {
            sanitize(edited, volumes);
            postfx::FroxelFogSettings check = edited;
            check.volumes = volumes.empty() ? nullptr : volumes.data();
            check.volumeCount = uint32_t(volumes.size());
            // sanitize makes every field valid; should a check ever disagree, keep the last settings.
            if (postfx::validateFroxelFogSettings(check).ok()) {
                // postfx draws one fog per frame: turning this one on turns the ray-marched fog off.
                if (edited.enabled && !scene.froxelFog.enabled) scene.fog.enabled = false;
                scene.froxelFog = edited;
                scene.froxelVolumes = std::move(volumes);
                changed = true;
            }
        }
    }
    ImGui::PopID();
    return changed;
}

}  // namespace demo::window
