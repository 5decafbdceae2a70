// Scene files: the keys both fogs share: the medium <-> postfx::FogMedium, `temporal` <->
// postfx::TemporalSettings. Keep docs/scene-format.md in sync.
#include "scene/medium_json.h"

#include "scene/json_read.h"

namespace demo::medium_json {
namespace {

using json = nlohmann::json;
using namespace json_read;

constexpr const char* kNoiseKeys[] = {"enabled",   "texture_size", "seed", "tiling",
                                      "threshold", "multiplier",   "wind"};
constexpr const char* kTemporalKeys[] = {"enabled", "blend_weight"};

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

}  // namespace

std::vector<const char*> effectKeys(std::span<const char* const> own) {
    std::vector<const char*> keys{"enabled"};
    keys.insert(keys.end(), std::begin(kMediumKeys), std::end(kMediumKeys));
    keys.insert(keys.end(), own.begin(), own.end());
    return keys;
}

void readMedium(const json& j, const std::string& path, postfx::FogMedium& m) {
    if (const json* v = find(j, "density")) m.density = readNumber(*v, child(path, "density"));
    if (const json* v = find(j, "albedo")) m.albedo = readVec3(*v, child(path, "albedo"), Range::Unit);
    if (const json* v = find(j, "anisotropy")) m.anisotropy = readNumber(*v, child(path, "anisotropy"));
    if (const json* v = find(j, "height_falloff"))
        m.heightFalloff = readNumber(*v, child(path, "height_falloff"));
    if (const json* v = find(j, "base_height")) m.baseHeight = readNumber(*v, child(path, "base_height"));
    if (const json* v = find(j, "max_distance")) m.maxDistance = readNumber(*v, child(path, "max_distance"));
    if (const json* v = find(j, "self_shadow")) m.selfShadow = readBool(*v, child(path, "self_shadow"));
    if (const json* v = find(j, "analytic_tail")) m.analyticTail = readBool(*v, child(path, "analytic_tail"));
    if (const json* v = find(j, "noise")) readNoise(*v, child(path, "noise"), m.noise);
}

void writeMedium(const postfx::FogMedium& m, json& effect) {
    const postfx::FogNoiseSettings& n = m.noise;
    effect["density"] = number(m.density);
    effect["albedo"] = vec3(m.albedo);
    effect["anisotropy"] = number(m.anisotropy);
    effect["height_falloff"] = number(m.heightFalloff);
    effect["base_height"] = number(m.baseHeight);
    effect["max_distance"] = number(m.maxDistance);
    effect["self_shadow"] = m.selfShadow;
    effect["analytic_tail"] = m.analyticTail;
    effect["noise"] = {{"enabled", n.enabled},
                       {"texture_size", n.textureSize},
                       {"seed", n.seed},
                       {"tiling", number(n.tiling)},
                       {"threshold", number(n.threshold)},
                       {"multiplier", number(n.multiplier)},
                       {"wind", vec3(n.wind)}};
}

void readTemporal(const json& j, const std::string& path, postfx::TemporalSettings& t) {
    expectObject(j, path);
    checkKeys(j, path, kTemporalKeys);
    if (const json* v = find(j, "enabled")) t.enabled = readBool(*v, child(path, "enabled"));
    if (const json* v = find(j, "blend_weight")) t.blendWeight = readNumber(*v, child(path, "blend_weight"));
}

json temporalToJson(const postfx::TemporalSettings& t) {
    return {{"enabled", t.enabled}, {"blend_weight", number(t.blendWeight)}};
}

void throwIfInvalid(const postfx::Status& status, const std::string& prefix, const std::string& path) {
    if (status.ok()) return;
    const std::string& m = status.message;
    const bool named = m.size() > prefix.size() && m.compare(0, prefix.size(), prefix) == 0 &&
                       (m[prefix.size()] == '.' || m[prefix.size()] == ':' || m[prefix.size()] == '[');
    if (named) throw ReadError{path + m.substr(prefix.size())};
    fail(path, m);
}

}  // namespace demo::medium_json
