#include "core/settings_check.h"

#include "core/checks.h"
#include "core/temporal.h"

#include <postfx/types.h>

#include <cmath>
#include <cstring>

namespace postfx {

const SettingField* findSettingByMember(std::span<const SettingField> table, const char* member) {
    for (const SettingField& f : table)
        if (std::strcmp(f.member, member) == 0) return &f;
    return nullptr;
}

const SettingField* findSettingByKey(std::span<const SettingField> table, const char* key) {
    for (const SettingField& f : table)
        if (f.key && std::strcmp(f.key, key) == 0) return &f;
    return nullptr;
}

bool settingUsed(std::span<const SettingField> table, const SettingField& field, const void* settings) {
    if (!field.usedWith) return true;
    const SettingField* mode = findSettingByMember(table, field.usedWith);
    if (!mode || mode->kind != SettingKind::Enum) return true;
    const uint32_t v = settingValue<uint32_t>(*mode, settings);
    for (uint32_t c : field.usedWithChoices)
        if (c == v) return true;
    return false;
}

std::string settingUnusedReason(std::span<const SettingField> table, const SettingField& field,
                                const void* settings) {
    if (settingUsed(table, field, settings)) return "";
    const SettingField& mode = *findSettingByMember(table, field.usedWith);
    const uint32_t v = settingValue<uint32_t>(mode, settings);
    std::string value = std::to_string(v);
    for (const SettingChoice& c : mode.choices)
        if (c.value == v) value = std::string("\"") + c.key + "\"";
    std::string uses;
    for (size_t i = 0; i < field.usedWithChoices.size(); ++i)
        for (const SettingChoice& c : mode.choices)
            if (c.value == field.usedWithChoices[i])
                uses += std::string(i == 0                                  ? ""
                                    : i + 1 == field.usedWithChoices.size() ? " or "
                                                                            : ", ") +
                        "\"" + c.key + "\"";
    return std::string("with ") + (mode.key ? mode.key : mode.member) + " " + value + " (used with " + uses +
           ")";
}

namespace core {
namespace {

std::string interval(const SettingField& f) {
    return (f.minOpen ? "(" : "[") + numberText(f.min) + ", " + numberText(f.max) + (f.maxOpen ? ")" : "]");
}

// One number against the field's range; `name` names it.
Status checkNumber(const SettingField& f, double v, const std::string& name) {
    const bool bounded = std::isfinite(f.max);
    if (!bounded) {
        if (!std::isfinite(v)) return invalid(name + ": is not finite");
        if (std::isfinite(f.min) && (v < f.min || (f.minOpen && v <= f.min)))
            return invalid(name + ": " + numberText(v) + " must be " + (f.minOpen ? "> " : ">= ") +
                           numberText(f.min));
        return Status::success();
    }
    if (std::isnan(v)) return invalid(name + ": is NaN");
    if (v < f.min || v > f.max || (f.minOpen && v <= f.min) || (f.maxOpen && v >= f.max))
        return invalid(name + ": " + numberText(v) + " is outside " + interval(f));
    return Status::success();
}

// "<name>[c]": a vector's component.
std::string component(const std::string& name, int c) {
    return name + "[" + std::to_string(c) + "]";
}

Status checkEnum(const SettingField& f, uint32_t v, const std::string& name) {
    std::string names;
    for (size_t i = 0; i < f.choices.size(); ++i) {
        if (f.choices[i].value == v) return Status::success();
        names += (i == 0 ? "" : i + 1 == f.choices.size() ? " or " : ", ");
        names += f.choices[i].member;
    }
    return invalid(name + ": " + std::to_string(v) + " is not a " + f.typeName + " (" + names + ")");
}

}  // namespace

std::string settingName(const std::string& prefix, const SettingField& field) {
    return prefix + "." + field.member;
}

bool settingActive(std::span<const SettingField> table, const SettingField& field, const void* settings) {
    if (!field.activeIf) return true;
    const SettingField* on = findSettingByMember(table, field.activeIf);
    return !on || settingValue<bool>(*on, settings);
}

Status checkSettings(std::span<const SettingField> table, const void* settings, const std::string& prefix) {
    for (const SettingField& f : table) {
        if (f.customCheck || !settingActive(table, f, settings)) continue;
        const std::string name = settingName(prefix, f);
        switch (f.kind) {
            case SettingKind::Bool:
            case SettingKind::Opaque:
                break;
            case SettingKind::Uint:
                if (Status s = checkNumber(f, settingValue<uint32_t>(f, settings), name); !s) return s;
                break;
            case SettingKind::Float:
                if (Status s = checkNumber(f, settingValue<float>(f, settings), name); !s) return s;
                break;
            case SettingKind::Double:
                if (Status s = checkNumber(f, settingValue<double>(f, settings), name); !s) return s;
                break;
            case SettingKind::Vec3:
            case SettingKind::Color:
                for (int c = 0; c < 3; ++c)
                    if (Status s = checkNumber(f, settingValue<Vec3>(f, settings)[c], component(name, c)); !s)
                        return s;
                break;
            case SettingKind::DVec3:
                for (int c = 0; c < 3; ++c)
                    if (Status s = checkNumber(f, settingValue<DVec3>(f, settings)[c], component(name, c));
                        !s)
                        return s;
                break;
            case SettingKind::UVec2:
                for (int c = 0; c < 2; ++c)
                    if (Status s = checkNumber(f, settingValue<UVec2>(f, settings)[c], component(name, c));
                        !s)
                        return s;
                break;
            case SettingKind::UVec3:
                for (int c = 0; c < 3; ++c)
                    if (Status s = checkNumber(f, settingValue<UVec3>(f, settings)[c], component(name, c));
                        !s)
                        return s;
                break;
            case SettingKind::Enum:
                if (Status s = checkEnum(f, settingValue<uint32_t>(f, settings), name); !s) return s;
                break;
        }
    }
    return Status::success();
}

uint64_t hashSettings(uint64_t h, std::span<const SettingField> table, const void* settings) {
    for (const SettingField& f : table) {
        if (!f.history || !settingActive(table, f, settings)) continue;
        switch (f.kind) {
            case SettingKind::Bool:
                h = hashValue(h, settingValue<bool>(f, settings));
                break;
            case SettingKind::Uint:
            case SettingKind::Enum:
                h = hashValue(h, settingValue<uint32_t>(f, settings));
                break;
            case SettingKind::Float:
                h = hashValue(h, settingValue<float>(f, settings));
                break;
            case SettingKind::Double:
                h = hashValue(h, settingValue<double>(f, settings));
                break;
            case SettingKind::Vec3:
            case SettingKind::Color:
                h = hashValue(h, settingValue<Vec3>(f, settings));
                break;
            case SettingKind::DVec3:
                h = hashValue(h, settingValue<DVec3>(f, settings));
                break;
            case SettingKind::UVec2:
                h = hashValue(h, settingValue<UVec2>(f, settings));
                break;
            case SettingKind::UVec3:
                h = hashValue(h, settingValue<UVec3>(f, settings));
                break;
            case SettingKind::Opaque:
                h = hashBytes(h, f.address(const_cast<void*>(settings)), f.size);
                break;
        }
    }
    return h;
}

}  // namespace core
}  // namespace postfx
