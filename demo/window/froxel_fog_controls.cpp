#include "window/froxel_fog_controls.h"

#include "window/medium_controls.h"

#include <imgui.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace demo::window {
namespace {

using widgets::clampOrLow;
using widgets::sliderUint;
using widgets::tooltip;

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// postfx's ranges (validateFroxelFogSettings, docs/effects/froxel-fog.md).
constexpr int kMaxGrid = int(postfx::kMaxFroxelGridSize);
constexpr uint32_t kMaxTileSize = 4096;
constexpr double kMaxVolumeCentre = 1e9;   // [m]
constexpr float kMaxVolumeSize = 1e7f;     // half sizes, radius, edge falloff [m]
constexpr float kMaxVolumeDensity = 1e6f;  // [1/m]
// The volume widgets' own ranges: what a scene places by hand (files may hold more).
constexpr float kCentreDragRange = 1e5f;

bool buildGrid(postfx::FroxelFogSettings& f) {
    bool changed = false;
    int grid[3] = {int(std::min<uint32_t>(f.grid.x, kMaxGrid)), int(std::min<uint32_t>(f.grid.y, kMaxGrid)),
                   int(std::min<uint32_t>(f.grid.z, kMaxGrid))};
    if (ImGui::SliderInt3("grid x, y, z", grid, 1, kMaxGrid, "%d", kClamp)) {
        for (int a = 0; a < 3; ++a)
            f.grid[a] = uint32_t(std::clamp(grid[a], 1, kMaxGrid));
        changed = true;
    }
    tooltip("froxels across the view (x, y) and in depth (z); a tile size replaces x and y");
    changed |= sliderUint("tile size [px]", f.tileSizePx, 0, 256);
    tooltip("0: grid x and y as set; otherwise one froxel column per tile of this many pixels");
    int distribution = f.depthDistribution == postfx::FroxelDepthDistribution::Log ? 1 : 0;
    if (ImGui::Combo("depth slices", &distribution, "power\0log\0")) {
        f.depthDistribution =
            distribution == 1 ? postfx::FroxelDepthDistribution::Log : postfx::FroxelDepthDistribution::Power;
        changed = true;
    }
    tooltip("power: near + (far - near) z^k, finer near the camera; log: slices of equal relative thickness");
    const bool power = f.depthDistribution == postfx::FroxelDepthDistribution::Power;
    if (!power) ImGui::BeginDisabled();
    changed |= ImGui::SliderFloat("depth exponent k", &f.depthExponent, 1.0f, 8.0f, "%.2f", kClamp);
    if (!power) ImGui::EndDisabled();
    changed |= ImGui::Checkbox("tricubic", &f.tricubic);
    tooltip("read the volume with a tricubic B-spline instead of trilinear filtering");
    ImGui::SameLine();
    changed |= ImGui::Checkbox("jitter", &f.jitter);
    tooltip("move each froxel's sample per frame (Halton 2, 3, 5)");
    return changed;
}

bool buildVolume(postfx::FogVolume& v) {
    bool changed = false;
    int shape = v.shape == postfx::FogVolumeShape::Sphere ? 1 : 0;
    if (ImGui::Combo("shape", &shape, "box\0sphere\0")) {
        v.shape = shape == 1 ? postfx::FogVolumeShape::Sphere : postfx::FogVolumeShape::Box;
        changed = true;
    }
    glm::vec3 centre(v.center);
    if (ImGui::DragFloat3("centre [m]", &centre.x, 0.05f, -kCentreDragRange, kCentreDragRange, "%.2f",
                          kClamp)) {
        v.center = postfx::DVec3(centre);
        changed = true;
    }
    if (v.shape == postfx::FogVolumeShape::Box) {
        changed |= ImGui::DragFloat3("half size [m]", &v.halfSize.x, 0.02f, 0.0f, 1000.0f, "%.2f", kClamp);
        tooltip("half the box's extent along world x, y and z");
    } else {
        changed |= ImGui::SliderFloat("radius [m]", &v.radius, 0.01f, 1000.0f, "%.3g", kLog);
    }
    changed |= ImGui::SliderFloat("density [1/m]", &v.density, 1e-4f, 10.0f, "%.4g", kLog);
    tooltip("extinction added to the medium's inside the volume (at full strength)");
    changed |= ImGui::SliderFloat("edge falloff [m]", &v.edgeFalloff, 0.0f, 100.0f, "%.3g", kLog);
    tooltip("the density ramps up over this depth inside the surface; 0: a hard edge");
    return changed;
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
    sanitizeMedium(f);
    sanitizeTemporal(f.temporal);
    for (int a = 0; a < 3; ++a)
        f.grid[a] = std::clamp<uint32_t>(f.grid[a], 1, postfx::kMaxFroxelGridSize);
    f.tileSizePx = std::min(f.tileSizePx, kMaxTileSize);
    if (f.depthDistribution != postfx::FroxelDepthDistribution::Log)
        f.depthDistribution = postfx::FroxelDepthDistribution::Power;
    f.depthExponent = clampOrLow(f.depthExponent, 1.0f, 8.0f);
    f.volumes = nullptr;  // the scene's volumes are froxelVolumes (froxelFogSettings)
    f.volumeCount = 0;
    if (volumes.size() > postfx::kMaxFogVolumes) volumes.resize(postfx::kMaxFogVolumes);
    for (postfx::FogVolume& v : volumes) {
        if (v.shape != postfx::FogVolumeShape::Sphere) v.shape = postfx::FogVolumeShape::Box;
        for (int c = 0; c < 3; ++c) {
            const double x = v.center[c];
            v.center[c] = x >= -kMaxVolumeCentre ? std::min(x, kMaxVolumeCentre) : -kMaxVolumeCentre;
            v.halfSize[c] = clampOrLow(v.halfSize[c], 0.0f, kMaxVolumeSize);
        }
        v.radius = clampOrLow(v.radius, 0.0f, kMaxVolumeSize);
        v.density = clampOrLow(v.density, 0.0f, kMaxVolumeDensity);
        v.edgeFalloff = clampOrLow(v.edgeFalloff, 0.0f, kMaxVolumeSize);
    }
}

bool FroxelFogControls::build(Scene& scene) {
    bool changed = false;
    ImGui::PushID("froxel_fog");
    ImGui::SetNextItemOpen(scene.froxelFog.enabled, ImGuiCond_Once);  // at first: open when it is on
    if (ImGui::CollapsingHeader("Froxel fog")) {
        postfx::FroxelFogSettings edited = scene.froxelFog;
        std::vector<postfx::FogVolume> volumes = scene.froxelVolumes;
        bool edits = ImGui::Checkbox("enabled", &edited.enabled);
        tooltip("the froxel fog; turning it on turns the ray-marched fog off (postfx draws one of them)");
        edits |= buildMediumControls(edited);  // the same widgets as the ray-marched fog's
        edits |= buildGrid(edited);
        edits |= buildTemporalControls(edited.temporal);
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
