#include "window/clouds_controls.h"

#include "window/medium_controls.h"

#include <imgui.h>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace demo::window {
namespace {

using widgets::clampOrLow;
using widgets::sliderUint;
using widgets::tooltip;

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// postfx's ranges (validateCloudSettings, postfx/clouds.h).
constexpr float kMaxHeight = 1e6f;         // bottom / top height [m]
constexpr float kMaxDensity = 1e3f;        // [1/m]
constexpr float kMaxAnisotropy = 0.999f;   // |g|
constexpr uint32_t kMaxSteps = 1024;       // view-ray samples
constexpr uint32_t kMaxLightSteps = 64;    // light-march samples
constexpr uint32_t kMaxOctaves = 8;        // multiple scattering
constexpr float kMaxLightDistance = 1e6f;  // [m]
constexpr float kMaxDistance = 1e7f;       // [m]
constexpr float kMaxWind = 1e3f;           // [m/s]
constexpr double kMaxBoxCentre = 1e9;      // [m]
constexpr float kMaxBoxHalfSize = 1e7f;    // [m]
constexpr float kMaxAngleDeg = 360.0f;     // box yaw / pitch
constexpr float kMinResolutionScale = 0.25f;
constexpr uint32_t kMinShadowSize = 16, kMaxShadowSize = 4096;       // [texels]
constexpr float kMinShadowExtent = 100.0f, kMaxShadowExtent = 1e6f;  // [m]
constexpr float kMinTiling = 1.0f, kMaxTiling = 1e7f;                // [m]
// The sliders' own ranges, narrower where a wider one is useless (files may hold more).
constexpr float kHeightSliderMax = 2e4f;          // [m]: the troposphere
constexpr float kDensitySliderMax = 1.0f;         // [1/m]: 1 km of it is an optical depth of 1000
constexpr float kLightDistanceSliderMin = 10.0f;  // [m]
constexpr float kLightDistanceSliderMax = 1e5f;
constexpr float kMaxDistanceSliderMin = 100.0f;  // [m]
constexpr float kMaxDistanceSliderMax = 1e6f;
constexpr float kWindSliderMax = 100.0f;                             // [m/s]
constexpr float kBoxSliderMax = 1e5f;                                // box centre and half size [m]
constexpr float kTilingSliderMin = 100.0f, kTilingSliderMax = 1e5f;  // [m]

// The scene files' names of the quality presets, in enum order.
constexpr std::array<const char*, 6> kQualityNames{"custom", "low", "medium", "high", "ultra", "auto"};
constexpr int kQualityCount = int(kQualityNames.size());

// The noise textures' sizes postfx accepts (powers of two).
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

// An unsigned slider on a logarithmic scale over [lo, hi].
bool sliderUintLog(const char* label, uint32_t& value, int lo, int hi) {
    int v = int(std::min<uint32_t>(value, uint32_t(INT32_MAX)));
    if (!ImGui::SliderInt(label, &v, lo, hi, "%d", kLog)) return false;
    value = uint32_t(std::clamp(v, lo, hi));
    return true;
}

// The quality combo and the four knobs a preset sets (steps, light steps, resolution scale, temporal). With
// a preset they show the preset's values and cannot be edited.
bool buildQuality(postfx::CloudSettings& s) {
    bool changed = false;
    int quality = std::clamp(int(s.quality), 0, kQualityCount - 1);
    if (ImGui::Combo("quality", &quality, kQualityNames.data(), kQualityCount)) {
        s.quality = postfx::CloudQuality(std::clamp(quality, 0, kQualityCount - 1));
        changed = true;
    }
    tooltip(
        "a preset sets steps, light steps, resolution scale and temporal; custom: as set below; auto "
        "measures the presets on this GPU and uses the most accurate within the budget (or the frame's)");
    if (s.quality == postfx::CloudQuality::Auto) {
        changed |= ImGui::SliderFloat("auto budget [ms]", &s.autoBudgetMs, 0.05f, 50.0f, "%.3g", kLog);
        tooltip("GPU time the clouds' passes may take per frame (without the frame budget)");
    }
    const bool custom = s.quality == postfx::CloudQuality::Custom;
    postfx::CloudSettings preset = postfx::applyCloudQuality(s, s.quality);
    postfx::CloudSettings& k = custom ? s : preset;  // what the knobs show and edit
    if (!custom) ImGui::BeginDisabled();
    bool knobs = sliderUintLog("steps", k.steps, 1, int(kMaxSteps));
    tooltip("samples along each view ray's part inside the clouds, however long");
    knobs |= sliderUintLog("light steps", k.lightSteps, 1, int(kMaxLightSteps));
    tooltip("samples of each sample's march toward the sun; few overbrighten a low sun (16: about 1%)");
    knobs |=
        ImGui::SliderFloat("resolution scale", &k.resolutionScale, kMinResolutionScale, 1.0f, "%.2f", kClamp);
    tooltip("march at this fraction of width and height, then upsample depth-aware");
    knobs |= ImGui::Checkbox("temporal", &k.temporal.enabled);
    tooltip(
        "accumulate the march over frames, reprojected at the clouds' mean distance and moved by the wind");
    if (!custom) ImGui::EndDisabled();
    return changed || (custom && knobs);
}

bool buildShape(postfx::CloudSettings& s) {
    bool changed = false;
    int shape = s.shape == postfx::CloudShape::Box ? 1 : 0;
    if (ImGui::Combo("shape", &shape, "layer\0box\0")) {
        s.shape = shape == 1 ? postfx::CloudShape::Box : postfx::CloudShape::Layer;
        changed = true;
    }
    tooltip(
        "layer: between the two heights (curved with the planet when the atmosphere is on); box: inside "
        "an oriented box");
    if (s.shape == postfx::CloudShape::Layer) {
        changed |=
            ImGui::SliderFloat("bottom height [m]", &s.bottomHeight, 0.0f, kHeightSliderMax, "%.0f", kClamp);
        tooltip("the layer's bottom above the ground (y = 0)");
        changed |= ImGui::SliderFloat("top height [m]", &s.topHeight, 1.0f, kHeightSliderMax, "%.0f", kClamp);
        tooltip("the layer's top (kept above the bottom)");
    } else if (ImGui::TreeNodeEx("Box", ImGuiTreeNodeFlags_DefaultOpen)) {
        glm::vec3 centre(float(s.box.center.x), float(s.box.center.y), float(s.box.center.z));
        if (ImGui::DragFloat3("centre [m]", &centre.x, 10.0f, -kBoxSliderMax, kBoxSliderMax, "%.0f",
                              kClamp)) {
            s.box.center = postfx::DVec3(double(centre.x), double(centre.y), double(centre.z));
            changed = true;
        }
        changed |=
            ImGui::DragFloat3("half size [m]", &s.box.halfSize.x, 10.0f, 1.0f, kBoxSliderMax, "%.0f", kClamp);
        tooltip("half the box's extent along its own axes");
        changed |= ImGui::SliderFloat("yaw [deg]", &s.box.yawDeg, -180.0f, 180.0f, "%.1f", kClamp);
        tooltip("rotation about world y");
        changed |= ImGui::SliderFloat("pitch [deg]", &s.box.pitchDeg, -90.0f, 90.0f, "%.1f", kClamp);
        tooltip("then about the box's own x");
        ImGui::TreePop();
    }
    return changed;
}

bool buildMedium(postfx::CloudSettings& s) {
    bool changed = false;
    changed |= ImGui::SliderFloat("coverage", &s.coverage, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("fraction of the sky covered; 0: no clouds (nothing runs)");
    changed |= ImGui::SliderFloat("cloud type", &s.cloudType, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("height profile: 0 stratus (thinning upward), 1 cumulus (full height, rounded top)");
    changed |= ImGui::SliderFloat("density [1/m]", &s.density, 0.0f, kDensitySliderMax, "%.4g", kLog);
    tooltip("extinction where the density field is 1; 0.02/m: 1 km of cloud has an optical depth of 20");
    changed |= ImGui::SliderFloat("albedo", &s.albedo, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("single-scattering albedo (water droplets: nearly 1)");
    changed |= ImGui::SliderFloat("anisotropy forward g", &s.anisotropyForward, 0.0f, kMaxAnisotropy, "%.3f",
                                  kClamp);
    tooltip("Henyey-Greenstein g of the forward lobe: the silver lining toward the sun");
    changed |=
        ImGui::SliderFloat("anisotropy back g", &s.anisotropyBack, -kMaxAnisotropy, 0.0f, "%.3f", kClamp);
    tooltip("g of the back lobe");
    changed |= ImGui::SliderFloat("lobe mix", &s.lobeMix, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("weight of the back lobe");
    if (ImGui::TreeNode("Multiple scattering")) {
        postfx::CloudMultipleScattering& m = s.multipleScattering;
        int model = int(m.model);
        const char* models[] = {"slab (delta-Eddington)", "octaves (Wrenninge)"};
        if (ImGui::Combo("model", &model, models, 2)) {
            m.model = postfx::CloudScatteringModel(model);
            changed = true;
        }
        tooltip(
            "slab: the local slab's diffuse light, close to a path tracer; octaves: art-directable, "
            "too dark in thick clouds");
        changed |= sliderUint("octaves", m.octaves, 1, int(kMaxOctaves));
        tooltip("Wrenninge's octaves; 1: single scattering only");
        changed |= ImGui::SliderFloat("attenuation a", &m.attenuation, 0.01f, 1.0f, "%.3f", kClamp);
        tooltip("octave i sees the optical depth toward the sun times a^i");
        changed |= ImGui::SliderFloat("contribution b", &m.contribution, 0.0f, 1.0f, "%.3f", kClamp);
        tooltip("octave i adds b^i of the single-scattering term; kept at most a (energy)");
        changed |= ImGui::SliderFloat("eccentricity c", &m.eccentricity, 0.0f, 1.0f, "%.3f", kClamp);
        tooltip("octave i's phase has the asymmetry times c^i");
        ImGui::TreePop();
    }
    return changed;
}

bool buildMarch(postfx::CloudSettings& s) {
    bool changed = false;
    changed |= ImGui::SliderFloat("light distance [m]", &s.lightDistance, kLightDistanceSliderMin,
                                  kLightDistanceSliderMax, "%.0f", kLog);
    tooltip("how far toward the sun each sample looks for cloud that shades it");
    changed |= ImGui::SliderFloat("max distance [m]", &s.maxDistance, kMaxDistanceSliderMin,
                                  kMaxDistanceSliderMax, "%.0f", kLog);
    tooltip("view rays are marched to the nearer of the geometry and this");
    changed |=
        ImGui::DragFloat3("wind [m/s]", &s.wind.x, 0.1f, -kWindSliderMax, kWindSliderMax, "%.1f", kClamp);
    tooltip("velocity of the density field");
    changed |= ImGui::Checkbox("jitter", &s.jitter);
    tooltip("offset each pixel's first sample per frame: banding becomes noise that accumulation removes");
    if (!s.temporal.enabled) ImGui::BeginDisabled();
    changed |=
        ImGui::SliderFloat("blend weight", &s.temporal.blendWeight, kMinBlendWeight, 1.0f, "%.3f", kLog);
    tooltip("temporal: weight of the current frame; lower is smoother and slower to follow changes");
    if (!s.temporal.enabled) ImGui::EndDisabled();
    return changed;
}

bool buildShadows(postfx::CloudSettings& s) {
    bool changed = ImGui::Checkbox("cast shadows", &s.castShadows);
    tooltip("the clouds' shadow map dims the sun on the surfaces (one frame late) and in both fogs");
    if (!s.castShadows) ImGui::BeginDisabled();
    changed |=
        sliderUintLog("shadow map size [texels]", s.shadowMap.size, int(kMinShadowSize), int(kMaxShadowSize));
    tooltip("edge of the shadow map");
    changed |= ImGui::SliderFloat("shadow map extent [m]", &s.shadowMap.extent, kMinShadowExtent,
                                  kMaxShadowExtent, "%.0f", kLog);
    tooltip("edge of the square around the camera it covers; beyond it no cloud shadow");
    if (!s.castShadows) ImGui::EndDisabled();
    return changed;
}

bool buildNoise(postfx::CloudNoiseSettings& n) {
    bool changed = ImGui::Checkbox("enabled", &n.enabled);
    tooltip("off: the density field is 1 inside the shape (with coverage 1 a homogeneous layer)");
    if (!n.enabled) ImGui::BeginDisabled();
    changed |= sizeCombo("base size [texels]", n.baseSize, kBaseSizes, kBaseSizeNames);
    tooltip(
        "edge of the Perlin-Worley base-shape texture postfx generates (again when a size or the seed "
        "changes)");
    changed |= sizeCombo("detail size [texels]", n.detailSize, kDetailSizes, kDetailSizeNames);
    tooltip("edge of the Worley detail texture");
    const uint32_t step = 1;
    changed |= ImGui::InputScalar("seed", ImGuiDataType_U32, &n.seed, &step, nullptr, "%u");
    changed |= ImGui::SliderFloat("tiling [m]", &n.tiling, kTilingSliderMin, kTilingSliderMax, "%.0f", kLog);
    tooltip("the base texture repeats every this many metres, the detail every tiling / 8");
    changed |= ImGui::SliderFloat("detail strength", &n.detailStrength, 0.0f, 1.0f, "%.3f", kClamp);
    tooltip("how much the detail noise erodes the edges; 0: none");
    if (!n.enabled) ImGui::EndDisabled();
    return changed;
}

}  // namespace

CloudsControls::CloudsControls(const Scene& sceneFile) : fileClouds_(sceneFile.clouds) {}

void CloudsControls::sanitize(postfx::CloudSettings& s) {
    if (uint32_t(s.quality) > uint32_t(postfx::CloudQuality::Auto)) s.quality = postfx::CloudQuality::Custom;
    if (!(s.autoBudgetMs > 0.0f)) s.autoBudgetMs = 0.05f;  // also NaN
    s.autoBudgetMs = std::min(s.autoBudgetMs, 1e6f);
    if (s.shape != postfx::CloudShape::Box) s.shape = postfx::CloudShape::Layer;
    s.bottomHeight = clampOrLow(s.bottomHeight, 0.0f, kMaxHeight - 1.0f);
    s.topHeight = clampOrLow(s.topHeight, 0.0f, kMaxHeight);
    if (!(s.topHeight > s.bottomHeight))
        s.topHeight = s.bottomHeight + 1.0f;  // the top follows the bottom up
    for (int c = 0; c < 3; ++c) {
        const double x = s.box.center[c];
        s.box.center[c] = x >= -kMaxBoxCentre ? std::min(x, kMaxBoxCentre) : -kMaxBoxCentre;  // NaN: low
        s.box.halfSize[c] = clampOrLow(s.box.halfSize[c], 1.0f, kMaxBoxHalfSize);
    }
    s.box.yawDeg = clampOrLow(s.box.yawDeg, -kMaxAngleDeg, kMaxAngleDeg);
    s.box.pitchDeg = clampOrLow(s.box.pitchDeg, -kMaxAngleDeg, kMaxAngleDeg);
    s.coverage = clampOrLow(s.coverage, 0.0f, 1.0f);
    s.cloudType = clampOrLow(s.cloudType, 0.0f, 1.0f);
    s.density = clampOrLow(s.density, 0.0f, kMaxDensity);
    s.albedo = clampOrLow(s.albedo, 0.0f, 1.0f);
    s.anisotropyForward = clampOrLow(s.anisotropyForward, 0.0f, kMaxAnisotropy);
    s.anisotropyBack = clampOrLow(s.anisotropyBack, -kMaxAnisotropy, 0.0f);
    s.lobeMix = clampOrLow(s.lobeMix, 0.0f, 1.0f);
    postfx::CloudMultipleScattering& m = s.multipleScattering;
    if (uint32_t(m.model) > uint32_t(postfx::CloudScatteringModel::Octaves))
        m.model = postfx::CloudScatteringModel::Slab;
    m.octaves = std::clamp<uint32_t>(m.octaves, 1, kMaxOctaves);
    m.attenuation = clampOrLow(m.attenuation, 0.01f, 1.0f);
    m.contribution = clampOrLow(m.contribution, 0.0f, m.attenuation);
    m.eccentricity = clampOrLow(m.eccentricity, 0.0f, 1.0f);
    s.steps = std::clamp<uint32_t>(s.steps, 1, kMaxSteps);
    s.lightSteps = std::clamp<uint32_t>(s.lightSteps, 1, kMaxLightSteps);
    s.lightDistance = clampOrLow(s.lightDistance, 1.0f, kMaxLightDistance);
    s.maxDistance = clampOrLow(s.maxDistance, 1.0f, kMaxDistance);
    for (int c = 0; c < 3; ++c)
        s.wind[c] = clampOrLow(s.wind[c], -kMaxWind, kMaxWind);
    s.resolutionScale = clampOrLow(s.resolutionScale, kMinResolutionScale, 1.0f);
    sanitizeTemporal(s.temporal);
    s.shadowMap.size = std::clamp(s.shadowMap.size, kMinShadowSize, kMaxShadowSize);
    s.shadowMap.extent = clampOrLow(s.shadowMap.extent, kMinShadowExtent, kMaxShadowExtent);
    postfx::CloudNoiseSettings& n = s.noise;
    n.baseSize = kBaseSizes[size_t(sizeIndex(kBaseSizes, n.baseSize))];
    n.detailSize = kDetailSizes[size_t(sizeIndex(kDetailSizes, n.detailSize))];
    n.tiling = clampOrLow(n.tiling, kMinTiling, kMaxTiling);
    n.detailStrength = clampOrLow(n.detailStrength, 0.0f, 1.0f);
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
    bool edit = ImGui::Checkbox("enabled", &edited.enabled);
    tooltip("postfx's volumetric clouds: in front of the sky, behind nearer geometry");
    edit |= buildQuality(edited);
    edit |= buildShape(edited);
    edit |= buildMedium(edited);
    edit |= buildMarch(edited);
    edit |= buildShadows(edited);
    if (ImGui::TreeNode("Noise")) {
        edit |= buildNoise(edited.noise);
        ImGui::TreePop();
    }
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
