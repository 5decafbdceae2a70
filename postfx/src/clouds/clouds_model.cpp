#include "clouds/clouds_model.h"

#include <postfx/reference.h>
#include "clouds/clouds_shared.h"
#include "common/ray_sphere.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace postfx::clouds {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// (tNear, tFar) of ray o + t·d against the sphere of `radius` at the origin, (-1, -1) when it misses
// (as shaders/common/ray_sphere.glsl).
dvec2 raySphere(const dvec3& o, const dvec3& d, double radius) {
    const common::SphereHit hit = common::raySphere(o, d, radius);
    return hit.hit ? dvec2(hit.tNear, hit.tFar) : dvec2(-1.0);
}

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace

double NoiseVolume::sample(const dvec3& uvw) const {
    const double n = double(size);
    const dvec3 p = uvw * n - 0.5;
    const dvec3 f0 = glm::floor(p);
    const dvec3 f = p - f0;
    const auto wrap = [&](double v) {
        const auto i = int64_t(v) % int64_t(size);
        return uint32_t(i < 0 ? i + int64_t(size) : i);
    };
    double result = 0.0;
    for (int k = 0; k < 8; ++k) {
        const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
        const uint32_t x = wrap(f0.x + dx), y = wrap(f0.y + dy), z = wrap(f0.z + dz);
        const double w = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y) * (dz ? f.z : 1.0 - f.z);
        result += w * texels[(size_t(z) * size + y) * size + x];
    }
    return result;
}

double CoverageMapTexels::sample(const dvec2& uv) const {
    const dvec2 p = uv * dvec2(width, height) - 0.5;
    const dvec2 f0 = glm::floor(p);
    const dvec2 f = p - f0;
    const auto wrap = [](double v, uint32_t n) {
        const auto i = int64_t(v) % int64_t(n);
        return uint32_t(i < 0 ? i + int64_t(n) : i);
    };
    double result = 0.0;
    for (int k = 0; k < 4; ++k) {
        const int dx = k & 1, dy = k >> 1;
        const uint32_t x = wrap(f0.x + dx, width), y = wrap(f0.y + dy, height);
        result += (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y) * texels[size_t(y) * width + x];
    }
    return result;
}

bool followsPlanet(const FrameInfo& frame) {
    return frame.atmosphere.enabled && frame.clouds.shape == CloudShape::Layer;
}

glm::dvec2 heightRange(const CloudSettings& s) {
    if (s.shape == CloudShape::Box) return {-double(s.box.halfSize.y), double(s.box.halfSize.y)};
    return {s.bottomHeight, s.topHeight};
}

glm::dmat3 worldToBox(const CloudBox& box) {
    glm::dmat4 boxToWorld = glm::rotate(glm::dmat4(1.0), glm::radians(double(box.yawDeg)), {0.0, 1.0, 0.0});
    boxToWorld = glm::rotate(boxToWorld, glm::radians(double(box.pitchDeg)), {1.0, 0.0, 0.0});
    return glm::transpose(glm::dmat3(boxToWorld));
}

double topFalloff(double cloudType) {
    return gpu::kCloudTopFalloffStratus +
           (gpu::kCloudTopFalloffCumulus - gpu::kCloudTopFalloffStratus) * cloudType;
}

Model modelFrom(const FrameInfo& frame, NoiseVolume base, NoiseVolume detail, CoverageMapTexels coverageMap) {
    Model m;
    m.s = frame.clouds;
    const CloudSettings& s = m.s;
    m.camera = dvec3(frame.camera.position);
    m.curved = followsPlanet(frame);
    m.groundRadius = frame.atmosphere.groundRadius;
    const glm::dvec2 range = heightRange(s);
    m.bottom = range.x;
    m.top = range.y;
    m.worldToBox = worldToBox(s.box);
    m.boxCenter = dvec3(s.box.center);
    m.topFalloff = topFalloff(s.cloudType);
    m.noiseOrigin = m.camera - dvec3(s.wind) * frame.timeSeconds;
    m.base = base;
    m.detail = detail;
    m.coverageMap = coverageMap;
    m.toSun = glm::normalize(dvec3(frame.sun.toSun));
    m.sunIlluminance = dvec3(frame.sun.illuminance);
    m.ambient = dvec3(frame.ambient);
    m.slab = slabMedium(s);
    if (frame.atmosphere.enabled) m.atmosphere = common::makeAir(frame.atmosphere);
    return m;
}

