// Scene files: `effects.froxel_fog` (docs/scene-format.md#effectsfroxel_fog) <-> postfx::FroxelFogSettings
// and its local fog volumes; internal to demo_scene.
#pragma once

#include <postfx/froxel_fog.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace demo {

// Reads `effects.froxel_fog` (at key path `path`): the settings into `settings` (enabled unless it says
// `"enabled": false`; its `volumes` pointer left null and volumeCount 0) and the `volumes` array into
// `volumes` (at most postfx::kMaxFogVolumes). Unknown keys and bad values throw json_read::ReadError
// naming the key path ("effects.froxel_fog.volumes[2].radius: -1 is outside [0, 1e+07]"); the ranges are
// postfx::validateFroxelFogSettings' (the noise's checked even while it is off, as for effects.fog).
void readFroxelFog(const nlohmann::json& j, const std::string& path, postfx::FroxelFogSettings& settings,
                   std::vector<postfx::FogVolume>& volumes);

// `effects.froxel_fog` with every key written (each volume with its shape's keys), in the form
// readFroxelFog reads back exactly.
nlohmann::json froxelFogToJson(const postfx::FroxelFogSettings& settings,
                               const std::vector<postfx::FogVolume>& volumes);

// The scene-file names of the volume shapes ("box", "sphere").
const char* fogVolumeShapeName(postfx::FogVolumeShape shape);

}  // namespace demo
