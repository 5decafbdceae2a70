// Scene files: `effects.atmosphere` (docs/scene-format.md#effectsatmosphere) <-> postfx::AtmosphereSettings;
// internal to demo_scene.
#pragma once

#include <postfx/atmosphere.h>
#include <nlohmann/json.hpp>

#include <string>

namespace demo {

// Reads `effects.atmosphere` (at key path `path`): enabled unless it says `"enabled": false`, absent keys
// keep AtmosphereSettings' defaults (Earth). Unknown keys and bad values throw json_read::ReadError naming
// the key path ("effects.atmosphere.top_radius: 6e+06 must be greater than ground_radius (6.36e+06)"); the
// ranges are postfx::validateAtmosphereSettings'.
postfx::AtmosphereSettings readAtmosphere(const nlohmann::json& j, const std::string& path);

// `effects.atmosphere` with every key written, in the form readAtmosphere reads back exactly.
nlohmann::json atmosphereToJson(const postfx::AtmosphereSettings& settings);

}  // namespace demo