dvec2 segment(const Model& m, const dvec3& x0, const dvec3& d, double far) {
    dvec2 seg(0.0, far);
    if (m.s.shape == CloudShape::Box) {
        const dvec3 o = m.worldToBox * (x0 + m.camera - m.boxCenter), dir = m.worldToBox * d;
        const dvec3 half(m.s.box.halfSize);
        for (int a = 0; a < 3; ++a) {
            if (dir[a] == 0.0) {
                if (o[a] < -half[a] || o[a] > half[a]) return {1.0, 0.0};
                continue;
            }
            const double t0 = (-half[a] - o[a]) / dir[a], t1 = (half[a] - o[a]) / dir[a];
            seg.x = std::max(seg.x, std::min(t0, t1));
            seg.y = std::min(seg.y, std::max(t0, t1));
        }
    } else if (m.curved) {
        const dvec3 o = m.camera + x0 + dvec3(0.0, m.groundRadius, 0.0);
        const dvec2 outer = raySphere(o, d, m.groundRadius + m.top);
        if (outer.y <= 0.0) return {1.0, 0.0};  // misses it or it lies behind
        seg = dvec2(std::max(seg.x, outer.x), std::min(seg.y, outer.y));
        const dvec2 inner = raySphere(o, d, m.groundRadius + m.bottom);
        if (inner.y > inner.x && inner.x <= seg.x && inner.y > seg.x) seg.x = inner.y;
        const dvec2 planet = raySphere(o, d, m.groundRadius);
        // A ray that meets the ground ends where it enters the bottom sphere (below the layer the field
        // is 0); the shader's cloudSegment says why.
        if (planet.y > planet.x && planet.x > 0.0) seg.y = std::min(seg.y, std::min(inner.x, planet.x));
    } else {
        const double y = m.camera.y + x0.y;
        if (d.y == 0.0) {
            if (y < m.bottom || y > m.top) return {1.0, 0.0};
        } else {
            const double ta = (m.bottom - y) / d.y, tb = (m.top - y) / d.y;
            seg = dvec2(std::max(seg.x, std::min(ta, tb)), std::min(seg.y, std::max(ta, tb)));
        }
    }
    return seg;
}

double heightFraction(const Model& m, const dvec3& x) {
    double altitude;
    if (m.s.shape == CloudShape::Box)
        altitude = (m.worldToBox * (x + m.camera - m.boxCenter)).y;
    else if (m.curved)
        altitude = glm::length(m.camera + x + dvec3(0.0, m.groundRadius, 0.0)) - m.groundRadius;
    else
        altitude = m.camera.y + x.y;
    return (altitude - m.bottom) / (m.top - m.bottom);
}

double heightProfile(const Model& m, double h) {
    return clamp01(h / gpu::kCloudBottomRamp) * clamp01((1.0 - h) / m.topFalloff);
}

double field(const Model& m, const dvec3& x, double h) {
    if (h < -gpu::kCloudHeightSlack || h > 1.0 + gpu::kCloudHeightSlack) return 0.0;
    h = clamp01(h);
    const dvec3 world = m.noiseOrigin + x;
    double map = 1.0;  // the host's coverage map at the point's world (x, z)
    if (m.coverageMap.present()) {
        const CloudCoverageMap& c = m.s.coverageMap;
        // A negative size runs v along -z (settingsToPostfx).
        map = m.coverageMap.sample(dvec2(world.x - c.originX, world.z - c.originZ) /
                                   dvec2(std::abs(double(c.size)), double(c.size)));
        if (!(map > 0.0)) return 0.0;
    }
    if (!m.s.noise.enabled) return map;
    const double coverage = m.s.coverage * map;
    const double basePeriod = m.s.noise.tiling;
    const double detailPeriod = basePeriod / gpu::kCloudDetailTilingRatio;
    const double shape = m.base.sample(world / basePeriod) * heightProfile(m, h);
    const double f = clamp01((shape - (1.0 - coverage)) / coverage);
    if (f <= 0.0 || m.s.noise.detailStrength <= 0.0f) return f;
    const double e = m.s.noise.detailStrength * m.detail.sample(world / detailPeriod);
    return clamp01((f - e) / std::max(1.0 - e, 1e-6));
}

double extinction(const Model& m, const dvec3& x) {
    return m.s.density * field(m, x, heightFraction(m, x));
}

double sunOpticalDepth(const Model& m, const dvec3& x, uint32_t steps) {
    const dvec2 seg = segment(m, x, m.toSun, m.s.lightDistance);
    const double length = seg.y > seg.x ? std::max(seg.y, 0.0) : 0.0;
    if (length <= 0.0) return 0.0;
    // Step k spans [(k/n)², ((k+1)/n)²]·length, sampled at its middle (lighting.glsl).
    const double n2 = double(steps) * steps;
    double tau = 0.0;
    for (uint32_t k = 0; k < steps; ++k) {
        const double a = double(k) * k / n2, b = double(k + 1) * (k + 1) / n2;
        tau += extinction(m, x + m.toSun * (0.5 * (a + b) * length)) * ((b - a) * length);
    }
    return tau;
}

