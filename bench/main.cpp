// postfx-bench: postfx's accuracy–cost benchmark (docs/accuracy-cost/README.md). One mode a run; the GPU
// modes time postfx's passes (timestamp queries, Context::readPassTimings) and measure the error against
// a CPU reference:
//   (default)     the ray-marched fog on the fog scenes: a sweep of its quality knobs (steps, jitter,
//                 resolution scale, noise texture size, shadow kernel) and its presets, the error of 1, 8
//                 and 16 jittered frames, the two baselines (bench/baseline.h) on the same frames, the
//                 presets in motion (bench/motion.h); writes results.csv, results.md, plot.svg, motion.csv
//   --froxel      the froxel fog beside the ray-marched fog, and a light-count sweep (bench/froxel_run.h)
//   --atmosphere  the sky's LUT sizes and sample counts against reference (a) (bench/atmosphere_run.h)
//   --clouds      the clouds' knobs and presets, converged and panning (bench/clouds_run.h)
//   --frame       every effect together in the showcase scene, per preset and size (bench/frame_run.h)
//   --first-frame the CPU time of a new context's first record(), prewarmed or not, with a pipeline cache
//                 or not (bench/first_frame.h)
//   --worst-case  each effect alone at its largest allowed sizes and step counts (bench/worst_case.h)
// CPU only: --atmosphere-truth (the sky's path-traced table, bench/atmosphere_truth.h) and --clouds-slabs
// (the clouds' multiple scattering against the path tracer, bench/clouds_slabs.h). --pipeline-stats prints
// what the driver compiled the fog's march pipelines into (bench/pipeline_stats.h).
#include "atmosphere_run.h"
#include "atmosphere_truth.h"
#include "clouds_run.h"
#include "clouds_slabs.h"
#include "conclusions.h"
#include "first_frame.h"
#include "frame_run.h"
#include "froxel_report.h"
#include "froxel_run.h"
#include "motion.h"
#include "motion_report.h"
#include "pipeline_stats.h"
#include "progress.h"
#include "report.h"
#include "runner.h"
#include "small_orders_table.h"
#include "stats.h"
#include "worst_case.h"

#include "cli_args.h"
#include "scene/scene.h"

#include <postfx/fog.h>
#include <postfx/froxel_fog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace cli = demo::cli;

