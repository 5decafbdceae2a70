#include "host/scene_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demo {
namespace {

void addQuad(SceneMesh& mesh, const glm::vec3 corners[4], glm::vec3 normal) {
    const auto base = uint32_t(mesh.vertices.size());
    for (int i = 0; i < 4; ++i)
        mesh.vertices.push_back({corners[i], normal});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        mesh.indices.push_back(base + i);
}

void addBox(SceneMesh& mesh, const Object& box) {
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 normal(0.0f), du(0.0f), dv(0.0f);
            normal[axis] = sign;
            du[u] = box.halfSize[u];
            dv[v] = box.halfSize[v];
            const glm::vec3 c = box.position + normal * box.halfSize[axis];
            const glm::vec3 corners[4] = {c - du - dv, c + du - dv, c + du + dv, c - du + dv};
            addQuad(mesh, corners, normal);
        }
    }
}

void addSphere(SceneMesh& mesh, const Object& sphere) {
    const auto base = uint32_t(mesh.vertices.size());
    for (uint32_t i = 0; i <= kSphereRings; ++i) {
        const float theta = std::numbers::pi_v<float> * float(i) / float(kSphereRings);
        for (uint32_t j = 0; j <= kSphereSegments; ++j) {
            const float phi = 2.0f * std::numbers::pi_v<float> * float(j) / float(kSphereSegments);
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.vertices.push_back({sphere.position + sphere.radius * n, n});
        }
    }
    const uint32_t row = kSphereSegments + 1;
    for (uint32_t i = 0; i < kSphereRings; ++i) {
        for (uint32_t j = 0; j < kSphereSegments; ++j) {
            const uint32_t a = base + i * row + j, b = a + row;
            for (uint32_t k : {a, b, a + 1, a + 1, b, b + 1})
                mesh.indices.push_back(k);
        }
    }
}

void addPlane(SceneMesh& mesh, const Object& plane, const Camera& camera, bool infiniteFar) {
    const glm::vec3 n = glm::normalize(plane.normal);
    const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(n, helper));
    const glm::vec3 b = glm::cross(n, t);
    const glm::vec3 centre = camera.position - glm::dot(camera.position - plane.position, n) * n;
    const float extent = infiniteFar ? kMaxPlaneExtent : std::min(camera.farPlane, kMaxPlaneExtent);
    const glm::vec3 du = t * extent, dv = b * extent;
    const glm::vec3 corners[4] = {centre - du - dv, centre + du - dv, centre + du + dv, centre - du + dv};
    addQuad(mesh, corners, n);
}

}  // namespace

SceneMesh buildSceneMesh(const Scene& scene, bool infiniteFar) {
    SceneMesh mesh;
    for (const Object& o : scene.objects) {
        MeshDraw draw;
        draw.firstIndex = uint32_t(mesh.indices.size());
        draw.albedo = o.albedo;
        switch (o.type) {
            case ObjectType::Box:
                addBox(mesh, o);
                break;
            case ObjectType::Sphere:
                addSphere(mesh, o);
                break;
            case ObjectType::Plane:
                addPlane(mesh, o, scene.camera, infiniteFar);
                break;
        }
        draw.indexCount = uint32_t(mesh.indices.size()) - draw.firstIndex;
        mesh.draws.push_back(draw);
    }
    return mesh;
}

}  // namespace demo
