#include "froxel_scenes.h"

#include <algorithm>
#include <cmath>

namespace bench {

std::vector<Setting> froxelSweep(const Setting& base, const FroxelSweepOptions& options) {
    std::vector<Setting> out;
    for (const auto& [x, y] : options.grids) {
        for (uint32_t slices : options.slices) {
            for (bool log : options.logSlices) {
                for (bool tricubic : options.tricubic) {
                    Setting s = base;
                    s.method = Method::Froxel;
                    s.gridX = x;
                    s.gridY = y;
                    s.gridZ = slices;
                    s.logSlices = log;
                    s.tricubic = tricubic;
                    out.push_back(s);
                }
            }
        }
    }
    return out;
}

bool froxelScene(const demo::Scene& scene, demo::Scene& out, std::string& error) {
    out = scene;
    if (scene.froxelFog.enabled) return true;
    if (!scene.fog.enabled) {
        error = "the scene has neither effects.fog nor effects.froxel_fog";
        return false;
    }
    // The medium, as both fogs share it (postfx::FogMedium); the froxel fog's own keys keep postfx's
    // defaults.
    static_cast<postfx::FogMedium&>(out.froxelFog) = static_cast<const postfx::FogMedium&>(scene.fog);
    out.froxelFog.enabled = true;
    out.froxelVolumes.clear();
    out.fog.enabled = false;
    return true;
}

demo::Scene withFroxelKnobs(const demo::Scene& scene, const Setting& setting) {
    demo::Scene s = scene;
    s.froxelFog.grid = postfx::UVec3(setting.gridX, setting.gridY, setting.gridZ);
    s.froxelFog.tileSizePx = 0;
    s.froxelFog.depthDistribution =
        setting.logSlices ? postfx::FroxelDepthDistribution::Log : postfx::FroxelDepthDistribution::Power;
    s.froxelFog.tricubic = setting.tricubic;
    if (setting.lightSweep)
        s.froxelFog.lightListMinLights = setting.lightLists ? 1u : postfx::kMaxLocalLights + 1;
    return s;
}

std::vector<demo::Light> sweepLights(const demo::Camera& camera, uint32_t count) {
    count = std::min(count, postfx::kMaxLocalLights);
    // Six saturated colours, the brightest channel at kSweepLightIntensity.
    const glm::vec3 colours[] = {{1.0f, 0.55f, 0.2f}, {0.2f, 0.45f, 1.0f}, {1.0f, 0.2f, 0.75f},
                                 {0.3f, 1.0f, 0.35f}, {1.0f, 0.95f, 0.8f}, {0.6f, 0.3f, 1.0f}};
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));  // the golden angle [rad]
    std::vector<demo::Light> lights;
    for (uint32_t i = 0; i < count; ++i) {
        const double r = double(kSweepLightDisc) * std::sqrt((double(i) + 0.5) / double(count));
        const double a = double(i) * golden;
        // Heights 0.5..4 m by the golden ratio's multiples (spread for any count).
        const double h = 0.5 + 3.5 * std::fmod(double(i) * 0.6180339887498949, 1.0);
        demo::Light l;
        l.kind = demo::LightKind::Point;
        l.position = camera.lookAt + glm::vec3(float(r * std::cos(a)), float(h), float(r * std::sin(a)));
        l.intensity = colours[i % std::size(colours)] * kSweepLightIntensity;
        l.radius = 0.1f;
        l.range = kSweepLightRange;
        lights.push_back(l);
    }
    return lights;
}

uint32_t froxelLightCount(const demo::Scene& scene) {
    return uint32_t(std::count_if(scene.lights.begin(), scene.lights.end(),
                                  [](const demo::Light& l) { return l.intensity != glm::vec3(0.0f); }));
}

}  // namespace bench
