// Temporal accumulation of the fogs and the clouds (docs/temporal.md): each frame's result is blended
// with the previous frames' result reprojected into the current view, so the jittered frames converge
// toward the reference while the camera and the lights move. History that no longer belongs is rejected
// (per pixel or froxel: off screen, disoccluded, outside the neighbourhood, near a light that changed) or
// reset (the whole image or volume: FrameInfo::cameraCut, a change of extent, settings or medium, of the
// sun, the ambient or the shadow map's matrix).
#pragma once

#include <cstdint>

namespace postfx {

// Every setting: unit, default, valid range; checked when the effect is enabled.
struct TemporalSettings {
    // Blend each frame with the reprojected history. Each effect documents its default.
    bool enabled = false;
    // Weight of the current frame: result = history + blendWeight · (current - history) [1]; in (0, 1].
    // 1 keeps no history. After a reset the weight is max(blendWeight, 1/(n+1)) for the n-th frame since
    // (a running mean), so a still view converges at once and then settles on the exponential blend,
    // whose history decays as (1 - blendWeight)^n (docs/temporal.md, "Blend").
    float blendWeight = 0.1f;
};

// Thresholds of the history's rejection (docs/temporal.md, "What resets history"). A light's state is
// compared with the one its history was last rejected for, so changes below a threshold do not add up
// beyond it.
//
// A local light is "changed" when its position moved by more than this fraction of its range [1] ...
inline constexpr float kTemporalLightMoveFraction = 0.001f;
// ... or its intensity (largest RGB change over its largest channel), or its range, changed by more than
// this relative amount [1] (turning a light on or off is always a change) ...
inline constexpr float kTemporalLightRelativeChange = 0.02f;
// ... or its cone axis turned, or a cone angle changed, by more than this [rad] (0.5°).
inline constexpr float kTemporalLightAngle = 0.0087266f;
// The sun resets all history when its direction turns by more than kTemporalLightAngle or its
// illuminance changes by more than kTemporalLightRelativeChange; the ambient by more than
// kTemporalLightRelativeChange.
//
// At most this many spheres of changed local lights (old and new place, each a light's range) are rejected
// per frame; a frame with more resets the whole volume.
inline constexpr uint32_t kTemporalMaxRejectedSpheres = 64;

}  // namespace postfx
