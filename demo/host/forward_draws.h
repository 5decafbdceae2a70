// What the forward pass draws in one frame, back to front: the scene's objects drawnForward (ranges of the
// scene mesh) and its particles (quads built here), sorted by their distance from the camera.
#pragma once

#include "host/scene_mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace demo {

struct ForwardDraw {
    bool particle = false;  // false: indices [first, first + count) of the scene mesh; true: vertices of
                            // ForwardFrame::particleVertices
    uint32_t first = 0;
    uint32_t count = 0;
    uint32_t kind = 0;  // shared::kForwardOpenSurface, kForwardClosedSurface or kForwardParticle
    glm::vec3 albedo{0.5f};
    float opacity = 1.0f;
    float distance = 0.0f;  // [m] from the camera to the object's centre (a plane: to the plane)
};

struct ForwardFrame {
    std::vector<ForwardDraw> draws;  // farthest first
    // Six vertices per particle (two triangles, forward.vert's corner order), normals toward the camera.
    std::vector<MeshVertex> particleVertices;
};

// The forward draws of `scene` (objects as meshed in `meshDraws`, one per object) with its particles at
// time `seconds` [s] (the frame's time, FrameInfo::timeSeconds), facing its camera.
ForwardFrame buildForwardFrame(const Scene& scene, std::span<const MeshDraw> meshDraws, double seconds);

// The scene mesh's draws of the objects the G-buffer draws (not drawnForward), and of those that cast
// shadows (castsShadows).
std::vector<MeshDraw> opaqueDraws(const Scene& scene, std::span<const MeshDraw> meshDraws);
std::vector<MeshDraw> shadowCasterDraws(const Scene& scene, std::span<const MeshDraw> meshDraws);

}  // namespace demo
