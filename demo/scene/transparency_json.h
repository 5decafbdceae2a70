// The scene-file keys of the forward pass (docs/scene-format.md#particles and #volumetrics_lookup): the
// top-level `particles` array and `volumetrics_lookup` object; internal to demo_scene.
#pragma once

#include "scene/particles.h"

#include <postfx/volumetrics_lookup.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace demo {

// Reads `particles` (at key path `path`); bad values throw json_read::ReadError naming the key path
// ("particles[1].count: ...").
std::vector<ParticleEmitter> readParticles(const nlohmann::json& particles, const std::string& path);
nlohmann::json particlesToJson(const std::vector<ParticleEmitter>& particles);

// Reads `volumetrics_lookup` over the defaults of `out` (every key optional; `enabled` untouched).
void readVolumetricsLookup(const nlohmann::json& j, const std::string& path,
                           postfx::VolumetricsLookupSettings& out);
nlohmann::json volumetricsLookupToJson(const postfx::VolumetricsLookupSettings& lookup);

}  // namespace demo
