// Camera helpers shared by the effects.
#pragma once

#include <glm/glm.hpp>

namespace postfx::core {

// The camera's rotation-only view (translation removed): world directions -> view directions. Effects
// work camera-relative, so their clip <-> direction matrices leave the camera's position out.
inline glm::dmat4 rotationOnly(const glm::mat4& view) {
    glm::dmat4 r(view);
    r[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    return r;
}

}  // namespace postfx::core
