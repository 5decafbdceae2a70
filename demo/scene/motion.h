// Motion of scene files (docs/scene-format.md#motion): the camera's velocity and yaw rate, each light's
// velocity and intensity change, `frame_time` and `camera_cut_frame`. The one definition of "the scene at
// frame n": Renderer::render and renderReference, postfx-render, the window demo and the tests use it.
#pragma once

#include "scene/scene.h"

#include <cstdint>

namespace demo {

// The time of frame `frame` [s]: frame · scene.frameTime (in double). The renderer gives it to postfx
// (FrameInfo::timeSeconds) unless RenderOptions::fixedTimeSeconds replaces it.
double frameTimeSeconds(const Scene& scene, uint64_t frame);

// Whether any frame differs from frame 0: a camera velocity or yaw rate, a light's velocity or intensity
// change. (A camera cut alone moves nothing.)
bool hasMotion(const Scene& scene);

// The camera at time t [s] (frame 0 is `camera` itself):
//   position(t) = position + velocity · t, each coordinate stopping at ±limits::kMaxCoordinate;
//   the view direction (look_at - position) and `up` turned about world +y by yaw_rate · t, positive to
//   the right (from -z toward +x, clockwise seen from above); look_at(t) = position(t) + that direction
//   times the file's look distance (at least 1e-4 · the largest |position(t)| coordinate, so that look_at
//   stays distinct from position in float far from the origin).
// Computed in double; a camera without velocity and yaw rate is returned unchanged.
Camera cameraAt(const Camera& camera, double t);

// The light at frame `frame`, time t [s]: position + velocity · t (stopping at ±limits::kMaxCoordinate;
// unchanged without velocity), and from frame intensity_change.frame on that change's intensity.
Light lightAt(const Light& light, uint64_t frame, double t);

// Sets state.camera and state.lights to `scene`'s at frame `frame` (cameraAt, lightAt at
// frameTimeSeconds); every other member of `state` is left as it is. For a loop over frames that keeps
// one copy of the scene (`state`, a copy of `scene`) instead of copying its objects every frame.
void moveToFrame(const Scene& scene, uint64_t frame, Scene& state);

// `scene` as frame `frame` shows it: a copy with its camera and lights moved (moveToFrame).
Scene sceneAtFrame(const Scene& scene, uint64_t frame);

// FrameInfo::cameraCut of frame `frame`: scene.cameraCutFrame names it.
bool isCameraCut(const Scene& scene, uint64_t frame);

}  // namespace demo
