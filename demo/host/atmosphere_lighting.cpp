// The demo's surface lighting through the atmosphere (atmosphere_lighting.h).
#include "host/atmosphere_lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace demo {
namespace {

bool same(const postfx::AtmosphereSettings& a, const postfx::AtmosphereSettings& b) {
    return a.enabled == b.enabled && a.groundRadius == b.groundRadius && a.topRadius == b.topRadius &&
           a.rayleighScattering == b.rayleighScattering && a.rayleighScaleHeight == b.rayleighScaleHeight &&
           a.mieScattering == b.mieScattering && a.mieAbsorption == b.mieAbsorption &&
           a.mieScaleHeight == b.mieScaleHeight && a.mieAnisotropy == b.mieAnisotropy &&
           a.ozoneAbsorption == b.ozoneAbsorption && a.ozoneCenterHeight == b.ozoneCenterHeight &&
           a.ozoneHalfWidth == b.ozoneHalfWidth && a.groundAlbedo == b.groundAlbedo &&
           a.multipleScattering == b.multipleScattering && a.ambientFromSky == b.ambientFromSky;
    // The LUTs' sizes and counts and the sun disk change neither the CPU transmittance nor the irradiance.
}

glm::vec3 opticalDepth(const postfx::AtmosphereSettings& s, float altitude, const glm::vec3& toSun) {
    const postfx::Vec3 t =
        postfx::atmosphereSunTransmittance(s, postfx::DVec3(0.0, altitude, 0.0), postfx::Vec3(toSun));
    glm::vec3 tau;
    for (int c = 0; c < 3; ++c)
        tau[c] = t[c] > 0.0f ? std::min(-std::log(t[c]), kMaxOpticalDepth) : kMaxOpticalDepth;
    return tau;
}

}  // namespace

glm::vec2 sceneAltitudeRange(const Scene& scene) {
    float lo = std::numeric_limits<float>::infinity(), hi = -std::numeric_limits<float>::infinity();
    for (const Object& o : scene.objects) {
        float bottom = o.position.y, top = o.position.y;
        if (o.type == ObjectType::Box) {
            bottom -= o.halfSize.y;
            top += o.halfSize.y;
        } else if (o.type == ObjectType::Sphere) {
            bottom -= o.radius;
            top += o.radius;
        }
        lo = std::min(lo, bottom);
        hi = std::max(hi, top);
    }
    if (!(lo <= hi)) lo = hi = 0.0f;  // no objects
    lo = std::max(lo, 0.0f);
    hi = std::max(hi, lo + 1.0f);
    return {lo, hi};
}

const AtmosphereLighting& AtmosphereLightingCache::update(const Scene& scene) {
    const postfx::AtmosphereSettings& s = scene.atmosphere;
    result_.sky = s.enabled ? glm::vec3(0.0f) : scene.sky;
    if (!s.enabled) {
        result_.opticalDepthLow = result_.opticalDepthHigh = glm::vec3(0.0f);
        result_.ambient = scene.ambient;
        return result_;
    }
    const TransmittanceKey key{s, glm::normalize(scene.sun.direction), sceneAltitudeRange(scene)};
    const auto sameKey = [](const TransmittanceKey& a, const TransmittanceKey& b) {
        return same(a.settings, b.settings) && a.toSun == b.toSun && a.altitudes == b.altitudes;
    };
    if (!transmittanceKey_ || !sameKey(*transmittanceKey_, key)) {
        result_.altitudeLow = key.altitudes.x;
        result_.altitudeHigh = key.altitudes.y;
        result_.opticalDepthLow = opticalDepth(s, key.altitudes.x, key.toSun);
        result_.opticalDepthHigh = opticalDepth(s, key.altitudes.y, key.toSun);
        transmittanceKey_ = key;
        ++transmittanceUpdates_;
    }
    if (!s.ambientFromSky) {
        result_.ambient = scene.ambient;
        return result_;
    }
    if (!ambientKey_ || !sameKey(ambientKey_->transmittance, key) ||
        ambientKey_->sunIlluminance != scene.sun.illuminance) {
        const postfx::Vec3 e =
            postfx::atmosphereSkyIrradiance(s, postfx::DVec3(0.0, key.altitudes.x, 0.0),
                                            postfx::Vec3(key.toSun), postfx::Vec3(scene.sun.illuminance));
        skyAmbient_ = glm::vec3(e) / std::numbers::pi_v<float>;
        ambientKey_ = AmbientKey{key, scene.sun.illuminance};
        ++ambientUpdates_;
    }
    result_.ambient = skyAmbient_;
    return result_;
}

}  // namespace demo
