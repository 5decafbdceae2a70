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
                                      "quality",
                                      "auto_budget_ms",
                                      "resolution_scale",
                                      "temporal",
                                      "cast_shadows",
                                      "shadow_map",
                                      "noise"};
constexpr const char* kBoxKeys[] = {"center", "half_size", "yaw_deg", "pitch_deg"};
constexpr const char* kMultipleScatteringKeys[] = {"model", "octaves", "attenuation", "contribution",
                                                   "eccentricity"};
constexpr const char* kShadowMapKeys[] = {"size", "extent"};
constexpr const char* kNoiseKeys[] = {"enabled", "base_size", "detail_size",
                                      "seed",    "tiling",    "detail_strength"};

// The object at `key` of `j` when present (its keys checked against `keys`), with its key path in `path`;
// null when absent.
template <std::size_t N>
const json* nestedObject(const json& j, const std::string& parent, const char* key,
                         const char* const (&keys)[N], std::string& path) {
    const json* o = find(j, key);
    if (!o) return nullptr;
    path = child(parent, key);
    expectObject(*o, path);
    checkKeys(*o, path, keys);
    return o;
}

struct QualityName {
    postfx::CloudQuality quality;
    const char* name;
};
constexpr QualityName kQualityNames[] = {
    {postfx::CloudQuality::Custom, "custom"}, {postfx::CloudQuality::Low, "low"},
    {postfx::CloudQuality::Medium, "medium"}, {postfx::CloudQuality::High, "high"},
    {postfx::CloudQuality::Ultra, "ultra"},   {postfx::CloudQuality::Auto, "auto"}};

postfx::CloudQuality readQuality(const json& j, const std::string& path) {
    if (j.is_string())
        for (const QualityName& q : kQualityNames)
            if (j.get<std::string>() == q.name) return q.quality;
    fail(path, "expected \"custom\", \"low\", \"medium\", \"high\", \"ultra\" or \"auto\"" + got(j));
}

const char* qualityName(postfx::CloudQuality quality) {
    for (const QualityName& q : kQualityNames)
        if (q.quality == quality) return q.name;
    return "custom";
}

postfx::CloudShape readShape(const json& j, const std::string& path) {
    if (j == "layer") return postfx::CloudShape::Layer;
    if (j == "box") return postfx::CloudShape::Box;
    fail(path, "expected \"layer\" or \"box\"" + got(j));
}

postfx::CloudScatteringModel readScatteringModel(const json& j, const std::string& path) {
    if (j == "slab") return postfx::CloudScatteringModel::Slab;
    if (j == "octaves") return postfx::CloudScatteringModel::Octaves;
    fail(path, "expected \"slab\" or \"octaves\"" + got(j));
}

}  // namespace

postfx::CloudSettings readClouds(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kCloudKeys);
    postfx::CloudSettings s;
    s.enabled = true;  // the object's presence turns the clouds on unless it says otherwise
    readOptional(j, path, "enabled", s.enabled);
    if (const json* v = find(j, "shape")) s.shape = readShape(*v, child(path, "shape"));
    readOptional(j, path, "bottom_height", s.bottomHeight);
    readOptional(j, path, "top_height", s.topHeight);
    std::string p;
    if (const json* b = nestedObject(j, path, "box", kBoxKeys, p)) {
        // Read as the froxel fog's volumes' centres: a float triple, validated by postfx (within ±1e9).
        if (const json* c = find(*b, "center"))
            s.box.center = postfx::DVec3(readVec3(*c, child(p, "center")));
        readOptional(*b, p, "half_size", s.box.halfSize);
        readOptional(*b, p, "yaw_deg", s.box.yawDeg);
        readOptional(*b, p, "pitch_deg", s.box.pitchDeg);
    }
    readOptional(j, path, "coverage", s.coverage);
    readOptional(j, path, "cloud_type", s.cloudType);
    readOptional(j, path, "density", s.density);
    readOptional(j, path, "albedo", s.albedo);
    readOptional(j, path, "anisotropy_forward", s.anisotropyForward);
    readOptional(j, path, "anisotropy_back", s.anisotropyBack);
    readOptional(j, path, "lobe_mix", s.lobeMix);
    if (const json* m = nestedObject(j, path, "multiple_scattering", kMultipleScatteringKeys, p)) {
        if (const json* v = find(*m, "model"))
            s.multipleScattering.model = readScatteringModel(*v, child(p, "model"));
        readOptional(*m, p, "octaves", s.multipleScattering.octaves);
        readOptional(*m, p, "attenuation", s.multipleScattering.attenuation);
        readOptional(*m, p, "contribution", s.multipleScattering.contribution);
        readOptional(*m, p, "eccentricity", s.multipleScattering.eccentricity);
    }
    readOptional(j, path, "steps", s.steps);
    readOptional(j, path, "light_steps", s.lightSteps);
    readOptional(j, path, "light_distance", s.lightDistance);
    readOptional(j, path, "max_distance", s.maxDistance);
    readOptional(j, path, "wind", s.wind);
    readOptional(j, path, "jitter", s.jitter);
    if (const json* v = find(j, "quality")) s.quality = readQuality(*v, child(path, "quality"));
    readOptional(j, path, "auto_budget_ms", s.autoBudgetMs);
    readOptional(j, path, "resolution_scale", s.resolutionScale);
    if (const json* v = find(j, "temporal"))
        medium_json::readTemporal(*v, child(path, "temporal"), s.temporal);
    readOptional(j, path, "cast_shadows", s.castShadows);
    if (const json* m = nestedObject(j, path, "shadow_map", kShadowMapKeys, p)) {
        readOptional(*m, p, "size", s.shadowMap.size);
        readOptional(*m, p, "extent", s.shadowMap.extent);
    }
    if (const json* n = nestedObject(j, path, "noise", kNoiseKeys, p)) {
        s.noise.enabled = true;  // a `noise` object turns the noise on unless it says otherwise
        readOptional(*n, p, "enabled", s.noise.enabled);
        readOptional(*n, p, "base_size", s.noise.baseSize);
        readOptional(*n, p, "detail_size", s.noise.detailSize);
        readOptional(*n, p, "seed", s.noise.seed);
        readOptional(*n, p, "tiling", s.noise.tiling);
        readOptional(*n, p, "detail_strength", s.noise.detailStrength);
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
                 {{"center", vec3(glm::vec3(b.center))},
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
                 {{"model", m.model == postfx::CloudScatteringModel::Octaves ? "octaves" : "slab"},
                  {"octaves", m.octaves},
                  {"attenuation", number(m.attenuation)},
                  {"contribution", number(m.contribution)},
                  {"eccentricity", number(m.eccentricity)}}},
                {"steps", s.steps},
                {"light_steps", s.lightSteps},
                {"light_distance", number(s.lightDistance)},
                {"max_distance", number(s.maxDistance)},
                {"wind", vec3(glm::vec3(s.wind))},
                {"jitter", s.jitter},
                {"quality", qualityName(s.quality)},
                {"auto_budget_ms", number(s.autoBudgetMs)},
                {"resolution_scale", number(s.resolutionScale)},
                {"temporal", medium_json::temporalToJson(s.temporal)},
                {"cast_shadows", s.castShadows},
                {"shadow_map", {{"size", s.shadowMap.size}, {"extent", number(s.shadowMap.extent)}}},
                {"noise",
                 {{"enabled", n.enabled},
                  {"base_size", n.baseSize},
                  {"detail_size", n.detailSize},
                  {"seed", n.seed},
                  {"tiling", number(n.tiling)},
                  {"detail_strength", number(n.detailStrength)}}}};
}

}  // namespace demo
