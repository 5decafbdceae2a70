// Scene files: `effects.clouds` (docs/scene-format.md#effectsclouds) <-> postfx::CloudSettings; internal to
// demo_scene.
#pragma once

#include <postfx/clouds.h>
#include <nlohmann/json.hpp>

#include <string>

namespace demo {

// Reads `effects.clouds` (at key path `path`): enabled unless it says `"enabled": false`, absent keys keep
// CloudSettings' defaults. Unknown keys and bad values throw json_read::ReadError naming the key path
// ("effects.clouds.top_height: 1000 must be greater than bottom_height (1500)"); the ranges are
// postfx::validateCloudSettings'.
postfx::CloudSettings readClouds(const nlohmann::json& j, const std::string& path);

// `effects.clouds` with every key written, in the form readClouds reads back exactly.
nlohmann::json cloudsToJson(const postfx::CloudSettings& settings);

}  // namespace demo
