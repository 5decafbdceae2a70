// The fog model's equations in double precision (docs/effects/fog.md, section "Model").
#include "common/reference_model.h"

#include "common/medium.h"

#include <postfx/reference.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace postfx::reference {

// Phase: p(cosθ) = (1 - g²) / (4π (1 + g² - 2g·cosθ)^{3/2}), g clamped to ±kMaxAnisotropy.
double henyeyGreenstein(double cosTheta, double g) {
    const double gMax = common::kMaxAnisotropy;
    g = std::clamp(g, -gMax, gMax);
    const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * std::numbers::pi * denom * std::sqrt(denom));
}

namespace detail {

// Medium: h(y) = exp(-height_falloff · (y - base_height)), the exponent clamped to at most 80.
double heightExponent(double y, double heightFalloff, double baseHeight) {
    return std::min(-heightFalloff * (y - baseHeight), double(common::kMaxHeightExponent));
}

double heightTerm(double y, double heightFalloff, double baseHeight) {
    return std::exp(heightExponent(y, heightFalloff, baseHeight));
}

namespace {

// The texel index `i` (an integer-valued double, any sign or size) wrapped into [0, size).
int64_t wrapIndex(double i, uint32_t size) {
    double w = std::fmod(i, double(size));  // exact for integer-valued doubles
    if (w < 0.0) w += double(size);
    return int64_t(w);
}

}  // namespace

// Noise: trilinear with repeat addressing. Texel i's centre is at (i + 0.5)/size, so the sample at
// texel coordinate s = u·size - 0.5 interpolates texels floor(s) and floor(s) + 1 (mod size) with
// weight fract(s) on the second.
double sampleNoise(std::span<const float> texels, uint32_t size, const glm::dvec3& u) {
    int64_t lo[3], hi[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double s = u[c] * double(size) - 0.5;
        const double fl = std::floor(s);
        f[c] = s - fl;
        lo[c] = wrapIndex(fl, size);
        hi[c] = (lo[c] + 1) % int64_t(size);
    }
    const int64_t n = size;
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const bool bx = corner & 1, by = corner & 2, bz = corner & 4;
        const double w = (bx ? f[0] : 1.0 - f[0]) * (by ? f[1] : 1.0 - f[1]) * (bz ? f[2] : 1.0 - f[2]);
        const int64_t x = bx ? hi[0] : lo[0], y = by ? hi[1] : lo[1], z = bz ? hi[2] : lo[2];
        sum += w * double(texels[size_t(x + n * (y + n * z))]);
    }
    return sum;
}

// One tap of the shadow test (the GPU's shadowTapLit): inside the map's depth range [0, 1], `z - bias <=
// stored` (standard Z) or `z + bias >= stored` (reversed Z). Beyond the far plane (z > 1 standard, z < 0
// reversed) the texel's caster, wherever it is along the column, is nearer the sun than the sample: shadowed
// when the texel holds one (stored < 1 standard, > 0 reversed: not the cleared far value), lit otherwise.
// Before the near plane the caller has already returned lit.
bool shadowTapLit(const ShadowMap& map, double z, double stored) {
    if (map.reversedZ) return z < 0.0 ? stored <= 0.0 : z + map.bias >= stored;
    return z > 1.0 ? stored >= 1.0 : z - map.bias <= stored;
}

