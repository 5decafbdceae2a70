// postfx-bench --atmosphere-truth (docs/accuracy-cost/README.md, "The sky against the path tracer"): the
// path-traced sky of every view of the atmosphere's truth table, CPU only, written as the test fixture
// tests/atmosphere/data/path_traced_sky.csv. Views: the camera on the ground, at 1 km, 10 km, 100 km and in
// orbit (400 km); the sun from 60° up to 2° below the horizon; view zenith 0–120°; azimuths toward, across
// and away from the sun; ground albedo 0 and 0.3; Earth's media and a hazy one (5× Mie). Each entry's
// paths are added in batches until its largest relative standard error is below the target or the path
// budget is spent; the standard error is written with it.
#pragma once

#include <cstdint>
#include <string>

namespace bench {

struct AtmosphereTruthArgs {
    double targetError = 0.0025;  // relative standard error per channel
    uint64_t batchPaths = 50000;  // per channel, per batch
    uint64_t maxPaths = 4000000;  // per channel
    std::string out;              // the CSV's path
};

int runAtmosphereTruth(const AtmosphereTruthArgs& args, const std::string& commandLine,
                       const std::string& date);

}  // namespace bench
