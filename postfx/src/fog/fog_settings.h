// Checks of FogSettings and the frame inputs the fog reads, shared by the GPU pass and the CPU reference.
#pragma once

#include <postfx/fog.h>
#include <postfx/result.h>

namespace postfx::fog {

constexpr float kMaxAnisotropy = 0.999f;    // |g| is clamped to this
constexpr float kMaxHeightExponent = 80.f;  // -height_falloff·(y - base_height) is clamped to this

// InvalidArgument naming the field ("fog.density: -1 is negative") for any value out of range or NaN.
Status validateSettings(const FogSettings& settings);
// The sun and ambient inputs (finite, non-negative illuminance, non-zero direction).
Status validateLighting(const SunInput& sun, const glm::vec3& ambient);

// g clamped to [-kMaxAnisotropy, kMaxAnisotropy].
float clampedAnisotropy(float g);

}  // namespace postfx::fog
