// The windowed demo's "Atmosphere" section of the ImGui panel: edits the live scene's
// postfx::AtmosphereSettings (on/off, the media, multiple scattering, the sun disk, ambient from the
// sky), the sun's elevation and azimuth (dragged live; the atmosphere's look changes most with them) and the
// camera's altitude. Every value it leaves in the scene is within the range postfx accepts
// (validateAtmosphereSettings), so Context::record never fails because of the UI.
#pragma once

#include "scene/scene.h"

#include <postfx/atmosphere.h>

namespace demo::window {

class AtmosphereControls {
public:
    // `sceneFile`: the scene as loaded; "Reset atmosphere" restores its atmosphere. The media sliders scale
    // the file's Rayleigh and ozone coefficients.
    explicit AtmosphereControls(const Scene& sceneFile);

    // Adds the section to the current ImGui window (call between Begin and End), editing scene.atmosphere,
    // scene.sun.direction and scene.camera (position.y and lookAt.y together: the view direction stays).
    // Closed at first unless the scene has the atmosphere on. Returns true if anything changed this frame.
    bool build(Scene& scene);

private:
    postfx::AtmosphereSettings fileAtmosphere_;
    float rayleighScale_ = 1.0f;  // scene.atmosphere.rayleighScattering = file's × this
    float ozoneScale_ = 1.0f;     // scene.atmosphere.ozoneAbsorption = file's × this
    float azimuthDeg_ = 0.0f;     // kept while the sun is at the zenith (where the direction has none)
};

}  // namespace demo::window
