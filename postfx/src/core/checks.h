// Checks shared by every part of postfx: an InvalidArgument status naming the field, finiteness of
// vectors and matrices, and the checks of the inputs every effect shares (FrameInfo's images, camera,
// sun, ambient, shadow map, lights), run once per frame by the context whichever effects run.
#pragma once

#include <postfx/context.h>

#include <cmath>
#include <limits>
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

// Every component finite and within float's range, so that converting it to float (as postfx does for the
// uniforms it builds in double) gives no Inf.
template <glm::length_t C, glm::length_t R, glm::qualifier Q>
bool finiteAsFloat(const glm::mat<C, R, double, Q>& m) {
    for (glm::length_t c = 0; c < C; ++c)
        for (glm::length_t r = 0; r < R; ++r)
            if (!(std::abs(m[c][r]) <= double(std::numeric_limits<float>::max()))) return false;
    return true;
}

// Bound of every world-space position postfx takes (camera, lights) [m]: camera-relative quantities built
// from them (the height above the fog's base, the shadow map's camera-relative transform, the noise
// coordinate) then stay finite and precise in float.
inline constexpr double kMaxWorldCoordinate = 1e9;
// Bound of FrameInfo::timeSeconds [s]: wind · time stays finite and the noise coordinate keeps its precision.
inline constexpr double kMaxTimeSeconds = 1e12;
// FrameInfo::budgetMs [ms].
inline constexpr float kMaxBudgetMs = 1000.0f;
// FrameInfo::preExposure's range, and the largest pre-exposed light (illuminance and ambient; a local
// light's intensity: kMaxPreExposedIntensity): the ranges the light itself has.
inline constexpr double kMinPreExposure = 1e-10, kMaxPreExposure = 1e10;
inline constexpr double kMaxPreExposedLight = 1e7, kMaxPreExposedIntensity = 1e9;

// "1920x1080"
std::string extentText(VkExtent2D extent);

// What a projection does with depth, read from it: which of Vulkan's depths 0 and 1 is nearer, and the
// distances [view units] of the view's centre at the near and far ends (far: +∞ for an infinite far plane).
struct ProjectedDepth {
    bool reversedZ = false;
    double near = 0.0, far = 0.0;
};
ProjectedDepth projectedDepth(const Mat4& projection);
// InvalidArgument naming ContextCreateInfo.depth and FrameInfo.camera.projection when a perspective
// projection maps depth another way than the context was created for: the other of depths 0 and 1
// nearer, or a finite far plane within 1e5 near distances where the context says infinite (one beyond
// passes for either: float cannot tell one beyond about 1e7 from infinity); an affine (orthographic)
// projection is not checked.
Status checkDepthConvention(const Mat4& projection, const DepthConvention& depth);

// Number as the messages print it (shortest round-trip form: "1e+07", "0.5").
std::string numberText(double value);

// InvalidArgument "<field>: <value> is outside [lo, hi]" (or "is NaN"); success when lo <= value <= hi.
Status checkRange(const char* field, double value, double lo, double hi);

// Everything record() and plan() check in `frame` before any effect looks at it, but the command buffer:
// structSize, color, depth, output (not the color image, same extent and format), usage flags, the
// camera, sun, ambient, time, shadow map and local lights.
Status checkSharedInputs(const FrameInfo& frame, const ContextCreateInfo& info);
// FrameInfo::preExposure: in [kMinPreExposure, kMaxPreExposure], the light it pre-exposes within range
// (the light itself already checked).
Status checkPreExposure(const FrameInfo& frame);
// FrameInfo::localShadows and the lights' shadow indices: every light's shadow kNoLocalShadow or below
// shadowCount; with an atlas or shadows, the atlas image, each shadow's face count and bias, each face's
// region inside the atlas and its transform finite, finite camera-relative in float, and invertible.
Status checkLocalShadows(const FrameInfo& frame, double unitsPerMetre = 1.0);
// The shadows alone (also used by the CPU reference): at most kMaxLocalLights, not null when count > 0, each
// one's faces and bias, each face inside a width × height atlas, its transform as above. `name` names the
// array ("FrameInfo.localShadows.shadows").
// `unitsPerMetre` (ContextCreateInfo::world) scales the camera-relative transforms as postfx's frame has
// them.
Status checkLocalShadowList(const LocalShadow* shadows, uint32_t count, uint32_t width, uint32_t height,
                            const DVec3& camera, const std::string& name, double unitsPerMetre = 1.0);

// The camera alone (also used by the CPU references): position within ±kMaxWorldCoordinate, view and
// projection finite, projection times the view's rotation invertible with an inverse finite in float.
// `prefix` names the struct ("FrameInfo.camera"). With the host's `unitsPerMetre` the inverse is checked as
// postfx's frame has it (WorldTransform::camera: its x, y, z rows divided by it).
Status checkCamera(const CameraInput& camera, const std::string& prefix, double unitsPerMetre = 1.0);
// The sun and ambient: finite, illuminance and ambient in [0, 1e7], a direction of length >= 1e-6 (as
// computed in double). `prefix` is put before "sun." and "ambient" ("FrameInfo.").
Status checkLighting(const SunInput& sun, const Vec3& ambient, const std::string& prefix);
// The frame's time: finite, within ±kMaxTimeSeconds. `field` names it.
Status checkTime(double timeSeconds, const std::string& field);
// The shadow map's transform (also used by the CPU references): finite, and worldToClip · translate(camera)
// (the camera-relative transform the GPU gets in float, in postfx's frame: its x, y, z columns times the
// host's `unitsPerMetre`) finite in float. `field` names the matrix.
Status checkShadowTransform(const DMat4& worldToClip, const DVec3& camera, const std::string& field,
                            double unitsPerMetre = 1.0);
// One local light (also used by the CPU references): type, position within ±kMaxWorldCoordinate, intensity
// in [0, 1e9], range, source radius, cone angles, a spot's direction. `name` names it
// ("FrameInfo.lights[2]").
Status checkLight(const LocalLight& light, const std::string& name);
// A VkImageLayout of the Vulkan headers postfx was built with (not a value cast from another int).
bool knownImageLayout(VkImageLayout layout);

}  // namespace postfx::core
