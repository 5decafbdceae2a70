// Double-precision CPU reference of the froxel fog (docs/effects/froxel-fog.md): the shared medium plus
// local fog volumes, lit by the sun, ambient and local lights, evaluated continuously along each pixel's
// ray with a converged midpoint march (no grid, no jitter), then the ray-marched fog's analytic tail.
#include "common/medium.h"
#include "common/parallel.h"
#include "common/reference_image.h"
#include "common/reference_model.h"
#include "core/checks.h"

#include <postfx/reference.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace postfx::reference {
namespace {

using glm::dvec3;

using core::invalid;
using detail::checkCount;

constexpr double kPi = 3.14159265358979323846;

Status validate(const FroxelFogInputs& in) {
    if (Status s = detail::checkImage("FroxelFogInputs", in.width, in.height, in.color, in.depth); !s)
        return s;
    if (Status s = validateFroxelFogSettings(in.settings); !s) return s;
    if (in.lights.size() > kMaxLocalLights)
        return invalid("FroxelFogInputs.lights: " + std::to_string(in.lights.size()) +
                       " lights exceed kMaxLocalLights (" + std::to_string(kMaxLocalLights) + ")");
    for (size_t i = 0; i < in.lights.size(); ++i) {
        const std::string n = "FroxelFogInputs.lights[" + std::to_string(i) + "]";
        if (Status s = core::checkLight(in.lights[i], n); !s) return s;
        if (in.lights[i].shadow != kNoLocalShadow && in.lights[i].shadow >= in.localShadows.size())
            return invalid(n + ".shadow: " + std::to_string(in.lights[i].shadow) +
                           " is neither kNoLocalShadow nor below localShadows' size (" +
                           std::to_string(in.localShadows.size()) + ")");
    }
    if (!in.localShadows.empty()) {
        if (in.localShadowDepth.size() != size_t(in.localShadowWidth) * in.localShadowHeight ||
            in.localShadowDepth.empty())
            return invalid("FroxelFogInputs.localShadowDepth: " + std::to_string(in.localShadowDepth.size()) +
                           " texels for a " + std::to_string(in.localShadowWidth) + "x" +
                           std::to_string(in.localShadowHeight) + " atlas");
        if (Status s = core::checkLocalShadowList(in.localShadows.data(), uint32_t(in.localShadows.size()),
                                                  in.localShadowWidth, in.localShadowHeight,
                                                  in.camera.position, "FroxelFogInputs.localShadows");
            !s)
            return s;
    }
    return detail::checkMediumInputs("FroxelFogInputs", "froxel_fog", in);
}

double smoothstep(double e0, double e1, double x) {
    if (!(e1 > e0)) return x >= e1 ? 1.0 : 0.0;  // hard step where the two edges meet
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A local light's shadow as the reference reads it (LocalShadow, camera-relative).
struct ShadowModel {
    uint32_t faceCount = 0;
    glm::dmat4 clip[kMaxLocalShadowFaces];  // camera-relative position -> the face's clip space
    glm::uvec2 offset[kMaxLocalShadowFaces], extent[kMaxLocalShadowFaces];
    bool reversedZ = false;
    double bias = 0.0;
};

// Everything the march reads, converted to double once.
struct Model : detail::MediumModel {
    std::vector<FogVolume> volumes;  // centres made camera-relative
    std::vector<LocalLight> lights;  // positions made camera-relative
    std::vector<ShadowModel> shadows;
    std::span<const float> atlas;  // the local shadow atlas, row-major
    uint32_t atlasWidth = 0;
    bool filterShadows = false;
};

Model makeModel(const FroxelFogInputs& in) {
    const FroxelFogSettings& s = in.settings;
    Model m;
    // An empty shared medium (common::fogMediumEmpty) has no extinction: the volumes may still have some.
    detail::fillMediumModel(m, in, s, 1);  // the froxel fog filters no shadow kernel
    if (common::fogMediumEmpty(s, s.noise.enabled)) m.density = 0.0;  // the tail's included
    for (uint32_t i = 0; i < s.volumeCount; ++i) {
        FogVolume v = s.volumes[i];
        if (v.density <= 0.0f) continue;
        v.center = DVec3(dvec3(v.center) - m.camera);
        m.volumes.push_back(v);
    }
    for (const LocalLight& l : in.lights)
        if (l.intensity != Vec3(0.0f)) {
            LocalLight relative = l;
            relative.position = DVec3(dvec3(l.position) - m.camera);
            m.lights.push_back(relative);
        }
    const glm::dmat4 fromCamera = glm::translate(glm::dmat4(1.0), m.camera);
    for (const LocalShadow& s : in.localShadows) {
        ShadowModel& sm = m.shadows.emplace_back();
        sm.faceCount = s.faceCount;
        sm.reversedZ = s.reversedZ;
        sm.bias = s.depthBias;
        for (uint32_t f = 0; f < s.faceCount; ++f) {
            sm.clip[f] = glm::dmat4(s.faces[f].worldToClip) * fromCamera;
            sm.offset[f] = glm::uvec2(s.faces[f].offset);
            sm.extent[f] = glm::uvec2(s.faces[f].extent);
        }
    }
    m.atlas = in.localShadowDepth;
    m.atlasWidth = in.localShadowWidth;
    m.filterShadows = s.localShadowFilter;
    return m;
}

// One tap (LocalShadow's rule, the sun's): inside [0, 1] the comparison with the bias; beyond the far
// plane shadowed where the texel holds a caster (not the cleared far value); z before the near plane is
// the caller's (lit).
bool localShadowTapLit(const ShadowModel& s, double z, double stored) {
    if (s.reversedZ) return z < 0.0 ? stored <= 0.0 : z + s.bias >= stored;
    return z > 1.0 ? stored >= 1.0 : z - s.bias <= stored;
}

// V(x) of a light's shadow at camera-relative x (the GPU's localShadowVisibility, in double): the first
// face whose clip square holds x; one texel, or the 2×2 texels around it weighted bilinearly (indices
// clamped to the region); 1 before the near plane or when no face holds x.
double localShadowVisibility(const Model& m, const ShadowModel& s, const dvec3& x) {
    for (uint32_t f = 0; f < s.faceCount; ++f) {
        const glm::dvec4 c = s.clip[f] * glm::dvec4(x, 1.0);
        if (!(c.w > 0.0) || std::abs(c.x) > c.w || std::abs(c.y) > c.w) continue;
        const double z = c.z / c.w;
        if (s.reversedZ ? !(z <= 1.0) : !(z >= 0.0)) return 1.0;
        const double u = c.x / c.w * 0.5 + 0.5, v = c.y / c.w * 0.5 + 0.5;
        const int w = int(s.extent[f].x), h = int(s.extent[f].y);
        auto tap = [&](int i, int j) {
            i = std::clamp(i, 0, w - 1);
            j = std::clamp(j, 0, h - 1);
            const size_t texel =
                size_t(s.offset[f].y + uint32_t(j)) * m.atlasWidth + s.offset[f].x + uint32_t(i);
            return localShadowTapLit(s, z, double(m.atlas[texel])) ? 1.0 : 0.0;
        };
        if (!m.filterShadows) return tap(int(u * w), int(v * h));
        const double pu = u * w - 0.5, pv = v * h - 0.5;
        const int i0 = int(std::floor(pu)), j0 = int(std::floor(pv));
        const double fu = pu - i0, fv = pv - j0;
        return (1.0 - fu) * (1.0 - fv) * tap(i0, j0) + fu * (1.0 - fv) * tap(i0 + 1, j0) +
               (1.0 - fu) * fv * tap(i0, j0 + 1) + fu * fv * tap(i0 + 1, j0 + 1);
    }
    return 1.0;
}

// Shared medium's extinction at camera-relative x: density·h(y)·noise(x) (the ray-marched fog's σt).
double mediumExtinction(const Model& m, const dvec3& x, double& h) {
    h = detail::heightTerm(m.camera.y + x.y, m.heightFalloff, m.baseHeight);
    if (m.density == 0.0) return 0.0;
    double noise = 1.0;
    if (m.noise) {
        const double n = detail::sampleNoise(m.noiseTexels, m.noiseSize, m.noiseOrigin + x * m.noiseScale);
        noise = std::clamp(n - m.noiseThreshold, 0.0, 1.0) * m.noiseMultiplier;
    }
    return m.density * h * noise;
}

// In-scattered radiance per unit σs from the local lights at camera-relative x, seen along d:
// Σ E_i(x)·p(cos θ_i), θ_i between the light's direction of travel and the direction toward the camera
// (cos θ_i = d · toLight, as the sun's d · toSun). Fog between the light and x does not attenuate it.
dvec3 localLights(const Model& m, const dvec3& x, const dvec3& d) {
    dvec3 sum(0.0);
    for (const LocalLight& l : m.lights) {
        const dvec3 toLight = dvec3(l.position) - x;
        const double distance = glm::length(toLight);
        // At the light itself the direction is undefined: isotropic there.
        const double phase =
            distance > 0.0 ? henyeyGreenstein(glm::dot(d, toLight / distance), m.g) : 1.0 / (4.0 * kPi);
        const dvec3 e = dvec3(localLightIlluminance(l, DVec3(x)));
        if (e == dvec3(0.0)) continue;
        const double v = l.shadow != kNoLocalShadow && !m.shadows.empty()
                             ? localShadowVisibility(m, m.shadows[l.shadow], x)
                             : 1.0;
        sum += phase * v * e;
    }
    return sum;
}

struct Radiance {
    dvec3 L{0.0};
    double T = 1.0;
};

// L += T·albedo·light·(1 - e^{-τ}); T *= e^{-τ} (fog_reference.cpp's step: exact, 0 at σt = 0).
void addSegment(const Model& m, const dvec3& light, double tau, Radiance& r) {
    r.L += r.T * m.albedo * light * -std::expm1(-tau);
    r.T *= std::exp(-tau);
}

// March [0, D], D = min(D_s, max_distance): N midpoint steps, σt and the source held over each.
void marchPixel(const Model& m, const detail::PixelRay& ray, const dvec3& sunPhase, Radiance& r) {
    const double D = std::min(ray.distance, m.maxDistance);
    const double dt = D / m.steps;
    for (uint32_t k = 0; k < m.steps; ++k) {
        const dvec3 x = (k + 0.5) * dt * ray.d;
        double h;
        double sigmaT = mediumExtinction(m, x, h);
        for (const FogVolume& v : m.volumes)
            sigmaT += double(v.density) * fogVolumeWeight(v, DVec3(x));
        if (sigmaT == 0.0) continue;
        dvec3 sun(0.0);
        if (sunPhase != dvec3(0.0)) {
            double v = detail::shadowVisibility(m.shadow, m.camera + x) *
                       detail::cloudShadowVisibility(m.cloudShadow, m.camera + x);
            if (m.selfShadow) v *= detail::sunTransmittance(m.density, h, m.heightFalloff, m.toSun.y);
            sun = v > 0.0 ? v * detail::atmosphereSunTransmittance(m, x) : dvec3(0.0);
        }
        addSegment(m, sunPhase * sun + m.ambient + localLights(m, x, ray.d), sigmaT * dt, r);
    }
}

// The ray-marched fog's analytic tail beyond max_distance: the shared medium's height fog without noise,
// shadow map, volumes or local lights (fog_reference.cpp's tailContribution).
void tailContribution(const Model& m, const detail::PixelRay& ray, const dvec3& sunPhase, Radiance& r) {
    const double t0 = m.maxDistance;
    const double exponent0 = detail::heightExponent(m.camera.y + t0 * ray.d.y, m.heightFalloff, m.baseHeight);
    const double tau =
        detail::tailOpticalDepth(m.density, exponent0, m.heightFalloff * ray.d.y, ray.distance - t0);
    double sun = 1.0;
    if (m.selfShadow)
        sun = detail::sunTransmittance(m.density, std::exp(exponent0), m.heightFalloff, m.toSun.y);
    const dvec3 atmosphere = detail::atmosphereSunTransmittance(m, t0 * ray.d);
    addSegment(m, sunPhase * sun * atmosphere + m.ambient, tau, r);
}

Radiance scatterAlong(const Model& m, const detail::PixelRay& ray) {
    const dvec3 sunPhase = m.sunIlluminance * henyeyGreenstein(glm::dot(ray.d, m.toSun), m.g);
    Radiance r;
    marchPixel(m, ray, sunPhase, r);
    if (m.analyticTail && ray.distance > m.maxDistance && m.density > 0.0)
        tailContribution(m, ray, sunPhase, r);
    return r;
}

}  // namespace

Vec3 localLightIlluminance(const LocalLight& s, const DVec3& x) {
    const dvec3 fromLight = dvec3(x) - dvec3(s.position);
    const double distance = glm::length(fromLight);
    if (!(distance < double(s.range))) return Vec3(0.0f);
    const double r = s.sourceRadius, q = distance / double(s.range);
    const double window = (1.0 - q * q * q * q) * (1.0 - q * q * q * q);
    double cone = 1.0;
    if (s.type == LightType::Spot) {
        const dvec3 axis = glm::normalize(dvec3(s.direction));
        const double cosAngle = distance > 0.0 ? glm::dot(fromLight / distance, axis) : 1.0;
        cone = smoothstep(std::cos(double(s.outerConeAngle)), std::cos(double(s.innerConeAngle)), cosAngle);
    }
    return Vec3(dvec3(s.intensity) * (cone * window / (distance * distance + r * r)));
}

double fogVolumeWeight(const FogVolume& v, const DVec3& x) {
    const dvec3 p = dvec3(x) - dvec3(v.center);
    double depth;  // distance inside the surface, <= 0 outside
    if (v.shape == FogVolumeShape::Sphere) {
        depth = double(v.radius) - glm::length(p);
    } else {
        const dvec3 inside = dvec3(v.halfSize) - glm::abs(p);
        depth = std::min({inside.x, inside.y, inside.z});
    }
    if (!(depth > 0.0)) return 0.0;
    return v.edgeFalloff > 0.0f ? smoothstep(0.0, double(v.edgeFalloff), depth) : 1.0;
}

Status renderFroxelFog(const FroxelFogInputs& in, std::vector<float>& out) {
    if (Status s = validate(in); !s) return s;
    std::vector<float> result;  // not `out` directly: `in.color` may view it
    try {
        result.assign(in.color.begin(), in.color.end());
    } catch (const std::bad_alloc&) {
        return {Result::OutOfMemory, "reference::renderFroxelFog: cannot allocate the output image"};
    }
    if (in.settings.enabled) {
        Model m;
        try {
            m = makeModel(in);
        } catch (const std::bad_alloc&) {
            return {Result::OutOfMemory,
                    "reference::renderFroxelFog: cannot allocate the lights and volumes"};
        }
        const bool empty =
            common::fogMediumEmpty(in.settings, in.settings.noise.enabled) && m.volumes.empty();
        if (!empty)
            common::parallelFor(m.height, in.threads, [&](uint32_t j) {
                for (uint32_t i = 0; i < m.width; ++i) {
                    const size_t p = size_t(j) * m.width + i;
                    const detail::PixelRay ray =
                        detail::pixelRay(m.clipToView, m.farDepth, m.width, m.height, i, j, in.depth[p]);
                    const Radiance r = scatterAlong(m, ray);
                    detail::composite(r.L, r.T, &in.color[p * 4], &result[p * 4]);
                }
            });
    }
    out.swap(result);
    return Status::success();
}

}  // namespace postfx::reference
