// The windowed demo's "Clouds" section of the ImGui panel: edits the live scene's postfx::CloudSettings
// (every field: on/off, the quality preset and the four knobs it sets, the shape and its box, the layer's
// heights, coverage, cloud type, density, albedo, the dual-lobe phase, multiple scattering, the march and
// light march, wind, jitter, the temporal accumulation, the shadow map, the noise). Every value it leaves in
// the scene is within the range postfx accepts (validateCloudSettings), so Context::record never fails
// because of the UI.
#pragma once

#include "scene/scene.h"

#include <postfx/clouds.h>

namespace demo::window {

class CloudsControls {
public:
    // `sceneFile`: the scene as loaded; "Reset clouds" restores its clouds.
    explicit CloudsControls(const Scene& sceneFile);

    // Adds the section to the current ImGui window (call between Begin and End), editing scene.clouds.
    // Closed at first unless the scene has the clouds on. Returns true if anything changed this frame.
    bool build(Scene& scene);

    // Brings every field into the range postfx accepts (validateCloudSettings): numbers clamped (NaN to
    // the low end), top_height above bottom_height, contribution at most attenuation, the texture sizes to
    // the nearest power of two in range, an unknown shape or quality to layer / custom. Valid values are
    // left exactly as they are.
    static void sanitize(postfx::CloudSettings& settings);

private:
    postfx::CloudSettings fileClouds_;
};

}  // namespace demo::window