const char* kUsage =
    "usage: postfx-bench [--scenes a,b,...] [--scene-dir DIR] [--size WxH] [--warmup W] [--warmup-ms T]\n"
    "                    [--cold-warmup-ms T] [--frames N] [--reference-steps N] [--error-stride K] "
    "[--texture-rate GTEXELS]\n"
    "                    [--out DIR] [--steps a,b,...] [--scales a,b,...] [--noise-sizes a,b,...]\n"
    "                    [--shadow-kernels a,b,...] [--step-lengths a,b,...] [--preset-scene S] "
    "[--preset-budgets l,m,h,u]\n"
    "                    [--no-presets] [--no-baselines] [--quick] [--validation]\n"
    "                    [--no-motion] [--motion-scenes a,b,...] [--motion-warmup W] [--motion-frames K]\n"
    "                    [--motion-frame-step S] [--motion-error-stride K] [--motion-speed M/S]\n"
    "                    [--motion-yaw-rate DEG/S] [--motion-light N] [--switch-off-frames M]\n"
    "                    [--temporal-blend W]\n"
    "       postfx-bench --froxel [--froxel-grids XxY,...] [--froxel-slices a,b,...] "
    "[--froxel-distributions power,log]\n"
    "                    [--froxel-tricubic off,on] [--froxel-lights a,b,...] [--froxel-target-scene S] "
    "[--bandwidth GB/S]\n"
    "                    [--steps a,b,...] [--scales a,b,...] and the options above but the fog sweep's\n"
    "Sweeps postfx's fog quality knobs on the named scenes, times each postfx pass on the GPU and measures\n"
    "the error against the CPU reference; the seed's shader (as written, and fixed but still a Riemann sum)\n"
    "runs on the same frames. Writes results.csv, results.md and plot.svg to --out.\n"
    "options (defaults in brackets; --quick changes the defaults to a tiny sweep for CI):\n"
    "  --scenes LIST          scene files in --scene-dir, without .json "
    "[fog_default,fog_height,fog_shadowed,\n"
    "                         fog_valley,fog_valley_unskipped]\n"
    "  --scene-dir DIR        [demo/scenes if it exists here, else the source tree's demo/scenes]\n"
    "  --size WxH             frame size [1920x1080; quick: 64x36]\n"
    "  --warmup W             frames recorded before timing, per setting, at least [5; quick: 1]\n"
    "  --warmup-ms T          ... and for at least T ms of wall time (GPU clocks ramp up) [200; quick: 0]\n"
    "  --cold-warmup-ms T     ... T ms instead after a CPU reference (the GPU sat idle) [1000; quick: 0]\n"
    "  --frames N             timed frames per setting: median, p10-p90, min-max [30; quick: 2]\n"
    "  --reference-steps N    midpoint steps per pixel of the CPU reference [4096; quick: 1024]\n"
    "  --error-stride K       error on every K-th pixel in x and y (the reference costs 1/K^2)\n"
    "                         [max(1, width / 480): 4 at 1920x1080]\n"
    "  --texture-rate G       the device's texture rate [GTexel/s] for the texture-fetch floor [none]\n"
    "  --out DIR              output folder [docs/accuracy-cost]\n"
    "  --steps LIST           postfx fog steps [4,8,16,32,64,128,256; quick: 4,16,64]\n"
    "  --scales LIST          postfx fog resolution scales, each in [0.25, 1] [1,0.5,0.25; quick: 1,0.5]\n"
    "  --noise-sizes LIST     noise texture edges for scenes with noise [32,64,128; quick: 32]\n"
    "  --shadow-kernels LIST  fog.shadow_kernel values (odd, 1..7) swept at the scene's own noise size in\n"
    "                         scenes with a shadow map; other noise sizes keep the scene's kernel [1,3]\n"
    "  --step-lengths LIST    baseline step lengths [m] [4,2,1,0.5,0.25,0.125; quick: 4,1]\n"
    "  --preset-scene S       the scene the presets are proposed from and the targets measured on\n"
    "                         [fog_default if in --scenes, else the first]\n"
    "  --preset-budgets LIST  GPU ms budgets of the proposed low,medium,high,ultra [0.25,0.5,1,2]\n"
    "  --no-presets           do not measure the quality presets (low, medium, high, ultra) as such\n"
    "  --no-baselines         postfx's fog only\n"
    "  --validation           Vulkan validation layer with synchronization validation; any message fails\n"
    "calibration (every GPU-timed mode; docs/accuracy-cost/README.md, \"Calibration\"): a fixed ALU\n"
    "dispatch timed right before and right after each row's timed frames; a row whose calibration moved by\n"
    "more than the tolerance (after against before, or either against the run's reference, taken at the\n"
    "start after a warm-up) is timed again; the CSVs say each row's calibration, the summary its spread.\n"
    "  --calibration-tolerance F  the drift that has a row timed again [0.05]\n"
    "  --calibration-retries N    at most this many more attempts, then the row is kept and flagged [3;\n"
    "                             quick: 0, lavapipe's calibration follows the CPU's load]\n"
    "  --calibration-ms T         the dispatch's work sized at the start to take about T ms [2]\n"
    "  --calibration-work N       ... or fixed: N loop steps (the summary says the run's) [sized]\n"
    "  --no-calibration           time each row once, without it\n"
    "in motion (docs/accuracy-cost/README.md, \"In motion\"): each preset with temporal off and on (froxel:\n"
    "the light-count sweep's grid) on sequences that start with a camera cut: the camera walking and "
    "turning\n"
    "(froxel: also a light moving, and a light switched off); after a warm-up, frames against their own\n"
    "references. Writes motion.csv and a section of results.md.\n"
    "  --no-motion            skip it\n"
    "  --motion-scenes LIST   [the run's scenes but *_unskipped; froxel: the target scene and the scenes\n"
    "                         with lights; quick: the preset scene; froxel: the scenes with lights]\n"
    "  --motion-warmup W      frames before the first measured one [32; quick: 4]\n"
    "  --motion-frames K      frames measured, each against its own reference [8; quick: 2]\n"
    "  --motion-frame-step S  every S-th frame from the warm-up on [4; quick: 2]\n"
    "  --motion-error-stride K  the motion references' stride [--error-stride]\n"
    "  --motion-speed V       the camera's (and the light's) speed [m/s] [1.4]\n"
    "  --motion-yaw-rate R    the camera's turn [deg/s], positive left [20]\n"
    "  --motion-light N       froxel: the light that moves and is switched off [0]\n"
    "  --switch-off-frames M  froxel: frames measured from the switch-off on [8; quick: 4]\n"
    "  --temporal-blend W     the temporal-on rows' blend weight in (0, 1] [the fog's own]\n"
    "froxel fog (--froxel; docs/accuracy-cost/README.md, \"Froxel fog\"): each scene with effects.fog runs\n"
    "as its froxel version (the same medium in effects.froxel_fog) with the ray-marched fog's rows beside "
    "it\n"
    "(--steps x --scales, jitter on, shadow kernel 1), a scene with effects.froxel_fog alone; error of 1, 8\n"
    "and 16 frames against the froxel fog's CPU reference, time of each froxel_fog.* pass; then, on the\n"
    "target scene, a light-count sweep (generated point lights, light lists on and off, timed only).\n"
    "Writes results.csv and results.md (targets, light lists, froxel against ray-marched at equal error).\n"
    "  --froxel               this mode; the defaults below replace the fog sweep's [--scenes fog_default,\n"
    "                         fog_height,fog_shadowed,fog_valley,froxel_lights; --out\n"
    "                         docs/accuracy-cost/froxel; --steps 8,16,32,64,128; --scales 1,0.5;\n"
    "                         quick: --scenes fog_default,froxel_lights, --steps 4,16, --scales 1]\n"
    "  --froxel-grids LIST    froxels along x and y, XxY each 1..512 [80x45,160x90,240x135; quick: 16x9]\n"
    "  --froxel-slices LIST   depth slices, each 1..512 [64,128,256; quick: 16,32]\n"
    "  --froxel-distributions LIST  power and/or log [power,log]\n"
    "  --froxel-tricubic LIST off and/or on [off,on]\n"
    "  --froxel-lights LIST   light counts of the light-count sweep, each 0..256; 0: none [0,1,2,4,8,16,\n"
    "                         32,64,128,256; quick: 0,4,16]\n"
    "  --froxel-shadowed LIST of the sweep's 64 lights, how many cast shadows (the shadow sweep), each\n"
    "                         0..64 [0,1,4,16,64; quick: 0,4]\n"
    "  --froxel-shadow-resolution N  texels per shadow face edge in the shadow sweep, 16..4096 [512;\n"
    "                         quick: 32]\n"
    "  --froxel-target-scene S  the targets' scene, which the light-count sweep runs on [fog_default if in\n"
    "                         --scenes, else the first]; quick: the light-count sweep on the first grid\n"
    "                         and slice count, not postfx's default grid\n"
    "  --bandwidth G          memory bandwidth [GB/s] for the apply pass's floor [the copy bandwidth the\n"
    "                         run measures]\n"
    "atmosphere (--atmosphere; docs/accuracy-cost/README.md, \"Atmosphere (--atmosphere)\"): sky scenes "
    "(camera\n"
    "near the ground with the sun at 30 and 5 degrees, terrain in the lower part; 100 km up), each pass's "
    "GPU\n"
    "time in frames that rebuild nothing (still), the view-dependent LUTs (camera, sun) or every LUT "
    "(media),\n"
    "and the error against reference (a) (postfx::reference::renderAtmosphere) for a sweep of LUT sizes and\n"
    "sample counts, one knob at a time. Writes results.csv and results.md; the fog sweep's options do not\n"
    "apply, --size, --warmup*, --frames, --reference-steps [512; quick: 128], --error-stride, --out\n"
    "[docs/accuracy-cost/atmosphere], --quick and --validation do; quick's rows start from a\n"
    "scattering-orders table of 16x16x8 nodes, 4 azimuths and 144 directions.\n"
    "  --atmosphere           this mode\n"
    "  --atmosphere-views LIST  ground_sun30, ground_sunset, space_sun30, orbit_sun30 [all]\n"
    "  --atmosphere-sweep-views LIST  the views the sweep runs on [all measured; quick: ground_sunset]\n"
    "  --atmosphere-sweep KNOB=a,b,...  a knob's values (repeatable; 'none' sweeps nothing): "
    "transmittance_size\n"
    "                         [64x16,128x32,256x64,512x128], transmittance_steps [10,20,40,80], ms_size\n"
    "                         [16,32,64], ms_directions [16,64,256], ms_steps [10,20,40], sky_view_size\n"
    "                         [96x54,192x108,384x216], sky_view_steps [10,30,60], ap_size [16,32,64] (N^3),\n"
    "                         ap_steps_per_slice [1,2,4]; quick: one value of five knobs\n"
    "clouds (--clouds; docs/accuracy-cost/README.md, \"Clouds (--clouds)\"): views of the cloud layer with "
    "the\n"
    "atmosphere on (from the ground at noon and at sunset, from above), the clouds.* passes' GPU time with\n"
    "camera and sun still, and the error against postfx::reference::renderClouds after convergence (still)\n"
    "and with the camera panning (motion), for the Medium preset's settings with one knob changed and each\n"
    "preset. --size, --warmup*, --frames, --reference-steps [512; quick: 64], --error-stride, --out\n"
    "[docs/accuracy-cost/clouds], --quick and --validation apply.\n"
    "  --clouds               this mode\n"
    "  --clouds-views LIST    ground_noon, ground_sunset, above [all]\n"
    "  --clouds-sweep-views LIST  the views the sweep runs on [all measured; quick: ground_noon]\n"
    "  --clouds-sweep KNOB=a,b,...  a knob's values (repeatable; 'none' sweeps nothing): model "
    "[slab,octaves],\n"
    "                         steps\n"
    "                         [16,32,64,96,128,192], light_steps [2,4,6,12,16,32], resolution_scale "
    "[1,0.5,0.25],\n"
    "                         base_size [32,64,128,256], detail_size [16,32,64], temporal [off],\n"
    "                         update_block [1,4], preset [low,medium,high,ultra]; quick: steps 16, scale 1,\n"
    "                         base_size 32, preset low\n"
    "  --clouds-reference-light-steps N  the reference's light steps [128; quick: 16]\n"
    "  --clouds-converged-frames N  still frames before the still error of a temporal row [32; quick: 4]\n"
    "  --clouds-motion-frames N  panning frames before the motion error [32; quick: 4]\n"
    "  --clouds-truth-paths N  paths per pixel of the path-traced truth the model and GPU errors are also\n"
    "                         measured against (0: none) [256; quick: 8]\n"
    "  --clouds-truth-stride K  the truth at every K-th pixel, a multiple of --error-stride [4 x it]\n"
    "                         quick also shrinks the clouds' shadow map to 64x64\n"
    "\n"
    "clouds against the path tracer (--clouds-slabs; CPU only): the multiple-scattering models on\n"
    "homogeneous layers (optical depth 0.5-50, albedo 0.9-1, g 0.2-0.8, three suns, three views) against\n"
    "the path-traced truth; --out [docs/accuracy-cost/clouds-slabs], --quick.\n"
    "  --clouds-slab-paths N  paths per case [20000; quick: 200]\n"
    "\n"
    "the sky against the path tracer (--atmosphere-truth; CPU only): the path-traced sky of every view of\n"
    "the atmosphere's truth table (five altitudes, five suns, seven view zeniths, three azimuths, ground\n"
    "albedo 0 and 0.3, Earth's media and a hazy one), each until its standard error is below the target;\n"
    "--out [tests/atmosphere/data/path_traced_sky.csv].\n"
    "  --truth-target E      relative standard error per channel [0.0025; quick: 0.05]\n"
    "  --truth-max-paths N   paths per channel at most [4000000; quick: 20000]\n"
    "\n"
    "whole frame (--frame; docs/accuracy-cost/README.md, \"Whole frame (--frame)\"): the showcase scene\n"
    "(atmosphere, clouds, froxel fog with shadows and lights) and the same with the ray-marched fog, per\n"
    "preset and frame size: every postfx pass's GPU time, each effect's share, the error against the\n"
    "demo's combined CPU reference. --warmup*, --frames, --reference-steps [512; quick: 64],\n"
    "--error-stride [8 at 1920 wide, scaled with the width], --out [docs/accuracy-cost/frame], --quick\n"
    "and --validation apply.\n"
    "  --frame                this mode\n"
    "  --frame-sizes LIST     frame sizes WxH [1920x1080,3840x2160; quick: 64x36]\n"
    "  --frame-presets LIST   low, medium, high, ultra [all; quick: medium]\n"
    "  --frame-budget MS      also a row per fog with the clouds and the ray-marched fog on quality Auto\n"
    "                         under one frame budget (FrameInfo::budgetMs) [1; quick: 0]; 0: none\n"
    "                         quick also shrinks the clouds' shadow map to 64x64, the atmosphere's\n"
    "                         scattering-orders table to 16x16x8, 4 azimuths, 144 directions, the froxel\n"
    "                         grid to 32x18x32 and the lights' shadow maps to at most 128x128\n"
    "first frame (--first-frame; docs/integration.md, \"Pipelines\"): the CPU time of record() in a new\n"
    "context's first frames, on the showcase (froxel fog), its ray-marched fog version, and that one with\n"
    "the clouds and the fog on quality Auto: without prewarm, after Context::prewarm, with a "
    "VkPipelineCache\n"
    "saved by an earlier context, both, and without again; pipelines compiled in each. Prints a table.\n"
    "--size [1920x1080; quick: 160x90], --frames (after the first) [12; quick: 4], --validation apply;\n"
    "quick also makes every LUT, volume, noise texture and shadow map small (the same pipelines).\n"
    "  --first-frame          this mode (the drivers' shader disk caches are turned off for it)\n"
    "  --driver-cache         leave the drivers' disk caches as the environment has them\n"
    "  --first-frame-scenes LIST  of froxel (the showcase), raymarched (its ray-marched fog version), auto\n"
    "                         (that one with the clouds and the fog on quality Auto) [all]\n"
    "worst case (--worst-case; docs/reliability.md, \"Memory and cost budget\"): each effect alone at its\n"
    "largest allowed sizes and step counts on the showcase's frame: the first and a later frame's time\n"
    "(record to idle), the GPU passes, the plan's bytes, or the library's refusal. Prints a table.\n"
    "--size [64x36], --frames [3], --validation apply.\n"
    "  --worst-case           this mode\n"
    "  --worst-case-rows LIST of atmosphere_hillaire, atmosphere_orders, clouds, fog, froxel_fog, lookup "
    "[all]\n"
    "pipeline statistics (--pipeline-stats): on a device of its own with "
    "VK_KHR_pipeline_executable_properties,\n"
    "compiles the fog's march pipelines (fog.raymarch at full size, reduced, reduced with temporal) and "
    "prints\n"
    "every statistic the driver reports (registers, instructions, ...); nothing is rendered\n"
    "environment: POSTFX_DEVICE=<substring of the device name> picks the Vulkan device; --clouds:\n"
    "  POSTFX_BENCH_DUMP=DIR writes each row's GPU and reference images (the error's pixels) to DIR as PFM\n";

