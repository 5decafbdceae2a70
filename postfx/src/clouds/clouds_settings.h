// The clouds' settings checks (postfx/clouds.h, validateCloudSettings) and the ranges they enforce.
#pragma once

#include <postfx/clouds.h>

#include "core/world_frame.h"

namespace postfx::clouds {

inline constexpr double kMaxHeight = 1e6;                    // bottom / top height [m]
inline constexpr double kMaxDensity = 1e3;                   // σt where the field is 1 [1/m]
inline constexpr double kMaxDistance = 1e7;                  // max distance [m]
inline constexpr double kMaxLightDistance = 1e6;             // [m]
inline constexpr double kMaxBoxHalfSize = 1e7;               // [m]
inline constexpr double kMaxWind = 1e3;                      // [m/s]
inline constexpr double kMinTiling = 1.0, kMaxTiling = 1e7;  // [m]
inline constexpr uint32_t kMaxSteps = 1024, kMaxLightSteps = 64, kMaxOctaves = 8;
inline constexpr uint32_t kMaxUpdateBlock = 4;  // CloudSettings::updateBlock: 1, 2 or this
inline constexpr uint32_t kMinBaseSize = 16, kMaxBaseSize = 256, kMinDetailSize = 8, kMaxDetailSize = 128;
inline constexpr float kMaxAnisotropy = 0.999f;
inline constexpr float kMinResolutionScale = 0.25f;
inline constexpr uint32_t kMinShadowSize = 16, kMaxShadowSize = 2048;      // [texels]
inline constexpr double kMinShadowExtent = 100.0, kMaxShadowExtent = 1e6;  // [m]

// A quality preset's values (postfx/clouds.h, CloudQuality; docs/effects/clouds.md, "Quality presets").
struct QualityPreset {
    CloudQuality quality;
    uint32_t steps, lightSteps;
    float resolutionScale;
    bool temporal;
    uint32_t updateBlock;
    // Its converged relative RMSE against the reference, the mean over the benchmark's views
    // (ground_noon, ground_sunset, above) of the H100 run's preset= rows
    // (docs/accuracy-cost/clouds/results.csv; tests/frame/test_frame_fronts.cpp holds them equal): what
    // FrameInfo::budgetMs weighs.
    double error;
};
inline constexpr QualityPreset kQualityPresets[] = {
    {CloudQuality::Low, 32, 4, 0.25f, true, 1, 0.06593},
    {CloudQuality::Medium, 80, 8, 0.5f, true, 1, 0.006867},
    {CloudQuality::High, 128, 12, 0.5f, true, 1, 0.007172},
    {CloudQuality::Ultra, 128, 12, 1.0f, true, 1, 0.004081},
};

Status validateSettings(const CloudSettings& settings);

// The settings' world-space fields in postfx's frame (core/world_frame.h; checked in the host's): the
// wind (m/s along the host's axes), the box (its centre and half sizes, its yaw about the up axis and
// pitch about its x with a mirror's sign) and the coverage map's placement. The map's u runs along the
// host's x, postfx's +x; its v along the host's other horizontal axis, which is postfx's z or -z: in
// postfx's frame a negative `size` says v runs along -z (|size| is the map's edge).
void settingsToPostfx(const core::WorldTransform& world, CloudSettings& settings);

}  // namespace postfx::clouds
