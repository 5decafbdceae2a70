// The shared medium (FogMedium: the ray-marched and the froxel fog; docs/effects/fog.md, "Model"): its
// rules beside its settings table (common/medium_table.h), its bounds and its part of the uniforms
// (gpu::FogUniforms, shaders/common/medium_shared.h; the GLSL side is shaders/common/medium/).
#pragma once

#include <postfx/context.h>
#include <postfx/fog.h>
#include <postfx/result.h>

#include "common/medium_shared.h"
#include "core/world_frame.h"

#include <string>

namespace postfx::common {

constexpr float kMaxAnisotropy = 0.999f;                       // the range of |g|; ±1 would be a delta
constexpr float kMaxHeightExponent = gpu::kMaxHeightExponent;  // -height_falloff·(y - base_height) <= this

// The shared medium's checks that are not ranges of its table (common/medium_table.h), used by both fogs:
// the generated noise's texture size (a power of two in [16, 256]) and the host texture's layout, while the
// noise is on; named with the settings' C++ path `prefix` ("FrameInfo.froxelFog.noise.textureSize: ...").
Status checkMediumRules(const FogMedium& medium, const std::string& prefix);

// The medium is empty everywhere: density 0, or noise on with multiplier 0 or a threshold at or above the
// texels' maximum of 1. The fog then records nothing (docs/frame-plan.md) and the reference leaves the
// color as it is, so the analytic tail (which has no noise term) never adds fog to an empty medium.
inline bool fogMediumEmpty(const FogMedium& s, bool noiseEnabled) {
    return s.density <= 0.0f || (noiseEnabled && (s.noise.multiplier <= 0.0f || s.noise.threshold >= 1.0f));
}

// The medium's one world-space field in postfx's frame (core/world_frame.h): the noise's wind, given along
// the host's axes in m/s (its ranges hold either way: a signed permutation of a box is the box).
inline void mediumToPostfx(const core::WorldTransform& world, FogMedium& medium) {
    medium.noise.wind = world.direction(glm::vec3(medium.noise.wind));
}

// Empty-space skipping (fog.md, "Empty space"): the optical depth that the march may leave out.
constexpr double kNegligibleOpticalDepth = 1e-4;

// Height above base_height above which the medium's extinction bound density · noise_max · h(y) is below
// kNegligibleOpticalDepth / max_distance, so that no march segment above it can hold more than that
// optical depth; noise_max = clamp(1 - threshold, 0, 1) · multiplier (noise values are in [0, 1]).
// +Inf when the height term does not fall (height_falloff 0), -Inf for an empty medium.
double fogMediumTop(const FogMedium& s, bool noiseEnabled);

// g clamped to [-kMaxAnisotropy, kMaxAnisotropy].
float clampedAnisotropy(float g);

// The shared medium's part (FogMedium: both fogs), with a 1×1 shadow kernel, no march and no jitter.
// `noiseEnabled`: a noise texture will be bound; `shadowMapEnabled`: a shadow map will be bound.
gpu::FogUniforms buildMediumUniforms(const FogMedium& medium, const FrameInfo& frame,
                                     const DepthConvention& depth, bool noiseEnabled, bool shadowMapEnabled);

}  // namespace postfx::common
