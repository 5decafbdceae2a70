// Scene-file reading and writing of an effect's settings from its postfx settings table
// (postfx/settings_table.h): the known keys, the readers by field kind, the writers, and the mapping of a
// postfx check's error (named by C++ member, "FrameInfo.fog.noise.textureSize: ...") to the file's key
// path ("effects.fog.noise.texture_size: ..."); internal to demo_scene.
#pragma once

#include <postfx/result.h>
#include <postfx/settings_table.h>
#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <vector>

namespace demo::settings_json {

// The keys of the object at `group` ("" the effect's object, "noise" its `noise` object) in table order:
// each field's key inside it, a nested object's name once; then `extra` (keys read by hand).
std::vector<std::string> tableKeys(std::span<const postfx::SettingField> table, const std::string& group,
                                   std::span<const char* const> extra = {});

// Checks the keys of the effect object `j` (at key path `path`) and of its nested objects (unknown keys are
// errors; `extra`: the effect object's keys read by hand) and reads every table field present into
// `settings` (of the table's struct); absent keys keep their value. Types are checked here
// (json_read::ReadError naming the key path), ranges by postfx (throwIfInvalid). Colours are read in
// [0, 1]; an enum by its choices' names. A key that the chosen mode ignores (postfx::settingUsed: a box's
// size with shape "layer") is an error naming it.
void readFields(const nlohmann::json& j, const std::string& path, std::span<const postfx::SettingField> table,
                void* settings, std::span<const char* const> extra = {});

// readFields without the check of the effect object's own keys (the caller checks them).
void readPresentFields(const nlohmann::json& j, const std::string& path,
                       std::span<const postfx::SettingField> table, void* settings);

// Every table field with a key that the settings' modes use (postfx::settingUsed), in the form readFields
// reads back exactly, added to `out`.
void writeFields(std::span<const postfx::SettingField> table, const void* settings, nlohmann::json& out);

// A failed postfx check as a ReadError at the file's key path: the message names the field as
// "<cppPrefix>.<member>" ("FrameInfo.fog.noise.textureSize"), which becomes "<path>.<key>"
// ("effects.fog.noise.texture_size"); an element of a list, "<list>[i].<member>", is named through the
// list's element table (`list`, `element`: "volumes", postfx::fogVolumeSettingsTable()); a member no table
// holds keeps its name. Does nothing for success.
void throwIfInvalid(const postfx::Status& status, const std::string& cppPrefix,
                    std::span<const postfx::SettingField> table, const std::string& path,
                    const char* list = nullptr, std::span<const postfx::SettingField> element = {});

}  // namespace demo::settings_json
