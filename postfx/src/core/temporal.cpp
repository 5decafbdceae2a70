#include "core/temporal.h"

#include "core/camera_math.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace postfx::core {
namespace {

double maxComponent(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

// |a - b| over the larger of the two's largest channel: 0 when both are 0.
double relativeChange(const Vec3& a, const Vec3& b) {
    const glm::dvec3 da(a), db(b);
    const double scale = std::max(maxComponent(da), maxComponent(db));
    if (scale <= 0.0) return 0.0;
    return maxComponent(glm::abs(da - db)) / scale;
}

double relativeChange(double a, double b) {
    const double scale = std::max(std::abs(a), std::abs(b));
    return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

// Angle between two directions [rad] (each normalised in double; a zero vector counts as +y).
double angleBetween(const Vec3& a, const Vec3& b) {
    auto unit = [](const Vec3& v) {
        const glm::dvec3 d(v);
        const double l = glm::length(d);
        return l > 0.0 ? d / l : glm::dvec3(0.0, 1.0, 0.0);
    };
    return std::acos(std::clamp(glm::dot(unit(a), unit(b)), -1.0, 1.0));
}

bool lit(const LocalLight& l) {
    return l.intensity.x > 0.0f || l.intensity.y > 0.0f || l.intensity.z > 0.0f;
}

// Whether light `now` differs from `then` beyond the thresholds of postfx/temporal.h.
bool lightChanged(const LocalLight& then, const LocalLight& now) {
    if (lit(then) != lit(now)) return true;
    if (!lit(now)) return false;  // off before and after
    if (then.type != now.type) return true;
    if ((then.shadow == kNoLocalShadow) != (now.shadow == kNoLocalShadow)) return true;
    const double range = std::max(then.range, now.range);
    if (glm::length(glm::dvec3(now.position) - glm::dvec3(then.position)) >
        kTemporalLightMoveFraction * range)
        return true;
    if (relativeChange(then.intensity, now.intensity) > kTemporalLightRelativeChange) return true;
    if (relativeChange(then.range, now.range) > kTemporalLightRelativeChange) return true;
    if (relativeChange(then.sourceRadius, now.sourceRadius) > kTemporalLightRelativeChange) return true;
    if (now.type == LightType::Spot) {
        if (angleBetween(then.direction, now.direction) > kTemporalLightAngle) return true;
        if (std::abs(then.innerConeAngle - now.innerConeAngle) > kTemporalLightAngle) return true;
        if (std::abs(then.outerConeAngle - now.outerConeAngle) > kTemporalLightAngle) return true;
    }
    return false;
}

bool sunChanged(const SunInput& then, const SunInput& now) {
    if (relativeChange(then.illuminance, now.illuminance) > kTemporalLightRelativeChange) return true;
    const bool lit = now.illuminance.x > 0.0f || now.illuminance.y > 0.0f || now.illuminance.z > 0.0f;
    return lit && angleBetween(then.toSun, now.toSun) > kTemporalLightAngle;
}

// The shadow map's matrix changed: an element moved by more than 1e-6 of the largest element.
bool matrixChanged(const DMat4& a, const DMat4& b) {
    double scale = 0.0, difference = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            scale = std::max({scale, std::abs(a[c][r]), std::abs(b[c][r])});
            difference = std::max(difference, std::abs(a[c][r] - b[c][r]));
        }
    return difference > 1e-6 * scale;
}

}  // namespace

uint64_t hashBytes(uint64_t hash, const void* bytes, size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

gpu::TemporalUniforms temporalUniforms(const TemporalFrame& t) {
    gpu::TemporalUniforms u{};
    u.previousClip = t.previousClipFromCurrent;
    u.cameraDelta = glm::vec4(t.cameraDelta, t.currentWeight);
    u.previous = glm::vec4(0.0f, t.historyScale, 0.0f, 0.0f);
    u.state = glm::uvec4(t.historyValid ? 1u : 0u, uint32_t(t.rejected.size()), 0u, 0u);
    for (size_t i = 0; i < t.rejected.size() && i < gpu::kTemporalMaxSpheres; ++i)
        u.spheres[i] = glm::vec4(t.rejected[i].center, t.rejected[i].radius);
    return u;
}

TemporalFrame TemporalHistory::decide(const FrameInfo& frame, const TemporalSettings& settings, uint64_t key,
                                      bool localLights) const {
    return evaluate(frame, settings, key, localLights, nullptr);
}

void TemporalHistory::recorded(const FrameInfo& frame, const TemporalSettings& settings, uint64_t key,
                               bool localLights) {
    TemporalHistory next;
    evaluate(frame, settings, key, localLights, &next);
    *this = std::move(next);
}

TemporalFrame TemporalHistory::evaluate(const FrameInfo& frame, const TemporalSettings& settings,
                                        uint64_t key, bool localLights, TemporalHistory* next) const {
    TemporalFrame t;
    t.writeSlot = 1u - writtenSlot_;
    t.readSlot = writtenSlot_;
    t.previousCamera = camera_;

    const bool shadowMap = frame.shadowMap.image.present();
    if (!valid_)
        t.resetReason = "no history";
    else if (frame.cameraCut)
        t.resetReason = "camera cut";
    else if (key != key_)
        t.resetReason = "extent, settings or medium changed";
    else if (sunChanged(sun_, frame.sun))
        t.resetReason = "sun changed";
    else if (relativeChange(ambient_, frame.ambient) > kTemporalLightRelativeChange)
        t.resetReason = "ambient changed";
    else if (shadowMap != shadowMap_ ||
             (shadowMap && matrixChanged(shadowMatrix_, frame.shadowMap.worldToClip)))
        t.resetReason = "shadow map's matrix changed";
    else
        t.resetReason = "";

    // Local lights: compared with the state each was last rejected for (after a reset: this frame's).
    std::vector<LocalLight> lights;
    if (localLights) lights.assign(frame.lights, frame.lights + frame.lightCount);
    bool reset = *t.resetReason != '\0';
    const glm::dvec3 camera = frame.camera.position;
    if (!reset && localLights) {
        const size_t count = std::max(lights.size(), lights_.size());
        for (size_t i = 0; i < count && !reset; ++i) {
            const LocalLight off{};  // intensity 0
            const LocalLight& then = i < lights_.size() ? lights_[i] : off;
            const LocalLight& now = i < lights.size() ? lights[i] : off;
            if (!lightChanged(then, now)) {
                if (i < lights.size()) lights[i] = then;  // keep the reference state
                continue;
            }
            for (const LocalLight* l : {&then, &now})
                if (lit(*l)) t.rejected.push_back({glm::vec3(glm::dvec3(l->position) - camera), l->range});
            if (t.rejected.size() > kTemporalMaxRejectedSpheres) {
                t.rejected.clear();
                t.resetReason = "more local lights changed than spheres can be rejected";
                reset = true;
            }
        }
    }
    if (reset) {
        t.rejected.clear();
        if (localLights) lights.assign(frame.lights, frame.lights + frame.lightCount);
    }

    t.historyValid = !reset;
    t.framesSinceReset = reset ? 0u : std::min(frames_, 1u << 20);
    t.currentWeight = reset ? 1.0f : std::max(settings.blendWeight, 1.0f / float(t.framesSinceReset + 1u));
    if (t.historyValid) {
        // previous clip = P' · R' · (x + camera - camera'), composed in double.
        const glm::dvec3 delta = camera - glm::dvec3(camera_.position);
        t.cameraDelta = glm::vec3(delta);
        t.previousClipFromCurrent = glm::mat4(glm::dmat4(camera_.projection) * rotationOnly(camera_.view) *
                                              glm::translate(glm::dmat4(1.0), delta));
        // Both in [kMinPreExposure, kMaxPreExposure] (checked): the ratio is finite and positive.
        t.historyScale = float(double(frame.preExposure) / double(preExposure_));
    }

    if (next) {
        next->valid_ = true;
        next->writtenSlot_ = t.writeSlot;
        next->frames_ = t.framesSinceReset + 1u;
        next->key_ = key;
        next->camera_ = frame.camera;
        next->preExposure_ = frame.preExposure;
        next->sun_ = reset ? frame.sun : sun_;
        next->ambient_ = reset ? frame.ambient : ambient_;
        next->shadowMap_ = shadowMap;
        next->shadowMatrix_ = reset ? frame.shadowMap.worldToClip : shadowMatrix_;
        next->lights_ = std::move(lights);
    }
    return t;
}

}  // namespace postfx::core
