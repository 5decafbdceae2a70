// What postfx derives from a settings table (postfx/settings_table.h): the range checks with their error
// names, and the history key's hash of the fields that invalidate the temporal history.
#pragma once

#include <postfx/result.h>
#include <postfx/settings_table.h>

#include <cstdint>
#include <string>

namespace postfx::core {

// The error name of `field` under `prefix`: "<prefix>.<member>" ("FrameInfo.fog.noise.tiling").
std::string settingName(const std::string& prefix, const SettingField& field);

// Checks every active field of `table` in `settings` (of the table's struct) against its range, in table
// order, skipping customCheck fields: InvalidArgument naming the first bad one ("FrameInfo.fog.density:
// -1 is outside [0, 1e+06]"; unbounded above: "must be > 0", "is not finite"; an enum: "is not a FogQuality
// (Custom, Low, ...)").
Status checkSettings(std::span<const SettingField> table, const void* settings, const std::string& prefix);

// `hash` continued with every active field of `table` whose `history` is set.
uint64_t hashSettings(uint64_t hash, std::span<const SettingField> table, const void* settings);

// Whether `field` is active in `settings` (its activeIf switch, if any, is on).
bool settingActive(std::span<const SettingField> table, const SettingField& field, const void* settings);

}  // namespace postfx::core
