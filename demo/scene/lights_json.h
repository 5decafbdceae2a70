// The top-level `lights` array of scene files (docs/scene-format.md#lights); internal to demo_scene.
#pragma once

#include "scene/light.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace demo {

// Reads `lights` (at key path `path`). Unknown keys and bad values throw json_read::ReadError naming
// the key path ("lights[2].inner_angle_deg: ..."); more than postfx::kMaxLocalLights entries is an error.
std::vector<Light> readLights(const nlohmann::json& lights, const std::string& path);

// The `lights` array with every key written, in the form readLights reads back exactly.
nlohmann::json lightsToJson(const std::vector<Light>& lights);

}  // namespace demo
