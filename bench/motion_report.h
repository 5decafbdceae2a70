// The "in motion" part of postfx-bench's reports (docs/accuracy-cost/README.md, "In motion"): motion.csv
// (every frame's numbers) and the markdown sections of results.md, with the targets and where the
// ray-marched fog's temporal pass pays, computed from the measured rows here (never written by hand).
#pragma once

#include "bench_types.h"
#include "motion.h"

#include <string>
#include <vector>

namespace bench {

// The in-motion targets: at the Medium preset, the in-motion error with temporal on within this multiple of
// the still camera's 16-frame error; a switched-off light's remaining fog contribution below
// kSwitchOffRemaining after at most kSwitchOffFrames frames (counting the frame it is switched off in as 0).
constexpr double kMotionTargetRatio = 1.5;
constexpr double kSwitchOffRemaining = 0.01;
constexpr uint32_t kSwitchOffFrames = 2;
// A pixel is touched by the switched-off light when it adds more than this fraction of the pixel's
// magnitude (touchedPixels).
constexpr double kTouchedTolerance = 0.01;

// The run's motion settings, for the reports.
struct MotionInfo {
    MotionOptions options;
    uint32_t errorStride = 1;  // the references' stride
    uint32_t referenceSteps = 0;
    std::vector<std::pair<std::string, double>> referenceSeconds;  // per scene and motion, CPU time [s]
};

// The in-motion target (ray-marched fog): the preset scene's Medium row in motion with temporal on, its
// still (temporal off) 16-frame error from the sweep's preset row.
struct MotionTarget {
    const MotionResult* motion = nullptr;  // nullptr: not measured
    const MotionResult* still = nullptr;   // the same sequence with temporal off: its still 16 frames
    double ratio = NAN;                    // motion->meanError() / still 16-frame error
    bool met() const { return ratio <= kMotionTargetRatio; }
};
MotionTarget motionTarget(const RunInfo& info, const std::vector<Result>& results,
                          const std::vector<MotionResult>& motion);

// Where the temporal pass pays, per preset (the mean in-motion error over the motion's scenes, GPU time
// on the preset scene): with temporal on, its time and error; the cheapest temporal-off preset whose
// error is at most that (nullptr: none), and whether temporal pays: its error is lower than the preset's
// own without temporal and no temporal-off preset reaches it in less time.
struct TemporalPays {
    std::string preset;
    double offMs = NAN, onMs = NAN, temporalMs = NAN;  // preset scene [ms]
    double offError = NAN, onError = NAN;              // mean over the scenes of each mean in-motion error
    std::string cheapestOff;                           // the temporal-off preset at <= onError; "" none
    double cheapestOffMs = NAN;
    bool pays = false;
};
std::vector<TemporalPays> temporalPays(const RunInfo& info, const std::vector<MotionResult>& motion);

// motion.csv's columns, in order.
const std::vector<std::string>& motionCsvColumns();
bool writeMotionCsv(const std::string& path, const RunInfo& info, const MotionInfo& motionInfo,
                    const std::vector<MotionResult>& motion, const std::vector<SwitchOffResult>& switchOff,
                    std::string& error);

// results.md's section "In motion" of the ray-marched fog (the target, where temporal pays, per scene).
std::string motionMarkdown(const RunInfo& info, const MotionInfo& motionInfo,
                           const std::vector<Result>& results, const std::vector<MotionResult>& motion);
// The froxel fog's section "In motion" (camera and light motion, the switched-off light's target).
std::string froxelMotionMarkdown(const RunInfo& info, const MotionInfo& motionInfo,
                                 const std::vector<MotionResult>& motion,
                                 const std::vector<SwitchOffResult>& switchOff);
// A few lines for stdout.
std::string motionSummary(const RunInfo& info, const std::vector<Result>& results,
                          const std::vector<MotionResult>& motion,
                          const std::vector<SwitchOffResult>& switchOff);

}  // namespace bench
