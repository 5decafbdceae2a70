// Scene files: `effects.froxel_fog` <-> postfx::FroxelFogSettings and its volumes (the medium keys it
// shares with effects.fog: medium_json.cpp). Keep docs/scene-format.md#effectsfroxel_fog in sync.
#include "scene/froxel_fog_json.h"

#include "scene/json_read.h"
#include "scene/json_text.h"
#include "scene/medium_json.h"

namespace demo {
namespace {

using namespace json_read;

// The froxel fog's own keys (besides "enabled" and the medium's).
constexpr const char* kFroxelKeys[] = {"grid",     "tile_size_px", "depth_distribution",    "depth_exponent",
                                       "tricubic", "jitter",       "light_list_min_lights", "volumes",
                                       "temporal"};
constexpr const char* kBoxVolumeKeys[] = {"shape", "center", "half_size", "density", "edge_falloff"};
constexpr const char* kSphereVolumeKeys[] = {"shape", "center", "radius", "density", "edge_falloff"};

postfx::FroxelDepthDistribution readDistribution(const json& j, const std::string& path) {
    if (j.is_string()) {
        if (j.get<std::string>() == "power") return postfx::FroxelDepthDistribution::Power;
        if (j.get<std::string>() == "log") return postfx::FroxelDepthDistribution::Log;
    }
    fail(path, "expected \"power\" or \"log\"" + got(j));
}

// One entry of `volumes`; ranges are checked with the rest by validateFroxelFogSettings.
postfx::FogVolume readVolume(const json& j, const std::string& path) {
    expectObject(j, path);
    const std::string shapePath = child(path, "shape");
    const json& shape = require(j, path, "shape");
    if (!shape.is_string()) fail(shapePath, "expected a string (box or sphere)" + got(shape));
    const std::string& name = shape.get_ref<const std::string&>();
    postfx::FogVolume v;
    if (name == "box") {
        checkKeys(j, path, kBoxVolumeKeys, " for a box volume");
        v.shape = postfx::FogVolumeShape::Box;
        v.halfSize = readVec3(require(j, path, "half_size"), child(path, "half_size"));
    } else if (name == "sphere") {
        checkKeys(j, path, kSphereVolumeKeys, " for a sphere volume");
        v.shape = postfx::FogVolumeShape::Sphere;
        v.radius = readNumber(require(j, path, "radius"), child(path, "radius"));
    } else {
        fail(shapePath, "unknown volume shape " + json_text::quote(name) + " (expected box or sphere)");
    }
    v.center = postfx::DVec3(readVec3(require(j, path, "center"), child(path, "center")));
    if (const json* d = find(j, "density")) v.density = readNumber(*d, child(path, "density"));
    if (const json* e = find(j, "edge_falloff")) v.edgeFalloff = readNumber(*e, child(path, "edge_falloff"));
    return v;
}

std::vector<postfx::FogVolume> readVolumes(const json& j, const std::string& path) {
    if (!j.is_array()) fail(path, "expected an array of volumes" + got(j));
    if (j.size() > postfx::kMaxFogVolumes) {
        fail(path, std::to_string(j.size()) + " volumes are more than the limit of " +
                       std::to_string(postfx::kMaxFogVolumes));
    }
    std::vector<postfx::FogVolume> out;
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i)
        out.push_back(readVolume(j[i], element(path, i)));
    return out;
}

json volumeToJson(const postfx::FogVolume& v) {
    json j = {{"shape", fogVolumeShapeName(v.shape)},
              {"center", vec3(glm::vec3(v.center))},
              {"density", number(v.density)},
              {"edge_falloff", number(v.edgeFalloff)}};
    if (v.shape == postfx::FogVolumeShape::Sphere)
        j["radius"] = number(v.radius);
    else
        j["half_size"] = vec3(v.halfSize);
    return j;
}

}  // namespace

const char* froxelDepthDistributionName(postfx::FroxelDepthDistribution distribution) {
    return distribution == postfx::FroxelDepthDistribution::Log ? "log" : "power";
}

const char* fogVolumeShapeName(postfx::FogVolumeShape shape) {
    return shape == postfx::FogVolumeShape::Sphere ? "sphere" : "box";
}

void readFroxelFog(const json& j, const std::string& path, postfx::FroxelFogSettings& settings,
                   std::vector<postfx::FogVolume>& volumes) {
    expectObject(j, path);
    checkKeys(j, path, medium_json::effectKeys(kFroxelKeys));
    postfx::FroxelFogSettings s;
    s.enabled = true;  // the object's presence turns the froxel fog on unless it says otherwise
    if (const json* v = find(j, "enabled")) s.enabled = readBool(*v, child(path, "enabled"));
    medium_json::readMedium(j, path, s);
    if (const json* v = find(j, "grid")) s.grid = readUvec3(*v, child(path, "grid"));
    if (const json* v = find(j, "tile_size_px")) s.tileSizePx = readUint32(*v, child(path, "tile_size_px"));
    if (const json* v = find(j, "depth_distribution"))
        s.depthDistribution = readDistribution(*v, child(path, "depth_distribution"));
    if (const json* v = find(j, "depth_exponent"))
        s.depthExponent = readNumber(*v, child(path, "depth_exponent"));
    if (const json* v = find(j, "tricubic")) s.tricubic = readBool(*v, child(path, "tricubic"));
    if (const json* v = find(j, "jitter")) s.jitter = readBool(*v, child(path, "jitter"));
    if (const json* v = find(j, "light_list_min_lights"))
        s.lightListMinLights = readUint32(*v, child(path, "light_list_min_lights"));
    if (const json* v = find(j, "temporal"))
        medium_json::readTemporal(*v, child(path, "temporal"), s.temporal);
    std::vector<postfx::FogVolume> vs;
    if (const json* v = find(j, "volumes")) vs = readVolumes(*v, child(path, "volumes"));

    // Ranges: postfx's own check (as for effects.fog), with the noise's keys checked even while it is off.
    // postfx names the field "froxel_fog.<key>"; it becomes "effects.froxel_fog.<key>".
    postfx::FroxelFogSettings check = s;
    check.noise.enabled = true;
    check.volumes = vs.data();
    check.volumeCount = uint32_t(vs.size());
    medium_json::throwIfInvalid(postfx::validateFroxelFogSettings(check), "froxel_fog", path);
    settings = s;
    volumes = std::move(vs);
}

json froxelFogToJson(const postfx::FroxelFogSettings& s, const std::vector<postfx::FogVolume>& volumes) {
    json vs = json::array();
    for (const postfx::FogVolume& v : volumes)
        vs.push_back(volumeToJson(v));
    json j = {{"enabled", s.enabled},
              {"grid", {s.grid.x, s.grid.y, s.grid.z}},
              {"tile_size_px", s.tileSizePx},
              {"depth_distribution", froxelDepthDistributionName(s.depthDistribution)},
              {"depth_exponent", number(s.depthExponent)},
              {"tricubic", s.tricubic},
              {"jitter", s.jitter},
              {"light_list_min_lights", s.lightListMinLights},
              {"temporal", medium_json::temporalToJson(s.temporal)},
              {"volumes", std::move(vs)}};
    medium_json::writeMedium(s, j);
    return j;
}

}  // namespace demo
