// The demo's surface lighting through postfx's atmosphere (docs/effects/atmosphere.md, "The demo"): with
// Scene::atmosphere on, scene.sun.illuminance is the sun's outside the atmosphere, and lighting.comp
// attenuates it by the transmittance toward the sun at each lit point; the ambient may come from the sky.
//
// The transmittance is evaluated on the CPU (postfx::atmosphereSunTransmittance) at two altitudes, the
// scene's lowest and highest object (at least 1 m apart, the lower clamped to the ground y = 0), and the
// shader interpolates its optical depth -ln T linearly in altitude between them (clamped outside): exact at
// both ends, and within the demo's scenes (a few km of altitude) the optical depth toward a fixed sun
// direction is close to linear in altitude over such a span (it is exponential over the scale heights:
// 8 km Rayleigh, 1.2 km Mie). It ignores the planet's curvature across the scene (the sun's elevation
// changes by 1° every 111 km) and the depth's own curvature in altitude.
#pragma once

#include "scene/scene.h"

#include <postfx/atmosphere.h>
#include <glm/glm.hpp>

#include <optional>

namespace demo {

struct AtmosphereLighting {
    // Optical depth toward the sun [1] at altitudes low and high [m]: 0 with the atmosphere off (the shader's
    // exp(-0) = 1 leaves the sun as the scene gives it). A sun the planet hides: kMaxOpticalDepth.
    glm::vec3 opticalDepthLow{0.0f}, opticalDepthHigh{0.0f};
    float altitudeLow = 0.0f, altitudeHigh = 1.0f;
    // The ambient radiance the surfaces get [cd/m²]: scene.ambient, or with the atmosphere on and
    // ambientFromSky, postfx::atmosphereSkyIrradiance at altitudeLow / π.
    glm::vec3 ambient{0.0f};
    // The radiance of pixels without geometry: scene.sky, or black with the atmosphere on (space: postfx
    // draws the sky over it).
    glm::vec3 sky{0.0f};
};

// exp(-40) ≈ 4e-18: no light, and finite in the shader's interpolation.
inline constexpr float kMaxOpticalDepth = 40.0f;

// The lowest and highest altitude of the scene's objects (planes at their point, boxes and spheres at
// their bottom and top), the lower clamped to >= 0 and the higher to >= lower + 1 m.
glm::vec2 sceneAltitudeRange(const Scene& scene);

// AtmosphereLighting for a scene, recomputed only when what it depends on changes: the transmittance when
// the sun's direction, the atmosphere's settings or the altitude range change; the sky's ambient
// (atmosphereSkyIrradiance, tens of ms) when those or the sun's illuminance change.
class AtmosphereLightingCache {
public:
    const AtmosphereLighting& update(const Scene& scene);
    // How many times each part was computed (tests, the window's statistics).
    uint64_t transmittanceUpdates() const { return transmittanceUpdates_; }
    uint64_t ambientUpdates() const { return ambientUpdates_; }

private:
    struct TransmittanceKey {
        postfx::AtmosphereSettings settings;
        glm::vec3 toSun{0.0f};
        glm::vec2 altitudes{0.0f};
    };
    struct AmbientKey {
        TransmittanceKey transmittance;
        glm::vec3 sunIlluminance{0.0f};
    };
    std::optional<TransmittanceKey> transmittanceKey_;
    std::optional<AmbientKey> ambientKey_;
    glm::vec3 skyAmbient_{0.0f};
    AtmosphereLighting result_;
    uint64_t transmittanceUpdates_ = 0, ambientUpdates_ = 0;
};

}  // namespace demo
