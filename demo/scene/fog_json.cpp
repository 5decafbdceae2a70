// Scene files: `effects` and `effects.fog` <-> postfx::FogSettings (the froxel fog: froxel_fog_json.cpp;
// the atmosphere: atmosphere_json.cpp; the medium keys both fogs share: medium_json.cpp). Keep
// docs/scene-format.md#effects in sync.
#include "scene/fog_json.h"

#include "scene/atmosphere_json.h"
#include "scene/clouds_json.h"
#include "scene/froxel_fog_json.h"
#include "scene/json_read.h"
#include "scene/medium_json.h"
#include "scene/scene.h"

namespace demo {
namespace {

using namespace json_read;

constexpr const char* kEffectsKeys[] = {"fog", "froxel_fog", "atmosphere", "clouds"};
// The ray-marched fog's own keys (besides "enabled" and the medium's).
constexpr const char* kFogKeys[] = {"steps",
                                    "jitter",
                                    "resolution_scale",
                                    "transmittance_cutoff",
                                    "skip_empty_space",
                                    "shadow_kernel",
                                    "quality",
                                    "auto_budget_ms",
                                    "temporal"};

struct QualityName {
    postfx::FogQuality quality;
    const char* name;
};
constexpr QualityName kQualityNames[] = {
    {postfx::FogQuality::Custom, "custom"}, {postfx::FogQuality::Low, "low"},
    {postfx::FogQuality::Medium, "medium"}, {postfx::FogQuality::High, "high"},
    {postfx::FogQuality::Ultra, "ultra"},   {postfx::FogQuality::Auto, "auto"},
};

postfx::FogQuality readQuality(const json& j, const std::string& path) {
    if (j.is_string())
        for (const QualityName& q : kQualityNames)
            if (j.get<std::string>() == q.name) return q.quality;
    fail(path, "expected \"custom\", \"low\", \"medium\", \"high\", \"ultra\" or \"auto\"" + got(j));
}

postfx::FogSettings readFog(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, medium_json::effectKeys(kFogKeys));
    postfx::FogSettings s;
    s.enabled = true;  // the object's presence turns the fog on unless it says otherwise
    if (const json* v = find(j, "enabled")) s.enabled = readBool(*v, child(path, "enabled"));
    medium_json::readMedium(j, path, s);
    if (const json* v = find(j, "steps")) s.steps = readUint32(*v, child(path, "steps"));
    if (const json* v = find(j, "jitter")) s.jitter = readBool(*v, child(path, "jitter"));
    if (const json* v = find(j, "resolution_scale"))
        s.resolutionScale = readNumber(*v, child(path, "resolution_scale"));
    if (const json* v = find(j, "transmittance_cutoff"))
        s.transmittanceCutoff = readNumber(*v, child(path, "transmittance_cutoff"));
    if (const json* v = find(j, "skip_empty_space"))
        s.skipEmptySpace = readBool(*v, child(path, "skip_empty_space"));
    if (const json* v = find(j, "shadow_kernel"))
        s.shadowKernel = readUint32(*v, child(path, "shadow_kernel"));
    if (const json* v = find(j, "quality")) s.quality = readQuality(*v, child(path, "quality"));
    if (const json* v = find(j, "auto_budget_ms"))
        s.autoBudgetMs = readNumber(*v, child(path, "auto_budget_ms"));
    if (const json* v = find(j, "temporal"))
        medium_json::readTemporal(*v, child(path, "temporal"), s.temporal);

    // Ranges: postfx's own check, so that the file accepts exactly what Context::record does. The
    // noise keys are checked even when the noise is off, so that turning it on cannot make a file
    // invalid. postfx names the field as "fog.<key>: ..."; it becomes "effects.fog.<key>: ...".
    postfx::FogSettings check = s;
    check.noise.enabled = true;
    medium_json::throwIfInvalid(postfx::validateFogSettings(check), "fog", path);
    return s;
}

json fogToJson(const postfx::FogSettings& s) {
    json fog = {{"enabled", s.enabled},
                {"steps", s.steps},
                {"jitter", s.jitter},
                {"resolution_scale", number(s.resolutionScale)},
                {"transmittance_cutoff", number(s.transmittanceCutoff)},
                {"skip_empty_space", s.skipEmptySpace},
                {"shadow_kernel", s.shadowKernel},
                {"quality", fogQualityName(s.quality)},
                {"auto_budget_ms", number(s.autoBudgetMs)},
                {"temporal", medium_json::temporalToJson(s.temporal)}};
    medium_json::writeMedium(s, fog);
    return fog;
}

}  // namespace

const char* fogQualityName(postfx::FogQuality quality) {
    for (const QualityName& q : kQualityNames)
        if (q.quality == quality) return q.name;
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
