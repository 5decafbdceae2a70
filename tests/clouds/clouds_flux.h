// The flux through a plane from any radiance function (the path tracer's, the real-time model's): a Monte
// Carlo estimate over cosine-weighted directions, for energy checks of the clouds' light.
#pragma once

#include "clouds/clouds_path_tracer.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <functional>

namespace test {

// radiance(origin, dir): the radiance arriving at `origin` from along `dir` (unit, from the eye).
using RadianceFunction = std::function<glm::dvec3(const glm::dvec3& origin, const glm::dvec3& dir)>;

struct FluxEstimate {
    glm::dvec3 flux{0.0};           // per unit area, in the radiance's unit × sr
    glm::dvec3 standardError{0.0};  // per channel: the sample standard deviation / sqrt(n)
};

// The flux arriving at `origin` through the plane of normal `look` (unit) from the hemisphere `look` points
// into: ∫_{ω·look > 0} L(origin, ω) (ω·look) dω = π · E[L(origin, ω)] for ω drawn with pdf (ω·look)/π,
// estimated from `nDirections` >= 2 directions drawn from `rng` (one radiance call each). Looking down
// (look = -y) from above a layer gives the flux it sends up; looking up from below, the flux it lets down.
inline FluxEstimate hemisphereFlux(const RadianceFunction& radiance, const glm::dvec3& origin,
                                   const glm::dvec3& look, uint32_t nDirections, postfx::clouds::Rng& rng) {
    const double pi = glm::pi<double>();
    // An orthonormal basis around `look` (Duff et al. 2017).
    const double sign = std::copysign(1.0, look.z);
    const double a = -1.0 / (sign + look.z), b = look.x * look.y * a;
    const glm::dvec3 t1(1.0 + sign * look.x * look.x * a, sign * b, -sign * look.x);
    const glm::dvec3 t2(b, sign + look.y * look.y * a, -look.y);
    glm::dvec3 mean(0.0), m2(0.0);  // Welford's running mean and sum of squared deviations
    for (uint32_t i = 0; i < nDirections; ++i) {
        const double u = rng.uniform(), phi = 2.0 * pi * rng.uniform();
        const double r = std::sqrt(u);
        const glm::dvec3 dir =
            glm::normalize(r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1.0 - u) * look);
        const glm::dvec3 L = radiance(origin, dir);
        const glm::dvec3 delta = L - mean;
        mean += delta / double(i + 1);
        m2 += delta * (L - mean);
    }
    FluxEstimate e;
    e.flux = pi * mean;
    if (nDirections > 1) e.standardError = pi * glm::sqrt(m2 / (double(nDirections - 1) * nDirections));
    return e;
}

}  // namespace test
