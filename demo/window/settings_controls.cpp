#include "window/settings_controls.h"

#include "window/medium_controls.h"

#include <postfx/types.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace demo::window {
namespace {

using postfx::SettingField;
using postfx::SettingKind;

// The editor's range of a number: the table's hint, else the valid range.
void editorRange(const SettingField& f, double& lo, double& hi) {
    const bool hint = f.uiMin != 0.0 || f.uiMax != 0.0;
    lo = hint ? f.uiMin : f.min;
    hi = hint ? f.uiMax : f.max;
}

const char* groupKey(const SettingField& f, const std::string& group) {
    if (!f.key) return nullptr;
    if (group.empty()) return std::strchr(f.key, '.') ? nullptr : f.key;
    if (std::strncmp(f.key, group.c_str(), group.size()) != 0 || f.key[group.size()] != '.') return nullptr;
    const char* k = f.key + group.size() + 1;
    return std::strchr(k, '.') ? nullptr : k;
}

float sanitizeNumber(const SettingField& f, float v) {
    if (!std::isfinite(f.max)) {  // unbounded above
        if (std::isnan(v) || (!std::isfinite(f.min) && std::isinf(v))) return float(f.defaults[0]);
        if (std::isfinite(f.min) && (v < f.min || (f.minOpen && v <= f.min)))
            return float(f.minOpen ? f.uiMin : f.min);
        return std::isfinite(v) ? v : float(f.uiMax);
    }
    if (std::isnan(v) || v < f.min || (f.minOpen && v <= f.min)) return float(f.minOpen ? f.uiMin : f.min);
    if (v > f.max || (f.maxOpen && v >= f.max))
        return float(f.maxOpen ? f.max - (f.max - f.min) * 1e-3 : f.max);
    return v;
}

// An integer slider per component of an unsigned vector (`n` components at `v`) over [lo, hi].
bool sliderUints(const char* label, uint32_t* v, int n, double lo, double hi) {
    int i[3] = {};
    for (int c = 0; c < n; ++c)
        i[c] = int(std::min(v[c], uint32_t(INT32_MAX)));
    const int min = int(lo), max = int(hi);
    if (!ImGui::SliderScalarN(label, ImGuiDataType_S32, i, n, &min, &max, "%d", ImGuiSliderFlags_AlwaysClamp))
        return false;
    for (int c = 0; c < n; ++c)
        v[c] = uint32_t(std::clamp(i[c], min, max));
    return true;
}

}  // namespace

std::string settingLabel(const SettingField& f) {
    const char* dot = std::strrchr(f.key ? f.key : f.member, '.');
    std::string label = dot ? dot + 1 : (f.key ? f.key : f.member);
    std::replace(label.begin(), label.end(), '_', ' ');
    if (f.unit[0] && std::strcmp(f.unit, "1") != 0) label += std::string(" [") + f.unit + "]";
    return label;
}

bool settingControl(const SettingField& f, void* s) {
    const std::string label = settingLabel(f);
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp | (f.logScale ? ImGuiSliderFlags_Logarithmic : 0);
    double lo = 0.0, hi = 0.0;
    editorRange(f, lo, hi);
    bool changed = false;
    switch (f.kind) {
        case SettingKind::Bool:
            changed = ImGui::Checkbox(label.c_str(), &postfx::settingValue<bool>(f, s));
            break;
        case SettingKind::Uint: {
            uint32_t& v = postfx::settingValue<uint32_t>(f, s);
            if (hi - lo > 1e6) {  // a seed: any value, typed
                const uint32_t step = 1;
                changed = ImGui::InputScalar(label.c_str(), ImGuiDataType_U32, &v, &step, nullptr, "%u");
            } else {
                changed = widgets::sliderUint(label.c_str(), v, int(lo), int(hi));
            }
            break;
        }
        case SettingKind::Double: {
            const double min = lo, max = hi;
            changed =
                ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &postfx::settingValue<double>(f, s),
                                  std::isfinite(hi - lo) ? float(hi - lo) / 4000.0f : 1.0f, &min, &max,
                                  "%.2f", ImGuiSliderFlags_AlwaysClamp);
            break;
        }
        case SettingKind::Float: {
            float& v = postfx::settingValue<float>(f, s);
            if (std::isfinite(lo) && std::isfinite(hi))
                changed = ImGui::SliderFloat(label.c_str(), &v, float(lo), float(hi), "%.4g", flags);
            else
                changed = ImGui::DragFloat(label.c_str(), &v, 0.1f, 0.0f, 0.0f, "%.4g");
            break;
        }
        case SettingKind::Vec3: {
            postfx::Vec3& v = postfx::settingValue<postfx::Vec3>(f, s);
            const float speed = std::isfinite(hi - lo) ? float(hi - lo) / 4000.0f : 0.05f;
            changed = ImGui::DragFloat3(label.c_str(), &v.x, speed, float(lo), float(hi), "%.2f",
                                        ImGuiSliderFlags_AlwaysClamp);
            break;
        }
        case SettingKind::DVec3: {
            postfx::DVec3& v = postfx::settingValue<postfx::DVec3>(f, s);
            const double dlo = lo, dhi = hi;
            changed =
                ImGui::DragScalarN(label.c_str(), ImGuiDataType_Double, &v.x, 3, float(hi - lo) / 4000.0f,
                                   &dlo, &dhi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
            break;
        }
        case SettingKind::UVec2:
            changed = sliderUints(label.c_str(), &postfx::settingValue<postfx::UVec2>(f, s).x, 2, lo, hi);
            break;
        case SettingKind::UVec3:
            changed = sliderUints(label.c_str(), &postfx::settingValue<postfx::UVec3>(f, s).x, 3, lo, hi);
            break;
        case SettingKind::Color:
            changed = ImGui::ColorEdit3(label.c_str(), &postfx::settingValue<postfx::Vec3>(f, s).x,
                                        ImGuiColorEditFlags_Float);
            break;
        case SettingKind::Enum: {
            uint32_t& v = postfx::settingValue<uint32_t>(f, s);
            std::vector<const char*> names;
            int index = 0;
            for (size_t i = 0; i < f.choices.size(); ++i) {
                names.push_back(f.choices[i].key);
                if (f.choices[i].value == v) index = int(i);
            }
            if (ImGui::Combo(label.c_str(), &index, names.data(), int(names.size()))) {
                v = f.choices[size_t(std::clamp(index, 0, int(names.size()) - 1))].value;
                changed = true;
            }
            break;
        }
        case SettingKind::Opaque:
            return false;
    }
    widgets::tooltip(f.meaning);
    return changed;
}

