// postfx-bench --clouds: the volumetric clouds' GPU time per pass with camera and sun still, and their error
// against postfx::reference::renderClouds after convergence (still) and with the camera panning, over a
// sweep of steps, light steps, resolution scale, noise sizes and the quality presets (bench/clouds_bench.h);
// writes results.csv and results.md.
#pragma once

#include "clouds_bench.h"
#include "runner.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct CloudsRunArgs {
    RunnerOptions runner;
    uint32_t referenceSteps = 512;  // the reference's view steps per pixel
    uint32_t referenceLightSteps = 128;
    uint32_t errorStride = 1;
    uint32_t convergedFrames = 32;  // still frames before the still error (temporal rows)
    uint32_t motionFrames = 32;     // panning frames before the motion error
    uint32_t shadowMapSize = 0;     // every row's shadow_map.size; 0: postfx's default (--quick: 64)
    // The path-traced truth (CloudsTruthError): paths per pixel (0: none) at every truthStride-th pixel (a
    // multiple of errorStride; 0: 4 × errorStride).
    uint32_t truthPaths = 256;
    uint32_t truthStride = 0;
    std::string out;
    std::vector<std::string> views;       // cloudsViews() names; empty: all
    std::vector<std::string> sweepViews;  // the views the sweep runs on; empty: every measured view
    CloudsSweepOptions sweep;
};

int runClouds(const CloudsRunArgs& args, const std::string& commandLine, const std::string& date);

}  // namespace bench
