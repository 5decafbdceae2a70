// A ray against a sphere centred at the origin, in double (the GLSL side is
// shaders/common/ray_sphere.glsl): the atmosphere's shells, the clouds' layer, the planet.
#pragma once

#include <glm/glm.hpp>

namespace postfx::common {

// Ray o + t·d (|d| = 1) against the sphere |x| = radius centred at the origin: the two roots tNear <= tFar
// (either may be negative: behind the origin), hit false when the ray misses (a tangent ray hits with
// tNear == tFar). Robust for an origin anywhere from inside the planet to far in space: the discriminant is
// radius² - h², h the ray's distance to the centre computed from o - (o·d)d (no cancellation of |o|² - b²),
// and the roots as q = -b - sign(b)·√disc, c/q (no cancellation of -b ± √disc).
struct SphereHit {
    bool hit = false;
    double tNear = 0.0, tFar = 0.0;
};
SphereHit raySphere(const glm::dvec3& origin, const glm::dvec3& dir, double radius);

}  // namespace postfx::common
