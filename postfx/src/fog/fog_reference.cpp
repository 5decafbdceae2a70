// Double-precision CPU reference of the ray-marched fog: the model of docs/effects/fog.md evaluated
// with a converged midpoint march (no jitter, no early cutoff), multithreaded over rows.
#include "common/parallel.h"
#include "common/reference_image.h"
#include "common/reference_model.h"
#include "core/checks.h"
#include "fog/fog_settings.h"
#include "fog/fog_shared.h"

#include <postfx/reference.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <new>
#include <string>
#include <system_error>
#include <thread>

namespace postfx::reference {
namespace {

using glm::dvec3;
using glm::dvec4;

using core::allFinite;
using core::invalid;
using detail::checkCount;
using detail::clipToView;
using detail::fillMediumModel;
using detail::MediumModel;

Status validate(const FogInputs& in) {
    if (Status s = detail::checkImage("FogInputs", in.width, in.height, in.color, in.depth); !s) return s;
    if (Status s = fog::validateSettings(in.settings); !s) return s;
    return detail::checkMediumInputs("FogInputs", "fog", in);
}

// Everything the march reads, converted to double once.
struct Model : MediumModel {
    bool skipEmptySpace;
    double mediumTop;  // above base height: fogMediumTop
};

Model makeModel(const FogInputs& in) {
    const FogSettings& s = in.settings;
    Model m;
    fillMediumModel(m, in, s, s.shadowKernel);
    m.skipEmptySpace = s.skipEmptySpace;
    m.mediumTop = common::fogMediumTop(s, s.noise.enabled);
    return m;
}

using Ray = detail::PixelRay;
Ray pixelRay(const Model& m, uint32_t i, uint32_t j, double z) {
    return detail::pixelRay(m.clipToView, m.farDepth, m.width, m.height, i, j, z);
}

// noise(x) = clamp(n(u) - threshold, 0, 1) · multiplier, 1 with noise disabled.
double noiseAt(const Model& m, const dvec3& x) {
    if (!m.noise) return 1.0;
    const double n = detail::sampleNoise(m.noiseTexels, m.noiseSize, m.noiseOrigin + x * m.noiseScale);
    return std::clamp(n - m.noiseThreshold, 0.0, 1.0) * m.noiseMultiplier;
}

struct Radiance {
    dvec3 L{0.0};    // in-scattered radiance
    double T = 1.0;  // transmittance (σt is grey: albedo only scales σs)
};

void composite(const Radiance& r, const float* color, float* out) {
    detail::composite(r.L, r.T, color, out);
}

// Adds a segment of constant light and optical depth τ: L += T·albedo·light·(1 - e^{-τ}); T *= e^{-τ}.
// With S = σs·light = albedo·σt·light this is the doc's T·S·(1 - exp(-σtΔ))/σt for τ = σtΔ, exact
// (-expm1 in double) and exactly 0 (= S·Δ) at σt = 0.
void addSegment(const Model& m, const dvec3& light, double tau, Radiance& r) {
    r.L += r.T * m.albedo * light * -std::expm1(-tau);
    r.T *= std::exp(-tau);
}

// Empty-space skipping: the part [t0, t1] of [0, D] below the medium's top (fog.md, "Empty space");
// t0 >= t1 when the ray crosses no medium.
void mediumInterval(const Model& m, const Ray& ray, double D, double& t0, double& t1) {
    t0 = 0.0;
    t1 = D;
    if (!m.skipEmptySpace) return;
    const double below = m.mediumTop - (m.camera.y - m.baseHeight);  // top above the camera
    if (ray.d.y == 0.0) {
        if (!(below > 0.0)) t1 = 0.0;
        return;
    }
    const double tCross = std::clamp(below / ray.d.y, 0.0, D);
    (ray.d.y > 0.0 ? t1 : t0) = tCross;
}

// March: D = min(D_s, max_distance), [t0, t1] its part inside the medium, Δ = (t1 - t0)/N; step k
// evaluates the medium at t = t0 + (k + 0.5)·Δ and holds σt and S(x) = σs·(E·p·V·Tsun + ambient) constant
// over its Δ.
void marchPixel(const Model& m, const Ray& ray, const dvec3& sunPhase, Radiance& r) {
    double t0, t1;
    mediumInterval(m, ray, std::min(ray.distance, m.maxDistance), t0, t1);
    if (!(t1 > t0)) return;
    const double dt = (t1 - t0) / m.steps;
    for (uint32_t k = 0; k < m.steps; ++k) {
        const dvec3 x = (t0 + (k + 0.5) * dt) * ray.d;
        const double h = detail::heightTerm(m.camera.y + x.y, m.heightFalloff, m.baseHeight);
        const double sigmaT = m.density * h * noiseAt(m, x);
        if (sigmaT == 0.0) continue;  // empty step: adds nothing, T unchanged
        dvec3 sun(0.0);               // V·Tsun; not looked up when the sun adds nothing
        if (sunPhase != dvec3(0.0)) {
            double v = detail::shadowVisibility(m.shadow, m.camera + x) *
                       detail::cloudShadowVisibility(m.cloudShadow, m.camera + x);
            if (m.selfShadow) v *= detail::sunTransmittance(m.density, h, m.heightFalloff, m.toSun.y);
            sun = v > 0.0 ? v * detail::atmosphereSunTransmittance(m, x) : dvec3(0.0);
        }
        addSegment(m, sunPhase * sun + m.ambient, sigmaT * dt, r);
    }
}

// Analytic tail over [max_distance, D_s]: height fog without noise or shadow map, light constant
// (E·p·Tsun(x(t0)) + ambient), optical depth τtail in closed form.
void tailContribution(const Model& m, const Ray& ray, const dvec3& sunPhase, Radiance& r) {
    const double t0 = m.maxDistance;
    const double exponent0 = detail::heightExponent(m.camera.y + t0 * ray.d.y, m.heightFalloff, m.baseHeight);
    const double a = m.heightFalloff * ray.d.y;
    const double tau = detail::tailOpticalDepth(m.density, exponent0, a, ray.distance - t0);
    double sun = 1.0;
    if (m.selfShadow)
        sun = detail::sunTransmittance(m.density, std::exp(exponent0), m.heightFalloff, m.toSun.y);
    const dvec3 atmosphere = detail::atmosphereSunTransmittance(m, t0 * ray.d);
    addSegment(m, sunPhase * sun * atmosphere + m.ambient, tau, r);
}

// (L, T) along a pixel's ray: the march, then the analytic tail beyond max_distance.
Radiance scatterAlong(const Model& m, const Ray& ray) {
    const dvec3 sunPhase = m.sunIlluminance * henyeyGreenstein(glm::dot(ray.d, m.toSun), m.g);  // E·p(cosθ)
    Radiance r;
    marchPixel(m, ray, sunPhase, r);
    if (m.analyticTail && ray.distance > m.maxDistance) tailContribution(m, ray, sunPhase, r);
    return r;
}

// Reduced resolution, as the GPU does it (raymarch_reduced.comp, upsample.comp): texel (i, j) of the
// w×h march marches the ray of pixel min(floor((i + 0.5)·W/w), W - 1) (same in y); each pixel blends the
// 2×2 texels around its centre whose surface distance is within kFogUpsampleDistanceTolerance of its
// own, with bilinear weights, or takes the texel of nearest distance when none is.
struct ReducedMarch {
    uint32_t w = 0, h = 0;
    std::vector<Radiance> scatter;  // w·h
    std::vector<double> distance;   // w·h: D_s of the texel's ray
};

uint32_t sourcePixel(uint32_t texel, uint32_t size, uint32_t marchSize) {
    return std::min(uint32_t((2ull * texel + 1) * size / (2ull * marchSize)), size - 1);
}

// Texel t0 left of (or at) the pixel centre, the next one t1 (clamped), and the weight f of t1.
void footprint(uint32_t pixel, uint32_t size, uint32_t marchSize, uint32_t& t0, uint32_t& t1, double& f) {
    const uint64_t num = (2ull * pixel + 1) * marchSize, den = 2ull * size;
    const uint64_t shifted = num >= size ? num - size : 0;
    t0 = uint32_t(std::min<uint64_t>(shifted / den, marchSize - 1));
    f = num >= size ? std::min(double(shifted - t0 * den) / double(den), 1.0) : 0.0;
    t1 = std::min(t0 + 1, marchSize - 1);
}

double distanceDifference(double a, double b) {
    return std::isinf(a) && std::isinf(b) ? 0.0 : std::abs(a - b);
}

Radiance upsample(const ReducedMarch& r, const Model& m, uint32_t i, uint32_t j, double distance) {
    uint32_t x0, x1, y0, y1;
    double fx, fy;
    footprint(i, m.width, r.w, x0, x1, fx);
    footprint(j, m.height, r.h, y0, y1, fy);
    const size_t texels[4] = {size_t(y0) * r.w + x0, size_t(y0) * r.w + x1, size_t(y1) * r.w + x0,
                              size_t(y1) * r.w + x1};
    const double bilinear[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    Radiance sum{dvec3(0.0), 0.0}, nearest;
    double weight = 0.0, nearestDifference = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
        const Radiance& s = r.scatter[texels[k]];
        const double difference = distanceDifference(r.distance[texels[k]], distance);
        if (!std::isinf(difference) && difference <= double(gpu::kFogUpsampleDistanceTolerance) * distance) {
            sum.L += bilinear[k] * s.L;
            sum.T += bilinear[k] * s.T;
            weight += bilinear[k];
        }
        if (k == 0 || difference < nearestDifference) {
            nearest = s;
            nearestDifference = difference;
        }
    }
    if (weight <= 0.0) return nearest;
    return {sum.L / weight, sum.T / weight};
}

}  // namespace

Status renderFog(const FogInputs& in, std::vector<float>& out) {
    if (Status s = validate(in); !s) return s;
    std::vector<float> result;  // not `out` directly: `in.color` may view it
    try {
        result.assign(in.color.begin(), in.color.end());
    } catch (const std::bad_alloc&) {
        return {Result::OutOfMemory, "reference::renderFog: cannot allocate the output image"};
    }
    // As on the GPU, an empty medium is not marched at all: the color stays as it is.
    if (in.settings.enabled && !common::fogMediumEmpty(in.settings, in.settings.noise.enabled)) {
        const Model m = makeModel(in);
        const glm::uvec2 size = fogMarchExtent(m.width, m.height, in.settings.resolutionScale);
        if (size.x == m.width && size.y == m.height) {
            common::parallelFor(m.height, in.threads, [&](uint32_t j) {
                for (uint32_t i = 0; i < m.width; ++i) {
                    const size_t p = size_t(j) * m.width + i;
                    composite(scatterAlong(m, pixelRay(m, i, j, in.depth[p])), &in.color[p * 4],
                              &result[p * 4]);
                }
            });
        } else {
            ReducedMarch r{size.x, size.y, {}, {}};
            try {
                r.scatter.resize(size_t(r.w) * r.h);
                r.distance.resize(size_t(r.w) * r.h);
            } catch (const std::bad_alloc&) {
                return {Result::OutOfMemory, "reference::renderFog: cannot allocate the reduced march"};
            }
            common::parallelFor(r.h, in.threads, [&](uint32_t j) {
                const uint32_t y = sourcePixel(j, m.height, r.h);
                for (uint32_t i = 0; i < r.w; ++i) {
                    const uint32_t x = sourcePixel(i, m.width, r.w);
                    const Ray ray = pixelRay(m, x, y, in.depth[size_t(y) * m.width + x]);
                    r.scatter[size_t(j) * r.w + i] = scatterAlong(m, ray);
                    r.distance[size_t(j) * r.w + i] = ray.distance;
                }
            });
            common::parallelFor(m.height, in.threads, [&](uint32_t j) {
                for (uint32_t i = 0; i < m.width; ++i) {
                    const size_t p = size_t(j) * m.width + i;
                    const double distance = pixelRay(m, i, j, in.depth[p]).distance;
                    composite(upsample(r, m, i, j, distance), &in.color[p * 4], &result[p * 4]);
                }
            });
        }
    }
    out.swap(result);
    return Status::success();
}

}  // namespace postfx::reference
