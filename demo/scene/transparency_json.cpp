// Scene files: `particles` and `volumetrics_lookup`. The lookup's ranges are postfx's
// (VolumetricsLookupSettings), so a file that loads renders.
#include "scene/transparency_json.h"

#include "scene/json_read.h"
#include "scene/json_text.h"
#include "scene/scene.h"

namespace demo {
namespace {

using json = nlohmann::json;
using namespace json_read;

constexpr const char* kEmitterKeys[] = {"center",  "half_size", "count",      "quad_size", "albedo",
                                        "opacity", "seed",      "rise_speed", "enabled"};
constexpr const char* kLookupKeys[] = {"extent", "near_distance", "max_distance"};

constexpr Interval kCoordinate{-limits::kMaxCoordinate, limits::kMaxCoordinate, "[-1e7, 1e7]"};
constexpr Interval kParticleSize{0.0, 1e4, "(0, 1e4]", true};
constexpr Interval kSpeed{-limits::kMaxSpeed, limits::kMaxSpeed, "[-1e4, 1e4]"};
constexpr Interval kNearDistance{0.01, 1e5, "[0.01, 1e5]"};

ParticleEmitter readEmitter(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kEmitterKeys, " for a particle emitter");
    ParticleEmitter e;
    e.center = readVec3(require(j, path, "center"), child(path, "center"), kCoordinate);
    e.halfSize = readVec3(require(j, path, "half_size"), child(path, "half_size"), kParticleSize);
    const std::string countPath = child(path, "count");
    const json& count = require(j, path, "count");
    e.count = readUint32(count, countPath);
    if (e.count > kMaxParticlesPerEmitter)
        fail(countPath,
             "expected an integer in [0, " + std::to_string(kMaxParticlesPerEmitter) + "]" + got(count));
    e.quadSize = readNumber(require(j, path, "quad_size"), child(path, "quad_size"), kParticleSize);
    e.albedo = readVec3(require(j, path, "albedo"), child(path, "albedo"), Range::Unit);
    if (const json* o = find(j, "opacity")) e.opacity = readNumber(*o, child(path, "opacity"), Range::Unit);
    if (const json* s = find(j, "seed")) e.seed = readUint32(*s, child(path, "seed"));
    if (const json* r = find(j, "rise_speed"))
        e.riseSpeed = readNumber(*r, child(path, "rise_speed"), kSpeed);
    if (const json* b = find(j, "enabled")) e.enabled = readBool(*b, child(path, "enabled"));
    return e;
}

}  // namespace

std::vector<ParticleEmitter> readParticles(const json& particles, const std::string& path) {
    if (!particles.is_array()) fail(path, "expected an array of particle emitters" + got(particles));
    if (particles.size() > kMaxParticleEmitters) {
        fail(path, std::to_string(particles.size()) + " particle emitters are more than the limit of " +
                       std::to_string(kMaxParticleEmitters));
    }
    std::vector<ParticleEmitter> out;
    for (std::size_t i = 0; i < particles.size(); ++i)
        out.push_back(readEmitter(particles[i], element(path, i)));
    return out;
}

json particlesToJson(const std::vector<ParticleEmitter>& particles) {
    json out = json::array();
    for (const ParticleEmitter& e : particles) {
        out.push_back({{"center", vec3(e.center)},
                       {"half_size", vec3(e.halfSize)},
                       {"count", e.count},
                       {"quad_size", number(e.quadSize)},
                       {"albedo", vec3(e.albedo)},
                       {"opacity", number(e.opacity)},
                       {"seed", e.seed},
                       {"rise_speed", number(e.riseSpeed)},
                       {"enabled", e.enabled}});
    }
    return out;
}

void readVolumetricsLookup(const json& j, const std::string& path, postfx::VolumetricsLookupSettings& out) {
    expectObject(j, path);
    checkKeys(j, path, kLookupKeys);
    if (const json* e = find(j, "extent")) {
        const std::string extentPath = child(path, "extent");
        const postfx::UVec3 extent = readUvec3(*e, extentPath);
        if (extent.x < 1 || extent.x > 1024 || extent.y < 1 || extent.y > 1024 || extent.z < 2 ||
            extent.z > 512)
            fail(extentPath, "expected [x, y, z] with x, y in [1, 1024] and z in [2, 512]" + got(*e));
        out.extent = extent;
    }
    if (const json* n = find(j, "near_distance"))
        out.nearDistance = readNumber(*n, child(path, "near_distance"), kNearDistance);
    if (const json* m = find(j, "max_distance")) {
        const Interval far{double(out.nearDistance), 1e7, "(near_distance, 1e7]", true};
        out.maxDistance = readNumber(*m, child(path, "max_distance"), far);
    } else if (!(out.maxDistance > out.nearDistance)) {
        fail(child(path, "max_distance"), "the default " + json_text::formatFloat(out.maxDistance) +
                                              " is not above near_distance: give a max_distance");
    }
}

json volumetricsLookupToJson(const postfx::VolumetricsLookupSettings& lookup) {
    return {{"extent", {lookup.extent.x, lookup.extent.y, lookup.extent.z}},
            {"near_distance", number(lookup.nearDistance)},
            {"max_distance", number(lookup.maxDistance)}};
}

}  // namespace demo
