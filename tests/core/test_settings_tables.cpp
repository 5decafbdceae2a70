// The settings tables (postfx/settings_table.h): each table's defaults are a default-constructed
// struct's, its members are unique, and docs/effects/<effect>.md's parameter table lists every field with
// the table's key, unit, default and range.
#include <postfx/postfx.h>
#include <postfx/settings_table.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using postfx::SettingField;
using postfx::SettingKind;

struct Table {
    const char* name;
    std::span<const SettingField> fields;
    std::function<void(const std::function<void(void*)>&)> withDefault;  // calls back with a default struct
    const char* doc;  // docs/effects/<doc>.md holds its parameter table; nullptr: none of its own
    int index = 0;    // which of the doc's parameter tables (0: the first)
};

template <class S>
std::function<void(const std::function<void(void*)>&)> defaultOf() {
    return [](const std::function<void(void*)>& f) {
        S s{};
        f(&s);
    };
}

std::vector<Table> tables() {
    return {
        {"FogSettings", postfx::fogSettingsTable(), defaultOf<postfx::FogSettings>(), "fog"},
        {"FogMedium", postfx::fogMediumSettingsTable(), defaultOf<postfx::FogMedium>(), nullptr},
        {"FroxelFogSettings", postfx::froxelFogSettingsTable(), defaultOf<postfx::FroxelFogSettings>(),
         "froxel-fog"},
        {"FogVolume", postfx::fogVolumeSettingsTable(), defaultOf<postfx::FogVolume>(), "froxel-fog", 1},
        {"AtmosphereSettings", postfx::atmosphereSettingsTable(), defaultOf<postfx::AtmosphereSettings>(),
         "atmosphere"},
        {"CloudSettings", postfx::cloudSettingsTable(), defaultOf<postfx::CloudSettings>(), "clouds"},
    };
}

// A number as the docs write it: the shortest of %g for a float, exponents without '+' and leading zeros
// (1e6, 3.996e-6).
std::string docNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", float(v));
    std::string t = text;
    const size_t e = t.find('e');
    if (e == std::string::npos) return t;
    std::string exponent = t.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, 1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    return t.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

// Components of a vector kind; 0 for the others.
int components(SettingKind kind) {
    switch (kind) {
        case SettingKind::UVec2:
            return 2;
        case SettingKind::Vec3:
        case SettingKind::DVec3:
        case SettingKind::UVec3:
        case SettingKind::Color:
            return 3;
        default:
            return 0;
    }
}

std::string expectedDefault(const SettingField& f) {
    if (const int n = components(f.kind)) {
        std::string t = "(";
        for (int c = 0; c < n; ++c)
            t += (c ? ", " : "") + docNumber(f.defaults[c]);
        return t + ")";
    }
    switch (f.kind) {
        case SettingKind::Bool:
            return f.defaults[0] != 0.0 ? "true" : "false";
        case SettingKind::Enum:
            for (const postfx::SettingChoice& c : f.choices)
                if (c.value == uint32_t(f.defaults[0])) return c.member;
            return "?";
        case SettingKind::Opaque:
            return "";
        default:
            return docNumber(f.defaults[0]);
    }
}

std::string expectedRange(const SettingField& f) {
    const std::string each = components(f.kind) ? "each " : "";
    switch (f.kind) {
        case SettingKind::Bool:
            return "bool";
        case SettingKind::Opaque:
            return "";
        case SettingKind::Enum: {
            std::string names;
            for (const postfx::SettingChoice& c : f.choices)
                names += (names.empty() ? "" : ", ") + std::string(c.member);
            return names;
        }
        default:
            break;
    }
    if (f.customCheck && components(f.kind)) return "";  // per-component bounds, documented in words
    if (f.kind == SettingKind::Uint && f.min == 0.0 && f.max == 4294967295.0) return "any uint";
    if (!std::isfinite(f.min) && !std::isfinite(f.max)) return "finite";
    if (!std::isfinite(f.max)) return each + (f.minOpen ? "> " : ">= ") + docNumber(f.min);
    return each + (f.minOpen ? "(" : "[") + docNumber(f.min) + ", " + docNumber(f.max) +
           (f.maxOpen ? ")" : "]");
}