double phase(const Model& m, const dvec3& d, double scale) {
    const double c = glm::dot(d, m.toSun);
    const double forward = reference::henyeyGreenstein(c, m.s.anisotropyForward * scale);
    const double back = reference::henyeyGreenstein(c, m.s.anisotropyBack * scale);
    return forward + (back - forward) * m.s.lobeMix;
}

SlabMedium slabMedium(const CloudSettings& s) {
    SlabMedium r;
    const double gf = s.anisotropyForward, gb = s.anisotropyBack, mix = s.lobeMix;
    r.g = gf + (gb - gf) * mix;
    r.f = gf * gf + (gb * gb - gf * gf) * mix;
    const double w = s.albedo;
    r.depthScale = 1.0 - w * r.f;
    r.albedo = w * (1.0 - r.f) / r.depthScale;
    r.asymmetry = (r.g - r.f) / (1.0 - r.f);
    return r;
}

glm::dvec2 slabDiffuse(const SlabMedium& medium, double tt, double tb, double mu0, double beam,
                       double farBeam) {
    // As lighting.glsl's cloudSlabDiffuse, which says why; in double the sinh forms need no rewriting,
    // but the same guards keep the two alike.
    const double w = medium.albedo, g = medium.asymmetry;
    const double k = std::max(std::sqrt(std::max(3.0 * (1.0 - w) * (1.0 - w * g), 0.0)), 1e-6);
    const double tau0 = std::max(tt + tb, 1e-6);
    double pole = 1.0 - k * k * mu0 * mu0;
    const double gap = gpu::kCloudSlabPoleGap;
    if (std::abs(pole) < gap) pole = pole < 0.0 ? -gap : gap;
    const double A = -3.0 * w * (1.0 + g * (1.0 - w)) * mu0 * mu0 / pole;
    const double D = 3.0 * (1.0 - w * g), B = 3.0 * w * g * mu0;
    const double q0 = -std::expm1(-2.0 * k * tau0);
    const double et = std::exp(-k * tt), eb = std::exp(-k * tb), e0 = et * eb;
    const double u1 = et * -std::expm1(-2.0 * k * tb) / q0, u2 = eb * -std::expm1(-2.0 * k * tt) / q0;
    const double u1d = -k * et * (1.0 + eb * eb) / q0, u2d = k * eb * (1.0 + et * et) / q0;
    const double c = k * (1.0 + e0 * e0) / q0, sn = 2.0 * k * e0 / q0;
    const double p = 1.0 + 2.0 * c / D, q = 2.0 * sn / D;
    const double pMinusQ = 1.0 + 2.0 * k * -std::expm1(-k * tau0) / ((1.0 + e0) * D);
    const double top = B + A / mu0;
    const double r1 = -A - 2.0 * top / D, r2 = farBeam * (-A + 2.0 * top / D);
    const double common = p / (p + q) * (r1 + r2) / pMinusQ;
    const double a = common - r2 / (p + q), b = common - r1 / (p + q);
    const double U = a * u1 + b * u2 + A * beam;
    const double slope =
        common * k * (eb - et) / (1.0 + e0) - (r2 * u1d + r1 * u2d) / (p + q) - A / mu0 * beam;
    const double F = (B * beam - slope) / D;
    return {std::max(U, 0.0), F};
}

dvec3 slabNormal(const Model& m, const dvec3& x) {
    if (m.s.shape == CloudShape::Box) return glm::transpose(m.worldToBox)[1];
    if (m.curved) return glm::normalize(m.camera + x + dvec3(0.0, m.groundRadius, 0.0));
    return {0.0, 1.0, 0.0};
}

double slabAmbientTerm(const Model& m, const dvec3& n, const dvec3& d, double sigma, double h) {
    // As lighting.glsl's cloudSlabAmbient, which says why.
    const SlabMedium& medium = m.slab;
    const double w = medium.albedo, g = medium.asymmetry;
    const double k = std::max(std::sqrt(std::max(3.0 * (1.0 - w) * (1.0 - w * g), 0.0)), 1e-6);
    const double D = 3.0 * (1.0 - w * g);
    const double hc = clamp01(h), thickness = m.top - m.bottom;
    const double tt = medium.depthScale * sigma * (1.0 - hc) * thickness;
    const double tb = medium.depthScale * sigma * hc * thickness;
    const double et = std::exp(-k * tt), eb = std::exp(-k * tb), e0 = et * eb;
    const double den = 0.25 * (1.0 + e0) + k / (2.0 * D) * -std::expm1(-k * (tt + tb));
    const double U = kPi * (et + eb) / den;
    const double F = -kPi * k * (eb - et) / (D * den);
    return std::max(U + 3.0 * medium.g * F * glm::dot(d, n), 0.0) / (4.0 * kPi);
}