struct Args {
    std::vector<std::string> scenes = {"fog_default", "fog_height", "fog_shadowed", "fog_valley",
                                       "fog_valley_unskipped"};
    std::string sceneDir;
    bench::RunnerOptions runner;
    uint32_t referenceSteps = 4096;
    uint32_t errorStride = 0;  // 0: automatic
    double textureRate = NAN;
    std::string out = "docs/accuracy-cost";
    std::vector<uint32_t> steps = {4, 8, 16, 32, 64, 128, 256};
    std::vector<float> scales = {1.0f, 0.5f, 0.25f};
    std::vector<uint32_t> noiseSizes = {32, 64, 128};
    std::vector<uint32_t> shadowKernels = {1, 3};
    std::vector<float> stepLengths = {4.0f, 2.0f, 1.0f, 0.5f, 0.25f, 0.125f};
    bool baselines = true;
    bool presets = true;
    std::string presetScene;  // empty: fog_default if in --scenes, else the first scene
    std::vector<bench::PresetBudget> presetBudgets = bench::defaultPresetBudgets();
    // --froxel
    bool froxel = false;
    bench::FroxelSweepOptions froxelSweep;
    std::vector<uint32_t> froxelLights = {0, 1, 2, 4, 8, 16, 32, 64, 128, 256};
    // The shadow sweep: of kFroxelTargetLights lights, this many shadowed, each face this size.
    std::vector<uint32_t> froxelShadowed = {0, 1, 4, 16, 64};
    uint32_t froxelShadowResolution = 512;
    std::string froxelTargetScene;
    double bandwidth = NAN;
    bool froxelQuick = false;  // --froxel --quick
    // --atmosphere
    bool atmosphere = false;
    std::vector<std::string> atmosphereViews, atmosphereSweepViews;
    std::vector<std::pair<std::string, std::vector<std::string>>> atmosphereSweep;  // --atmosphere-sweep
    bool atmosphereSweepNone = false;
    // --clouds
    bool clouds = false;
    std::vector<std::string> cloudsViews, cloudsSweepViews;
    std::vector<std::pair<std::string, std::vector<std::string>>> cloudsSweep;  // --clouds-sweep
    bool cloudsSweepNone = false;
    uint32_t cloudsLightSteps = 0, cloudsConvergedFrames = 0, cloudsMotionFrames = 0;  // 0: the default
    int64_t cloudsTruthPaths = -1;                                                     // < 0: the default
    bool cloudsSlabs = false;                                                          // --clouds-slabs
    uint32_t cloudsSlabPaths = 0;                                                      // 0: the default
    bool atmosphereTruth = false;                                                      // --atmosphere-truth
    double truthTarget = 0.0;                                                          // 0: the default
    uint32_t truthMaxPaths = 0;                                                        // 0: the default
    uint32_t cloudsTruthStride = 0;  // 0: 4 × the error stride
    // --frame
    bool frame = false;
    bool pipelineStats = false;              // --pipeline-stats: the fog march pipelines' driver statistics
    bool firstFrame = false;                 // --first-frame
    bool worstCase = false;                  // --worst-case
    std::vector<std::string> worstCaseRows;  // --worst-case-rows; empty: all
    bool driverCache = false;                // --driver-cache
    std::vector<std::string> firstFrameScenes;              // --first-frame-scenes; empty: all
    std::vector<std::pair<uint32_t, uint32_t>> frameSizes;  // empty: the default
    std::vector<std::string> framePresets;                  // empty: the default
    double frameBudgetMs = -1.0;                            // < 0: the default
    bool quick = false;
    // In motion
    bool motion = true;
    std::vector<std::string> motionScenes;  // empty: the default
    bench::MotionOptions motionOptions;
    uint32_t motionErrorStride = 0;  // 0: --error-stride
    bool motionQuick = false;        // --quick: by default fewer scenes in motion
};

// --froxel-distributions / --froxel-tricubic: each item one of two words, at least one.
std::vector<bool> twoWordList(const std::string& option, const std::string& text, const char* no,
                              const char* yes) {
    std::vector<bool> out;
    for (const std::string& item : cli::splitList(text)) {
        if (item != no && item != yes)
            throw cli::UsageError{option + " '" + text + "': expected " + no + " and/or " + yes +
                                  ", comma-separated"};
        if (!std::count(out.begin(), out.end(), item == yes)) out.push_back(item == yes);
    }
    if (out.empty()) throw cli::UsageError{option + " is empty"};
    return out;
}