bool settingControl(std::span<const SettingField> table, const char* member, void* settings) {
    return settingControl(*postfx::findSettingByMember(table, member), settings);
}

bool settingControls(std::span<const SettingField> table, void* settings, const std::string& group,
                     std::initializer_list<const char*> skip, std::span<const SettingField> drawn) {
    bool changed = false;
    for (const SettingField& f : table) {
        if (!groupKey(f, group) || postfx::findSettingByMember(drawn, f.member)) continue;
        if (std::any_of(skip.begin(), skip.end(),
                        [&](const char* m) { return std::strcmp(m, f.member) == 0; }))
            continue;
        const SettingField* on = f.activeIf ? postfx::findSettingByMember(table, f.activeIf) : nullptr;
        // Greyed while its switch is off; hidden while the chosen mode ignores it (a box's size with a
        // layer).
        if (!postfx::settingUsed(table, f, settings)) continue;
        const bool disabled = on && !postfx::settingValue<bool>(*on, static_cast<const void*>(settings));
        if (disabled) ImGui::BeginDisabled();
        changed |= settingControl(f, settings);
        if (disabled) ImGui::EndDisabled();
    }
    return changed;
}

void sanitizeSettings(std::span<const SettingField> table, void* s) {
    for (const SettingField& f : table) {
        switch (f.kind) {
            case SettingKind::Bool:
            case SettingKind::Opaque:
                break;
            case SettingKind::Uint: {
                uint32_t& v = postfx::settingValue<uint32_t>(f, s);
                v = uint32_t(std::clamp(double(v), f.min, f.max));
                break;
            }
            case SettingKind::Float: {
                float& v = postfx::settingValue<float>(f, s);
                v = sanitizeNumber(f, v);
                break;
            }
            case SettingKind::Double: {
                double& v = postfx::settingValue<double>(f, s);
                v = std::isnan(v) ? f.defaults[0] : std::clamp(v, f.min, f.max);
                break;
            }
            case SettingKind::Vec3:
            case SettingKind::Color: {
                postfx::Vec3& v = postfx::settingValue<postfx::Vec3>(f, s);
                for (int c = 0; c < 3; ++c)
                    v[c] = sanitizeNumber(f, v[c]);
                break;
            }
            case SettingKind::DVec3: {
                postfx::DVec3& v = postfx::settingValue<postfx::DVec3>(f, s);
                for (int c = 0; c < 3; ++c)
                    v[c] = std::isnan(v[c]) ? f.defaults[c] : std::clamp(v[c], f.min, f.max);
                break;
            }
            case SettingKind::UVec2: {
                postfx::UVec2& v = postfx::settingValue<postfx::UVec2>(f, s);
                for (int c = 0; c < 2; ++c)
                    v[c] = uint32_t(std::clamp(double(v[c]), f.min, f.max));
                break;
            }
            case SettingKind::UVec3: {
                postfx::UVec3& v = postfx::settingValue<postfx::UVec3>(f, s);
                for (int c = 0; c < 3; ++c)
                    v[c] = uint32_t(std::clamp(double(v[c]), f.min, f.max));
                break;
            }
            case SettingKind::Enum: {
                uint32_t& v = postfx::settingValue<uint32_t>(f, s);
                if (std::none_of(f.choices.begin(), f.choices.end(),
                                 [&](const auto& c) { return c.value == v; }))
                    v = uint32_t(f.defaults[0]);
                break;
            }
        }
    }
}

}  // namespace demo::window
