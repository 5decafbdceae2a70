// Scene files: `effects.clouds` <-> postfx::CloudSettings, read and written from its settings table
// (postfx::cloudSettingsTable, settings_json.cpp). Keep docs/scene-format.md#effectsclouds in sync.
#include "scene/clouds_json.h"

#include "scene/json_read.h"
#include "scene/settings_json.h"

#include <postfx/settings_table.h>

namespace demo {

using namespace json_read;

postfx::CloudSettings readClouds(const json& j, const std::string& path) {
    postfx::CloudSettings s;
    s.enabled = true;  // the object's presence turns the clouds on unless it says otherwise
    // and a `noise` object the noise
    if (j.is_object() && find(j, "noise")) s.noise.enabled = true;
    settings_json::readFields(j, path, postfx::cloudSettingsTable(), &s);
    // Ranges: postfx's own check, which names the field "FrameInfo.clouds.<member>"; it becomes
    // "effects.clouds.<key>".
    settings_json::throwIfInvalid(postfx::validateCloudSettings(s), "FrameInfo.clouds",
                                  postfx::cloudSettingsTable(), path);
    return s;
}

json cloudsToJson(const postfx::CloudSettings& s) {
    json j = json::object();
    settings_json::writeFields(postfx::cloudSettingsTable(), &s, j);
    return j;
}

}  // namespace demo
