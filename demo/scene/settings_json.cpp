#include "scene/settings_json.h"

#include "scene/json_read.h"

#include <postfx/types.h>

#include <algorithm>
#include <cstring>

namespace demo::settings_json {
namespace {

using json = nlohmann::json;
using postfx::SettingField;
using postfx::SettingKind;
using namespace json_read;

// The field's key below `group` ("texture_size" for "noise.texture_size" in "noise"), or nullptr when the
// field is not inside it.
const char* keyIn(const SettingField& f, const std::string& group) {
    if (!f.key) return nullptr;
    if (group.empty()) return f.key;
    if (std::strncmp(f.key, group.c_str(), group.size()) != 0 || f.key[group.size()] != '.') return nullptr;
    return f.key + group.size() + 1;
}

// The first segment of a dotted key ("noise" of "noise.seed"); the key itself when not dotted.
std::string head(const char* key) {
    const char* dot = std::strchr(key, '.');
    return dot ? std::string(key, dot) : std::string(key);
}

void checkObjectKeys(const json& j, const std::string& path, const std::vector<std::string>& keys) {
    std::vector<const char*> names;
    for (const std::string& k : keys)
        names.push_back(k.c_str());
    checkKeys(j, path, names);
}

void readEnum(const json& j, const std::string& path, const SettingField& f, uint32_t& out) {
    if (j.is_string())
        for (const postfx::SettingChoice& c : f.choices)
            if (j.get<std::string>() == c.key) {
                out = c.value;
                return;
            }
    std::string names;
    for (size_t i = 0; i < f.choices.size(); ++i)
        names += std::string(i == 0                      ? ""
                             : i + 1 == f.choices.size() ? " or "
                                                         : ", ") +
                 "\"" + f.choices[i].key + "\"";
    fail(path, "expected " + names + got(j));
}

void readField(const json& j, const std::string& path, const SettingField& f, void* s) {
    switch (f.kind) {
        case SettingKind::Bool:
            postfx::settingValue<bool>(f, s) = readBool(j, path);
            break;
        case SettingKind::Uint:
            postfx::settingValue<uint32_t>(f, s) = readUint32(j, path);
            break;
        case SettingKind::Float:
            postfx::settingValue<float>(f, s) = readNumber(j, path);
            break;
        case SettingKind::Double:
            postfx::settingValue<double>(f, s) = readDouble(j, path, {f.min, f.max, "the field's range"});
            break;
        case SettingKind::Vec3:
            postfx::settingValue<postfx::Vec3>(f, s) = readVec3(j, path);
            break;
        case SettingKind::Color:
            postfx::settingValue<postfx::Vec3>(f, s) = readVec3(j, path, Range::Unit);
            break;
        case SettingKind::DVec3:
            postfx::settingValue<postfx::DVec3>(f, s) = postfx::DVec3(readVec3(j, path));
            break;
        case SettingKind::UVec2:
            postfx::settingValue<postfx::UVec2>(f, s) = readUvec2(j, path);
            break;
        case SettingKind::UVec3:
            postfx::settingValue<postfx::UVec3>(f, s) = readUvec3(j, path);
            break;
        case SettingKind::Enum:
            readEnum(j, path, f, postfx::settingValue<uint32_t>(f, s));
            break;
        case SettingKind::Opaque:
            break;
    }
}

json writeField(const SettingField& f, const void* s) {
    switch (f.kind) {
        case SettingKind::Bool:
            return postfx::settingValue<bool>(f, s);
        case SettingKind::Uint:
            return postfx::settingValue<uint32_t>(f, s);
        case SettingKind::Float:
            return number(postfx::settingValue<float>(f, s));
        case SettingKind::Double:
            return doubleNumber(postfx::settingValue<double>(f, s));
        case SettingKind::Vec3:
        case SettingKind::Color:
            return vec3(postfx::settingValue<postfx::Vec3>(f, s));
        case SettingKind::DVec3:
            return vec3(glm::vec3(postfx::settingValue<postfx::DVec3>(f, s)));
        case SettingKind::UVec2: {
            const postfx::UVec2& v = postfx::settingValue<postfx::UVec2>(f, s);
            return {v.x, v.y};
        }
        case SettingKind::UVec3: {
            const postfx::UVec3& v = postfx::settingValue<postfx::UVec3>(f, s);
            return {v.x, v.y, v.z};
        }
        case SettingKind::Enum: {
            const uint32_t v = postfx::settingValue<uint32_t>(f, s);
            for (const postfx::SettingChoice& c : f.choices)
                if (c.value == v) return c.key;
            return f.choices.empty() ? json() : json(f.choices[0].key);  // a value cast from another int
        }
        case SettingKind::Opaque:
            break;
    }
    return json();
}

}  // namespace

std::vector<std::string> tableKeys(std::span<const SettingField> table, const std::string& group,
                                   std::span<const char* const> extra) {
    std::vector<std::string> keys;
    for (const SettingField& f : table)
        if (const char* k = keyIn(f, group)) {
            const std::string h = head(k);
            if (std::find(keys.begin(), keys.end(), h) == keys.end()) keys.push_back(h);
        }
    keys.insert(keys.end(), extra.begin(), extra.end());
    return keys;
}

void readFields(const json& j, const std::string& path, std::span<const SettingField> table, void* settings,
                std::span<const char* const> extra) {
    expectObject(j, path);
    checkObjectKeys(j, path, tableKeys(table, "", extra));
    readPresentFields(j, path, table, settings);
}

void readPresentFields(const json& j, const std::string& path, std::span<const SettingField> table,
                       void* settings) {
    std::vector<std::string> checked;  // nested objects whose keys are checked
    std::vector<std::pair<const SettingField*, std::string>> present;  // fields given, and their paths
    for (const SettingField& f : table) {
        if (!f.key) continue;
        const json* object = &j;
        std::string objectPath = path;
        std::string group;
        const char* key = f.key;
        for (const char* dot; (dot = std::strchr(key, '.'));) {  // into the nested objects
            const std::string name(key, dot);
            const json* inner = find(*object, name.c_str());
            if (!inner) {
                object = nullptr;
                break;
            }
            group = group.empty() ? name : group + "." + name;
            objectPath = child(objectPath, name.c_str());
            if (std::find(checked.begin(), checked.end(), group) == checked.end()) {
                expectObject(*inner, objectPath);
                checkObjectKeys(*inner, objectPath, tableKeys(table, group));
                checked.push_back(group);
            }
            object = inner;
            key = dot + 1;
        }
        if (!object) continue;
        if (const json* v = find(*object, key)) {
            readField(*v, child(objectPath, key), f, settings);
            present.emplace_back(&f, child(objectPath, key));
        }
    }
    // A key the chosen mode ignores (a box's size with shape "layer") is refused, once every mode is read.
    for (const auto& [f, keyPath] : present)
        if (const std::string reason = postfx::settingUnusedReason(table, *f, settings); !reason.empty())
            fail(keyPath, "ignored " + reason);
}

void writeFields(std::span<const SettingField> table, const void* settings, json& out) {
    for (const SettingField& f : table) {
        if (!f.key || !postfx::settingUsed(table, f, settings)) continue;  // an unused key would be refused
        std::string p = "/" + std::string(f.key);
        std::replace(p.begin(), p.end(), '.', '/');
        out[json::json_pointer(p)] = writeField(f, settings);
    }
}

void throwIfInvalid(const postfx::Status& status, const std::string& cppPrefix,
                    std::span<const SettingField> table, const std::string& path, const char* list,
                    std::span<const SettingField> element) {
    if (status.ok()) return;
    const std::string& m = status.message;
    if (m.size() <= cppPrefix.size() + 1 || m.compare(0, cppPrefix.size(), cppPrefix) != 0 ||
        m[cppPrefix.size()] != '.')
        fail(path, m);
    std::string rest = m.substr(cppPrefix.size() + 1);
    std::string name;
    if (list && rest.rfind(std::string(list) + "[", 0) == 0 && rest.find("].") != std::string::npos) {
        const size_t close = rest.find("].");
        name = rest.substr(0, close + 2);  // "volumes[2]."
        rest = rest.substr(close + 2);
        table = element;
    }
    const size_t end = rest.find_first_of(":[ ");
    const std::string member = rest.substr(0, end);
    const SettingField* f = postfx::findSettingByMember(table, member.c_str());
    name += f && f->key ? std::string(f->key) : member;
    throw ReadError{path + "." + name + (end == std::string::npos ? "" : rest.substr(end))};
}

}  // namespace demo::settings_json
