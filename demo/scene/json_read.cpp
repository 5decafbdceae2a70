#include "scene/json_read.h"

#include "scene/json_text.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace demo::json_read {

void fail(const std::string& path, const std::string& what) {
    throw ReadError{(path.empty() ? std::string("(root)") : path) + ": " + what};
}

std::string child(const std::string& path, const char* key) {
    return json_text::keyPath(path, key);
}
std::string element(const std::string& path, std::size_t i) {
    return json_text::indexPath(path, i);
}

std::string got(const json& j) {
    return ", got " + json_text::describe(j);
}

namespace {

// readDirection keeps a vector whose length is within this of 1 (a float normalised in double and
// rounded is within about 1e-7).
constexpr double kUnitLengthTolerance = 1e-6;

// "a, b, c or d"
std::string listOf(std::span<const char* const> names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
        out += names[i];
    }
    return out;
}

}  // namespace

void expectObject(const json& j, const std::string& path) {
    if (!j.is_object()) fail(path, "expected an object" + got(j));
}

void checkKeys(const json& obj, const std::string& path, std::span<const char* const> allowed,
               const std::string& what) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
        const bool known =
            std::any_of(allowed.begin(), allowed.end(), [&](const char* name) { return it.key() == name; });
        if (!known) {
            fail(json_text::keyPath(path, it.key()),
                 "unknown key" + what + " (expected " + listOf(allowed) + ")");
        }
    }
}

const json* find(const json& obj, const char* key) {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

const json& require(const json& obj, const std::string& path, const char* key) {
    const json* v = find(obj, key);
    if (!v) fail(child(path, key), "missing");
    return *v;
}

float readNumber(const json& j, const std::string& path, Range range) {
    if (!j.is_number()) fail(path, "expected a number" + got(j));
    const double d = j.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number" + got(j));
    if (std::fabs(d) > double(FLT_MAX)) fail(path, "expected a number of magnitude <= 3.4e38" + got(j));
    const float f = float(d);
    switch (range) {
        case Range::Any:
            break;
        case Range::Positive:
            if (!(f > 0.0f)) fail(path, "expected a number > 0" + got(j));
            break;
        case Range::NonNegative:
            if (!(f >= 0.0f)) fail(path, "expected a number >= 0" + got(j));
            break;
        case Range::Unit:
            if (!(f >= 0.0f && f <= 1.0f)) fail(path, "expected a number in [0, 1]" + got(j));
            break;
    }
    return f;
}

glm::vec3 readVec3(const json& j, const std::string& path, Range range) {
    if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers" + got(j));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = readNumber(j[std::size_t(i)], element(path, std::size_t(i)), range);
    return v;
}

float readNumber(const json& j, const std::string& path, const Interval& interval) {
    // Compared as floats, so that a bound written in the file (1e-6) is inside even where the float
    // nearest to it is not (float(1e-6) < 1e-6).
    const float f = readNumber(j, path);
    const float lo = float(interval.lo), hi = float(interval.hi);
    const bool aboveLo = interval.openLo ? f > lo : f >= lo;
    if (!aboveLo || f > hi) fail(path, std::string("expected a number in ") + interval.text + got(j));
    return f;
}

glm::vec3 readVec3(const json& j, const std::string& path, const Interval& interval) {
    if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers" + got(j));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = readNumber(j[std::size_t(i)], element(path, std::size_t(i)), interval);
    return v;
}

double readDouble(const json& j, const std::string& path, const Interval& interval) {
    if (!j.is_number()) fail(path, "expected a number" + got(j));
    const double d = j.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number" + got(j));
    const bool aboveLo = interval.openLo ? d > interval.lo : d >= interval.lo;
    if (!aboveLo || d > interval.hi)
        fail(path, std::string("expected a number in ") + interval.text + got(j));
    return d;
}

glm::vec3 readDirection(const json& j, const std::string& path) {
    // Computed in double, so tiny vectors are fine too.
    const glm::vec3 f = readVec3(j, path);
    const glm::dvec3 v(f);
    const double length = glm::length(v);
    if (!(length > 0.0)) fail(path, "expected a non-zero vector" + got(j));
    // A vector already of unit length (as normalised and written by sceneToJson) is kept: normalising it
    // again can move a component by one float step, and the file would not read back as the same scene.
    if (std::fabs(length - 1.0) <= kUnitLengthTolerance) return f;
    return glm::vec3(v / length);
}

bool readBool(const json& j, const std::string& path) {
    if (!j.is_boolean()) fail(path, "expected true or false" + got(j));
    return j.get<bool>();
}

uint32_t readUint32(const json& j, const std::string& path) {
    constexpr double kMax = 4294967295.0;
    if (j.is_number_unsigned()) {
        const auto u = j.get<json::number_unsigned_t>();
        if (u > json::number_unsigned_t(UINT32_MAX))
            fail(path, "expected an integer in [0, 4294967295]" + got(j));
        return uint32_t(u);
    }
    if (j.is_number_integer()) {  // signed: negative (non-negative integers parse as unsigned)
        const auto i = j.get<json::number_integer_t>();
        if (i < 0 || double(i) > kMax) fail(path, "expected an integer in [0, 4294967295]" + got(j));
        return uint32_t(i);
    }
    if (!j.is_number()) fail(path, "expected an integer" + got(j));
    const double d = j.get<double>();
    if (!std::isfinite(d) || d != std::floor(d)) fail(path, "expected an integer" + got(j));
    if (d < 0.0 || d > kMax) fail(path, "expected an integer in [0, 4294967295]" + got(j));
    return uint32_t(d);
}

json number(float f) {
    return json(json_text::roundTripDouble(f));
}

json doubleNumber(double d) {
    return json(d);  // nlohmann writes a double in its shortest round-trip form
}

json vec3(const glm::vec3& v) {
    return json::array({number(v.x), number(v.y), number(v.z)});
}

namespace {
template <class V>
V readUvec(const json& j, const std::string& path) {
    constexpr auto n = std::size_t(V::length());
    if (!j.is_array() || j.size() != n)
        fail(path, "expected an array of " + std::to_string(n) + " integers" + got(j));
    V v;
    for (std::size_t i = 0; i < n; ++i)
        v[glm::length_t(i)] = readUint32(j[i], element(path, i));
    return v;
}
}  // namespace

postfx::UVec2 readUvec2(const json& j, const std::string& path) {
    return readUvec<postfx::UVec2>(j, path);
}
postfx::UVec3 readUvec3(const json& j, const std::string& path) {
    return readUvec<postfx::UVec3>(j, path);
}

void readOptional(const json& j, const std::string& path, const char* key, float& out) {
    if (const json* v = find(j, key)) out = readNumber(*v, child(path, key));
}
void readOptional(const json& j, const std::string& path, const char* key, postfx::Vec3& out) {
    if (const json* v = find(j, key)) out = postfx::Vec3(readVec3(*v, child(path, key)));
}
void readOptional(const json& j, const std::string& path, const char* key, bool& out) {
    if (const json* v = find(j, key)) out = readBool(*v, child(path, key));
}
void readOptional(const json& j, const std::string& path, const char* key, uint32_t& out) {
    if (const json* v = find(j, key)) out = readUint32(*v, child(path, key));
}
void readOptional(const json& j, const std::string& path, const char* key, postfx::UVec2& out) {
    if (const json* v = find(j, key)) out = readUvec2(*v, child(path, key));
}
void readOptional(const json& j, const std::string& path, const char* key, postfx::UVec3& out) {
    if (const json* v = find(j, key)) out = readUvec3(*v, child(path, key));
}

}  // namespace demo::json_read
