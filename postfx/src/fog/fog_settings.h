// Checks of FogSettings and the frame inputs the fog reads, shared by the GPU pass and the CPU reference.
#pragma once

#include <postfx/fog.h>
#include <postfx/result.h>

#include "common/medium.h"
#include "fog/fog_shared.h"

#include <string>
#include <vector>

namespace postfx::fog {

// InvalidArgument naming the field ("FrameInfo.fog.density: -1 is outside [0, 1e+06]") for any value out of
// range or NaN: the table's ranges (fogSettingsTable) and the rules beside them.
Status validateSettings(const FogSettings& settings);

// Each preset's error on the committed accuracy–cost front, Low first (QualityPreset::error).
std::vector<double> qualityPresetErrors();

}  // namespace postfx::fog