Args parseArgs(int argc, char** argv) {
    Args args;
    bool quick = false;
    bool sizeGiven = false, warmupGiven = false, warmupMsGiven = false, coldGiven = false,
         framesGiven = false, refGiven = false, stepsGiven = false, noiseGiven = false, lengthsGiven = false,
         scalesGiven = false, scenesGiven = false, outGiven = false, gridsGiven = false, slicesGiven = false,
         lightsGiven = false, motionWarmupGiven = false, motionFramesGiven = false, motionStepGiven = false,
         switchOffGiven = false, shadowedGiven = false, shadowResolutionGiven = false, retriesGiven = false;
    const auto toFloats = [](const std::vector<double>& values) {
        return std::vector<float>(values.begin(), values.end());
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&] { return cli::optionValue(argc, argv, i); };
        if (a == "-h" || a == "--help") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        } else if (a == "--scenes") {
            args.scenes = cli::splitList(value());
            if (args.scenes.empty()) throw cli::UsageError{"--scenes is empty"};
            scenesGiven = true;
        } else if (a == "--scene-dir") {
            args.sceneDir = value();
        } else if (a == "--size") {
            cli::sizeOption(value(), 16384, args.runner.width, args.runner.height);
            sizeGiven = true;
        } else if (a == "--warmup") {
            cli::uintOption(a, value(), 0, 100000, args.runner.warmup);
            warmupGiven = true;
        } else if (a == "--warmup-ms") {
            args.runner.warmupMs = cli::numberOption(
                a, value(), [](double v) { return v >= 0 && v <= 1e6; },
                "a number of milliseconds in 0..1e6");
            warmupMsGiven = true;
        } else if (a == "--cold-warmup-ms") {
            args.runner.coldWarmupMs = cli::numberOption(
                a, value(), [](double v) { return v >= 0 && v <= 1e6; },
                "a number of milliseconds in 0..1e6");
            coldGiven = true;
        } else if (a == "--frames") {
            cli::uintOption(a, value(), 1, 100000, args.runner.frames);
            framesGiven = true;
        } else if (a == "--reference-steps") {
            cli::uintOption(a, value(), 1, 1u << 20, args.referenceSteps);
            refGiven = true;
        } else if (a == "--error-stride") {
            cli::uintOption(a, value(), 1, 4096, args.errorStride);
        } else if (a == "--texture-rate") {
            args.textureRate = cli::numberOption(
                a, value(), [](double v) { return v > 0; }, "a number > 0 [GTexel/s]");
        } else if (a == "--out") {
            args.out = value();
            outGiven = true;
        } else if (a == "--steps") {
            args.steps = cli::uintListOption(a, value(), 1, 4096);
            stepsGiven = true;
        } else if (a == "--scales") {
            args.scales = toFloats(cli::numberListOption(
                a, value(), [](double v) { return v >= 0.25 && v <= 1.0; }, "numbers in [0.25, 1]"));
            scalesGiven = true;
        } else if (a == "--noise-sizes") {
            args.noiseSizes = cli::uintListOption(a, value(), 16, 256);
            for (uint32_t n : args.noiseSizes)
                if (n & (n - 1))
                    throw cli::UsageError{"--noise-sizes: " + std::to_string(n) + " is not a power of two"};
            noiseGiven = true;
        } else if (a == "--shadow-kernels") {
            args.shadowKernels = cli::uintListOption(a, value(), 1, 7);
            for (uint32_t k : args.shadowKernels)
                if (k % 2 == 0)
                    throw cli::UsageError{"--shadow-kernels: " + std::to_string(k) + " is not odd"};
        } else if (a == "--step-lengths") {
            args.stepLengths = toFloats(cli::numberListOption(
                a, value(), [](double v) { return v > 0; }, "numbers > 0 [m]"));
            lengthsGiven = true;
        } else if (a == "--preset-scene") {
            args.presetScene = value();
        } else if (a == "--preset-budgets") {
            const std::string text = value();
            std::vector<bench::PresetBudget> budgets = bench::defaultPresetBudgets();
            if (cli::splitList(text).size() != budgets.size())
                throw cli::UsageError{"--preset-budgets '" + text +
                                      "': expected 4 budgets [ms] (low,medium,high,ultra)"};
            const std::vector<double> ms = cli::numberListOption(
                a, text, [](double v) { return v > 0; }, "numbers > 0 [ms]");
            for (size_t k = 0; k < budgets.size(); ++k)
                budgets[k].ms = ms[k];
            args.presetBudgets = budgets;
        } else if (a == "--no-presets") {
            args.presets = false;
        } else if (a == "--no-baselines") {
            args.baselines = false;
        } else if (a == "--quick") {
            quick = true;
        } else if (a == "--validation") {
            args.runner.validation = true;
        } else if (a == "--calibration-tolerance") {
            args.runner.calibration.tolerance = cli::numberOption(
                a, value(), [](double v) { return v >= 0 && v <= 10; }, "a fraction in 0..10");
        } else if (a == "--calibration-retries") {
            cli::uintOption(a, value(), 0, 100, args.runner.calibration.retries);
            retriesGiven = true;
        } else if (a == "--calibration-work") {
            cli::uintOption(a, value(), 1, 1u << 30, args.runner.calibration.iterations);
        } else if (a == "--calibration-ms") {
            args.runner.calibration.targetMs = cli::numberOption(
                a, value(), [](double v) { return v >= 0.01 && v <= 1000; }, "milliseconds in 0.01..1000");
        } else if (a == "--no-calibration") {
            args.runner.calibration.enabled = false;
        } else if (a == "--froxel") {
            args.froxel = true;
        } else if (a == "--atmosphere") {
            args.atmosphere = true;
        } else if (a == "--atmosphere-views") {
            args.atmosphereViews = cli::splitList(value());
            if (args.atmosphereViews.empty()) throw cli::UsageError{"--atmosphere-views is empty"};
        } else if (a == "--atmosphere-sweep-views") {
            args.atmosphereSweepViews = cli::splitList(value());
            if (args.atmosphereSweepViews.empty()) throw cli::UsageError{"--atmosphere-sweep-views is empty"};
        } else if (a == "--atmosphere-sweep") {
            const std::string text = value();
            const size_t eq = text.find('=');
            if (text == "none") {
                args.atmosphereSweepNone = true;
            } else if (eq == std::string::npos || cli::splitList(text.substr(eq + 1)).empty() ||
                       !std::count(bench::atmosphereKnobs().begin(), bench::atmosphereKnobs().end(),
                                   text.substr(0, eq))) {
                throw cli::UsageError{"--atmosphere-sweep '" + text +
                                      "': expected KNOB=a,b,... or none (see --help)"};
            } else {
                args.atmosphereSweep.emplace_back(text.substr(0, eq), cli::splitList(text.substr(eq + 1)));
            }
        } else if (a == "--pipeline-stats") {
            args.pipelineStats = true;
        } else if (a == "--first-frame") {
            args.firstFrame = true;
        } else if (a == "--worst-case") {
            args.worstCase = true;
        } else if (a == "--worst-case-rows") {
            args.worstCaseRows = cli::splitList(value());
            if (args.worstCaseRows.empty()) throw cli::UsageError{"--worst-case-rows is empty"};
        } else if (a == "--driver-cache") {
            args.driverCache = true;
        } else if (a == "--first-frame-scenes") {
            args.firstFrameScenes = cli::splitList(value());
            for (const std::string& scene : args.firstFrameScenes)
                if (scene != "froxel" && scene != "raymarched" && scene != "auto")
                    throw cli::UsageError{"--first-frame-scenes: '" + scene +
                                          "' is not froxel, raymarched or auto"};
            if (args.firstFrameScenes.empty()) throw cli::UsageError{"--first-frame-scenes is empty"};
        } else if (a == "--frame") {
            args.frame = true;
        } else if (a == "--frame-sizes") {
            for (const std::string& item : cli::splitList(value())) {
                unsigned w = 0, h = 0;
                char x = 0;
                if (std::sscanf(item.c_str(), "%u%c%u", &w, &x, &h) != 3 || x != 'x' || w == 0 || h == 0 ||
                    w > 16384 || h > 16384)
                    throw cli::UsageError{"--frame-sizes '" + item + "': expected WxH, each 1..16384"};
                args.frameSizes.emplace_back(w, h);
            }
            if (args.frameSizes.empty()) throw cli::UsageError{"--frame-sizes is empty"};
        } else if (a == "--frame-budget") {
            const std::string v = value();
            char* end = nullptr;
            args.frameBudgetMs = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end != '\0' ||
                !(args.frameBudgetMs >= 0.0 && args.frameBudgetMs <= 1000.0))
                throw cli::UsageError{"--frame-budget '" + v + "': expected a number of ms in [0, 1000]"};
        } else if (a == "--frame-presets") {
            args.framePresets = cli::splitList(value());
            for (const std::string& p : args.framePresets)
                if (p != "low" && p != "medium" && p != "high" && p != "ultra")
                    throw cli::UsageError{"--frame-presets: '" + p + "' is not low, medium, high or ultra"};
            if (args.framePresets.empty()) throw cli::UsageError{"--frame-presets is empty"};
        } else if (a == "--clouds") {
            args.clouds = true;
        } else if (a == "--clouds-slabs") {
            args.cloudsSlabs = true;
        } else if (a == "--atmosphere-truth") {
            args.atmosphereTruth = true;
        } else if (a == "--truth-target") {
            const std::string v = value();
            char* end = nullptr;
            args.truthTarget = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end || !(args.truthTarget > 0.0 && args.truthTarget < 1.0))
                throw cli::UsageError{"--truth-target '" + v + "': expected a number in (0, 1)"};
        } else if (a == "--truth-max-paths") {
            cli::uintOption(a, value(), 1000, 1u << 30, args.truthMaxPaths);
        } else if (a == "--clouds-slab-paths") {
            cli::uintOption(a, value(), 2, 1u << 24, args.cloudsSlabPaths);
        } else if (a == "--clouds-views") {
            args.cloudsViews = cli::splitList(value());
            if (args.cloudsViews.empty()) throw cli::UsageError{"--clouds-views is empty"};
        } else if (a == "--clouds-sweep-views") {
            args.cloudsSweepViews = cli::splitList(value());
            if (args.cloudsSweepViews.empty()) throw cli::UsageError{"--clouds-sweep-views is empty"};
        } else if (a == "--clouds-sweep") {
            const std::string text = value();
            const size_t eq = text.find('=');
            if (text == "none") {
                args.cloudsSweepNone = true;
            } else if (eq == std::string::npos || cli::splitList(text.substr(eq + 1)).empty() ||
                       !std::count(bench::cloudsKnobs().begin(), bench::cloudsKnobs().end(),
                                   text.substr(0, eq))) {
                throw cli::UsageError{"--clouds-sweep '" + text +
                                      "': expected KNOB=a,b,... or none (see --help)"};
            } else {
                args.cloudsSweep.emplace_back(text.substr(0, eq), cli::splitList(text.substr(eq + 1)));
            }
        } else if (a == "--clouds-reference-light-steps") {
            cli::uintOption(a, value(), 1, 4096, args.cloudsLightSteps);
        } else if (a == "--clouds-converged-frames") {
            cli::uintOption(a, value(), 1, 100000, args.cloudsConvergedFrames);
        } else if (a == "--clouds-motion-frames") {
            cli::uintOption(a, value(), 1, 100000, args.cloudsMotionFrames);
        } else if (a == "--clouds-truth-paths") {
            uint32_t n = 0;
            cli::uintOption(a, value(), 0, 1u << 24, n);
            args.cloudsTruthPaths = n;
        } else if (a == "--clouds-truth-stride") {
            cli::uintOption(a, value(), 1, 4096, args.cloudsTruthStride);
        } else if (a == "--froxel-grids") {
            const std::string text = value();
            args.froxelSweep.grids.clear();
            for (const std::string& item : cli::splitList(text)) {
                const size_t x = item.find('x');
                uint32_t gx = 0, gy = 0;
                if (x == std::string::npos ||
                    !cli::parseUint(std::string_view(item).substr(0, x), 1, postfx::kMaxFroxelGridSize, gx) ||
                    !cli::parseUint(std::string_view(item).substr(x + 1), 1, postfx::kMaxFroxelGridSize, gy))
                    throw cli::UsageError{"--froxel-grids '" + text + "': expected XxY, each 1.." +
                                          std::to_string(postfx::kMaxFroxelGridSize) + ", comma-separated"};
                args.froxelSweep.grids.emplace_back(gx, gy);
            }
            if (args.froxelSweep.grids.empty()) throw cli::UsageError{"--froxel-grids is empty"};
            gridsGiven = true;
        } else if (a == "--froxel-slices") {
            args.froxelSweep.slices = cli::uintListOption(a, value(), 1, postfx::kMaxFroxelGridSize);
            slicesGiven = true;
        } else if (a == "--froxel-distributions") {
            args.froxelSweep.logSlices = twoWordList(a, value(), "power", "log");
        } else if (a == "--froxel-tricubic") {
            args.froxelSweep.tricubic = twoWordList(a, value(), "off", "on");
        } else if (a == "--froxel-lights") {
            args.froxelLights = cli::uintListOption(a, value(), 0, postfx::kMaxLocalLights);
            lightsGiven = true;
        } else if (a == "--froxel-shadowed") {
            args.froxelShadowed = cli::uintListOption(a, value(), 0, bench::kFroxelTargetLights);
            shadowedGiven = true;
        } else if (a == "--froxel-shadow-resolution") {
            cli::uintOption(a, value(), 16, 4096, args.froxelShadowResolution);
            shadowResolutionGiven = true;
        } else if (a == "--froxel-target-scene") {
            args.froxelTargetScene = value();
        } else if (a == "--bandwidth") {
            args.bandwidth = cli::numberOption(
                a, value(), [](double v) { return v > 0; }, "a number > 0 [GB/s]");
        } else if (a == "--no-motion") {
            args.motion = false;
        } else if (a == "--motion-scenes") {
            args.motionScenes = cli::splitList(value());
            if (args.motionScenes.empty()) throw cli::UsageError{"--motion-scenes is empty"};
        } else if (a == "--motion-warmup") {
            cli::uintOption(a, value(), 0, 100000, args.motionOptions.warmup);
            motionWarmupGiven = true;
        } else if (a == "--motion-frames") {
            cli::uintOption(a, value(), 1, 10000, args.motionOptions.frames);
            motionFramesGiven = true;
        } else if (a == "--motion-frame-step") {
            cli::uintOption(a, value(), 1, 10000, args.motionOptions.frameStep);
            motionStepGiven = true;
        } else if (a == "--motion-error-stride") {
            cli::uintOption(a, value(), 1, 4096, args.motionErrorStride);
        } else if (a == "--motion-speed") {
            const double v = cli::numberOption(
                a, value(), [](double x) { return x >= 0 && x <= 1000; }, "a speed in 0..1000 [m/s]");
            args.motionOptions.cameraSpeed = args.motionOptions.lightSpeed = float(v);
        } else if (a == "--motion-yaw-rate") {
            args.motionOptions.yawRateDeg = float(cli::numberOption(
                a, value(), [](double x) { return std::abs(x) <= 3600; }, "a rate in -3600..3600 [deg/s]"));
        } else if (a == "--motion-light") {
            cli::uintOption(a, value(), 0, postfx::kMaxLocalLights - 1, args.motionOptions.light);
        } else if (a == "--temporal-blend") {
            args.motionOptions.temporalBlend = float(cli::numberOption(
                a, value(), [](double x) { return x > 0 && x <= 1; }, "a weight in (0, 1]"));
        } else if (a == "--switch-off-frames") {
            cli::uintOption(a, value(), 1, 10000, args.motionOptions.switchOffFrames);
            switchOffGiven = true;
        } else {
            throw cli::UsageError{"unknown argument '" + a + "' (see --help)"};
        }
    }
    if (args.froxel) {
        if (!scenesGiven)
            args.scenes = quick ? std::vector<std::string>{"fog_default", "froxel_lights"}
                                : std::vector<std::string>{"fog_default", "fog_height", "fog_shadowed",
                                                           "fog_valley", "froxel_lights"};
        if (!outGiven) args.out = "docs/accuracy-cost/froxel";
        if (!stepsGiven)
            args.steps = quick ? std::vector<uint32_t>{4, 16} : std::vector<uint32_t>{8, 16, 32, 64, 128};
        if (!scalesGiven) args.scales = quick ? std::vector<float>{1.0f} : std::vector<float>{1.0f, 0.5f};
        if (quick && !gridsGiven) args.froxelSweep.grids = {{16, 9}};
        if (quick && !slicesGiven) args.froxelSweep.slices = {16, 32};
        if (quick && !lightsGiven) args.froxelLights = {0, 4, 16};
        if (quick && !shadowedGiven) args.froxelShadowed = {0, 4};
        if (quick && !shadowResolutionGiven) args.froxelShadowResolution = 32;
        stepsGiven = scalesGiven = true;  // not --quick's fog sweep below
        args.froxelQuick = quick;
        if (args.froxelTargetScene.empty())
            args.froxelTargetScene = std::count(args.scenes.begin(), args.scenes.end(), "fog_default")
                                         ? "fog_default"
                                         : args.scenes.front();
        else if (!std::count(args.scenes.begin(), args.scenes.end(), args.froxelTargetScene))
            throw cli::UsageError{"--froxel-target-scene '" + args.froxelTargetScene +
                                  "' is not in --scenes"};
    }
    if (int(args.froxel) + int(args.atmosphere) + int(args.clouds) + int(args.frame) + int(args.cloudsSlabs) +
            int(args.atmosphereTruth) + int(args.firstFrame) + int(args.worstCase) >
        1)
        throw cli::UsageError{
            "--froxel, --atmosphere, --atmosphere-truth, --clouds, --clouds-slabs, --frame and "
            "--first-frame, --worst-case: "
            "one mode at a time"};
    if (args.worstCase) {
        if (!sizeGiven) args.runner.width = 64, args.runner.height = 36;
        if (!framesGiven) args.runner.frames = 3;
        sizeGiven = framesGiven = true;
    }
    if (args.firstFrame) {
        if (!sizeGiven) args.runner.width = quick ? 160 : 1920, args.runner.height = quick ? 90 : 1080;
        if (!framesGiven) args.runner.frames = quick ? 4 : 12;
        sizeGiven = framesGiven = true;
    }
    if (args.atmosphereTruth) {
        if (!outGiven) args.out = "tests/atmosphere/data/path_traced_sky.csv";
        if (args.truthTarget == 0.0) args.truthTarget = quick ? 0.05 : 0.0025;
        if (args.truthMaxPaths == 0) args.truthMaxPaths = quick ? 20000 : 4000000;
    }
    if (args.cloudsSlabs) {
        if (!outGiven) args.out = "docs/accuracy-cost/clouds-slabs";
        if (args.cloudsSlabPaths == 0) args.cloudsSlabPaths = quick ? 200 : 20000;
    }
    if (args.frame) {
        if (!outGiven) args.out = "docs/accuracy-cost/frame";
        if (!refGiven) args.referenceSteps = quick ? 64 : 512;
        refGiven = true;
        if (args.errorStride == 0) args.errorStride = quick ? 1 : 8;  // at 1920 wide, scaled with the width
        if (args.frameSizes.empty())
            args.frameSizes = quick ? std::vector<std::pair<uint32_t, uint32_t>>{{64, 36}}
                                    : std::vector<std::pair<uint32_t, uint32_t>>{{1920, 1080}, {3840, 2160}};
        if (args.framePresets.empty())
            args.framePresets = quick ? std::vector<std::string>{"medium"}
                                      : std::vector<std::string>{"low", "medium", "high", "ultra"};
    }
    if (args.clouds) {
        if (!outGiven) args.out = "docs/accuracy-cost/clouds";
        if (!refGiven) args.referenceSteps = quick ? 64 : 512;
        refGiven = true;
        if (args.cloudsLightSteps == 0) args.cloudsLightSteps = quick ? 16 : 128;
        if (args.cloudsConvergedFrames == 0) args.cloudsConvergedFrames = quick ? 4 : 32;
        if (args.cloudsMotionFrames == 0) args.cloudsMotionFrames = quick ? 4 : 32;
        if (args.cloudsTruthPaths < 0) args.cloudsTruthPaths = quick ? 8 : 256;
        if (quick && args.cloudsSweepViews.empty()) args.cloudsSweepViews = {"ground_noon"};
    }
    if (args.atmosphere) {
        if (!outGiven) args.out = "docs/accuracy-cost/atmosphere";
        if (!refGiven) args.referenceSteps = quick ? 128 : 512;
        refGiven = true;
        if (quick && args.atmosphereSweepViews.empty()) args.atmosphereSweepViews = {"ground_sunset"};
    }
    args.quick = quick;
    if (quick) {
        if (!sizeGiven) args.runner.width = 64, args.runner.height = 36;
        if (!warmupGiven) args.runner.warmup = 1;
        if (!warmupMsGiven) args.runner.warmupMs = 0.0;
        if (!coldGiven) args.runner.coldWarmupMs = 0.0;
        if (!framesGiven) args.runner.frames = 2;
        // CI on lavapipe, whose calibration follows the machine's load: rows flagged, not timed again (a
        // media row of --atmosphere takes seconds a frame there).
        if (!retriesGiven) args.runner.calibration.retries = 0;
        if (!refGiven) args.referenceSteps = 1024;
        if (!stepsGiven) args.steps = {4, 16, 64};
        if (!noiseGiven) args.noiseSizes = {32};
        if (!scalesGiven) args.scales = {1.0f, 0.5f};
        if (!lengthsGiven) args.stepLengths = {4.0f, 1.0f};
        if (!motionWarmupGiven) args.motionOptions.warmup = 4;
        if (!motionFramesGiven) args.motionOptions.frames = 2;
        if (!motionStepGiven) args.motionOptions.frameStep = 2;
        if (!switchOffGiven) args.motionOptions.switchOffFrames = 4;
        args.motionQuick = true;
    }
    if (args.froxel) {
        // The fog sweep's preset scene is not used.
    } else if (args.presetScene.empty())
        args.presetScene = std::count(args.scenes.begin(), args.scenes.end(), "fog_default")
                               ? "fog_default"
                               : args.scenes.front();
    else if (!std::count(args.scenes.begin(), args.scenes.end(), args.presetScene))
        throw cli::UsageError{"--preset-scene '" + args.presetScene + "' is not in --scenes"};
    if (args.errorStride == 0) args.errorStride = std::max(1u, args.runner.width / 480);
    if (args.motionErrorStride == 0) args.motionErrorStride = args.errorStride;
    for (const std::string& scene : args.motionScenes)
        if (!std::count(args.scenes.begin(), args.scenes.end(), scene))
            throw cli::UsageError{"--motion-scenes: '" + scene + "' is not in --scenes"};
    std::sort(args.steps.begin(), args.steps.end());
    std::sort(args.noiseSizes.begin(), args.noiseSizes.end());
    std::sort(args.shadowKernels.begin(), args.shadowKernels.end());
    args.shadowKernels.erase(std::unique(args.shadowKernels.begin(), args.shadowKernels.end()),
                             args.shadowKernels.end());
    std::sort(args.scales.begin(), args.scales.end(), std::greater<>());
    if (args.sceneDir.empty()) {
        args.sceneDir =
            std::filesystem::is_directory("demo/scenes") ? "demo/scenes" : POSTFX_SOURCE_DIR "/demo/scenes";
    }
    return args;
}

