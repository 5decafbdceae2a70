// The keys both fogs of scene files share (`effects.fog` and `effects.froxel_fog`): the participating
// medium, postfx::FogMedium (docs/scene-format.md#effectsfog), and the temporal accumulation,
// postfx::TemporalSettings, read and written by one function each; internal to demo_scene.
#pragma once

#include <postfx/fog.h>
#include <postfx/result.h>
#include <postfx/temporal.h>
#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <vector>

namespace demo::medium_json {

// The medium's keys, in the order error messages list them.
inline constexpr const char* kMediumKeys[] = {"density",        "albedo",        "anisotropy",
                                              "height_falloff", "base_height",   "max_distance",
                                              "self_shadow",    "analytic_tail", "noise"};

// The keys an effect object accepts: "enabled", the medium's, then the effect's own `own`.
std::vector<const char*> effectKeys(std::span<const char* const> own);

// Reads the medium's keys present in the effect object `j` (at key path `path`) into `medium`; absent
// keys keep their value. Types are checked here (json_read::ReadError naming the key path), ranges by
// the effect's postfx check (throwIfInvalid). A `noise` object turns the noise on unless it says
// `"enabled": false`.
void readMedium(const nlohmann::json& j, const std::string& path, postfx::FogMedium& medium);

// The medium's keys with their values, in the form readMedium reads back exactly, added to `effect`.
void writeMedium(const postfx::FogMedium& medium, nlohmann::json& effect);

// The `temporal` object of either fog (postfx::TemporalSettings, docs/scene-format.md#effectsfog): its keys
// `enabled` and `blend_weight`, both optional; absent keys keep the value in `temporal` (the fog's default:
// unlike `noise`, the object's presence does not turn it on). Types are checked here, the range by the
// effect's postfx check.
void readTemporal(const nlohmann::json& j, const std::string& path, postfx::TemporalSettings& temporal);

// The `temporal` object with both keys, in the form readTemporal reads back exactly.
nlohmann::json temporalToJson(const postfx::TemporalSettings& temporal);

// A failed postfx check of an effect's settings as a ReadError: postfx names the field by its key with
// the effect's prefix ("froxel_fog.volumes[2].radius: ..."), which becomes the key path in the file
// (`path`, "effects.froxel_fog": "effects.froxel_fog.volumes[2].radius: ..."). Does nothing for success.
void throwIfInvalid(const postfx::Status& status, const std::string& prefix, const std::string& path);

}  // namespace demo::medium_json
