// The image side of the CPU references, shared by the ray-marched fog's (fog_reference.cpp) and the
// froxel fog's (froxel_fog/froxel_reference.cpp): pixel rays, the composite, the shared medium.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/clouds.h>
#include <postfx/fog.h>
#include <postfx/inputs.h>

#include <postfx/result.h>
#include "common/air.h"
#include "common/reference_model.h"
#include "core/checks.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace postfx::reference::detail {

// InvalidArgument "<field>: <count> values, expected <expected> (<what>)" unless count == expected.
Status checkCount(const char* field, size_t count, uint64_t expected, const char* what);

// The image a reference composites onto (`prefix`: "FogInputs", "CloudInputs", ...): a non-empty
// width×height, color of width·height·4 values, depth of width·height finite values.
Status checkImage(const std::string& prefix, uint32_t width, uint32_t height, std::span<const float> color,
                  std::span<const float> depth);

// The clouds' shadow map of a reference's inputs (`prefix`: "FogInputs", "FroxelFogInputs"), when given:
// width·height texels, each finite, and finite rows.
Status checkCloudShadow(const char* prefix, std::span<const float> texels, uint32_t width, uint32_t height,
                        const CloudShadowTransform& rows);

// Checks what both fogs' references read besides their settings (FogInputs, FroxelFogInputs: the same
// field names; `prefix` their type's name, `effect` the settings' scene-file key): light, camera, time,
// steps, the noise when on, the shadow map when given, the clouds' shadow map.
template <class Inputs>
Status checkMediumInputs(const std::string& prefix, const char* effect, const Inputs& in);

// Rotation-only view: the view matrix with its translation column zeroed (the march is camera-relative).
glm::dmat4 clipToView(const CameraInput& camera);

struct PixelRay {
    glm::dvec3 d;     // unit direction, camera-relative world space
    double distance;  // D_s: to the surface, ∞ for no geometry
};

// Ray: ndc of the pixel centre, p = clipToView · (ndc, z, 1), x_s = p.xyz / p.w, D_s = |x_s|, d = x_s / D_s.
// No geometry (z exactly `farDepth`): d from z = 0.5, D_s = ∞.
PixelRay pixelRay(const glm::dmat4& clipToView, double farDepth, uint32_t width, uint32_t height, uint32_t i,
                  uint32_t j, double z);

// Composite: out.rgb = color.rgb · T + L, out.a = color.a, as the GPU does it
// (shaders/common/composite.glsl): ±Inf color counts as ±FLT_MAX, the result is clamped to ±FLT_MAX, a NaN
// channel stays NaN.
void composite(const glm::dvec3& L, double T, const float* color, float* out);

// What both references' marches read of the shared medium and the frame, converted to double once.
struct MediumModel {
    glm::dmat4 clipToView;
    double farDepth;  // depth value of "no geometry": 0 reversed Z, 1 standard Z
    uint32_t width, height, steps;
    glm::dvec3 camera;
    double density, heightFalloff, baseHeight, maxDistance;
    glm::dvec3 albedo, sunIlluminance, toSun, ambient;
    double g;
    bool selfShadow, analyticTail, noise;
    std::span<const float> noiseTexels;
    uint32_t noiseSize;
    glm::dvec3 noiseOrigin;  // noise coordinate of the camera, wrapped to [0, 1)
    double noiseScale, noiseThreshold, noiseMultiplier;
    ShadowMap shadow;
    CloudShadowMap cloudShadow;  // the clouds' (their transmittance toward the sun); empty: none
    // The air (inputs' atmosphere.enabled): the sun's transmittance through it, null when off.
    std::shared_ptr<const common::Air> atmosphere;
};

// The atmosphere's transmittance toward the sun at camera-relative x: the table's at the planet-centred
// position clamped above the ground; 1 without an atmosphere.
inline glm::dvec3 atmosphereSunTransmittance(const MediumModel& m, const glm::dvec3& x) {
    if (!m.atmosphere) return glm::dvec3(1.0);
    return m.atmosphere->sunTransmittance(m.camera + x, m.toSun, true);
}

