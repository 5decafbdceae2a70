// Scene files: the `lights` array. Ranges equal what postfx::checkSharedInputs accepts for
// FrameInfo::lights (positions limited to the loader's 1e7 m), so a file that loads renders.
#include "scene/lights_json.h"

#include "scene/json_read.h"
#include "scene/json_text.h"
#include "scene/scene.h"

#include <glm/gtc/constants.hpp>

namespace demo {
namespace {

using json = nlohmann::json;
using namespace json_read;

constexpr const char* kPointKeys[] = {
    "type",     "position",         "intensity", "radius",           "range",
    "velocity", "intensity_change", "shadows",   "shadow_resolution"};
constexpr const char* kSpotKeys[] = {
    "type",    "position",         "direction",       "intensity", "radius",
    "range",   "inner_angle_deg",  "outer_angle_deg", "velocity",  "intensity_change",
    "shadows", "shadow_resolution"};
constexpr const char* kIntensityChangeKeys[] = {"frame", "intensity"};

constexpr Interval kCoordinate{-limits::kMaxCoordinate, limits::kMaxCoordinate, "[-1e7, 1e7]"};
constexpr Interval kIntensity{0.0, 1e9, "[0, 1e9]"};
constexpr Interval kRange{0.0, 1e9, "(0, 1e9]", true};
// postfx accepts outer cone angles up to π/2 (exclusive in practice): 89.9° keeps the cone usable.
constexpr Interval kOuterAngle{0.0, 89.9, "[0, 89.9]"};
constexpr Interval kVelocity{-limits::kMaxSpeed, limits::kMaxSpeed, "[-1e4, 1e4]"};
// Texels per shadow face edge: 16 is the smallest map that still shows a shadow's shape; 4096 is a
// 64 MiB D32 face (six for a point light), as large as engines make local lights' maps.
constexpr uint32_t kMinShadowResolution = 16;
constexpr uint32_t kMaxShadowResolution = 4096;

// `intensity_change`: both keys required.
IntensityChange readIntensityChange(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kIntensityChangeKeys);
    IntensityChange c;
    c.frame = readUint32(require(j, path, "frame"), child(path, "frame"));
    c.intensity = readVec3(require(j, path, "intensity"), child(path, "intensity"), kIntensity);
    return c;
}

Light readLight(const json& j, const std::string& path) {
    expectObject(j, path);
    const std::string typePath = child(path, "type");
    const json& type = require(j, path, "type");
    if (!type.is_string()) fail(typePath, "expected a string (point or spot)" + got(type));
    const std::string& name = type.get_ref<const std::string&>();

    Light l;
    if (name == "point") {
        checkKeys(j, path, kPointKeys, " for a point light");
        l.kind = LightKind::Point;
    } else if (name == "spot") {
        checkKeys(j, path, kSpotKeys, " for a spot light");
        l.kind = LightKind::Spot;
    } else {
        fail(typePath, "unknown light type " + json_text::quote(name) + " (expected point or spot)");
    }
    l.position = readVec3(require(j, path, "position"), child(path, "position"), kCoordinate);
    l.intensity = readVec3(require(j, path, "intensity"), child(path, "intensity"), kIntensity);
    if (const json* r = find(j, "range")) l.range = readNumber(*r, child(path, "range"), kRange);
    if (const json* r = find(j, "radius")) {
        const Interval radius{0.0, double(l.range), "(0, range]", true};
        l.radius = readNumber(*r, child(path, "radius"), radius);
    } else if (l.radius > l.range) {
        fail(child(path, "radius"), "the default 0.05 exceeds range " + json_text::formatFloat(l.range) +
                                        ": give a radius in (0, range]");
    }
    if (l.kind == LightKind::Spot) {
        l.direction = readDirection(require(j, path, "direction"), child(path, "direction"));
        if (const json* a = find(j, "outer_angle_deg"))
            l.outerAngleDeg = readNumber(*a, child(path, "outer_angle_deg"), kOuterAngle);
        if (const json* a = find(j, "inner_angle_deg")) {
            const Interval inner{0.0, double(l.outerAngleDeg), "[0, outer_angle_deg]"};
            l.innerAngleDeg = readNumber(*a, child(path, "inner_angle_deg"), inner);
        }
    }
    if (const json* v = find(j, "velocity")) l.velocity = readVec3(*v, child(path, "velocity"), kVelocity);
    if (const json* c = find(j, "intensity_change"))
        l.intensityChange = readIntensityChange(*c, child(path, "intensity_change"));
    if (const json* s = find(j, "shadows")) l.shadows = readBool(*s, child(path, "shadows"));
    if (const json* r = find(j, "shadow_resolution")) {
        const std::string resolutionPath = child(path, "shadow_resolution");
        const uint32_t resolution = readUint32(*r, resolutionPath);
        if (resolution < kMinShadowResolution || resolution > kMaxShadowResolution)
            fail(resolutionPath, "expected an integer in [16, 4096]" + got(*r));
        l.shadowResolution = resolution;
    }
    return l;
}

}  // namespace

postfx::LocalLight toLocalLight(const Light& light) {
    postfx::LocalLight l;
    l.type = light.kind == LightKind::Spot ? postfx::LightType::Spot : postfx::LightType::Point;
    l.position = postfx::DVec3(light.position);
    l.direction = light.direction;
    l.intensity = light.intensity;
    l.range = light.range;
    l.sourceRadius = light.radius;
    const float toRad = glm::pi<float>() / 180.0f;
    l.innerConeAngle = light.kind == LightKind::Spot ? light.innerAngleDeg * toRad : 0.0f;
    l.outerConeAngle = light.kind == LightKind::Spot ? light.outerAngleDeg * toRad : 0.0f;
    return l;
}

std::vector<Light> readLights(const json& lights, const std::string& path) {
    if (!lights.is_array()) fail(path, "expected an array of lights" + got(lights));
    if (lights.size() > postfx::kMaxLocalLights) {
        fail(path, std::to_string(lights.size()) + " lights are more than the limit of " +
                       std::to_string(postfx::kMaxLocalLights));
    }
    std::vector<Light> out;
    out.reserve(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
        out.push_back(readLight(lights[i], element(path, i)));
    return out;
}

json lightsToJson(const std::vector<Light>& lights) {
    json out = json::array();
    for (const Light& l : lights) {
        json j = {{"type", l.kind == LightKind::Spot ? "spot" : "point"},
                  {"position", vec3(l.position)},
                  {"intensity", vec3(l.intensity)},
                  {"radius", number(l.radius)},
                  {"range", number(l.range)},
                  {"velocity", vec3(l.velocity)},
                  {"shadows", l.shadows},
                  {"shadow_resolution", l.shadowResolution}};
        if (l.intensityChange) {
            j["intensity_change"] = {{"frame", l.intensityChange->frame},
                                     {"intensity", vec3(l.intensityChange->intensity)}};
        }
        if (l.kind == LightKind::Spot) {
            j["direction"] = vec3(l.direction);
            j["inner_angle_deg"] = number(l.innerAngleDeg);
            j["outer_angle_deg"] = number(l.outerAngleDeg);
        }
        out.push_back(std::move(j));
    }
    return out;
}

}  // namespace demo
