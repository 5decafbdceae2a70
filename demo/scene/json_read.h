// Validating readers of scene-file values, shared by the parts of the scene parser (scene.cpp,
// fog_json.cpp); internal to demo_scene. Every reader names the key path of a bad value and throws
// ReadError, which parseScene catches: it never leaves demo_scene.
#pragma once

#include <postfx/types.h>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace demo::json_read {

using json = nlohmann::json;

// One line, starting with the key path of the offending value ("camera.near: ...").
struct ReadError {
    std::string message;
};

// Throws ReadError{"<path>: <what>"} ("(root)" for an empty path).
[[noreturn]] void fail(const std::string& path, const std::string& what);

std::string child(const std::string& path, const char* key);  // "a" + "b" -> "a.b"
std::string element(const std::string& path, std::size_t i);  // "a" + 2 -> "a[2]"
std::string got(const json& j);                               // ", got <value>"

void expectObject(const json& j, const std::string& path);
// Unknown keys are errors (typo protection). `what` is e.g. "" or " for a box".
void checkKeys(const json& obj, const std::string& path, std::span<const char* const> allowed,
               const std::string& what = "");
const json* find(const json& obj, const char* key);  // nullptr when absent
const json& require(const json& obj, const std::string& path, const char* key);

enum class Range { Any, Positive, NonNegative, Unit };

// An interval of accepted values and its text for messages: {0, 1e7, "[0, 1e7]"}; openLo excludes lo
// ({0, 1e6, "(0, 1e6]", true}).
struct Interval {
    double lo;
    double hi;
    const char* text;
    bool openLo = false;
};

// A finite number that fits a float, checked against `range`.
float readNumber(const json& j, const std::string& path, Range range = Range::Any);
glm::vec3 readVec3(const json& j, const std::string& path, Range range = Range::Any);
// The same in `interval`: "<path>: expected a number in <interval.text>, got <value>".
float readNumber(const json& j, const std::string& path, const Interval& interval);
glm::vec3 readVec3(const json& j, const std::string& path, const Interval& interval);
// A finite number in `interval` kept in double (as written, not rounded to a float).
double readDouble(const json& j, const std::string& path, const Interval& interval);
// A non-zero vector, returned normalised (as it is when its length is already within 1e-6 of 1, so
// that a scene written by sceneToJson reads back exactly).
glm::vec3 readDirection(const json& j, const std::string& path);
bool readBool(const json& j, const std::string& path);
// A whole number in [0, 4294967295], written as an integer or a decimal with no fraction (32, 32.0).
uint32_t readUint32(const json& j, const std::string& path);

// An array of V::length() whole numbers (readUint32 each): [w, h], [x, y, z].
postfx::UVec2 readUvec2(const json& j, const std::string& path);
postfx::UVec3 readUvec3(const json& j, const std::string& path);

// `out` = the value at `key` of object `j` (path `path`) read as its type's reader reads it, when the key is
// present; unchanged otherwise (the settings' default).
void readOptional(const json& j, const std::string& path, const char* key, float& out);
void readOptional(const json& j, const std::string& path, const char* key, postfx::Vec3& out);
void readOptional(const json& j, const std::string& path, const char* key, bool& out);
void readOptional(const json& j, const std::string& path, const char* key, uint32_t& out);
void readOptional(const json& j, const std::string& path, const char* key, postfx::UVec2& out);
void readOptional(const json& j, const std::string& path, const char* key, postfx::UVec3& out);

// Writers, in the form the readers accept back exactly.
json number(float f);
json vec3(const glm::vec3& v);
// A double in its shortest form that reads back as the same double (readDouble).
json doubleNumber(double d);

}  // namespace demo::json_read
