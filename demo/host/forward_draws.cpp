#include "host/forward_draws.h"

#include "demo_shared.h"
#include "host/camera_math.h"

#include <algorithm>
#include <cmath>

namespace demo {
namespace {

// forward.vert's kCorners.
constexpr glm::vec2 kCorners[6] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};

template <class Keep>
std::vector<MeshDraw> selectDraws(const Scene& scene, std::span<const MeshDraw> meshDraws, Keep keep) {
    std::vector<MeshDraw> out;
    for (size_t i = 0; i < meshDraws.size() && i < scene.objects.size(); ++i)
        if (keep(scene.objects[i])) out.push_back(meshDraws[i]);
    return out;
}

}  // namespace

ForwardFrame buildForwardFrame(const Scene& scene, std::span<const MeshDraw> meshDraws, double seconds) {
    ForwardFrame frame;
    const glm::dvec3 camera(scene.camera.position);
    for (size_t i = 0; i < meshDraws.size() && i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (!drawnForward(o)) continue;
        ForwardDraw d;
        d.first = meshDraws[i].firstIndex;
        d.count = meshDraws[i].indexCount;
        d.albedo = o.albedo;
        d.opacity = o.opacity;
        if (o.type == ObjectType::Plane) {
            d.kind = shared::kForwardOpenSurface;
            d.distance = float(std::abs(glm::dot(camera - glm::dvec3(o.position), glm::dvec3(o.normal))));
        } else {
            d.kind = shared::kForwardClosedSurface;
            d.distance = float(glm::length(glm::dvec3(o.position) - camera));
        }
        frame.draws.push_back(d);
    }

    // The camera's axes in world space (rows of the view rotation): quads lie in its image plane.
    const glm::mat4 view = cameraView(scene.camera);
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
    const glm::vec3 back(view[0][2], view[1][2], view[2][2]);  // toward the camera
    for (const ParticleEmitter& e : scene.particles) {
        const float half = 0.5f * e.quadSize;
        for (const Particle& p : emitParticles(e, seconds)) {
            if (!(p.opacity > 0.0f)) continue;
            ForwardDraw d;
            d.particle = true;
            d.first = uint32_t(frame.particleVertices.size());
            d.count = 6;
            d.kind = shared::kForwardParticle;
            d.albedo = e.albedo;
            d.opacity = p.opacity;
            d.distance = float(glm::length(glm::dvec3(p.center) - camera));
            for (const glm::vec2& c : kCorners)
                frame.particleVertices.push_back({p.center + (c.x * right + c.y * up) * half, back});
            frame.draws.push_back(d);
        }
    }
    std::stable_sort(frame.draws.begin(), frame.draws.end(),
                     [](const ForwardDraw& a, const ForwardDraw& b) { return a.distance > b.distance; });
    return frame;
}

std::vector<MeshDraw> opaqueDraws(const Scene& scene, std::span<const MeshDraw> meshDraws) {
    return selectDraws(scene, meshDraws, [](const Object& o) { return !drawnForward(o); });
}

std::vector<MeshDraw> shadowCasterDraws(const Scene& scene, std::span<const MeshDraw> meshDraws) {
    return selectDraws(scene, meshDraws, [](const Object& o) { return castsShadows(o); });
}

}  // namespace demo
