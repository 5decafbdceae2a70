// Reflection of the settings structs: one table per effect lists every setting once (its scene-file key,
// C++ member, unit, range, default, whether a change resets the temporal history, meaning) with an
// accessor to the field. postfx derives its range checks, error names and history keys from it; a host's
// editor or serializer can derive its own (the demo's scene files, ImGui controls and the docs' parameter
// tables are). docs/architecture.md, "Settings tables".
#pragma once

#include <postfx/export.h>

#include <cstdint>
#include <limits>
#include <span>
#include <string>

namespace postfx {

// What a field holds, and so how it is accessed (SettingField::address points to it).
enum class SettingKind : uint8_t {
    Bool,    // bool
    Uint,    // uint32_t
    Float,   // float
    Double,  // double (a world coordinate)
    Vec3,    // postfx::Vec3; the range holds for each component
    DVec3,   // postfx::DVec3 (a world position); the range holds for each component
    UVec2,   // postfx::UVec2 (sizes); the range holds for each component
    UVec3,   // postfx::UVec3 (sizes); the range holds for each component
    Color,   // postfx::Vec3 read as an RGB colour; the range holds for each component
    Enum,    // an enum of 32 bits, one of SettingField::choices (accessed as uint32_t)
    Opaque,  // a host handle (a Vulkan object or layout) of `size` bytes: no scene key, no range
};

// One value of an Enum field: its scene-file name, its C++ enumerator name, its value.
struct SettingChoice {
    const char* key;     // "medium"
    const char* member;  // "Medium"
    uint32_t value;
};

inline constexpr double kSettingUnbounded = std::numeric_limits<double>::infinity();

struct SettingField {
    // Scene-file key inside the effect's object; nested objects are dotted ("noise.texture_size").
    // nullptr: not in scene files (host handles).
    const char* key;
    // C++ member path inside the settings struct ("noise.textureSize"); error messages name it.
    const char* member;
    SettingKind kind;
    // "1/m", "m", "1" (a plain number); "" for switches and choices.
    const char* unit = "";
    // Valid range of Uint, Float, Vec3 and Color values; NaN is always refused, and with both bounds
    // infinite a Float must still be finite. minOpen/maxOpen exclude the bound.
    double min = -kSettingUnbounded;
    double max = kSettingUnbounded;
    bool minOpen = false;
    bool maxOpen = false;
    // Default of a default-constructed struct: Bool 0/1, Uint, Float, Enum value in [0]; each component of a
    // vector.
    double defaults[3] = {0.0, 0.0, 0.0};
    // A change resets the temporal history (the effect's history key hashes the field).
    bool history = false;
    // Member of a Bool field of the same table: while it is false this field is neither checked nor
    // hashed ("noise.enabled" for the noise's fields).
    const char* activeIf = nullptr;
    // Enum member of the same table whose value selects a mode: the field takes effect only while that
    // field holds one of `usedWithChoices` (a box's size with shape Box, the octave model's constants with
    // model Octaves, the steps a quality preset sets with quality Custom); other values ignore it. postfx
    // still checks and hashes it; a scene reader refuses the key then, naming it (settingUsed).
    const char* usedWith = nullptr;
    std::span<const uint32_t> usedWithChoices = {};
    // The range is documented here but checked by code beside the table (a power of two, odd sizes, a
    // rule across fields), which names the field by `member` too.
    bool customCheck = false;
    // Editor hints: the usual span of values for a slider (both 0: the valid range) and whether it is
    // logarithmic (the valid range spans decades).
    double uiMin = 0.0;
    double uiMax = 0.0;
    bool logScale = false;
    const char* meaning = "";
    // Enum only: the values and the C++ type's name (for messages).
    std::span<const SettingChoice> choices = {};
    const char* typeName = "";
    // Opaque only: the field's size in bytes.
    uint32_t size = 0;
    // The field inside a settings struct of the table's type (passed as void*).
    void* (*address)(void* settings) = nullptr;
};

// The field's value in `settings` (of the table's struct type), typed by the caller: bool, uint32_t, float,
// double, Vec3 (Vec3 and Color), DVec3, UVec2, UVec3, uint32_t (Enum).
template <class T>
T& settingValue(const SettingField& field, void* settings) {
    return *static_cast<T*>(field.address(settings));
}
template <class T>
const T& settingValue(const SettingField& field, const void* settings) {
    return *static_cast<const T*>(field.address(const_cast<void*>(settings)));
}

// The field whose `member` is `member`, nullptr when none.
POSTFX_API const SettingField* findSettingByMember(std::span<const SettingField> table, const char* member);
// The field whose `key` is `key`, nullptr when none.
POSTFX_API const SettingField* findSettingByKey(std::span<const SettingField> table, const char* key);

// Whether `field` takes effect in `settings` (of the table's struct): its usedWith mode, if any, holds one
// of its usedWithChoices. A reader or editor of settings refuses or hides an unused field.
POSTFX_API bool settingUsed(std::span<const SettingField> table, const SettingField& field,
                            const void* settings);
// "with shape \"layer\"": the mode that leaves `field` unused in `settings`, for a message ("" when used).
POSTFX_API std::string settingUnusedReason(std::span<const SettingField> table, const SettingField& field,
                                           const void* settings);

// The tables, one per settings struct; their fields' address functions take a pointer to that struct.
POSTFX_API std::span<const SettingField> fogSettingsTable();  // FogSettings (the medium's fields included)
POSTFX_API std::span<const SettingField> atmosphereSettingsTable();  // AtmosphereSettings
POSTFX_API std::span<const SettingField> cloudSettingsTable();       // CloudSettings
POSTFX_API std::span<const SettingField> froxelFogSettingsTable();   // FroxelFogSettings (medium included)
// FogVolume: one entry of FroxelFogSettings::volumes ("volumes[i].<member>" in messages).
POSTFX_API std::span<const SettingField> fogVolumeSettingsTable();
// FogMedium: the rows both fogs' tables share (the medium, its noise included), for code that edits a
// FogMedium of either fog.
POSTFX_API std::span<const SettingField> fogMediumSettingsTable();

// One effect's settings in a FrameInfo: its scene-file key ("froxel_fog"), its FrameInfo member
// ("froxelFog": messages name "FrameInfo.froxelFog.<member>"), its table, and the settings struct inside a
// FrameInfo (passed as void*). Code that goes over every setting of every effect (a generic editor, a
// fuzzer, the tests that put every key at the ends of its range) starts here.
struct EffectSettingsTable {
    const char* key;
    const char* member;
    std::span<const SettingField> (*table)();
    void* (*address)(void* frameInfo);
};
// Every effect's, in composite order.
POSTFX_API std::span<const EffectSettingsTable> effectSettingsTables();

}  // namespace postfx
