// postfx-bench --atmosphere: the sky and atmosphere's GPU time per pass in what a frame rebuilds (still,
// camera or sun moving, media changed) and its error against reference (a) over a sweep of LUT sizes
// and sample counts (bench/atmosphere_bench.h); writes results.csv and results.md.
#pragma once

#include "atmosphere_bench.h"
#include "runner.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct AtmosphereRunArgs {
    RunnerOptions runner;
    uint32_t referenceSteps = 512;  // reference (a)'s midpoint steps per pixel
    uint32_t errorStride = 1;
    uint32_t psiDirections = 256, psiSteps = 100;  // reference (a)'s Ψ table
    // Reference (a)'s scattering-orders table: false, its defaults (postfx::reference::AtmosphereInputs);
    // true, a coarse one (seconds on lavapipe's machine, as --quick's Ψ table).
    bool coarseOrders = false;
    std::string out;
    std::vector<std::string> views;       // atmosphereViews() names; empty: all
    std::vector<std::string> sweepViews;  // the views the sweep runs on; empty: every measured view
    AtmosphereSweepOptions sweep;
};

// `commandLine` and `date` (UTC, ISO 8601) go into the report's header. Returns the exit status.
int runAtmosphere(const AtmosphereRunArgs& args, const std::string& commandLine, const std::string& date);

}  // namespace bench
