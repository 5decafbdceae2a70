// The windowed demo's "Froxel fog" section of the ImGui panel: edits the live scene's
// postfx::FroxelFogSettings (the medium with the same widgets as the "Fog" section, the grid, the depth
// distribution, tricubic filtering, jitter, the temporal accumulation) and its local fog volumes (per volume:
// shape, centre, size, density, edge falloff; add and remove) every frame. Every value it leaves in the scene
// is within the range postfx accepts (validateFroxelFogSettings), and the froxel fog is never on together
// with the ray-marched fog (turning it on turns that off), so Context::record never fails because of the UI.
#pragma once

#include "scene/scene.h"

#include <postfx/froxel_fog.h>

#include <vector>

namespace demo::window {

class FroxelFogControls {
public:
    // Adds the section to the current ImGui window (call between Begin and End), editing scene.froxelFog,
    // scene.froxelVolumes and scene.fog.enabled (off when the froxel fog is turned on). Closed at first
    // (open when the scene file has froxel fog on). A new volume is placed 10 m in front of the camera.
    // Returns true if anything changed this frame.
    bool build(Scene& scene);

    // Brings every field into the range postfx accepts (the medium as FogControls does, the grid to
    // [1, 512] per axis, the tile size to [0, 4096], an unknown distribution to power, the exponent to
    // [1, 8], the temporal blend weight to (0, 1], at most kMaxFogVolumes volumes, each with an unknown
    // shape as a box and its numbers in their ranges, NaN to the low end). Valid values are left exactly
    // as they are.
    static void sanitize(postfx::FroxelFogSettings& settings, std::vector<postfx::FogVolume>& volumes);
};

}  // namespace demo::window
