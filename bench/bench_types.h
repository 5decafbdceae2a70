// What postfx-bench measures: one setting of one method on one scene, and its result.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// Ours: postfx's ray-marched fog; the seed baselines; Froxel: postfx's froxel fog (postfx-bench --froxel).
enum class Method { Ours, SeedAsWritten, SeedFixedRiemann, Froxel };
// "postfx-fog", "seed-as-written", "seed-fixed-riemann", "postfx-froxel"
const char* methodName(Method method);
// Whether the method's frames are postfx's own (timed by Context::readPassTimings): Ours and Froxel.
inline bool isPostfx(Method method) {
    return method == Method::Ours || method == Method::Froxel;
}

// One point of the sweep.
struct Setting {
    std::string scene;  // scene file name without .json
    Method method = Method::Ours;
    uint32_t steps = 0;            // Ours: fog.steps (march steps per pixel)
    float stepLength = 0.0f;       // baselines: fixed step length [m]
    bool jitter = false;           // fog.jitter: IGN start offset per pixel and frame (the baselines too)
    float resolutionScale = 1.0f;  // Ours: fog.resolution_scale (the baselines march every pixel)
    uint32_t noiseSize = 0;        // fog.noise.textureSize; 0: noise off
    uint32_t shadowKernel = 0;     // fog.shadowKernel when the frame has a shadow map, else 0
    // Ours: a quality preset as the host selects it ("low", ...; the fields above are what it set);
    // empty for the sweep's own points. Presets are not on the Pareto fronts (they repeat sweep points).
    std::string preset;
    // Froxel: the grid (FroxelFogSettings::grid), its depth distribution and filter, and the frame's
    // local lights (non-zero intensity) with whether the light lists ran (lightListMinLights).
    uint32_t gridX = 0, gridY = 0, gridZ = 0;
    bool logSlices = false;  // depth_distribution log (else power)
    bool tricubic = false;   // tricubic B-spline apply (else trilinear)
    uint32_t lights = 0;
    bool lightLists = false;  // the light-list pass ran (lights > 0 and lights >= lightListMinLights)
    bool lightSweep = false;  // a row of the light-count sweep (generated point lights; timed, no error)
    // A row of the shadow sweep (kFroxelTargetLights generated point lights, the first shadowedLights of
    // them casting shadows into the demo's atlas; timed, no error).
    bool shadowSweep = false;
    uint32_t shadowedLights = 0;  // lights with a shadow map (LocalLight::shadow)

    // "steps=64 jitter=on scale=0.5 kernel=3 noise=128" (kernel: with a shadow map), "preset=medium
    // (steps=16 ...)", "step=0.5m jitter=on noise=128", "grid=160x90x128 dist=power tricubic=off noise=128
    // lights=64 lists=on" (lights: when the frame has any)
    std::string label() const;
};

// Error of linear radiance against the CPU reference (tests/common/image_compare).
struct ErrorStats {
    double relativeRmse = NAN;  // sqrt(Σ(a-b)²) / sqrt(Σ b²) over RGB
    double maxAbsError = NAN;   // largest |a-b| of any RGB channel [radiance]
    double fractionOff = NAN;   // fraction of pixels with a channel off by > 1% of the pixel's magnitude
    uint64_t nonFinite = 0;     // NaN/Inf channels in the GPU image
    // Relative RMSE of the tonemapped images (bench/stats.h, tonemappedRmse): one pixel far brighter than
    // the rest (the sun's disk) cannot dominate it as it does relativeRmse.
    double tonemappedRmse = NAN;
};

// The calibration of one timed row (bench/calibration.h): the fixed calibration dispatch timed right
// before and right after the row's timed frames, of the attempt kept.
struct RowCalibration {
    double beforeMs = NAN, afterMs = NAN;
    // The largest relative change among after against before and each against the run's reference;
    // NaN without timestamps or without calibration.
    double drift = NAN;
    uint32_t remeasured = 0;  // how many times the row was timed again because drift > the tolerance
    bool flagged = false;     // kept with drift > the tolerance, its retries spent
    double ms() const { return 0.5 * (beforeMs + afterMs); }
};

