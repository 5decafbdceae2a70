// The pieces of the fog model (docs/effects/fog.md) in double precision, used by the CPU reference
// (fog_reference.cpp) and exposed to its unit tests. Each function is one equation of the doc.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace postfx::reference::detail {

// Exponent of the height term, -height_falloff · (y - base_height), clamped to <= kMaxHeightExponent.
double heightExponent(double y, double heightFalloff, double baseHeight);
// h(y) = exp(heightExponent(y)).
double heightTerm(double y, double heightFalloff, double baseHeight);

// n(u): the noise texture (size³ texels, x fastest, then y, then z) sampled with trilinear filtering
// and repeat addressing, texel centres at (i + 0.5) / size.
double sampleNoise(std::span<const float> texels, uint32_t size, const glm::dvec3& u);

// The host's shadow map as the reference reads it.
struct ShadowMap {
    std::span<const float> depth;  // width·height texels, row-major, row 0 at v = 0; empty: no map
    uint32_t width = 0, height = 0;
    glm::dmat4 worldToClip{1.0};
    bool reversedZ = false;
    double bias = 0.0;
    uint32_t kernel = 1;  // odd
};

// The clouds' shadow map as the references read it.
struct CloudShadowMap {
    std::span<const float> texels;  // width·height, row-major, row 0 at v = 0; empty: no map
    uint32_t width = 0, height = 0;
    glm::dvec4 u{0.0}, v{0.0};  // uv = (dot(u.xyz, x) + u.w, dot(v.xyz, x) + v.w) of world position x
};

// The clouds' transmittance toward the sun at world position `world`, read as the GPU reads the map
// (shaders/common/cloud_shadow.glsl with a linear, clamp-to-edge sampler): 1 outside uv ∈ [0, 1]² or
// without a map; otherwise bilinear between the texel centres (i + 0.5) / size, the indices clamped.
double cloudShadowVisibility(const CloudShadowMap& map, const glm::dvec3& world);

// One tap at shadow depth `z` (c.z/c.w) against texel depth `stored`, for z not before the near plane:
// inside [0, 1] the biased depth comparison; beyond the far plane lit only where the texel holds no caster
// (stored is the cleared far value: 1 standard, 0 reversed).
bool shadowTapLit(const ShadowMap& map, double z, double stored);

// V(x) at world position `world`: the mean of shadowTapLit over the kernel × kernel texels; 1 outside the
// map's uv, before its near plane, or when there is no map.
double shadowVisibility(const ShadowMap& map, const glm::dvec3& world);

// Tsun(x) = exp(-τsun), τsun = density · h / (height_falloff · toSunY) when height_falloff · toSunY > 0,
// otherwise ∞ (Tsun = 0). `h` is h(y) at x.
double sunTransmittance(double density, double h, double heightFalloff, double toSunY);

// τtail: optical depth of the height fog along t ∈ [t0, t0 + length] where the ray's height term is
// exp(exponent0 - a·(t - t0)), a = height_falloff · d.y. `length` may be +∞.
double tailOpticalDepth(double density, double exponent0, double a, double length);

}  // namespace postfx::reference::detail
