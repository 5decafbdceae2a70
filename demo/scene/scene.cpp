// Scene files (JSON): parsing, validation and serialisation. The format is documented in
// docs/scene-format.md; keep the two in sync.
#include "scene/scene.h"

#include "scene/fog_json.h"
#include "scene/json_read.h"
#include "scene/json_text.h"
#include "scene/lights_json.h"
#include "scene/transparency_json.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <utility>

namespace demo {
namespace {

using json = nlohmann::json;
using namespace json_read;

// ---- JSON text -> DOM ------------------------------------------------------------------------------

// Builds the DOM like nlohmann's own parser, but knows the key path of the value being parsed, so
// that it can reject duplicate keys, limit the nesting depth (copying and dumping a json are
// recursive) and name the key of a number that overflows (1e999).
class DomBuilder final : public json::json_sax_t {
public:
    DomBuilder(const std::string& text, json& root) : text_(text), root_(root) {}

    const std::string& error() const { return error_; }

    bool null() override { return value(json(nullptr)); }
    bool boolean(bool v) override { return value(json(v)); }
    bool number_integer(number_integer_t v) override { return value(json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return value(json(v)); }
    bool number_float(number_float_t v, const string_t& /*text*/) override { return value(json(v)); }
    bool string(string_t& v) override { return value(json(std::move(v))); }
    bool binary(binary_t& v) override { return value(json::binary(std::move(v))); }
    bool start_object(std::size_t /*elements*/) override { return open(json::object()); }
    bool start_array(std::size_t /*elements*/) override { return open(json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& k) override {
        Frame& top = stack_.back();
        const bool duplicate = top.node->contains(k);
        top.key = std::move(k);
        if (duplicate) return setError(pendingPath() + ": duplicate key");
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const json::exception& ex) override {
        if (ex.id == 406) {  // out_of_range.406: a number literal that overflows a double
            return setError(pendingPath() + ": expected a finite number, got " + truncated(lastToken, 40));
        }
        // A byte that is not UTF-8 inside a string: the object or array it is in, then its position.
        if (std::strstr(ex.what(), "ill-formed UTF-8") && !stack_.empty())
            return setError(containerPath() + ": " + json_text::syntaxError(text_, position, ex.what()));
        return setError(json_text::syntaxError(text_, position, ex.what()));
    }

private:
    static constexpr std::size_t kMaxDepth = 64;

    struct Frame {
        json* node;       // an open array or object
        std::string key;  // object: the key of the value being parsed
    };

    json* insert(json&& v) {
        if (stack_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Frame& top = stack_.back();
        if (top.node->is_array()) {
            top.node->push_back(std::move(v));
            return &top.node->back();
        }
        json& slot = (*top.node)[top.key];
        slot = std::move(v);
        return &slot;
    }

    bool value(json&& v) {
        insert(std::move(v));
        return true;
    }

    bool open(json&& container) {
        if (stack_.size() >= kMaxDepth) {
            return setError(pendingPath() + ": nested deeper than " + std::to_string(kMaxDepth) + " levels");
        }
        json* node = insert(std::move(container));
        stack_.push_back(Frame{node, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // The key path of the value about to be inserted.
    std::string pendingPath() const {
        std::string path;
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            const Frame& f = stack_[i];
            if (f.node->is_array()) {
                // Below the top, the open child is the array's last element; at the top, the next one.
                const std::size_t size = f.node->size();
                path = json_text::indexPath(path, i + 1 == stack_.size() ? size : size - 1);
            } else {
                path = json_text::keyPath(path, f.key);
            }
        }
        return path.empty() ? std::string("(root)") : path;
    }

    // The key path of the innermost open object or array.
    std::string containerPath() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < stack_.size(); ++i) {
            const Frame& f = stack_[i];
            path = f.node->is_array() ? json_text::indexPath(path, f.node->size() - 1)
                                      : json_text::keyPath(path, f.key);
        }
        return path.empty() ? std::string("(root)") : path;
    }

    bool setError(std::string message) {
        error_ = std::move(message);
        return false;  // stops the parser
    }

    static std::string truncated(const std::string& s, std::size_t maxBytes) {
        return json_text::truncateUtf8(s, maxBytes);
    }

    const std::string& text_;
    json& root_;
    std::vector<Frame> stack_;
    std::string error_;
};

// ---- scene -----------------------------------------------------------------------------------------

constexpr const char* kTopKeys[] = {"camera",           "sun",       "ambient",   "sky",
                                    "objects",          "lights",    "effects",   "frame_time",
                                    "camera_cut_frame", "budget_ms", "particles", "volumetrics_lookup"};
constexpr const char* kCameraKeys[] = {"position", "look_at", "up",       "fov_y_deg", "near",
                                       "far",      "ev100",   "velocity", "yaw_rate"};
constexpr const char* kSunKeys[] = {"direction", "illuminance", "shadows"};
constexpr const char* kPlaneKeys[] = {"type", "point", "normal", "albedo", "opacity", "forward"};
constexpr const char* kBoxKeys[] = {"type", "center", "half_size", "albedo", "opacity", "forward"};
constexpr const char* kSphereKeys[] = {"type", "center", "radius", "albedo", "opacity", "forward"};

// The view direction and up vector must make a usable basis: sin(angle) at least this.
constexpr double kMinSinUpView = 1e-3;
// look_at must be at least this far from position [m].
constexpr double kMinLookDistance = 1e-3;

// Intervals of the numeric keys (limits in scene.h; docs/scene-format.md lists them with each key).
constexpr Interval kCoordinate{-limits::kMaxCoordinate, limits::kMaxCoordinate, "[-1e7, 1e7]"};
constexpr Interval kObjectSize{0.0, limits::kMaxObjectSize, "(0, 1e7]", true};
constexpr Interval kFovYDeg{limits::kMinFovYDeg, limits::kMaxFovYDeg, "[0.01, 179]"};
constexpr Interval kNear{limits::kMinNear, limits::kMaxNear, "[1e-6, 1e6]"};
constexpr Interval kEv100{limits::kMinEv100, limits::kMaxEv100, "[-30, 30]"};
constexpr Interval kLight{0.0, limits::kMaxLight, "[0, 1e7]"};
constexpr Interval kVelocity{-limits::kMaxSpeed, limits::kMaxSpeed, "[-1e4, 1e4]"};
constexpr Interval kYawRate{-limits::kMaxYawRateDeg, limits::kMaxYawRateDeg, "[-36000, 36000]"};
constexpr Interval kFrameTime{0.0, limits::kMaxFrameTime, "(0, 1]", true};
constexpr Interval kBudgetMs{0.0, 1000.0, "[0, 1000]"};

Camera readCamera(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kCameraKeys);
    Camera c;
    c.position = readVec3(require(j, path, "position"), child(path, "position"), kCoordinate);
    c.lookAt = readVec3(require(j, path, "look_at"), child(path, "look_at"), kCoordinate);
    const json* up = find(j, "up");
    if (up) c.up = readVec3(*up, child(path, "up"), kCoordinate);

    c.fovYDeg = readNumber(require(j, path, "fov_y_deg"), child(path, "fov_y_deg"), kFovYDeg);
    c.nearPlane = readNumber(require(j, path, "near"), child(path, "near"), kNear);
    const json& far = require(j, path, "far");
    c.farPlane = readNumber(far, child(path, "far"));
    if (!(c.farPlane > c.nearPlane && c.farPlane <= limits::kMaxFar)) {
        fail(child(path, "far"), "expected a number in (near, 1e9], near being " +
                                     json_text::formatFloat(c.nearPlane) + got(far));
    }
    if (const json* ev = find(j, "ev100")) c.ev100 = readNumber(*ev, child(path, "ev100"), kEv100);
    if (const json* v = find(j, "velocity")) c.velocity = readVec3(*v, child(path, "velocity"), kVelocity);
    if (const json* y = find(j, "yaw_rate")) c.yawRateDeg = readNumber(*y, child(path, "yaw_rate"), kYawRate);

    const glm::dvec3 view = glm::dvec3(c.lookAt) - glm::dvec3(c.position);
    const double distance = glm::length(view);
    if (!(distance >= kMinLookDistance)) {
        fail(child(path, "look_at"), "must be at least 1 mm away from " + child(path, "position") +
                                         " (distance " + json_text::formatFloat(float(distance)) + " m)");
    }
    // The renderer builds the view basis in float (glm::lookAtRH): a shorter up would underflow there.
    const glm::dvec3 upd(c.up);
    const double upLength = glm::length(upd);
    if (!(upLength >= double(float(limits::kMinUpLength))))  // as written in a file: 1e-6
        fail(child(path, "up"), "expected a vector of length >= 1e-6" + (up ? got(*up) : ""));
    if (!(glm::length(glm::cross(view / distance, upd / upLength)) >= kMinSinUpView)) {
        fail(child(path, "up"),
             std::string("must not be parallel to the view direction (look_at - position)") +
                 (up ? "" : "; up defaults to [0, 1, 0]"));
    }
    return c;
}

Sun readSun(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kSunKeys);
    Sun s;
    s.direction = readDirection(require(j, path, "direction"), child(path, "direction"));
    s.illuminance = readVec3(require(j, path, "illuminance"), child(path, "illuminance"), kLight);
    s.shadows = readBool(require(j, path, "shadows"), child(path, "shadows"));
    return s;
}

Object readObject(const json& j, const std::string& path) {
    expectObject(j, path);
    const std::string typePath = child(path, "type");
    const json& type = require(j, path, "type");
    if (!type.is_string()) fail(typePath, "expected a string (plane, box or sphere)" + got(type));
    const std::string& name = type.get_ref<const std::string&>();

    Object o;
    const auto albedo = [&] {
        return readVec3(require(j, path, "albedo"), child(path, "albedo"), Range::Unit);
    };
    if (name == "plane") {
        checkKeys(j, path, kPlaneKeys, " for a plane");
        o.type = ObjectType::Plane;
        o.position = readVec3(require(j, path, "point"), child(path, "point"), kCoordinate);
        o.normal = readDirection(require(j, path, "normal"), child(path, "normal"));
        o.albedo = albedo();
    } else if (name == "box") {
        checkKeys(j, path, kBoxKeys, " for a box");
        o.type = ObjectType::Box;
        o.position = readVec3(require(j, path, "center"), child(path, "center"), kCoordinate);
        o.halfSize = readVec3(require(j, path, "half_size"), child(path, "half_size"), kObjectSize);
        o.albedo = albedo();
    } else if (name == "sphere") {
        checkKeys(j, path, kSphereKeys, " for a sphere");
        o.type = ObjectType::Sphere;
        o.position = readVec3(require(j, path, "center"), child(path, "center"), kCoordinate);
        o.radius = readNumber(require(j, path, "radius"), child(path, "radius"), kObjectSize);
        o.albedo = albedo();
    } else {
        fail(typePath, "unknown object type " + json_text::quote(name) + " (expected plane, box or sphere)");
    }
    if (const json* a = find(j, "opacity")) o.opacity = readNumber(*a, child(path, "opacity"), Range::Unit);
    if (const json* f = find(j, "forward")) o.forward = readBool(*f, child(path, "forward"));
    return o;
}

Scene readScene(const json& root) {
    if (!root.is_object()) fail("", "expected a JSON object" + got(root));
    checkKeys(root, "", kTopKeys);
    Scene scene;
    scene.camera = readCamera(require(root, "", "camera"), "camera");
    scene.sun = readSun(require(root, "", "sun"), "sun");
    if (const json* a = find(root, "ambient")) scene.ambient = readVec3(*a, "ambient", kLight);
    if (const json* s = find(root, "sky")) scene.sky = readVec3(*s, "sky", kLight);

    const json& objects = require(root, "", "objects");
    if (!objects.is_array()) fail("objects", "expected an array of objects" + got(objects));
    if (objects.size() > limits::kMaxObjects) {
        fail("objects", std::to_string(objects.size()) + " objects are more than the limit of " +
                            std::to_string(limits::kMaxObjects));
    }
    scene.objects.reserve(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i)
        scene.objects.push_back(readObject(objects[i], element("objects", i)));

    if (const json* lights = find(root, "lights")) scene.lights = readLights(*lights, "lights");
    if (const json* effects = find(root, "effects")) readEffects(*effects, "effects", scene);
    if (const json* p = find(root, "particles")) scene.particles = readParticles(*p, "particles");
    if (const json* v = find(root, "volumetrics_lookup"))
        readVolumetricsLookup(*v, "volumetrics_lookup", scene.volumetricsLookup);
    if (const json* t = find(root, "frame_time")) scene.frameTime = readDouble(*t, "frame_time", kFrameTime);
    if (const json* b = find(root, "budget_ms")) scene.budgetMs = readNumber(*b, "budget_ms", kBudgetMs);
    if (const json* c = find(root, "camera_cut_frame"))
        scene.cameraCutFrame = readUint32(*c, "camera_cut_frame");
    return scene;
}

}  // namespace

float exposureFromEv100(float ev100) {
    return 1.0f / (1.2f * std::exp2(ev100));
}

bool parseScene(const std::string& jsonText, Scene& scene, std::string& error) {
    std::string message;
    try {
        json root;
        DomBuilder builder(jsonText, root);
        if (json::sax_parse(jsonText, &builder, json::input_format_t::json, /*strict=*/true)) {
            Scene parsed = readScene(root);
            scene = std::move(parsed);
            error.clear();
            return true;
        }
        message = builder.error();
    } catch (const ReadError& e) {
        message = e.message;
    } catch (const std::exception& e) {
        message = std::string("(root): cannot read the scene: ") + e.what();
    } catch (...) {
        message = "(root): cannot read the scene: unknown error";
    }
    error = json_text::oneLine(message.empty() ? std::string("(root): invalid scene") : message);
    return false;
}

bool loadSceneFile(const std::string& path, Scene& scene, std::string& error) {
    std::string message;
    try {
        std::error_code ec;
        const auto status = std::filesystem::status(path, ec);
        if (!std::filesystem::exists(status)) {
            message = "no such file";
        } else if (ec) {
            message = "cannot open: " + ec.message();
        } else if (!std::filesystem::is_regular_file(status)) {
            message = "not a regular file";
        } else {
            std::ifstream in(path, std::ios::binary);
            std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            if (!in.good() && !in.eof()) {
                message = "cannot read the file";
            } else if (parseScene(text, scene, error)) {
                return true;
            } else {
                message = error;
            }
        }
    } catch (const std::exception& e) {
        message = std::string("cannot read the file: ") + e.what();
    } catch (...) {
        message = "cannot read the file";
    }
    error = json_text::oneLine(path + ": " + message);
    return false;
}

nlohmann::json sceneToJson(const Scene& scene) {
    json j = json::object();
    const Camera& c = scene.camera;
    j["camera"] = {
        {"position", vec3(c.position)},   {"look_at", vec3(c.lookAt)},    {"up", vec3(c.up)},
        {"fov_y_deg", number(c.fovYDeg)}, {"near", number(c.nearPlane)},  {"far", number(c.farPlane)},
        {"ev100", number(c.ev100)},       {"velocity", vec3(c.velocity)}, {"yaw_rate", number(c.yawRateDeg)}};
    j["sun"] = {{"direction", vec3(scene.sun.direction)},
                {"illuminance", vec3(scene.sun.illuminance)},
                {"shadows", scene.sun.shadows}};
    j["ambient"] = vec3(scene.ambient);
    j["sky"] = vec3(scene.sky);
    json objects = json::array();
    for (const Object& o : scene.objects) {
        switch (o.type) {
            case ObjectType::Plane:
                objects.push_back({{"type", "plane"},
                                   {"point", vec3(o.position)},
                                   {"normal", vec3(o.normal)},
                                   {"albedo", vec3(o.albedo)}});
                break;
            case ObjectType::Box:
                objects.push_back({{"type", "box"},
                                   {"center", vec3(o.position)},
                                   {"half_size", vec3(o.halfSize)},
                                   {"albedo", vec3(o.albedo)}});
                break;
            case ObjectType::Sphere:
                objects.push_back({{"type", "sphere"},
                                   {"center", vec3(o.position)},
                                   {"radius", number(o.radius)},
                                   {"albedo", vec3(o.albedo)}});
                break;
        }
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        objects[i]["opacity"] = number(scene.objects[i].opacity);
        objects[i]["forward"] = scene.objects[i].forward;
    }
    j["objects"] = std::move(objects);
    j["particles"] = particlesToJson(scene.particles);
    j["volumetrics_lookup"] = volumetricsLookupToJson(scene.volumetricsLookup);
    j["lights"] = lightsToJson(scene.lights);
    j["effects"] = effectsToJson(scene);
    j["frame_time"] = doubleNumber(scene.frameTime);
    if (scene.cameraCutFrame) j["camera_cut_frame"] = *scene.cameraCutFrame;
    j["budget_ms"] = number(scene.budgetMs);
    return j;
}

bool hasForwardDraws(const Scene& scene) {
    for (const Object& o : scene.objects)
        if (drawnForward(o)) return true;
    for (const ParticleEmitter& e : scene.particles)
        if (e.enabled && e.count > 0) return true;
    return false;
}

postfx::FroxelFogSettings froxelFogSettings(const Scene& scene) {
    postfx::FroxelFogSettings s = scene.froxelFog;
    s.volumes = scene.froxelVolumes.empty() ? nullptr : scene.froxelVolumes.data();
    s.volumeCount = uint32_t(scene.froxelVolumes.size());
    return s;
}

Scene defaultScene() {
    // Parsed once; tests/demo/test_scene.cpp checks that the embedded file is valid.
    static const Scene scene = [] {
        Scene s;
        std::string error;
        if (!parseScene(defaultSceneJson(), s, error)) {
            std::fprintf(stderr, "demo: the built-in default scene is invalid: %s\n", error.c_str());
            return Scene{};
        }
        return s;
    }();
    return scene;
}

}  // namespace demo
