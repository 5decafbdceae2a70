// Free-flight camera control of the windowed demo: WASD move along the view, Q/E down/up, Shift faster,
// hold the right mouse button and move to look (yaw about world y, pitch clamped to +-89 degrees).
#pragma once

#include "scene/scene.h"

struct GLFWwindow;

namespace demo::window {

class FlyCamera {
public:
    static constexpr float kSpeed = 5.0f;       // [m/s]
    static constexpr float kFastFactor = 5.0f;  // with Shift
    static constexpr float kRadiansPerPixel = 0.003f;
    static constexpr float kMaxPitchDeg = 89.0f;

    // Takes yaw and pitch from camera.lookAt - camera.position.
    void reset(const Camera& camera);

    // Applies this frame's input to `camera`; `dt` [s] is the frame time. Keyboard / mouse input that the
    // UI has taken is ignored (a look already in progress continues). Returns true if the camera changed.
    bool update(GLFWwindow* window, float dt, bool uiWantsMouse, bool uiWantsKeyboard, Camera& camera);

    float yawDeg() const;
    float pitchDeg() const;

private:
    float yaw_ = 0.0f;    // [rad] about +y, 0 looking down -z, positive turning toward +x
    float pitch_ = 0.0f;  // [rad] positive looking up
    bool looking_ = false;
    double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace demo::window
