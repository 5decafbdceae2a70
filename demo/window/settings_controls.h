// ImGui controls derived from a postfx settings table (postfx/settings_table.h): one generic control per
// field kind (a slider over the field's editor range, logarithmic where the table says so, a checkbox, a
// combo of an enum's choices, a colour editor, three drag fields), the field's meaning as its tooltip,
// and the clamping of edited values into the valid range. Panels keep hand-written controls only where a
// field needs one (each says why).
#pragma once

#include <postfx/settings_table.h>

#include <initializer_list>
#include <span>
#include <string>

namespace demo::window {

// The control's label: the key's last segment with spaces ("texture size"), the unit in brackets when it
// has one ("density [1/m]").
std::string settingLabel(const postfx::SettingField& field);

// The field's control editing `settings` (of the table's struct), its meaning as tooltip. Returns true if
// it changed this frame; the value may then be out of range until sanitizeSettings.
bool settingControl(const postfx::SettingField& field, void* settings);

// The controls of every field of `table` directly inside `group` ("" the top level, "noise", "temporal")
// but those whose member is in `skip` or in the table `drawn` (rows another panel part draws, as the
// shared medium's), in table order; a field whose activeIf switch is off is greyed.
bool settingControls(std::span<const postfx::SettingField> table, void* settings, const std::string& group,
                     std::initializer_list<const char*> skip = {},
                     std::span<const postfx::SettingField> drawn = {});

// The control of `table`'s field with member `member` (which must exist).
bool settingControl(std::span<const postfx::SettingField> table, const char* member, void* settings);

// Brings every number of `table`'s fields in `settings` into its valid range: NaN and values below to
// the low end (an open one: the editor's low end), values above to the high end (an open one: just
// below), an enum that is none of the choices to its default. Valid values are left exactly as they are.
// Rules beyond ranges (odd sizes, powers of two) are the panel's.
void sanitizeSettings(std::span<const postfx::SettingField> table, void* settings);

}  // namespace demo::window
