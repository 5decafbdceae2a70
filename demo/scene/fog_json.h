// The `effects` object of scene files and its `fog` settings (docs/scene-format.md#effects);
// internal to demo_scene.
#pragma once

#include <postfx/fog.h>
#include <nlohmann/json.hpp>

#include <string>

namespace demo {

// Reads `effects` (at key path `path`) into `fog`. Unknown keys and bad values throw
// json_read::ReadError naming the key path ("effects.fog.steps: 0 is outside [1, 4096]").
// Without `effects.fog` the fog keeps FogSettings' defaults (disabled); with it, `enabled` defaults
// to true (and likewise for `effects.fog.noise`).
void readEffects(const nlohmann::json& effects, const std::string& path, postfx::FogSettings& fog);

// The `effects` object with every fog key written, in the form readEffects reads back exactly.
nlohmann::json effectsToJson(const postfx::FogSettings& fog);

}  // namespace demo
