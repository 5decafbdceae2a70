// Scene files: `effects.froxel_fog` <-> postfx::FroxelFogSettings, read and written from its settings table
// (postfx::froxelFogSettingsTable, settings_json.cpp), and its volumes, read by hand (each entry's keys
// depend on its shape). Keep docs/scene-format.md#effectsfroxel_fog in sync.
#include "scene/froxel_fog_json.h"

#include "scene/json_read.h"
#include "scene/json_text.h"
#include "scene/settings_json.h"

#include <postfx/settings_table.h>

namespace demo {
namespace {

using namespace json_read;

// Read by hand besides the table's keys: a list whose entries take keys by their shape (readVolume).
constexpr const char* kVolumesKey[] = {"volumes"};
constexpr const char* kBoxVolumeKeys[] = {"shape", "center", "half_size", "density", "edge_falloff"};
constexpr const char* kSphereVolumeKeys[] = {"shape", "center", "radius", "density", "edge_falloff"};

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

const char* fogVolumeShapeName(postfx::FogVolumeShape shape) {
    return shape == postfx::FogVolumeShape::Sphere ? "sphere" : "box";
}

void readFroxelFog(const json& j, const std::string& path, postfx::FroxelFogSettings& settings,
                   std::vector<postfx::FogVolume>& volumes) {
    postfx::FroxelFogSettings s;
    s.enabled = true;  // the object's presence turns the froxel fog on unless it says otherwise
    // and a `noise` object the noise
    if (j.is_object() && find(j, "noise")) s.noise.enabled = true;
    settings_json::readFields(j, path, postfx::froxelFogSettingsTable(), &s, kVolumesKey);
    std::vector<postfx::FogVolume> vs;
    if (const json* v = find(j, "volumes")) vs = readVolumes(*v, child(path, "volumes"));

    // Ranges: postfx's own check (as for effects.fog), with the noise's keys checked even while it is off.
    // postfx names the field "FrameInfo.froxelFog.<member>" (a volume's "...volumes[i].<member>"); it
    // becomes "effects.froxel_fog.<key>".
    postfx::FroxelFogSettings check = s;
    check.noise.enabled = true;
    check.volumes = vs.data();
    check.volumeCount = uint32_t(vs.size());
    settings_json::throwIfInvalid(postfx::validateFroxelFogSettings(check), "FrameInfo.froxelFog",
                                  postfx::froxelFogSettingsTable(), path, "volumes",
                                  postfx::fogVolumeSettingsTable());
    settings = s;
    volumes = std::move(vs);
}

json froxelFogToJson(const postfx::FroxelFogSettings& s, const std::vector<postfx::FogVolume>& volumes) {
    json j = json::object();
    settings_json::writeFields(postfx::froxelFogSettingsTable(), &s, j);
    json vs = json::array();
    for (const postfx::FogVolume& v : volumes)
        vs.push_back(volumeToJson(v));
    j["volumes"] = std::move(vs);
    return j;
}

}  // namespace demo
