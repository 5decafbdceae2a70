// Scene files: `effects.atmosphere` <-> postfx::AtmosphereSettings, read and written from its settings table
// (postfx::atmosphereSettingsTable, settings_json.cpp). Keep
// docs/scene-format.md#effectsatmosphere in sync.
#include "scene/atmosphere_json.h"

#include "scene/json_read.h"
#include "scene/settings_json.h"

#include <postfx/settings_table.h>

namespace demo {

using namespace json_read;

postfx::AtmosphereSettings readAtmosphere(const json& j, const std::string& path) {
    postfx::AtmosphereSettings s;
    s.enabled = true;  // the object's presence turns the atmosphere on unless it says otherwise
    // Older scene files give multiple_scattering as true or false: read as "orders" and "off".
    json file = j;
    if (file.is_object() && file.contains("multiple_scattering") && file["multiple_scattering"].is_boolean())
        file["multiple_scattering"] = file["multiple_scattering"].get<bool>() ? "orders" : "off";
    settings_json::readFields(file, path, postfx::atmosphereSettingsTable(), &s);
    // Ranges: postfx's own check (whether or not enabled), which names the field
    // "FrameInfo.atmosphere.<member>"; it becomes "effects.atmosphere.<key>".
    settings_json::throwIfInvalid(postfx::validateAtmosphereSettings(s), "FrameInfo.atmosphere",
                                  postfx::atmosphereSettingsTable(), path);
    return s;
}

json atmosphereToJson(const postfx::AtmosphereSettings& s) {
    json j = json::object();
    settings_json::writeFields(postfx::atmosphereSettingsTable(), &s, j);
    return j;
}

}  // namespace demo
