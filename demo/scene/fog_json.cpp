// Scene files: `effects` and `effects.fog` <-> postfx::FogSettings, read and written from its settings
// table (postfx::fogSettingsTable, settings_json.cpp; the froxel fog: froxel_fog_json.cpp; the atmosphere:
// atmosphere_json.cpp). Keep docs/scene-format.md#effects in sync.
#include "scene/fog_json.h"

#include "scene/atmosphere_json.h"
#include "scene/clouds_json.h"
#include "scene/froxel_fog_json.h"
#include "scene/json_read.h"
#include "scene/scene.h"
#include "scene/settings_json.h"

#include <postfx/settings_table.h>

namespace demo {
namespace {

using namespace json_read;

constexpr const char* kEffectsKeys[] = {"fog", "froxel_fog", "atmosphere", "clouds"};

postfx::FogSettings readFog(const json& j, const std::string& path) {
    postfx::FogSettings s;
    s.enabled = true;  // the object's presence turns the fog on unless it says otherwise
    // and a `noise` object the noise
    if (j.is_object() && find(j, "noise")) s.noise.enabled = true;
    settings_json::readFields(j, path, postfx::fogSettingsTable(), &s);

    // Ranges: postfx's own check, so that the file accepts exactly what Context::record does. The
    // noise keys are checked even when the noise is off, so that turning it on cannot make a file
    // invalid. postfx names the field as "FrameInfo.fog.<member>: ..."; it becomes "effects.fog.<key>: ...".
    postfx::FogSettings check = s;
    check.noise.enabled = true;
    settings_json::throwIfInvalid(postfx::validateFogSettings(check), "FrameInfo.fog",
                                  postfx::fogSettingsTable(), path);
    return s;
}

json fogToJson(const postfx::FogSettings& s) {
    json fog = json::object();
    settings_json::writeFields(postfx::fogSettingsTable(), &s, fog);
    return fog;
}

}  // namespace

const char* fogQualityName(postfx::FogQuality quality) {
    const postfx::SettingField* f = postfx::findSettingByMember(postfx::fogSettingsTable(), "quality");
    for (const postfx::SettingChoice& c : f->choices)
        if (c.value == uint32_t(quality)) return c.key;
    return "custom";
}

void readEffects(const json& effects, const std::string& path, Scene& scene) {
    expectObject(effects, path);
    checkKeys(effects, path, kEffectsKeys);
    scene.fog = postfx::FogSettings{};
    scene.froxelFog = postfx::FroxelFogSettings{};
    scene.froxelVolumes.clear();
    scene.atmosphere = postfx::AtmosphereSettings{};
    scene.clouds = postfx::CloudSettings{};
    if (const json* f = find(effects, "fog")) scene.fog = readFog(*f, child(path, "fog"));
    if (const json* f = find(effects, "froxel_fog"))
        readFroxelFog(*f, child(path, "froxel_fog"), scene.froxelFog, scene.froxelVolumes);
    if (const json* a = find(effects, "atmosphere"))
        scene.atmosphere = readAtmosphere(*a, child(path, "atmosphere"));
    if (const json* c = find(effects, "clouds")) scene.clouds = readClouds(*c, child(path, "clouds"));
    // postfx draws one fog per frame (Context::record rejects both): the file says which.
    if (scene.fog.enabled && scene.froxelFog.enabled) {
        fail(path, child(path, "fog") + " and " + child(path, "froxel_fog") +
                       " are both enabled: postfx draws one fog per frame (give one \"enabled\": false)");
    }
}

json effectsToJson(const Scene& scene) {
    return json{{"fog", fogToJson(scene.fog)},
                {"froxel_fog", froxelFogToJson(scene.froxelFog, scene.froxelVolumes)},
                {"atmosphere", atmosphereToJson(scene.atmosphere)},
                {"clouds", cloudsToJson(scene.clouds)}};
}

}  // namespace demo
