// Scene files: `effects.clouds` <-> postfx::CloudSettings. Keep docs/scene-format.md#effectsclouds in sync.
#include "scene/clouds_json.h"

#include "scene/json_read.h"
#include "scene/medium_json.h"

namespace demo {
namespace {

using namespace json_read;

constexpr const char* kCloudKeys[] = {"enabled",
                                      "shape",
                                      "bottom_height",
                                      "top_height",
                                      "box",
                                      "coverage",
                                      "cloud_type",
                                      "density",
                                      "albedo",
                                      "anisotropy_forward",
                                      "anisotropy_back",
                                      "lobe_mix",
                                      "multiple_scattering",
                                      "steps",
                                      "light_steps",
                                      "light_distance",
                                      "max_distance",
                                      "wind",
                                      "jitter",
                                      "noise"};
constexpr const char* kBoxKeys[] = {"center", "half_size", "yaw_deg", "pitch_deg"};
constexpr const char* kMultipleScatteringKeys[] = {"octaves", "attenuation", "contribution", "eccentricity"};
constexpr const char* kNoiseKeys[] = {"enabled", "base_size", "detail_size",
                                      "seed",    "tiling",    "detail_strength"};

void read(const json& j, const std::string& path, const char* key, float& out) {
    if (const json* v = find(j, key)) out = readNumber(*v, child(path, key));
}
void read(const json& j, const std::string& path, const char* key, postfx::Vec3& out) {
    if (const json* v = find(j, key)) out = postfx::Vec3(readVec3(*v, child(path, key)));
}
void read(const json& j, const std::string& path, const char* key, bool& out) {
    if (const json* v = find(j, key)) out = readBool(*v, child(path, key));
}
void read(const json& j, const std::string& path, const char* key, uint32_t& out) {
    if (const json* v = find(j, key)) out = readUint32(*v, child(path, key));
}

postfx::CloudShape readShape(const json& j, const std::string& path) {
    if (j == "layer") return postfx::CloudShape::Layer;
    if (j == "box") return postfx::CloudShape::Box;
    fail(path, "expected \"layer\" or \"box\"" + got(j));
}

}  // namespace

postfx::CloudSettings readClouds(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kCloudKeys);
    postfx::CloudSettings s;
    s.enabled = true;  // the object's presence turns the clouds on unless it says otherwise
    read(j, path, "enabled", s.enabled);
    if (const json* v = find(j, "shape")) s.shape = readShape(*v, child(path, "shape"));
    read(j, path, "bottom_height", s.bottomHeight);
    read(j, path, "top_height", s.topHeight);
    if (const json* b = find(j, "box")) {
        const std::string p = child(path, "box");
        expectObject(*b, p);
        checkKeys(*b, p, kBoxKeys);
        if (const json* c = find(*b, "center"))
            for (int i = 0; i < 3; ++i) {
                if (!c->is_array() || c->size() != 3)
                    fail(child(p, "center"), "expected an array of 3 numbers" + got(*c));
                s.box.center[i] = readDouble((*c)[size_t(i)], element(child(p, "center"), size_t(i)),
                                             {-1e9, 1e9, "[-1e9, 1e9]"});
            }
        read(*b, p, "half_size", s.box.halfSize);
        read(*b, p, "yaw_deg", s.box.yawDeg);
        read(*b, p, "pitch_deg", s.box.pitchDeg);
    }
    read(j, path, "coverage", s.coverage);
    read(j, path, "cloud_type", s.cloudType);
    read(j, path, "density", s.density);
    read(j, path, "albedo", s.albedo);
    read(j, path, "anisotropy_forward", s.anisotropyForward);
    read(j, path, "anisotropy_back", s.anisotropyBack);
    read(j, path, "lobe_mix", s.lobeMix);
    if (const json* m = find(j, "multiple_scattering")) {
        const std::string p = child(path, "multiple_scattering");
        expectObject(*m, p);
        checkKeys(*m, p, kMultipleScatteringKeys);
        read(*m, p, "octaves", s.multipleScattering.octaves);
        read(*m, p, "attenuation", s.multipleScattering.attenuation);
        read(*m, p, "contribution", s.multipleScattering.contribution);
        read(*m, p, "eccentricity", s.multipleScattering.eccentricity);
    }
    read(j, path, "steps", s.steps);
    read(j, path, "light_steps", s.lightSteps);
    read(j, path, "light_distance", s.lightDistance);
    read(j, path, "max_distance", s.maxDistance);
    read(j, path, "wind", s.wind);
    read(j, path, "jitter", s.jitter);
    if (const json* n = find(j, "noise")) {
        const std::string p = child(path, "noise");
        expectObject(*n, p);
        checkKeys(*n, p, kNoiseKeys);
        s.noise.enabled = true;  // a `noise` object turns the noise on unless it says otherwise
        read(*n, p, "enabled", s.noise.enabled);
        read(*n, p, "base_size", s.noise.baseSize);
        read(*n, p, "detail_size", s.noise.detailSize);
        read(*n, p, "seed", s.noise.seed);
        read(*n, p, "tiling", s.noise.tiling);
        read(*n, p, "detail_strength", s.noise.detailStrength);
    }
    // Ranges: postfx's own check, which names the field "clouds.<key>"; it becomes "effects.clouds.<key>".
    medium_json::throwIfInvalid(postfx::validateCloudSettings(s), "clouds", path);
    return s;
}

json cloudsToJson(const postfx::CloudSettings& s) {
    const postfx::CloudBox& b = s.box;
    const postfx::CloudMultipleScattering& m = s.multipleScattering;
    const postfx::CloudNoiseSettings& n = s.noise;
    return json{{"enabled", s.enabled},
                {"shape", s.shape == postfx::CloudShape::Box ? "box" : "layer"},
                {"bottom_height", number(s.bottomHeight)},
                {"top_height", number(s.topHeight)},
                {"box",
                 {{"center", {doubleNumber(b.center.x), doubleNumber(b.center.y), doubleNumber(b.center.z)}},
                  {"half_size", vec3(glm::vec3(b.halfSize))},
                  {"yaw_deg", number(b.yawDeg)},
                  {"pitch_deg", number(b.pitchDeg)}}},
                {"coverage", number(s.coverage)},
                {"cloud_type", number(s.cloudType)},
                {"density", number(s.density)},
                {"albedo", number(s.albedo)},
                {"anisotropy_forward", number(s.anisotropyForward)},
                {"anisotropy_back", number(s.anisotropyBack)},
                {"lobe_mix", number(s.lobeMix)},
                {"multiple_scattering",
                 {{"octaves", m.octaves},
                  {"attenuation", number(m.attenuation)},
                  {"contribution", number(m.contribution)},
                  {"eccentricity", number(m.eccentricity)}}},
                {"steps", s.steps},
                {"light_steps", s.lightSteps},
                {"light_distance", number(s.lightDistance)},
                {"max_distance", number(s.maxDistance)},
                {"wind", vec3(glm::vec3(s.wind))},
                {"jitter", s.jitter},
                {"noise",
                 {{"enabled", n.enabled},
                  {"base_size", n.baseSize},
                  {"detail_size", n.detailSize},
                  {"seed", n.seed},
                  {"tiling", number(n.tiling)},
                  {"detail_strength", number(n.detailStrength)}}}};
}

}  // namespace demo
