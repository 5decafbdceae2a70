// The clouds' settings checks (postfx/clouds.h, validateCloudSettings) and the ranges they enforce.
#pragma once

#include <postfx/clouds.h>

namespace postfx::clouds {

inline constexpr double kMaxHeight = 1e6;                    // bottom / top height [m]
inline constexpr double kMaxDensity = 1e3;                   // σt where the field is 1 [1/m]
inline constexpr double kMaxDistance = 1e7;                  // max distance [m]
inline constexpr double kMaxLightDistance = 1e6;             // [m]
inline constexpr double kMaxBoxHalfSize = 1e7;               // [m]
inline constexpr double kMaxWind = 1e3;                      // [m/s]
inline constexpr double kMinTiling = 1.0, kMaxTiling = 1e7;  // [m]
inline constexpr uint32_t kMaxSteps = 1024, kMaxLightSteps = 64, kMaxOctaves = 8;
inline constexpr uint32_t kMinBaseSize = 16, kMaxBaseSize = 256, kMinDetailSize = 8, kMaxDetailSize = 128;
inline constexpr float kMaxAnisotropy = 0.999f;

Status validateSettings(const CloudSettings& settings);

}  // namespace postfx::clouds
