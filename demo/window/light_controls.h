// The windowed demo's "Lights" section of the ImGui panel: one collapsible entry per scene light
// (position, with a button moving it 5 m in front of the camera; colour and intensity; radius, range; spot
// direction, with a button aiming it along the view, and angles), add (in front of the camera) and remove
// buttons.
// Every value it leaves in the scene is within the range the scene loader and postfx accept
// (docs/scene-format.md#lights), so Context::record never fails because of the UI.
#pragma once

#include "scene/scene.h"

namespace demo::window {

class LightControls {
public:
    // Adds the section to the current ImGui window (call between Begin and End), editing scene.lights.
    // Returns true if anything changed this frame.
    bool build(Scene& scene);

    // Brings a light into the accepted ranges (NaN to the low end); valid values are left as they are.
    static void sanitize(Light& light);
};

}  // namespace demo::window
