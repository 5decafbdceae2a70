// An effect's temporal history across recorded frames (docs/temporal.md): whether the history images
// hold a result that may be blended into this frame, where the previous camera was, and which spheres
// of changed local lights must not use it. The fog, the froxel fog and the clouds hold one; the rules
// are written once, here.
//
// decide() (const: plan() and declare() call it) says what this frame does; recorded() moves the state
// on after record() recorded the frame, with the same rules; dropped() after a frame the effect did not
// record its history in (off, empty or temporal off), whose images the frame graph then released.
#pragma once

#include <postfx/context.h>

#include "common/shared.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace postfx::core {

struct TemporalSphere {
    glm::vec3 center{0.0f};  // camera-relative (this frame's camera) [m]
    float radius = 0.0f;     // [m]
};

// What one frame does with an effect's history.
struct TemporalFrame {
    // The image in `readSlot` holds the previous recorded frame's result, which this frame may blend.
    bool historyValid = false;
    // Why it does not (a reset), for messages and tests: "" when valid.
    const char* resetReason = "first frame";
    uint32_t framesSinceReset = 0;  // frames the history holds since the last reset (0: this one starts it)
    float currentWeight = 1.0f;     // max(blendWeight, 1/(framesSinceReset + 1)); 1 when not valid
    uint32_t readSlot = 1, writeSlot = 0;  // which of the effect's two history images is read / written
    // Current camera-relative position -> the previous frame's clip space (Vulkan, its DepthConvention).
    glm::mat4 previousClipFromCurrent{1.0f};
    glm::vec3 cameraDelta{0.0f};  // current camera position - previous [m]
    CameraInput previousCamera;   // the previous recorded frame's camera
    // This frame's FrameInfo::preExposure / the previous recorded frame's: the history holds radiance
    // pre-exposed with the previous frame's, so it is scaled by this before blending (1 when not valid).
    float historyScale = 1.0f;
    std::vector<TemporalSphere> rejected;  // changed local lights' spheres (old and new place)
};

class TemporalHistory {
public:
    // `key`: everything besides the camera and the lights that the history's contents depend on (the
    // effect's settings, the extent, the color format); `localLights`: the effect reads FrameInfo's
    // local lights (their changes reject spheres; otherwise they are ignored).
    TemporalFrame decide(const FrameInfo& frame, const TemporalSettings& settings, uint64_t key,
                         bool localLights) const;
    void recorded(const FrameInfo& frame, const TemporalSettings& settings, uint64_t key, bool localLights);
    void dropped() { valid_ = false; }

private:
    // decide(), and with `next` the state after this frame.
    TemporalFrame evaluate(const FrameInfo& frame, const TemporalSettings& settings, uint64_t key,
                           bool localLights, TemporalHistory* next) const;

    bool valid_ = false;  // a frame was recorded with history and nothing dropped it since
    uint32_t writtenSlot_ = 1;
    uint32_t frames_ = 0;  // frames the history holds
    uint64_t key_ = 0;
    CameraInput camera_;        // the last recorded frame's camera
    float preExposure_ = 1.0f;  // the last recorded frame's FrameInfo::preExposure
    // The lighting the history was last reset for (the sun, the ambient, the shadow map) and each
    // local light's state its spheres were last rejected for.
    SunInput sun_;
    Vec3 ambient_{0.0f};
    bool shadowMap_ = false;
    DMat4 shadowMatrix_{1.0};
    std::vector<LocalLight> lights_;
};

// The TemporalUniforms of a frame (shaders/common/shared.h): previous.y is the history's radiance factor
// (historyScale); the froxel fog sets previous.x and multiplies previous.y by its storage scale's change.
gpu::TemporalUniforms temporalUniforms(const TemporalFrame& frame);

// FNV-1a over `bytes`, continuing `hash` (keys of settings).
uint64_t hashBytes(uint64_t hash, const void* bytes, size_t size);
inline constexpr uint64_t kHashSeed = 1469598103934665603ull;
template <typename T>
uint64_t hashValue(uint64_t hash, const T& value) {
    return hashBytes(hash, &value, sizeof value);
}

}  // namespace postfx::core
