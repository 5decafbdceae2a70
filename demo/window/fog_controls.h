// The windowed demo's fog and sun controls: the "Fog" and "Sun" sections of the ImGui panel, which edit
// the live scene's postfx::FogSettings and sun every frame, and a "Reset to scene file" button (for both
// fogs: the froxel fog's section is FroxelFogControls). Every value they leave in the scene is within
// the range postfx accepts (docs/effects/fog.md, "Parameters"), and the fog is never on together with the
// froxel fog (turning it on turns that off), so Context::record never fails because of the UI.
#pragma once

#include "scene/scene.h"

#include <postfx/fog.h>
#include <postfx/froxel_fog.h>
#include <glm/glm.hpp>

#include <vector>

namespace demo::window {

class FogControls {
public:
    // `sceneFile`: the scene as loaded; "Reset to scene file" restores its fog, froxel fog and fog volumes
    // and sun (direction, illuminance). The sun sliders start from its sun.
    explicit FogControls(const Scene& sceneFile);

    // Adds the button and the sections to the current ImGui window (call between Begin and End), editing
    // scene.fog (and scene.froxelFog.enabled, off when the fog is turned on), scene.sun.direction and
    // scene.sun.illuminance. "Fog" is open (closed when the scene has the froxel fog on instead), its
    // "Noise" subsection and "Sun" closed at first. Returns true if anything changed this frame.
    bool build(Scene& scene);

    // Brings every field into the range postfx accepts: NaN or out-of-range values are clamped (NaN to
    // the lower end, steps >= 1, shadow kernel to the next odd size, texture size to the nearest power of
    // two in [16, 256], max distance, tiling and the auto budget to > 0, an unknown quality to Custom, the
    // temporal blend weight to (0, 1]).
    // Valid values are left exactly as they are.
    static void sanitize(postfx::FogSettings& fog);

private:
    void takeSun(const Sun& sun);  // the slider values of `sun`
    glm::vec3 sunDirection() const;
    glm::vec3 sunIlluminance() const;

    postfx::FogSettings fileFog_;
    postfx::FroxelFogSettings fileFroxelFog_;
    std::vector<postfx::FogVolume> fileVolumes_;
    Sun fileSun_;
    float elevationDeg_ = 90.0f;        // above the horizon
    float azimuthDeg_ = 0.0f;           // about +y, 0 toward -z, positive toward +x (the fly camera's yaw)
    float illuminanceLux_ = 0.0f;       // the brightest channel of sun.illuminance
    glm::vec3 illuminanceColor_{1.0f};  // sun.illuminance / illuminanceLux_ (white for a dark sun)
};

}  // namespace demo::window
