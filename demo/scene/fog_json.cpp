// Scene files: `effects.fog` <-> postfx::FogSettings. Keep docs/scene-format.md#effects in sync.
#include "scene/fog_json.h"

#include "scene/json_read.h"
#include "scene/scene.h"

namespace demo {
namespace {

using namespace json_read;

constexpr const char* kEffectsKeys[] = {"fog"};
constexpr const char* kFogKeys[] = {"enabled",
                                    "density",
                                    "albedo",
                                    "anisotropy",
                                    "height_falloff",
                                    "base_height",
                                    "max_distance",
                                    "steps",
                                    "jitter",
                                    "resolution_scale",
                                    "transmittance_cutoff",
                                    "self_shadow",
                                    "analytic_tail",
                                    "skip_empty_space",
                                    "shadow_kernel",
                                    "quality",
                                    "auto_budget_ms",
                                    "noise"};
constexpr const char* kNoiseKeys[] = {"enabled",   "texture_size", "seed", "tiling",
                                      "threshold", "multiplier",   "wind"};

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

void readNoise(const json& j, const std::string& path, postfx::FogNoiseSettings& n) {
    expectObject(j, path);
    checkKeys(j, path, kNoiseKeys);
    n.enabled = true;  // the object's presence turns the noise on unless it says otherwise
    if (const json* v = find(j, "enabled")) n.enabled = readBool(*v, child(path, "enabled"));
    if (const json* v = find(j, "texture_size")) n.textureSize = readUint32(*v, child(path, "texture_size"));
    if (const json* v = find(j, "seed")) n.seed = readUint32(*v, child(path, "seed"));
    if (const json* v = find(j, "tiling")) n.tiling = readNumber(*v, child(path, "tiling"));
    if (const json* v = find(j, "threshold")) n.threshold = readNumber(*v, child(path, "threshold"));
    if (const json* v = find(j, "multiplier")) n.multiplier = readNumber(*v, child(path, "multiplier"));
    if (const json* v = find(j, "wind")) n.wind = readVec3(*v, child(path, "wind"));
}

postfx::FogSettings readFog(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kFogKeys);
    postfx::FogSettings s;
    s.enabled = true;  // the object's presence turns the fog on unless it says otherwise
    if (const json* v = find(j, "enabled")) s.enabled = readBool(*v, child(path, "enabled"));
    if (const json* v = find(j, "density")) s.density = readNumber(*v, child(path, "density"));
    if (const json* v = find(j, "albedo")) s.albedo = readVec3(*v, child(path, "albedo"), Range::Unit);
    if (const json* v = find(j, "anisotropy")) s.anisotropy = readNumber(*v, child(path, "anisotropy"));
    if (const json* v = find(j, "height_falloff"))
        s.heightFalloff = readNumber(*v, child(path, "height_falloff"));
    if (const json* v = find(j, "base_height")) s.baseHeight = readNumber(*v, child(path, "base_height"));
    if (const json* v = find(j, "max_distance")) s.maxDistance = readNumber(*v, child(path, "max_distance"));
    if (const json* v = find(j, "steps")) s.steps = readUint32(*v, child(path, "steps"));
    if (const json* v = find(j, "jitter")) s.jitter = readBool(*v, child(path, "jitter"));
    if (const json* v = find(j, "resolution_scale"))
        s.resolutionScale = readNumber(*v, child(path, "resolution_scale"));
    if (const json* v = find(j, "transmittance_cutoff"))
        s.transmittanceCutoff = readNumber(*v, child(path, "transmittance_cutoff"));
    if (const json* v = find(j, "self_shadow")) s.selfShadow = readBool(*v, child(path, "self_shadow"));
    if (const json* v = find(j, "analytic_tail")) s.analyticTail = readBool(*v, child(path, "analytic_tail"));
    if (const json* v = find(j, "skip_empty_space"))
        s.skipEmptySpace = readBool(*v, child(path, "skip_empty_space"));
    if (const json* v = find(j, "shadow_kernel"))
        s.shadowKernel = readUint32(*v, child(path, "shadow_kernel"));
    if (const json* v = find(j, "quality")) s.quality = readQuality(*v, child(path, "quality"));
    if (const json* v = find(j, "auto_budget_ms"))
        s.autoBudgetMs = readNumber(*v, child(path, "auto_budget_ms"));
    if (const json* v = find(j, "noise")) readNoise(*v, child(path, "noise"), s.noise);

    // Ranges: postfx's own check, so that the file accepts exactly what Context::record does. The
    // noise keys are checked even when the noise is off, so that turning it on cannot make a file
    // invalid. postfx names the field as "fog.<key>: ..."; it becomes "effects.fog.<key>: ...".
    postfx::FogSettings check = s;
    check.noise.enabled = true;
    if (const postfx::Status status = postfx::validateFogSettings(check); !status.ok()) {
        const std::string& m = status.message;
        if (m.rfind("fog.", 0) == 0 || m.rfind("fog:", 0) == 0) throw ReadError{"effects." + m};
        fail(path, m);
    }
    return s;
}

}  // namespace

const char* fogQualityName(postfx::FogQuality quality) {
    for (const QualityName& q : kQualityNames)
        if (q.quality == quality) return q.name;
    return "custom";
}

void readEffects(const json& effects, const std::string& path, postfx::FogSettings& fog) {
    expectObject(effects, path);
    checkKeys(effects, path, kEffectsKeys);
    fog = postfx::FogSettings{};
    if (const json* f = find(effects, "fog")) fog = readFog(*f, child(path, "fog"));
}

json effectsToJson(const postfx::FogSettings& s) {
    const postfx::FogNoiseSettings& n = s.noise;
    const json noise = {{"enabled", n.enabled},
                        {"texture_size", n.textureSize},
                        {"seed", n.seed},
                        {"tiling", number(n.tiling)},
                        {"threshold", number(n.threshold)},
                        {"multiplier", number(n.multiplier)},
                        {"wind", vec3(n.wind)}};
    const json fog = {{"enabled", s.enabled},
                      {"density", number(s.density)},
                      {"albedo", vec3(s.albedo)},
                      {"anisotropy", number(s.anisotropy)},
                      {"height_falloff", number(s.heightFalloff)},
                      {"base_height", number(s.baseHeight)},
                      {"max_distance", number(s.maxDistance)},
                      {"steps", s.steps},
                      {"jitter", s.jitter},
                      {"resolution_scale", number(s.resolutionScale)},
                      {"transmittance_cutoff", number(s.transmittanceCutoff)},
                      {"self_shadow", s.selfShadow},
                      {"analytic_tail", s.analyticTail},
                      {"skip_empty_space", s.skipEmptySpace},
                      {"shadow_kernel", s.shadowKernel},
                      {"quality", fogQualityName(s.quality)},
                      {"auto_budget_ms", number(s.autoBudgetMs)},
                      {"noise", noise}};
    return json{{"fog", fog}};
}

}  // namespace demo