// Shadow-map visibility V: c = worldToClip · x_world, uv = c.xy/c.w · 0.5 + 0.5, z = c.z/c.w; outside
// uv ∈ [0,1]² or before the near plane (z < 0 standard, z > 1 reversed) V = 1; otherwise the mean of
// shadowTapLit over the kernel × kernel texels around ij = floor(uv · size) (indices clamped to the map).
double shadowVisibility(const ShadowMap& map, const glm::dvec3& world) {
    if (map.depth.empty()) return 1.0;
    const glm::dvec4 c = map.worldToClip * glm::dvec4(world, 1.0);
    const double u = c.x / c.w * 0.5 + 0.5, v = c.y / c.w * 0.5 + 0.5, z = c.z / c.w;
    // Written so that NaN (c.w = 0) also lands outside.
    const bool beforeNear = map.reversedZ ? !(z <= 1.0) : !(z >= 0.0);
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0) || beforeNear) return 1.0;
    const int64_t w = map.width, h = map.height, r = (int64_t(map.kernel) - 1) / 2;
    const int64_t i = int64_t(std::floor(u * double(w))), j = int64_t(std::floor(v * double(h)));
    int lit = 0;
    for (int64_t b = -r; b <= r; ++b) {
        for (int64_t a = -r; a <= r; ++a) {
            const int64_t x = std::clamp<int64_t>(i + a, 0, w - 1), y = std::clamp<int64_t>(j + b, 0, h - 1);
            lit += shadowTapLit(map, z, map.depth[size_t(y * w + x)]);
        }
    }
    return double(lit) / double(map.kernel * map.kernel);
}

double cloudShadowVisibility(const CloudShadowMap& map, const glm::dvec3& world) {
    if (map.texels.empty()) return 1.0;
    const double u = glm::dot(glm::dvec3(map.u), world) + map.u.w;
    const double v = glm::dot(glm::dvec3(map.v), world) + map.v.w;
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return 1.0;  // NaN too
    const double s = u * double(map.width) - 0.5, t = v * double(map.height) - 0.5;
    const double i = std::floor(s), j = std::floor(t), a = s - i, b = t - j;
    const auto texel = [&](double x, double y) {
        const int64_t cx = std::clamp<int64_t>(int64_t(x), 0, int64_t(map.width) - 1);
        const int64_t cy = std::clamp<int64_t>(int64_t(y), 0, int64_t(map.height) - 1);
        return double(map.texels[size_t(cy * int64_t(map.width) + cx)]);
    };
    return (1.0 - b) * ((1.0 - a) * texel(i, j) + a * texel(i + 1.0, j)) +
           b * ((1.0 - a) * texel(i, j + 1.0) + a * texel(i + 1.0, j + 1.0));
}

// Self-shadowing: τsun = density · h(y) / (height_falloff · toSun.y) when height_falloff · toSun.y > 0,
// ∞ otherwise (sun at or below the horizon, or homogeneous fog); Tsun = exp(-τsun).
double sunTransmittance(double density, double h, double heightFalloff, double toSunY) {
    const double rate = heightFalloff * toSunY;
    if (!(rate > 0.0)) return 0.0;
    return std::exp(-density * h / rate);
}

// Analytic tail: τtail = density · h0 · (1 - exp(-a·(t1 - t0))) / a, → density · h0 · (t1 - t0) as
// a → 0, ∞ when t1 = ∞ and a <= 0. Here h0 = exp(exponent0) and length = t1 - t0.
double tailOpticalDepth(double density, double exponent0, double a, double length) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    // No medium: nothing, also for the 0·∞ of an infinite tail.
    if (density == 0.0 || length == 0.0) return 0.0;
    if (std::isinf(length)) return a > 0.0 ? density * std::exp(exponent0) / a : kInf;
    const double x = a * length;
    double integral;  // ∫ exp(-a·s) ds over [0, length] = (1 - e^{-x}) / a
    if (std::abs(x) < 1e-4) {
        // Series of (1 - e^{-x}) / x: 1 - x/2 + x²/6 (relative error < x³/24 ≈ 4e-14).
        integral = length * (1.0 - x / 2.0 + x * x / 6.0);
    } else if (x < -700.0) {
        // Ray descending into ever denser fog: e^{-x} - 1 = e^{-x} to double precision; fold h0 into
        // the exponent so that an underflowed h0 does not make 0·∞.
        return density * std::exp(exponent0 - x) / -a;
    } else {
        integral = -std::expm1(-x) / a;
    }
    return density * std::exp(exponent0) * integral;
}

}  // namespace detail
}  // namespace postfx::reference