double slabSunTerm(const Model& m, dvec3 n, const dvec3& d, double sigma, double h, double tau) {
    const double cosSun = glm::dot(n, m.toSun);
    const double hc = clamp01(h);
    const double beyond = sigma * (m.top - m.bottom) * (cosSun >= 0.0 ? hc : 1.0 - hc);
    if (cosSun < 0.0) n = -n;
    const double mu0 = std::max(std::abs(cosSun), double(gpu::kCloudSlabMinCosine));
    const SlabMedium& medium = m.slab;
    const double direct = std::exp(-tau), beam = std::exp(-medium.depthScale * tau);
    const double tt = medium.depthScale * tau * mu0, tb = medium.depthScale * beyond;
    const glm::dvec2 UF = slabDiffuse(medium, tt, tb, mu0, beam, beam * std::exp(-tb / mu0));
    const double diffuse = std::max(UF.x + 3.0 * medium.g * UF.y * glm::dot(d, n), 0.0) / (4.0 * kPi);
    return phase(m, d, 1.0) * direct + phase(m, d, medium.g) * (beam - direct) + diffuse;
}

dvec3 inScattered(const Model& m, const dvec3& x, const dvec3& d, double sigma, double h,
                  uint32_t lightSteps) {
    const double tau = sunOpticalDepth(m, x, lightSteps);
    const CloudMultipleScattering& ms = m.s.multipleScattering;
    const bool slab = ms.model == CloudScatteringModel::Slab;
    const dvec3 n = slab ? slabNormal(m, x) : dvec3(0.0);
    double sunTerm = 0.0, a = 1.0, b = 1.0, c = 1.0;
    if (slab) {
        sunTerm = slabSunTerm(m, n, d, sigma, h, tau);
    } else {
        for (uint32_t i = 0; i < ms.octaves; ++i) {
            sunTerm += b * phase(m, d, c) * std::exp(-a * tau);
            a *= ms.attenuation;
            b *= ms.contribution;
            c *= ms.eccentricity;
        }
    }
    dvec3 sun = m.sunIlluminance;
    if (m.atmosphere) {
        sun *= m.atmosphere->sunTransmittance(m.camera + x, m.toSun, false);
    }
    const double thickness = m.top - m.bottom;
    const double hc = clamp01(h);
    const double ambient = slab ? slabAmbientTerm(m, n, d, sigma, h)
                                : 0.5 * (std::exp(-gpu::kCloudDiffusivity * sigma * (1.0 - hc) * thickness) +
                                         std::exp(-gpu::kCloudDiffusivity * sigma * hc * thickness));
    return sun * sunTerm + m.ambient * ambient;
}

MarchResult march(const Model& m, const dvec3& d, double far, uint32_t steps, double offset,
                  uint32_t lightSteps) {
    MarchResult r;
    const dvec2 seg = segment(m, dvec3(0.0), d, far);
    if (!(seg.y > seg.x)) return r;
    const double dt = (seg.y - seg.x) / steps;
    double weighted = 0.0, weightSum = 0.0;
    for (uint32_t i = 0; i < steps; ++i) {
        const double t = seg.x + (i + offset) * dt;
        const dvec3 x = d * t;
        const double h = heightFraction(m, x);
        const double sigma = m.s.density * field(m, x, h);
        if (sigma <= 0.0) continue;
        const double opticalDepth = sigma * dt;
        const dvec3 light = inScattered(m, x, d, sigma, h, lightSteps);
        // T·S·(1 - e^{-σt·Δ})/σt with S = albedo·σt·light: the density once.
        r.luminance += r.transmittance * m.s.albedo * light * -std::expm1(-opticalDepth);
        // Each step weighted by the light it removes, T·(1 - e^{-σΔ}) (as march.comp).
        const double removed = r.transmittance * -std::expm1(-opticalDepth);
        weighted += t * removed;
        weightSum += removed;
        r.transmittance *= std::exp(-opticalDepth);
    }
    if (weightSum > 0.0) r.meanDistance = weighted / weightSum;
    return r;
}

}  // namespace postfx::clouds