// GPU time of the method's passes per frame, over the measured frames [ms].
struct Timing {
    double median = NAN, p10 = NAN, p90 = NAN, min = NAN, max = NAN;
    uint32_t frames = 0;  // frames measured
    // Median of each pass over the frames that recorded it, in recording order ("fog.raymarch").
    std::vector<std::pair<std::string, double>> passMedians;
    RowCalibration calibration;
};

// The run's calibration (bench/calibration.h): its settings, the reference taken at the start after a
// warm-up, every calibration measurement (the reference first, re-measured attempts included) and how many
// rows were timed again.
struct CalibrationLog {
    bool enabled = false;  // false: not run (--no-calibration, or the queue has no timestamps)
    uint32_t iterations = 0, groups = 0, repeats = 0;  // the dispatch's work; dispatches per measurement
    double tolerance = 0.05;
    uint32_t retries = 3;
    double referenceMs = NAN;
    std::vector<double> measurements;  // [ms]
    uint32_t rows = 0;                 // timed rows bracketed
    uint32_t remeasuredRows = 0;       // rows timed more than once
    uint32_t remeasurements = 0;       // extra attempts over all rows
    uint32_t flaggedRows = 0;          // rows kept out of tolerance
};

constexpr std::array<uint32_t, 3> kAveragedFrames = {1, 8, 16};

struct Result {
    Setting setting;
    Timing timing;
    std::array<ErrorStats, 3> error;  // one frame, mean of 8 frames, mean of 16 frames (kAveragedFrames)
    double fetchesPerPixel = NAN;     // Ours: texture fetches per pixel (docs/accuracy-cost/README.md)
    double floorMs = NAN;             // fetches · pixels / texture rate; NaN without --texture-rate
    bool pareto1 = false;             // Ours: on the scene's Pareto front of (time, one-frame error)
    bool pareto16 = false;            // Ours: on the front of (time, 16-frame error)
};

// A quality preset's GPU time budget for the proposal (bench/conclusions.h) [ms], at the run's frame
// size on its device.
struct PresetBudget {
    std::string name;  // "low", "medium", "high", "ultra"
    double ms = 0;
};

// What the report's header says about the run.
struct RunInfo {
    std::string device;  // VulkanHost::deviceDescription()
    std::string vulkanApi;
    std::string date;  // UTC, ISO 8601
    std::string commandLine;
    uint32_t width = 0, height = 0;
    uint32_t errorStride = 1;
    uint32_t referenceSteps = 0;
    uint32_t warmup = 0, frames = 0;
    double warmupMs = 0;
    double coldWarmupMs = 0;   // the warm-up after the GPU sat idle (a CPU reference) [ms]
    double textureRate = NAN;  // [GTexel/s]; NaN: not given
    bool baselines = false;    // the baselines were run
    // Each scene's own noise texture size (0: no noise); the presets and baselines run at it.
    std::vector<std::pair<std::string, uint32_t>> sceneNoise;
    // The scene the presets are proposed from and the targets are measured on (--preset-scene).
    std::string presetScene;
    std::vector<PresetBudget> presetBudgets;  // --preset-budgets
    // CPU time of each reference: scene, noise size, seconds.
    std::vector<std::pair<std::string, double>> referenceSeconds;
    CalibrationLog calibration;

    // --froxel (bench/froxel_report.h): the device's copy bandwidth measured by the run (bytes read and
    // written per second; Runner::copyBandwidth) by a compute pass and by vkCmdCopyBuffer, and the
    // bandwidth the apply pass's floor is computed with (--bandwidth, else the larger measured one)
    // [GB/s]; the scene the targets and the light-count sweep are measured on; the build's
    // FroxelFogSettings::lightListMinLights default.
    double copyBandwidth = NAN;
    double transferBandwidth = NAN;
    double bandwidth = NAN;
    bool bandwidthGiven = false;
    std::string froxelTargetScene;
    uint32_t lightListDefault = 0;
};

// RunInfo::sceneNoise's entry for `scene`; 0 when it has none.
inline uint32_t sceneNoiseSize(const RunInfo& info, const std::string& scene) {
    for (const auto& [name, size] : info.sceneNoise)
        if (name == scene) return size;
    return 0;
}

}  // namespace bench