std::string commandLine(int argc, char** argv) {
    std::string text;
    for (int i = 0; i < argc; ++i) {
        std::string a = i == 0 ? std::filesystem::path(argv[0]).filename().string() : argv[i];
        if (a.find_first_of(" \t\"'") != std::string::npos) a = "'" + a + "'";
        text += (i ? " " : "") + a;
    }
    return text;
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

int fail(const std::string& message) {
    std::fprintf(stderr, "\npostfx-bench: %s\n", message.c_str());
    return 1;
}

struct ScenePlan {
    std::string name;
    demo::Scene scene;
    std::vector<uint32_t> noiseSizes;  // {0}: the scene has no noise
    uint32_t baselineNoise = 0;        // the noise size the baselines run at
    bool shadows = false;              // its frames give postfx a shadow map

    // The shadow kernels swept at `noise`: --shadow-kernels and the scene's own at its own noise size,
    // else the scene's own; {0} without a shadow map.
    std::vector<uint32_t> kernelsAt(uint32_t noise, const std::vector<uint32_t>& swept) const {
        if (!shadows) return {0};
        std::vector<uint32_t> kernels = {scene.fog.shadowKernel};
        if (noise == baselineNoise) kernels.insert(kernels.end(), swept.begin(), swept.end());
        std::sort(kernels.begin(), kernels.end());
        kernels.erase(std::unique(kernels.begin(), kernels.end()), kernels.end());
        return kernels;
    }
};

int runFroxel(const Args& args, const std::string& command) {
    bench::FroxelRunArgs f;
    f.scenes = args.scenes;
    f.sceneDir = args.sceneDir;
    f.runner = args.runner;
    f.referenceSteps = args.referenceSteps;
    f.errorStride = args.errorStride;
    f.out = args.out;
    f.sweep = args.froxelSweep;
    f.fogSteps = args.steps;
    f.fogScales = args.scales;
    f.lightCounts = args.froxelLights;
    f.shadowedCounts = args.froxelShadowed;
    f.shadowResolution = args.froxelShadowResolution;
    f.targetScene = args.froxelTargetScene;
    f.bandwidth = args.bandwidth;
    f.motion = args.motion;
    f.motionScenes = args.motionScenes;
    f.motionOptions = args.motionOptions;
    f.motionErrorStride = args.motionErrorStride;
    f.motionQuick = args.motionQuick;
    // The copy bandwidth's buffers: 256 MiB (far beyond the caches) on a GPU, 16 MiB at a small size
    // (lavapipe's device memory is the CI machine's).
    if (args.runner.width * uint64_t(args.runner.height) < 640 * 360) f.copyBytes = uint64_t(16) << 20;
    if (args.froxelQuick) {
        // --quick: the light-count sweep on the sweep's first grid (160×90×128 is slow on lavapipe).
        f.lightGrid[0] = args.froxelSweep.grids.front().first;
        f.lightGrid[1] = args.froxelSweep.grids.front().second;
        f.lightGrid[2] = args.froxelSweep.slices.front();
    }
    return bench::runFroxel(f, command, utcNow());
}

int runAtmosphere(const Args& args, const std::string& command) {
    bench::AtmosphereRunArgs a;
    a.runner = args.runner;
    a.referenceSteps = args.referenceSteps;
    a.errorStride = args.errorStride;
    a.out = args.out;
    a.views = args.atmosphereViews;
    a.sweepViews = args.atmosphereSweepViews;
    if (args.quick) {
        a.psiDirections = 64;  // reference (a)'s Ψ table, coarser: seconds on lavapipe's machine
        a.psiSteps = 40;
        a.coarseOrders = true;
    }
    a.sweep = bench::defaultAtmosphereSweep(args.quick);
    if (args.quick) test::smallScatteringOrders(a.sweep.base);
    if (args.atmosphereSweepNone) a.sweep.values.clear();
    for (const auto& [knob, values] : args.atmosphereSweep) {
        auto it = std::find_if(a.sweep.values.begin(), a.sweep.values.end(),
                               [&](const auto& kv) { return kv.first == knob; });
        if (it == a.sweep.values.end()) it = a.sweep.values.insert(a.sweep.values.end(), {knob, {}});
        it->second = values;
    }
    return bench::runAtmosphere(a, command, utcNow());
}

int runClouds(const Args& args, const std::string& command) {
    bench::CloudsRunArgs a;
    a.runner = args.runner;
    a.referenceSteps = args.referenceSteps;
    a.referenceLightSteps = args.cloudsLightSteps;
    a.errorStride = args.errorStride;
    a.convergedFrames = args.cloudsConvergedFrames;
    a.motionFrames = args.cloudsMotionFrames;
    a.truthPaths = uint32_t(args.cloudsTruthPaths);
    a.truthStride = args.cloudsTruthStride;
    if (args.quick) a.shadowMapSize = 64;  // lavapipe: the default 512² map would take most of the time
    a.out = args.out;
    a.views = args.cloudsViews;
    a.sweepViews = args.cloudsSweepViews;
    a.sweep = bench::defaultCloudsSweep(args.quick);
    if (args.cloudsSweepNone) a.sweep.values.clear();
    for (const auto& [knob, values] : args.cloudsSweep) {
        auto it = std::find_if(a.sweep.values.begin(), a.sweep.values.end(),
                               [&](const auto& kv) { return kv.first == knob; });
        if (it == a.sweep.values.end()) it = a.sweep.values.insert(a.sweep.values.end(), {knob, {}});
        it->second = values;
    }
    return bench::runClouds(a, command, utcNow());
}

int runFrame(const Args& args, const std::string& command) {
    bench::FrameRunArgs a;
    a.runner = args.runner;
    a.sizes = args.frameSizes;
    a.presets = args.framePresets;
    a.budgetMs = float(args.frameBudgetMs >= 0.0 ? args.frameBudgetMs : (args.quick ? 0.0 : 1.0));
    a.sceneDir = args.sceneDir;
    a.referenceSteps = args.referenceSteps;
    a.errorStride = args.errorStride;
    if (args.quick) a.shadowMapSize = 64;  // lavapipe: the default 512² map would take most of the time
    a.quickScene = args.quick;
    a.out = args.out;
    return bench::runFrame(a, command, utcNow());
}

int runFirstFrame(const Args& args, const std::string& command) {
    bench::FirstFrameArgs a;
    a.width = args.runner.width;
    a.height = args.runner.height;
    a.frames = args.runner.frames;
    a.sceneDir = args.sceneDir;
    a.validation = args.runner.validation;
    a.driverCache = args.driverCache;
    a.small = args.quick;
    if (!args.firstFrameScenes.empty()) a.scenes = args.firstFrameScenes;
    return bench::runFirstFrame(a, command);
}

int runWorstCase(const Args& args, const std::string& command) {
    bench::WorstCaseArgs a;
    a.width = args.runner.width;
    a.height = args.runner.height;
    a.frames = std::max(args.runner.frames, 1u);
    a.sceneDir = args.sceneDir;
    a.validation = args.runner.validation;
    a.rows = args.worstCaseRows;
    a.calibration = args.runner.calibration;
    a.calibrationWarmupMs = std::max(args.runner.warmupMs, args.runner.coldWarmupMs);
    return bench::runWorstCase(a, command);
}

int run(const Args& args, const std::string& command) {
    if (args.pipelineStats) return bench::runPipelineStats();
    if (args.worstCase) return runWorstCase(args, command);
    if (args.firstFrame) return runFirstFrame(args, command);
    if (args.frame) return runFrame(args, command);
    if (args.froxel) return runFroxel(args, command);
    if (args.clouds) return runClouds(args, command);
    if (args.atmosphereTruth) {
        bench::AtmosphereTruthArgs a;
        a.targetError = args.truthTarget;
        a.maxPaths = args.truthMaxPaths;
        a.batchPaths = std::min<uint64_t>(a.batchPaths, a.maxPaths);
        a.out = args.out;
        return bench::runAtmosphereTruth(a, command, utcNow());
    }
    if (args.cloudsSlabs) {
        bench::CloudsSlabsArgs a;
        a.paths = args.cloudsSlabPaths;
        a.out = args.out;
        return bench::runCloudsSlabs(a, command, utcNow());
    }
    if (args.atmosphere) return runAtmosphere(args, command);
    std::string error;
    // Plan everything first: a bad scene name fails before the GPU work.
    std::vector<ScenePlan> plans;
    for (const std::string& name : args.scenes) {
        ScenePlan p;
        p.name = name;
        const std::string path = args.sceneDir + "/" + name + ".json";
        if (!demo::loadSceneFile(path, p.scene, error)) return fail(error);
        if (!p.scene.fog.enabled) return fail(path + ": the scene has no fog (effects.fog)");
        if (p.scene.fog.noise.enabled && !p.scene.fog.noise.hostTexture) {
            p.noiseSizes = args.noiseSizes;
            const uint32_t own = p.scene.fog.noise.textureSize;
            p.baselineNoise =
                std::count(p.noiseSizes.begin(), p.noiseSizes.end(), own) ? own : p.noiseSizes.back();
        } else {
            p.noiseSizes = {0};
        }
        plans.push_back(std::move(p));
    }
    // The in-motion scenes: --motion-scenes, else the run's but an S_unskipped twin of a scene S of the run
    // (the same image); none without the presets (motion measures them).
    std::vector<std::string> motionScenes;
    if (args.motion && args.presets) {
        motionScenes = args.motionScenes;
        if (motionScenes.empty() && args.motionQuick) {
            motionScenes = {args.presetScene};  // --quick: the preset scene only
        } else if (motionScenes.empty()) {
            const std::string suffix = bench::kUnskippedSuffix;
            for (const std::string& name : args.scenes) {
                const bool twin = name.size() > suffix.size() &&
                                  name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
                                  std::count(args.scenes.begin(), args.scenes.end(),
                                             name.substr(0, name.size() - suffix.size()));
                if (!twin) motionScenes.push_back(name);
            }
        }
    }
    auto inMotion = [&](const std::string& name) {
        return std::count(motionScenes.begin(), motionScenes.end(), name) > 0;
    };
    const bench::MotionOptions& motionOptions = args.motionOptions;
    const std::vector<uint32_t> motionFrames = bench::measuredFrames(motionOptions);
    const uint32_t motionLength = bench::sequenceLength(motionOptions);
    bench::MotionInfo motionInfo;
    motionInfo.options = motionOptions;
    motionInfo.errorStride = args.motionErrorStride;
    motionInfo.referenceSteps = args.referenceSteps;
    std::vector<bench::MotionResult> motion;

    const bool baselines = args.baselines && bench::Runner::hasBaselines();
    if (args.baselines && !baselines)
        std::fprintf(stderr,
                     "postfx-bench: built without the baselines (bench/baseline.cmake): postfx only\n");

    auto runner = bench::Runner::create(args.runner, error);
    if (!runner) return fail(error);
    const demo::VulkanHost& host = runner->host();

    bench::RunInfo info;
    fillRunHeader(info, host, args.runner, args.errorStride, args.referenceSteps, utcNow(), command);
    if (!runner->calibrate(info.calibration, error)) return fail(error);
    info.textureRate = args.textureRate;
    info.baselines = baselines;
    info.presetScene = args.presetScene;
    info.presetBudgets = args.presetBudgets;
    for (const ScenePlan& p : plans)
        info.sceneNoise.emplace_back(p.name, p.baselineNoise);

    constexpr postfx::FogQuality kPresets[] = {postfx::FogQuality::Low, postfx::FogQuality::Medium,
                                               postfx::FogQuality::High, postfx::FogQuality::Ultra};
    const size_t presets = args.presets ? std::size(kPresets) : 0;
    size_t total = 0;
    for (ScenePlan& p : plans) {
        p.shadows = runner->hasShadowMap(p.scene);  // from the scene alone: no setScene needed
        for (uint32_t noise : p.noiseSizes)
            total += 1 + p.kernelsAt(noise, args.shadowKernels).size() * args.steps.size() * 2 *
                             args.scales.size();
        total += presets + (baselines ? 2 * args.stepLengths.size() : 0);
        if (inMotion(p.name)) total += 1 + 2 * presets;  // the references, then each preset off and on
    }
    std::fprintf(stderr, "postfx-bench on %s, %ux%u, %zu measurements\n", info.device.c_str(), info.width,
                 info.height, total);

    std::vector<bench::Result> results;
    {
        bench::Progress progress(total);
        for (const ScenePlan& p : plans) {
            if (!runner->setScene(p.scene, error)) return fail(p.name + ": " + error);
            for (uint32_t noise : p.noiseSizes) {
                demo::Scene scene = p.scene;
                if (noise) scene.fog.noise.textureSize = noise;
                const std::string noiseText = noise ? " noise=" + std::to_string(noise) : "";
                progress.show(p.name + " CPU reference" + noiseText + " (" +
                              std::to_string(args.referenceSteps) + " steps/pixel)");
                demo::ImageF reference;
                const auto start = std::chrono::steady_clock::now();
                if (!runner->reference(scene, args.referenceSteps, args.errorStride, reference, error))
                    return fail(p.name + " reference: " + error);
                info.referenceSeconds.emplace_back(
                    p.name + noiseText,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
                progress.advance();

                auto measure = [&](const demo::Scene& s, bench::Setting setting) -> bool {
                    progress.show(p.name + " " + bench::methodName(setting.method) + " " + setting.label());
                    bench::Result r;
                    r.setting = setting;
                    if (!runner->measure(s, setting.method, setting.stepLength, reference, args.errorStride,
                                         r.timing, r.error, error)) {
                        error = p.name + " " + bench::methodName(setting.method) + " " + setting.label() +
                                ": " + error;
                        return false;
                    }
                    if (setting.method == bench::Method::Ours) {
                        // Texture fetches per output pixel (docs/accuracy-cost/README.md): per march step
                        // one noise fetch (noise on) and kernel² shadow texels (shadow map present), one
                        // depth fetch per marched ray; per pixel one color load, and when the march is
                        // reduced to w×h: the pixel's depth and its 2×2 texels' scatter and depth.
                        const double perStep =
                            (noise ? 1.0 : 0.0) + double(setting.shadowKernel) * double(setting.shadowKernel);
                        const glm::uvec2 march =
                            postfx::fogMarchExtent(info.width, info.height, setting.resolutionScale);
                        const double marched = double(march.x) * march.y / (double(info.width) * info.height);
                        const bool reduced = march.x != info.width || march.y != info.height;
                        r.fetchesPerPixel =
                            marched * (double(setting.steps) * perStep + 1.0) + 1.0 + (reduced ? 9.0 : 0.0);
                        r.floorMs = r.fetchesPerPixel * double(info.width) * double(info.height) /
                                    (args.textureRate * 1e9) * 1e3;  // NaN without a rate
                    }
                    results.push_back(std::move(r));
                    progress.advance();
                    return true;
                };
                bench::Setting base;
                base.scene = p.name;
                base.noiseSize = noise;
                base.shadowKernel = p.shadows ? scene.fog.shadowKernel : 0;
                // The sweep varies shadow kernel, scale, jitter and steps from the scene's own settings (no
                // preset).
                for (uint32_t kernel : p.kernelsAt(noise, args.shadowKernels)) {
                    for (float scale : args.scales) {
                        for (bool jitter : {true, false}) {
                            for (uint32_t steps : args.steps) {
                                demo::Scene s = scene;
                                s.fog.quality = postfx::FogQuality::Custom;
                                s.fog.steps = steps;
                                s.fog.jitter = jitter;
                                s.fog.resolutionScale = scale;
                                if (kernel) s.fog.shadowKernel = kernel;
                                bench::Setting setting = base;
                                setting.steps = steps;
                                setting.jitter = jitter;
                                setting.resolutionScale = scale;
                                setting.shadowKernel = kernel;
                                if (!measure(s, setting)) return fail(error);
                            }
                        }
                    }
                }
                // The presets as a host selects them (FogSettings::quality), at the scene's noise size.
                for (size_t k = 0; k < presets && noise == p.baselineNoise; ++k) {
                    demo::Scene s = scene;
                    s.fog.quality = kPresets[k];
                    const postfx::FogSettings applied = postfx::applyFogQuality(s.fog, s.fog.quality);
                    bench::Setting setting = base;
                    setting.preset = demo::fogQualityName(kPresets[k]);
                    setting.steps = applied.steps;
                    setting.jitter = applied.jitter;
                    setting.resolutionScale = applied.resolutionScale;
                    setting.shadowKernel = p.shadows ? applied.shadowKernel : 0;
                    if (!measure(s, setting)) return fail(error);
                }
                // In motion: the references of the measured frames, then each preset with temporal off and
                // on: timed still (as the sweep), then its sequence.
                if (inMotion(p.name) && presets > 0 && noise == p.baselineNoise) {
                    progress.show(p.name + " in motion: " + std::to_string(motionFrames.size()) +
                                  " CPU references");
                    const auto start = std::chrono::steady_clock::now();
                    std::vector<demo::ImageF> references(motionFrames.size());
                    for (size_t k = 0; k < motionFrames.size(); ++k)
                        if (!runner->reference(
                                bench::cameraMotionScene(scene, motionOptions, motionFrames[k]),
                                args.referenceSteps, args.motionErrorStride, references[k], error))
                            return fail(p.name + " in motion, reference: " + error);
                    motionInfo.referenceSeconds.emplace_back(
                        p.name + " camera",
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
                    if (!runner->setScene(scene, error)) return fail(p.name + ": " + error);
                    progress.advance();
                    for (size_t k = 0; k < presets; ++k) {
                        for (bool temporal : {false, true}) {
                            // The preset's knobs as Custom settings, so that temporal is what this row says
                            // (the presets turn it on themselves).
                            demo::Scene s = scene;
                            const postfx::FogSettings asPreset = postfx::applyFogQuality(s.fog, kPresets[k]);
                            s.fog = asPreset;
                            s.fog.quality = postfx::FogQuality::Custom;
                            s.fog.temporal.enabled = temporal;
                            if (motionOptions.temporalBlend > 0.0f)
                                s.fog.temporal.blendWeight = motionOptions.temporalBlend;
                            const postfx::FogSettings applied = s.fog;
                            bench::MotionResult m;
                            m.setting = base;
                            m.setting.preset = demo::fogQualityName(kPresets[k]);
                            m.setting.steps = applied.steps;
                            m.setting.jitter = applied.jitter;
                            m.setting.resolutionScale = applied.resolutionScale;
                            m.setting.shadowKernel = p.shadows ? applied.shadowKernel : 0;
                            m.temporal = temporal;
                            m.blendWeight = s.fog.temporal.blendWeight;
                            m.kind = bench::MotionKind::Camera;
                            const std::string name = p.name + " in motion " + m.setting.label() +
                                                     (temporal ? " temporal=on" : " temporal=off");
                            progress.show(name);
                            // The preset's row measured above is this still measurement when the scene's own
                            // temporal settings are these.
                            const bench::Result* row = nullptr;
                            for (const bench::Result& r : results)
                                if (r.setting.scene == p.name && r.setting.method == bench::Method::Ours &&
                                    r.setting.preset == m.setting.preset && r.setting.noiseSize == noise)
                                    row = &r;
                            const postfx::TemporalSettings& own = asPreset.temporal;
                            if (row && own.enabled == temporal &&
                                (!temporal || own.blendWeight == s.fog.temporal.blendWeight)) {
                                m.timing = row->timing;
                                m.still = row->error;
                            } else if (!runner->measure(s, bench::Method::Ours, 0.0f, reference,
                                                        args.errorStride, m.timing, m.still, error)) {
                                return fail(name + ": " + error);
                            }
                            auto sceneAt = [&](uint32_t n) {
                                return bench::cameraMotionScene(s, motionOptions, n);
                            };
                            m.frames = motionFrames;
                            if (!runner->sequence(
                                    motionLength, sceneAt, motionFrames, args.motionErrorStride,
                                    [&](uint32_t, const std::vector<float>& image) {
                                        m.errors.push_back(
                                            bench::Runner::compare(image, references[m.errors.size()]));
                                        return true;
                                    },
                                    error))
                                return fail(name + ": " + error);
                            m.shadowMatrixChanges = runner->shadowMatrixChanges(sceneAt, motionLength);
                            motion.push_back(std::move(m));
                            progress.advance();
                        }
                    }
                }
                if (baselines && noise == p.baselineNoise) {
                    for (bench::Method method :
                         {bench::Method::SeedAsWritten, bench::Method::SeedFixedRiemann}) {
                        for (float length : args.stepLengths) {
                            bench::Setting setting = base;
                            setting.method = method;
                            setting.stepLength = length;
                            setting.jitter = scene.fog.jitter;  // the seed's start offset: IGN, as ours
                            if (!measure(scene, setting)) return fail(error);
                        }
                    }
                }
            }
        }
        progress.show("writing the report");
    }
    bench::markParetoFronts(results);

    const std::vector<std::string> messages = runner->validationMessages();
    runner.reset();

    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) return fail("cannot create '" + args.out + "': " + ec.message());
    const std::string csv = args.out + "/results.csv", md = args.out + "/results.md",
                      svg = args.out + "/plot.svg", motionCsv = args.out + "/motion.csv";
    if (!bench::writeCsv(csv, info, results, error) ||
        !bench::writeMarkdown(md, info, results, error,
                              bench::motionMarkdown(info, motionInfo, results, motion)) ||
        !bench::writeSvg(svg, info, results, error) ||
        (!motion.empty() && !bench::writeMotionCsv(motionCsv, info, motionInfo, motion, {}, error)))
        return fail(error);

    std::printf("postfx-bench: %s, %ux%u, error stride %u, reference %u steps\n", info.device.c_str(),
                info.width, info.height, info.errorStride, info.referenceSteps);
    std::printf("%-14s %-19s %-28s %10s %10s %10s %10s %10s %8s %3s\n", "scene", "method", "setting",
                "GPU ms", "RMSE 1", "RMSE 8", "RMSE 16", "TM 16", "calib ms", "re");
    for (const bench::Result& r : results) {
        std::printf("%-14s %-19s %-28s %10s %9s%% %9s%% %9s%% %9s%% %8s %3s%s\n", r.setting.scene.c_str(),
                    bench::methodName(r.setting.method), r.setting.label().c_str(),
                    bench::formatNumber(r.timing.median, 4).c_str(),
                    bench::formatNumber(r.error[0].relativeRmse * 100, 3).c_str(),
                    bench::formatNumber(r.error[1].relativeRmse * 100, 3).c_str(),
                    bench::formatNumber(r.error[2].relativeRmse * 100, 3).c_str(),
                    bench::formatNumber(r.error[2].tonemappedRmse * 100, 3).c_str(),
                    bench::calibrationMsText(r.timing.calibration).c_str(),
                    bench::remeasuredText(r.timing.calibration).c_str(), r.pareto1 ? "  pareto" : "");
    }
    std::printf("%s", bench::conclusionsSummary(info, results).c_str());
    std::printf("%s", bench::motionSummary(info, results, motion, {}).c_str());
    std::printf("calibration: %s\n", bench::calibrationSummary(info.calibration).c_str());
    std::printf("%s", bench::repeatSpreadText(results).c_str());
    std::printf("wrote %s, %s, %s%s\n", csv.c_str(), md.c_str(), svg.c_str(),
                motion.empty() ? "" : (", " + motionCsv).c_str());
    if (!messages.empty()) {
        for (const std::string& m : messages)
            std::fprintf(stderr, "validation: %s\n", m.c_str());
        return fail(std::to_string(messages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Args args = parseArgs(argc, argv);
        return run(args, commandLine(argc, argv));
    } catch (const cli::UsageError& e) {
        std::fprintf(stderr, "postfx-bench: %s\n%s", e.message.c_str(), kUsage);
        return 2;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
