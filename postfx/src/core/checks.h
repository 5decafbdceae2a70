// Checks shared by every part of postfx: an InvalidArgument status naming the field, finiteness of
// vectors and matrices, and the checks of the inputs every effect shares (FrameInfo's images, camera,
// sun, ambient, shadow map, lights), run once per frame by the context whichever effects run.
#pragma once

#include <postfx/context.h>

#include <cmath>
#include <string>

namespace postfx::core {

inline Status invalid(std::string message) {
    return {Result::InvalidArgument, std::move(message)};
}

// Every component finite (glm vectors and matrices of any size and qualifier).
template <glm::length_t L, class T, glm::qualifier Q>
bool allFinite(const glm::vec<L, T, Q>& v) {
    for (glm::length_t i = 0; i < L; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
bool allFinite(const glm::mat<C, R, T, Q>& m) {
    for (glm::length_t c = 0; c < C; ++c)
        if (!allFinite(m[c])) return false;
    return true;
}

// "1920x1080"
std::string extentText(VkExtent2D extent);

// Number as the messages print it (shortest round-trip form: "1e+07", "0.5").
std::string numberText(double value);

// InvalidArgument "<field>: <value> is outside [lo, hi]" (or "is NaN"); success when lo <= value <= hi.
Status checkRange(const char* field, double value, double lo, double hi);

// Everything record() and plan() check in `frame` before any effect looks at it, but the command buffer:
// structSize, color, depth, output (not the color image, same extent and format), usage flags, the
// camera, sun, ambient, time, shadow map and local lights.
Status checkSharedInputs(const FrameInfo& frame, const ContextCreateInfo& info);

// The camera alone (also used by the CPU references): position, view, projection finite, projection
// times the view's rotation invertible. `prefix` names the struct ("FrameInfo.camera").
Status checkCamera(const CameraInput& camera, const std::string& prefix);
// The sun and ambient: finite, illuminance and ambient in [0, 1e7], a direction that is not zero.
Status checkLighting(const SunInput& sun, const Vec3& ambient);

}  // namespace postfx::core
