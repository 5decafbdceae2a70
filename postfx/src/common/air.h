// The air (the atmosphere's media) as other effects' CPU references read it: the sun's transmittance at
// a point, and the light and transmittance of the air along a view ray. The contract is declared here and
// built by the atmosphere (atmosphere/atmosphere_air.cpp) from the public AtmosphereSettings, so that a
// reference reads the air without naming the atmosphere's headers; the GPU side is shaders/common/air/.
// A reference holds an Air only with the atmosphere on.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/inputs.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>

namespace postfx::common {

class Air {
public:
    virtual ~Air() = default;

    // The transmittance toward the sun (unit `toSun`) from world position `world` [m] (the ground at
    // y = 0, the planet's centre below the origin), as the GPU's LUT
    // holds it (0 where the planet hides the sun). `liftAboveGround`: a position below the ground is moved
    // onto it first (the fogs'; the clouds are always above it).
    virtual glm::dvec3 sunTransmittance(const glm::dvec3& world, const glm::dvec3& toSun,
                                        bool liftAboveGround) const = 0;

    // The air's in-scattered luminance and transmittance between the camera (makeViewAir's, lifted above
    // the ground) and `distance` [m] along unit `direction`; the ray goes on below the ground as the
    // aerial perspective of geometry does. Only for an Air from makeViewAir.
    struct Segment {
        glm::dvec3 luminance{0.0};
        glm::dvec3 transmittance{1.0};
    };
    virtual Segment viewSegment(const glm::dvec3& direction, double distance) const = 0;
};

// The air of `settings` for the sun's transmittance (its fine table, shared by every reference of the
// same media). Throws std::bad_alloc.
std::shared_ptr<const Air> makeAir(const AtmosphereSettings& settings);

// The air of `settings` seen from world position `camera` under `sun`, for view segments too: `steps`
// per segment, with the multiple scattering the settings choose (the references' coarse tables).
// Throws std::bad_alloc.
std::shared_ptr<const Air> makeViewAir(const AtmosphereSettings& settings, const SunInput& sun,
                                       const glm::dvec3& camera, uint32_t steps);

// The key of every atmosphere setting the aerial perspective and sky view depend on (media, sizes,
// steps): a reader's temporal history (the clouds') resets when it changes.
uint64_t airViewSettingsKey(const AtmosphereSettings& settings);

}  // namespace postfx::common
