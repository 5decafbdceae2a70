#include "window/fly_camera.h"

#include <GLFW/glfw3.h>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace demo::window {
namespace {

glm::vec3 forwardOf(float yaw, float pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

bool key(GLFWwindow* w, int k) {
    return glfwGetKey(w, k) == GLFW_PRESS;
}

}  // namespace

void FlyCamera::reset(const Camera& camera) {
    const glm::vec3 f = glm::normalize(camera.lookAt - camera.position);
    yaw_ = std::atan2(f.x, -f.z);
    pitch_ = std::asin(std::clamp(f.y, -1.0f, 1.0f));
    const float limit = glm::radians(kMaxPitchDeg);
    pitch_ = std::clamp(pitch_, -limit, limit);
}

float FlyCamera::yawDeg() const {
    return glm::degrees(yaw_);
}
float FlyCamera::pitchDeg() const {
    return glm::degrees(pitch_);
}

bool FlyCamera::update(GLFWwindow* window, float dt, bool uiWantsMouse, bool uiWantsKeyboard,
                       Camera& camera) {
    bool changed = false;

    // Look: only while the right button is held; the cursor is hidden and unbounded meanwhile.
    const bool rmb = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (rmb && !looking_ && !uiWantsMouse) {
        looking_ = true;
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        glfwGetCursorPos(window, &lastX_, &lastY_);
    } else if (!rmb && looking_) {
        looking_ = false;
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
    }
    if (looking_) {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window, &x, &y);
        const auto dx = float(x - lastX_), dy = float(y - lastY_);
        lastX_ = x;
        lastY_ = y;
        if (dx != 0.0f || dy != 0.0f) {
            const float limit = glm::radians(kMaxPitchDeg);
            yaw_ = std::remainder(yaw_ + dx * kRadiansPerPixel, 2.0f * glm::pi<float>());
            pitch_ = std::clamp(pitch_ - dy * kRadiansPerPixel, -limit, limit);
            camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
            camera.lookAt = camera.position + forwardOf(yaw_, pitch_);
            changed = true;
        }
    }

    if (uiWantsKeyboard) return changed;
    const glm::vec3 forward = glm::normalize(camera.lookAt - camera.position);
    const glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    glm::vec3 right = glm::cross(forward, worldUp);
    right = glm::length(right) > 1e-4f ? glm::normalize(right) : glm::vec3(1.0f, 0.0f, 0.0f);
    glm::vec3 move(0.0f);
    if (key(window, GLFW_KEY_W)) move += forward;
    if (key(window, GLFW_KEY_S)) move -= forward;
    if (key(window, GLFW_KEY_D)) move += right;
    if (key(window, GLFW_KEY_A)) move -= right;
    if (key(window, GLFW_KEY_E)) move += worldUp;
    if (key(window, GLFW_KEY_Q)) move -= worldUp;
    if (glm::length(move) > 0.0f) {
        const bool fast = key(window, GLFW_KEY_LEFT_SHIFT) || key(window, GLFW_KEY_RIGHT_SHIFT);
        const glm::vec3 delta = glm::normalize(move) * (kSpeed * (fast ? kFastFactor : 1.0f) * dt);
        camera.position += delta;
        camera.lookAt += delta;
        changed = true;
    }
    return changed;
}

}  // namespace demo::window
