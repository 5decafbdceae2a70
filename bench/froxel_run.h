// postfx-bench --froxel: the froxel fog's sweep beside the ray-marched fog on the same scenes, the
// light-count sweep, the copy bandwidth; writes results.csv and results.md (bench/froxel_report.h).
#pragma once

#include "froxel_scenes.h"
#include "motion.h"
#include "runner.h"

#include <postfx/froxel_fog.h>

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct FroxelRunArgs {
    // Scene files (without .json) in sceneDir: a scene with effects.fog runs as its froxel version
    // (froxelScene) and with the ray-marched fog beside it; one with effects.froxel_fog alone.
    std::vector<std::string> scenes;
    std::string sceneDir;
    RunnerOptions runner;
    uint32_t referenceSteps = 4096;
    uint32_t errorStride = 1;
    std::string out;
    FroxelSweepOptions sweep;
    // The ray-marched fog's rows: steps × resolution scales, jitter on, shadow kernel 1 (the froxel fog's
    // 1×1 shadow tap, so both are measured against the same reference).
    std::vector<uint32_t> fogSteps;
    std::vector<float> fogScales;
    // The light-count sweep (on targetScene, postfx's default grid): 0 once, every other count with
    // and without light lists. Empty: none.
    std::vector<uint32_t> lightCounts;
    // The shadow sweep (on targetScene at lightGrid): kFroxelTargetLights of the light-count sweep's
    // lights, the first n of them shadowed for each n here, each face shadowResolution² texels. Empty:
    // none.
    std::vector<uint32_t> shadowedCounts;
    uint32_t shadowResolution = 512;
    // The light-count sweep's grid (power slices, trilinear) [froxels]: postfx's default, the targets'.
    uint32_t lightGrid[3] = {postfx::FroxelFogSettings{}.grid.x, postfx::FroxelFogSettings{}.grid.y,
                             postfx::FroxelFogSettings{}.grid.z};
    std::string targetScene;                   // the targets' scene (--froxel-target-scene)
    double bandwidth = NAN;                    // --bandwidth [GB/s]; NaN: the measured copy
    uint64_t copyBytes = uint64_t(256) << 20;  // the bandwidth copy's size
    // In motion (bench/motion.h), at lightGrid with the scene's lights: the camera moving on motionScenes
    // (empty: the target scene and the scenes with lights; with motionQuick only those with lights), the
    // light moving and switched off on those of them with light motionOptions.light; temporal off and on. The
    // references at motionErrorStride.
    bool motion = true;
    std::vector<std::string> motionScenes;
    MotionOptions motionOptions;
    uint32_t motionErrorStride = 1;
    bool motionQuick = false;  // the default motionScenes: only those with lights (--quick)
};

// `commandLine` and `date` (UTC, ISO 8601) go into the report's header. Returns the exit status.
int runFroxel(const FroxelRunArgs& args, const std::string& commandLine, const std::string& date);

}  // namespace bench
