// The windowed demo's "Camera exposure" section of the ImGui panel: the camera's ev100, which sets both
// the tonemap's exposure and the pre-exposure the HDR image is stored with (postfx::FrameInfo::preExposure,
// docs/integration.md, "Pre-exposure"), shown next to it. Moving the slider changes the pre-exposure from
// frame to frame: the effects' temporal histories are rescaled, not reset.
#pragma once

#include "scene/scene.h"

namespace demo::window {

class CameraControls {
public:
    // Adds the section to the current ImGui window, editing scene.camera.ev100 within [-6, 20] (inside the
    // scene format's [-30, 30]); `preExposure`: the last recorded frame's (Renderer::preExposure).
    // Returns true if anything changed this frame.
    bool build(Scene& scene, float preExposure);
};

}  // namespace demo::window
