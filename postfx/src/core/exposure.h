// Pre-exposure (FrameInfo::preExposure; docs/integration.md, "Pre-exposure"): the host stores its color
// multiplied by it, and postfx writes its radiance the same way. Every radiance postfx adds is linear in
// the light it is given (the sun's illuminance, the ambient radiance, the local lights' intensities), so
// the effects pre-expose that light where they pack it into uniforms, and nothing else changes: the
// host's color passes through the transmittance as it is, and a temporal history is rescaled by the
// change of pre-exposure between frames (core/temporal.h, TemporalFrame::historyScale).
#pragma once

#include <postfx/types.h>

#include <glm/glm.hpp>

namespace postfx::core {

// `light` × `preExposure`, rounded once to float.
inline glm::vec3 preExposed(const Vec3& light, float preExposure) {
    return glm::vec3(glm::dvec3(light) * double(preExposure));
}

}  // namespace postfx::core