// The value of component c of a numeric field (a scalar: c = 0).
double valueOf(const SettingField& f, const void* s, int c) {
    switch (f.kind) {
        case SettingKind::Bool:
            return postfx::settingValue<bool>(f, s) ? 1.0 : 0.0;
        case SettingKind::Uint:
        case SettingKind::Enum:
            return postfx::settingValue<uint32_t>(f, s);
        case SettingKind::Float:
            return postfx::settingValue<float>(f, s);
        case SettingKind::Double:
            return postfx::settingValue<double>(f, s);
        case SettingKind::Vec3:
        case SettingKind::Color:
            return postfx::settingValue<postfx::Vec3>(f, s)[c];
        case SettingKind::DVec3:
            return postfx::settingValue<postfx::DVec3>(f, s)[c];
        case SettingKind::UVec2:
            return postfx::settingValue<postfx::UVec2>(f, s)[c];
        case SettingKind::UVec3:
            return postfx::settingValue<postfx::UVec3>(f, s)[c];
        case SettingKind::Opaque:
            return 0.0;
    }
    return 0.0;
}

std::string unquote(std::string cell) {
    while (!cell.empty() && cell.front() == ' ')
        cell.erase(cell.begin());
    while (!cell.empty() && cell.back() == ' ')
        cell.pop_back();
    if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`') cell = cell.substr(1, cell.size() - 2);
    return cell;
}

// The rows of the index-th table whose header is `| field | key | unit | default | range | meaning |`, by
// field.
std::map<std::string, std::vector<std::string>> docRows(const std::string& path, int index) {
    std::ifstream in(path);
    std::map<std::string, std::vector<std::string>> rows;
    bool inside = false;
    int tables = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("| field | key | unit | default | range | meaning |", 0) == 0) {
            inside = tables++ == index;
            continue;
        }
        if (!inside) continue;
        if (line.rfind("|---", 0) == 0) continue;
        if (line.empty() || line[0] != '|') break;
        std::vector<std::string> cells;
        std::stringstream s(line.substr(1));
        for (std::string cell; std::getline(s, cell, '|');)
            cells.push_back(unquote(cell));
        if (cells.size() >= 5) rows[cells[0]] = cells;
    }
    return rows;
}

TEST(CoreSettingsTables, DefaultsAreADefaultConstructedStructs) {
    for (const Table& t : tables()) {
        t.withDefault([&](void* s) {
            for (const SettingField& f : t.fields) {
                if (f.kind == SettingKind::Opaque) continue;
                const bool isFloat = f.kind == SettingKind::Float || f.kind == SettingKind::Vec3 ||
                                     f.kind == SettingKind::Color;
                for (int c = 0; c < std::max(1, components(f.kind)); ++c) {
                    // Float fields hold the default rounded to float.
                    const double expected = isFloat ? double(float(f.defaults[c])) : f.defaults[c];
                    EXPECT_EQ(valueOf(f, s, c), expected) << t.name << "." << f.member << "[" << c << "]";
                }
            }
        });
    }
}

TEST(CoreSettingsTables, MembersAndKeysAreUniqueAndSwitchesExist) {
    for (const Table& t : tables()) {
        std::set<std::string> members, keys;
        for (const SettingField& f : t.fields) {
            SCOPED_TRACE(std::string(t.name) + "." + f.member);
            EXPECT_TRUE(members.insert(f.member).second);
            if (f.key) {
                EXPECT_TRUE(keys.insert(f.key).second);
            }
            ASSERT_NE(f.address, nullptr);
            if (f.activeIf) {
                const SettingField* on = postfx::findSettingByMember(t.fields, f.activeIf);
                ASSERT_NE(on, nullptr);
                EXPECT_EQ(on->kind, SettingKind::Bool);
            }
            if (f.usedWith) {  // a mode of this table, and values it has
                const SettingField* mode = postfx::findSettingByMember(t.fields, f.usedWith);
                ASSERT_NE(mode, nullptr);
                EXPECT_EQ(mode->kind, SettingKind::Enum);
                EXPECT_FALSE(f.usedWithChoices.empty());
                for (uint32_t v : f.usedWithChoices)
                    EXPECT_TRUE(std::any_of(mode->choices.begin(), mode->choices.end(),
                                            [&](const postfx::SettingChoice& c) { return c.value == v; }));
            }
            if (f.kind == SettingKind::Enum) {
                EXPECT_FALSE(f.choices.empty());
            }
            EXPECT_LE(f.min, f.max);
        }
    }
}

// The registry lists every effect table once, and the address of each effect's settings in a FrameInfo.
TEST(CoreSettingsTables, EveryEffectTableIsRegisteredWithItsFrameMember) {
    postfx::FrameInfo frame;
    const std::pair<std::string, const void*> expected[] = {{"atmosphere", &frame.atmosphere},
                                                            {"clouds", &frame.clouds},
                                                            {"fog", &frame.fog},
                                                            {"froxelFog", &frame.froxelFog}};
    const auto registered = postfx::effectSettingsTables();
    ASSERT_EQ(registered.size(), std::size(expected));
    for (size_t i = 0; i < registered.size(); ++i) {
        EXPECT_EQ(registered[i].member, expected[i].first);
        EXPECT_EQ(registered[i].address(&frame), expected[i].second);
        EXPECT_FALSE(registered[i].table().empty());
    }
}

// A mode's unused fields: settingUsed follows the Enum, and the reason names the mode and its value.
TEST(CoreSettingsTables, FieldsOfAnotherModeAreUnused) {
    postfx::CloudSettings c;
    const auto table = postfx::cloudSettingsTable();
    const SettingField& center = *postfx::findSettingByMember(table, "box.center");
    EXPECT_FALSE(postfx::settingUsed(table, center, &c));
    EXPECT_EQ(postfx::settingUnusedReason(table, center, &c), "with shape \"layer\" (used with \"box\")");
    c.shape = postfx::CloudShape::Box;
    EXPECT_TRUE(postfx::settingUsed(table, center, &c));
    EXPECT_EQ(postfx::settingUnusedReason(table, center, &c), "");
    const SettingField& steps = *postfx::findSettingByMember(table, "steps");
    c.quality = postfx::CloudQuality::Medium;
    EXPECT_EQ(postfx::settingUnusedReason(table, steps, &c),
              "with quality \"medium\" (used with \"custom\")");
    const SettingField& density = *postfx::findSettingByMember(table, "density");
    EXPECT_TRUE(postfx::settingUsed(table, density, &c));  // no mode
}

TEST(CoreSettingsTables, DocsParameterTablesMatch) {
    for (const Table& t : tables()) {
        if (!t.doc) continue;
        const std::string path = std::string(POSTFX_SOURCE_DIR) + "/docs/effects/" + t.doc + ".md";
        const auto rows = docRows(path, t.index);
        ASSERT_FALSE(rows.empty()) << path << " has no parameter table";
        std::set<std::string> listed;
        for (const SettingField& f : t.fields) {
            SCOPED_TRACE(path + ": " + f.member);
            const auto row = rows.find(f.member);
            if (row == rows.end())
                std::printf("missing row: | `%s` | %s | %s | %s | %s | %s |\n", f.member,
                            f.key ? ("`" + std::string(f.key) + "`").c_str() : "–", f.unit[0] ? f.unit : "–",
                            expectedDefault(f).c_str(), expectedRange(f).c_str(), f.meaning);
            ASSERT_NE(row, rows.end()) << "no row for " << f.member;
            listed.insert(f.member);
            const std::vector<std::string>& c = row->second;
            EXPECT_EQ(c[1], f.key ? f.key : "–");
            EXPECT_EQ(c[2], f.unit[0] ? f.unit : "–");
            const std::string def = expectedDefault(f), range = expectedRange(f);
            EXPECT_EQ(c[3].rfind(def, 0), 0u) << "default \"" << c[3] << "\" does not start with " << def;
            EXPECT_NE(c[4].find(range), std::string::npos)
                << "range \"" << c[4] << "\" does not hold " << range;
        }
        for (const auto& [member, cells] : rows)
            EXPECT_TRUE(listed.count(member)) << path << " lists " << member << ", which the table has not";
    }
}

}  // namespace
