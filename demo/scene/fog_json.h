// The `effects` object of scene files: its `fog` (ray-marched), `froxel_fog` and `atmosphere` settings
// (docs/scene-format.md#effects); internal to demo_scene.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace demo {

struct Scene;

// Reads `effects` (at key path `path`) into scene.fog, scene.froxelFog, scene.froxelVolumes and
// scene.atmosphere. Unknown
// keys and bad values throw json_read::ReadError naming the key path ("effects.fog.steps: 0 is outside
// [1, 4096]"). Without `effects.fog` the fog keeps FogSettings' defaults (disabled); with it, `enabled`
// defaults to true (and likewise for `effects.fog.noise`, `effects.froxel_fog` and `effects.atmosphere`).
// Both fogs enabled is an error naming both keys: postfx draws one of them per frame.
void readEffects(const nlohmann::json& effects, const std::string& path, Scene& scene);

// The `effects` object with every key of both fogs and the atmosphere written, in the form readEffects reads
// back exactly.
nlohmann::json effectsToJson(const Scene& scene);

}  // namespace demo
