// postfx-bench --worst-case: each effect alone at its largest allowed sizes and step counts (every such
// key of its settings table at the table's maximum), on the showcase's frame (demo/scenes/showcase.json) at
// a small image: the time of its first frame (every LUT, noise texture and history built), of a later
// frame, its GPU passes and the frame plan's bytes (docs/reliability.md, "Memory and cost budget"). A
// frame the library refuses (a range rule across keys, the memory budget) prints the refusal. Needs only
// libvulkan.
#pragma once

#include "calibration.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct WorstCaseArgs {
    uint32_t width = 64, height = 36;
    std::string sceneDir;  // where showcase.json is
    // Of the rows' names (atmosphere_hillaire, atmosphere_orders, clouds, fog, froxel_fog, lookup); empty:
    // all.
    std::vector<std::string> rows;
    uint32_t frames = 3;  // frames recorded per row, each submitted and waited for
    bool validation = false;
    // Each row's frames bracketed by the calibration (bench/calibration.h); its reference after this long
    // a warm-up [ms].
    CalibrationOptions calibration;
    double calibrationWarmupMs = 1000.0;
};

int runWorstCase(const WorstCaseArgs& args, const std::string& commandLine);

}  // namespace bench
