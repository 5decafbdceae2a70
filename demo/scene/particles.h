// Particle emitters of scene files (the top-level `particles` array, docs/scene-format.md#particles): a
// box of camera-facing quads, placed at random once (from `seed`) and rising with the scene's time,
// drawn by the renderer's forward pass like transparent objects.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace demo {

// Limits: at most this many emitters, and this many particles in one emitter (the forward pass draws each
// particle on its own: 65536 draws at most).
inline constexpr uint32_t kMaxParticleEmitters = 16;
inline constexpr uint32_t kMaxParticlesPerEmitter = 4096;

struct ParticleEmitter {
    glm::vec3 center{0.0f};    // the box's centre [m], each in [-1e7, 1e7]
    glm::vec3 halfSize{0.5f};  // the box's half sizes [m], each in (0, 1e4]
    uint32_t count = 64;       // particles [1], [0, 4096]
    float quadSize = 0.5f;     // each quad's edge [m], (0, 1e4]
    glm::vec3 albedo{0.5f};    // diffuse reflectance, each in [0, 1]
    float opacity = 0.3f;      // each quad's coverage at its centre [1], [0, 1]
    uint32_t seed = 1;         // the placement's random seed, [0, 4294967295]
    float riseSpeed = 0.0f;    // upward speed [m/s], [-1e4, 1e4]; particles wrap within the box's height
    bool enabled = true;       // false: not drawn
};

// One particle of an emitter at time t [s].
struct Particle {
    glm::vec3 center{0.0f};  // [m] world
    float opacity = 0.0f;    // the emitter's, faded out within 10 % of the box's height from its ends
};

// The `count` particles of `emitter` at time `seconds`: positions uniform in the box from a hash of (seed,
// index); y advanced by riseSpeed · seconds and wrapped into the box's height.
std::vector<Particle> emitParticles(const ParticleEmitter& emitter, double seconds);

}  // namespace demo
