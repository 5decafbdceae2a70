// CPU meshes of the scene's objects, in world space, for the G-buffer and shadow passes.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace demo {

struct MeshVertex {
    glm::vec3 position;  // world [m]
    glm::vec3 normal;    // world, unit
};
static_assert(sizeof(MeshVertex) == 24);

struct MeshDraw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    glm::vec3 albedo{0.5f};
};

struct SceneMesh {
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;  // absolute (into `vertices`)
    std::vector<MeshDraw> draws;    // one per scene object, in scene order
};

constexpr uint32_t kSphereSegments = 48;  // around the y axis
constexpr uint32_t kSphereRings = 24;     // pole to pole
constexpr float kMaxPlaneExtent = 1e4f;   // [m] half-size limit of a plane's quad

// Boxes: 24 vertices / 36 indices with flat normals. Spheres: UV spheres with smooth normals.
// Planes: a square centred at the camera's projection onto the plane, half-size = camera far
// distance (kMaxPlaneExtent with infiniteFar, and at most that), so it reaches the far plane / horizon.
SceneMesh buildSceneMesh(const Scene& scene, bool infiniteFar);

}  // namespace demo
