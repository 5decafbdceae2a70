// Motion of scene files: the scene at frame n. Keep docs/scene-format.md#motion in sync.
#include "scene/motion.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace demo {
namespace {

// look_at's distance from position while moving, relative to the largest |position| coordinate: a float
// there is exact to about 6e-8 of it, so the view direction stays within about 1e-3 rad of its own.
constexpr double kMinRelativeLookDistance = 1e-4;

glm::dvec3 clampToLimits(const glm::dvec3& p) {
    return glm::clamp(p, glm::dvec3(-limits::kMaxCoordinate), glm::dvec3(limits::kMaxCoordinate));
}

bool moves(const glm::vec3& velocity) {
    return velocity != glm::vec3(0.0f);
}

// Turns `v` about world +y by `degrees` to the right (from -z toward +x): a right-handed rotation by
// -degrees.
glm::dvec3 yawRight(const glm::dvec3& v, double degrees) {
    const double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
    return {v.x * c - v.z * s, v.y, v.x * s + v.z * c};
}

}  // namespace

double frameTimeSeconds(const Scene& scene, uint64_t frame) {
    return double(frame) * scene.frameTime;
}

bool hasMotion(const Scene& scene) {
    if (moves(scene.camera.velocity) || scene.camera.yawRateDeg != 0.0f) return true;
    return std::any_of(scene.lights.begin(), scene.lights.end(),
                       [](const Light& l) { return moves(l.velocity) || l.intensityChange.has_value(); });
}

Camera cameraAt(const Camera& camera, double t) {
    if (!moves(camera.velocity) && camera.yawRateDeg == 0.0f) return camera;
    Camera c = camera;
    const glm::dvec3 p = clampToLimits(glm::dvec3(camera.position) + glm::dvec3(camera.velocity) * t);
    glm::dvec3 view = glm::dvec3(camera.lookAt) - glm::dvec3(camera.position);
    if (camera.yawRateDeg != 0.0f) {
        // The angle modulo one turn before the rotation keeps it exact for long times.
        const double degrees = std::fmod(double(camera.yawRateDeg) * t, 360.0);
        view = yawRight(view, degrees);
        c.up = glm::vec3(yawRight(glm::dvec3(camera.up), degrees));
    }
    const double length = glm::length(view);  // > 0 in a loaded scene: the loader checks it
    if (!(length > 0.0)) {
        c.position = glm::vec3(p);
        c.lookAt = c.position;
        return c;
    }
    const double largest = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double distance = std::max(length, kMinRelativeLookDistance * largest);
    c.position = glm::vec3(p);
    c.lookAt = glm::vec3(p + view * (distance / length));
    return c;
}

Light lightAt(const Light& light, uint64_t frame, double t) {
    Light l = light;
    if (moves(light.velocity))
        l.position = glm::vec3(clampToLimits(glm::dvec3(light.position) + glm::dvec3(light.velocity) * t));
    if (light.intensityChange && frame >= light.intensityChange->frame)
        l.intensity = light.intensityChange->intensity;
    return l;
}

void moveToFrame(const Scene& scene, uint64_t frame, Scene& state) {
    const double t = frameTimeSeconds(scene, frame);
    state.camera = cameraAt(scene.camera, t);
    state.lights.resize(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        state.lights[i] = lightAt(scene.lights[i], frame, t);
}

Scene sceneAtFrame(const Scene& scene, uint64_t frame) {
    Scene state = scene;
    moveToFrame(scene, frame, state);
    return state;
}

bool isCameraCut(const Scene& scene, uint64_t frame) {
    return scene.cameraCutFrame && frame == *scene.cameraCutFrame;
}

}  // namespace demo
