// Particle placement: a counter-based hash of (seed, index, axis), so that a particle's position does not
// depend on the count or on earlier frames.
#include "scene/particles.h"

#include <algorithm>
#include <cmath>

namespace demo {
namespace {

// PCG's output permutation over a 32-bit state (Jarzynski & Olano 2020, "Hash Functions for GPU
// Rendering").
uint32_t pcgHash(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1).
double unit(uint32_t seed, uint32_t index, uint32_t axis) {
    const uint32_t h = pcgHash(pcgHash(pcgHash(seed) ^ index) + axis);
    return double(h >> 8) / double(1u << 24);
}

// The fraction of the height over which a particle fades in at the bottom and out at the top.
constexpr double kFade = 0.1;

}  // namespace

std::vector<Particle> emitParticles(const ParticleEmitter& emitter, double seconds) {
    std::vector<Particle> out;
    if (!emitter.enabled) return out;
    out.reserve(emitter.count);
    const glm::dvec3 centre(emitter.center), half(emitter.halfSize);
    const double height = 2.0 * half.y;
    for (uint32_t i = 0; i < emitter.count; ++i) {
        glm::dvec3 u{unit(emitter.seed, i, 0), unit(emitter.seed, i, 1), unit(emitter.seed, i, 2)};
        // Height above the box's bottom, risen and wrapped: s in [0, 1).
        double s = std::fmod(u.y + double(emitter.riseSpeed) * seconds / height, 1.0);
        if (s < 0.0) s += 1.0;
        u.y = s;
        const double fade = std::clamp(std::min(s, 1.0 - s) / kFade, 0.0, 1.0);
        Particle p;
        p.center = glm::vec3(centre + (2.0 * u - 1.0) * half);
        p.opacity = float(double(emitter.opacity) * fade);
        out.push_back(p);
    }
    return out;
}

}  // namespace demo