// Fills `m` from a reference's inputs (FogInputs, FroxelFogInputs: the same field names) and its medium.
template <class Inputs>
void fillMediumModel(MediumModel& m, const Inputs& in, const FogMedium& s, uint32_t shadowKernel) {
    m.clipToView = clipToView(in.camera);
    m.farDepth = in.depthConvention.reversedZ ? 0.0 : 1.0;
    m.width = in.width;
    m.height = in.height;
    m.steps = in.stepsPerPixel;
    m.camera = glm::dvec3(in.camera.position);
    m.density = s.density;
    m.heightFalloff = s.heightFalloff;
    m.baseHeight = s.baseHeight;
    m.maxDistance = s.maxDistance;
    m.albedo = glm::dvec3(s.albedo);
    m.sunIlluminance = glm::dvec3(in.sun.illuminance);
    m.toSun = glm::normalize(glm::dvec3(in.sun.toSun));
    m.ambient = glm::dvec3(in.ambient);
    m.g = s.anisotropy;  // clamped by henyeyGreenstein
    m.selfShadow = s.selfShadow;
    m.analyticTail = s.analyticTail;
    m.noise = s.noise.enabled;
    m.noiseTexels = in.noise;
    m.noiseSize = in.noiseSize;
    m.noiseScale = 0.01 * double(s.noise.tiling);
    // u = (x_world - wind·time) · 0.01 · tiling with x_world = camera + x: the camera's part, wrapped.
    const glm::dvec3 origin = (m.camera - glm::dvec3(s.noise.wind) * in.timeSeconds) * m.noiseScale;
    m.noiseOrigin = origin - glm::floor(origin);
    m.noiseThreshold = s.noise.threshold;
    m.noiseMultiplier = s.noise.multiplier;
    m.shadow = {in.shadowDepth,       in.shadowWidth,     in.shadowHeight,
                in.shadowWorldToClip, in.shadowReversedZ, double(in.shadowDepthBias),
                shadowKernel};
    m.cloudShadow = {in.cloudShadow, in.cloudShadowWidth, in.cloudShadowHeight,
                     glm::dvec4(in.cloudShadowRows.u), glm::dvec4(in.cloudShadowRows.v)};
    m.atmosphere = nullptr;
    if (in.atmosphere.enabled) m.atmosphere = common::makeAir(in.atmosphere);
}

template <class Inputs>
Status checkMediumInputs(const std::string& prefix, const char* effect, const Inputs& in) {
    using core::invalid;
    if (Status s = core::checkLighting(in.sun, in.ambient, ""); !s) return s;
    if (Status s = validateAtmosphereSettings(in.atmosphere); !s) return s;
    if (Status s = core::checkCamera(in.camera, "camera"); !s) return s;
    if (!core::allFinite(clipToView(in.camera)))
        return invalid("camera.projection: projection · view rotation is not invertible");
    if (Status s = core::checkTime(in.timeSeconds, prefix + ".timeSeconds"); !s) return s;
    if (in.stepsPerPixel == 0) return invalid(prefix + ".stepsPerPixel: 0 must be >= 1");
    if (in.settings.noise.enabled) {
        if (in.noiseSize == 0) return invalid(prefix + ".noiseSize: 0 with " + effect + ".noise enabled");
        const uint64_t n = in.noiseSize;
        if (Status s = checkCount((prefix + ".noise").c_str(), in.noise.size(), n * n * n, "noiseSize³"); !s)
            return s;
    }
    if (!in.shadowDepth.empty()) {
        const uint64_t texels = uint64_t(in.shadowWidth) * in.shadowHeight;
        if (Status s = checkCount((prefix + ".shadowDepth").c_str(), in.shadowDepth.size(), texels,
                                  "shadowWidth·shadowHeight");
            !s)
            return s;
        if (Status s = core::checkShadowTransform(in.shadowWorldToClip, in.camera.position,
                                                  prefix + ".shadowWorldToClip");
            !s)
            return s;
        if (!(in.shadowDepthBias >= 0.0f) || !std::isfinite(in.shadowDepthBias))
            return invalid(prefix + ".shadowDepthBias: " + std::to_string(in.shadowDepthBias) +
                           " must be finite and >= 0");
    }
    return checkCloudShadow(prefix.c_str(), in.cloudShadow, in.cloudShadowWidth, in.cloudShadowHeight,
                            in.cloudShadowRows);
}

}  // namespace postfx::reference::detail
