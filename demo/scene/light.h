// Local lights of scene files (the top-level `lights` array, docs/scene-format.md#lights) and their
// conversion to postfx::LocalLight, which the demo passes in FrameInfo::lights.
#pragma once

#include <postfx/inputs.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace demo {

enum class LightKind { Point, Spot };

// A light's intensity from a given frame on (`lights[i].intensity_change`, docs/scene-format.md#motion).
struct IntensityChange {
    uint32_t frame = 0;         // the first frame with the new intensity, [0, 4294967295]
    glm::vec3 intensity{0.0f};  // [cd] per RGB channel, each in [0, 1e9]; 0 turns the light off
};

// Units and ranges are those of postfx::LocalLight; angles are kept in degrees as written in the file,
// so that a scene round-trips exactly. `position` and `intensity` are the light's at frame 0; its motion
// (velocity, intensity change) gives those of later frames (scene/motion.h).
struct Light {
    LightKind kind = LightKind::Point;
    glm::vec3 position{0.0f};                // [m], each in [-1e7, 1e7]
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot only: the cone's axis, unit (normalised on load)
    glm::vec3 intensity{0.0f};               // luminous intensity per RGB channel [cd], each in [0, 1e9]
    float radius = 0.05f;                    // source radius guarding the inverse square [m], (0, range]
    float range = 100.0f;                    // light ignored beyond it [m], (0, 1e9]
    float innerAngleDeg = 0.0f;              // spot: full intensity inside this half angle [deg], [0, outer]
    float outerAngleDeg = 45.0f;             // spot: dark outside this half angle [deg], [0, 89.9]
    glm::vec3 velocity{0.0f};                // [m/s] world, each in [-1e4, 1e4] (scene/motion.h)
    // Whether the light casts shadows: the renderer draws its shadow map (one face for a spot, six for a
    // point light) into the local shadow atlas, reads it on the surfaces and gives it to postfx.
    bool shadows = false;
    uint32_t shadowResolution = 512;  // texels per face edge, [16, 4096] (the renderer may halve it to fit)
    std::optional<IntensityChange> intensityChange;  // none: the intensity never changes
};

// The postfx description of `light` (angles in radians).
postfx::LocalLight toLocalLight(const Light& light);

}  // namespace demo
