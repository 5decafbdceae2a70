// What a loaded scene must satisfy for the demo renderer to draw it (docs/scene-format.md, "Limits"):
// the fuzz target (fuzz_scene_loader.cpp) aborts on a scene that loads but breaks it, and the unit tests
// run it on every committed scene and regression input.
#pragma once

#include "scene/scene.h"

#include <string>

namespace demo::fuzz {

// Empty when the scene renders; otherwise what would go wrong ("shadow fit: viewProj is not finite").
// It computes what the renderer computes, with the renderer's own functions: the meshes
// (buildSceneMesh), the camera matrices and the float inverse the G-buffer uses, the shadow fit and its
// depth bias, the PNG exposure; and runs postfx's own checks of the frame (core::checkSharedInputs with
// stand-in image handles, the fog's settings under every quality preset, the froxel fog's settings with
// the scene's volumes, never both fogs at once) for the extreme image shapes
// postfx-render allows (1x16384, 16384x1, 64x64), both depth conventions, with and without a far plane.
// A scene with motion (scene/motion.h) is checked in the state of several frames besides frame 0 (the
// next, the camera cut, each light's intensity change, 99999 and 2^32 - 1), at each frame's time.
std::string renderProblem(const Scene& scene);

}  // namespace demo::fuzz
