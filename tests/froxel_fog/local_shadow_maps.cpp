#include "local_shadow_maps.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace test {
namespace {

// The nearest t > 0 where origin + t·dir (dir unit) meets a sphere; +∞ if none.
double nearestHit(const glm::dvec3& origin, const glm::dvec3& dir, const std::vector<ShadowSphere>& spheres) {
    double best = std::numeric_limits<double>::infinity();
    for (const ShadowSphere& s : spheres) {
        const glm::dvec3 oc = origin - s.centre;
        const double b = glm::dot(oc, dir), c = glm::dot(oc, oc) - s.radius * s.radius;
        const double disc = b * b - c;
        if (disc < 0.0) continue;
        const double root = std::sqrt(disc);
        for (double t : {-b - root, -b + root})
            if (t > 0.0) {
                best = std::min(best, t);
                break;
            }
    }
    return best;
}

}  // namespace

void ShadowAtlas::drawFace(const glm::dmat4& worldToClip, const glm::dvec3& eye, glm::uvec2 offset,
                           uint32_t size, const std::vector<ShadowSphere>& spheres) {
    const glm::dmat4 clipToWorld = glm::inverse(worldToClip);
    for (uint32_t j = 0; j < size; ++j)
        for (uint32_t i = 0; i < size; ++i) {
            const glm::dvec2 ndc = (glm::dvec2(i, j) + 0.5) / double(size) * 2.0 - 1.0;
            const glm::dvec4 far = clipToWorld * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - eye);
            const double t = nearestHit(eye, dir, spheres);
            float depth = 1.0f;
            if (std::isfinite(t)) {
                const glm::dvec4 c = worldToClip * glm::dvec4(eye + t * dir, 1.0);
                depth = float(std::clamp(c.z / c.w, 0.0, 1.0));  // depth clamping, as a rasterizer's
            }
            texels[size_t(offset.y + j) * width + offset.x + i] = depth;
        }
}

postfx::LocalShadow ShadowAtlas::spot(const glm::dvec3& position, const glm::dvec3& direction, double fovRad,
                                      glm::uvec2 offset, uint32_t size, double nearPlane, double farPlane,
                                      const std::vector<ShadowSphere>& spheres) {
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec3 up = std::abs(d.y) > 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dmat4 m =
        glm::perspectiveRH_ZO(fovRad, 1.0, nearPlane, farPlane) * glm::lookAtRH(position, position + d, up);
    drawFace(m, position, offset, size, spheres);
    postfx::LocalShadow s;
    s.faceCount = 1;
    s.faces[0].offset = offset;
    s.faces[0].extent = {size, size};
    s.faces[0].worldToClip = m;
    return s;
}

postfx::LocalShadow ShadowAtlas::point(const glm::dvec3& position, glm::uvec2 offset, uint32_t size,
                                       double nearPlane, double farPlane,
                                       const std::vector<ShadowSphere>& spheres, const glm::dmat3& rotation) {
    const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::dvec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const glm::dmat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0), 1.0, nearPlane, farPlane);
    postfx::LocalShadow s;
    s.faceCount = 6;
    for (uint32_t f = 0; f < 6; ++f) {
        const glm::uvec2 o = offset + glm::uvec2((f % 3) * size, (f / 3) * size);
        const glm::dmat4 m =
            projection * glm::lookAtRH(position, position + rotation * axes[f], rotation * ups[f]);
        drawFace(m, position, o, size, spheres);
        s.faces[f].offset = o;
        s.faces[f].extent = {size, size};
        s.faces[f].worldToClip = m;
    }
    return s;
}

bool occluded(const glm::dvec3& x, const glm::dvec3& light, const std::vector<ShadowSphere>& spheres) {
    const glm::dvec3 d = light - x;
    const double length = glm::length(d);
    if (!(length > 0.0)) return false;
    return nearestHit(x, d / length, spheres) < length;
}

}  // namespace test
