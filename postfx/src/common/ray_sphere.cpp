#include "common/ray_sphere.h"

#include <algorithm>
#include <cmath>

namespace postfx::common {

SphereHit raySphere(const glm::dvec3& o, const glm::dvec3& d, double radius) {
    const double b = glm::dot(o, d);
    const glm::dvec3 closest = o - b * d;  // the ray's point nearest the centre
    const double h = glm::length(closest);
    const double disc = (radius - h) * (radius + h);
    if (disc < 0.0) return {};
    // c = |o|² - radius², factored so that it keeps its precision when |o| ≈ radius.
    const double len = glm::length(o);
    const double c = (len - radius) * (len + radius);
    const double q = -b - std::copysign(std::sqrt(disc), b);
    SphereHit hit;
    hit.hit = true;
    if (q == 0.0) {  // b = 0 and disc = 0: origin on the sphere, ray tangent
        hit.tNear = hit.tFar = 0.0;
        return hit;
    }
    const double t0 = q, t1 = c / q;
    hit.tNear = std::min(t0, t1);
    hit.tFar = std::max(t0, t1);
    return hit;
}

}  // namespace postfx::common
