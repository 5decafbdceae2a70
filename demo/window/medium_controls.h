// The ImGui controls both fog panels share (the "Fog" and "Froxel fog" sections of the windowed demo):
// the participating medium (postfx::FogMedium, from its settings table: density, albedo, anisotropy,
// height falloff, base height, max distance, self shadow, analytic tail and its "Noise" subsection), and
// the small widgets the panels use.
#pragma once

#include <postfx/fog.h>
#include <postfx/temporal.h>

#include <cstdint>

namespace demo::window {

// Adds the medium's widgets to the current ImGui window, editing `medium` (call between Begin and End,
// under the panel's own PushID). The "Noise" subsection is closed at first. Returns true if anything
// changed this frame; the values may then be out of range until sanitizeMedium.
bool buildMediumControls(postfx::FogMedium& medium);

// Brings every medium field into the range postfx accepts (the table's ranges, the noise's included
// whether or not it is on: sanitizeSettings) and the texture size to the nearest power of two in
// [16, 256]. Valid values are left exactly as they are.
void sanitizeMedium(postfx::FogMedium& medium);

namespace widgets {
// v clamped to [lo, hi]; NaN becomes lo.
float clampOrLow(float v, float lo, float hi);
// The last item's tooltip.
void tooltip(const char* text);
// An integer slider over [lo, hi] for an unsigned value (clamped when edited).
bool sliderUint(const char* label, uint32_t& value, int lo, int hi);
}  // namespace widgets

}  // namespace demo::window
