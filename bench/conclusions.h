// What a run concludes, computed from its rows (never written by hand): the quality presets proposed by
// a fixed rule from the measured front, where the targets stand, and what empty-space skipping
// saves (docs/accuracy-cost/README.md, "Presets and targets, computed by the run").
#pragma once

#include "bench_types.h"

#include <string>
#include <vector>

namespace bench {

// The targets (docs/accuracy-cost/README.md), for the NVIDIA H100 at 1920×1080.
constexpr double kTargetDefaultMs = 0.5;      // the default (Medium) preset, all fog passes [ms]
constexpr double kTargetRelativeRmse = 0.02;  // the error at which we are compared with baseline (b)
constexpr double kTargetSpeedup = 4.0;        // our fastest setting at that error against baseline (b)'s

// low 0.25, medium 0.5 (= kTargetDefaultMs), high 1, ultra 2: each preset may take twice the one below.
std::vector<PresetBudget> defaultPresetBudgets();

struct ProposedPreset {
    PresetBudget budget;
    const Result* row = nullptr;  // the chosen sweep point on the preset scene; nullptr: none fits
    double meanError16 = NAN;     // its 16-frame relative RMSE, averaged over proposalScenes()
};

// The scenes whose errors a proposal averages: the run's scenes (RunInfo::sceneNoise) but the
// S + kUnskippedSuffix twin of a scene S of the run (the same image as S: it would count S twice).
std::vector<std::string> proposalScenes(const RunInfo& info);

// The proposal rule. For each of info.presetBudgets: among info.presetScene's postfx-fog sweep rows (not
// preset rows) at its own noise size with jitter on, whose median GPU time is within the budget, the
// one whose knobs (steps, scale, shadow kernel) give the lowest mean over proposalScenes() of the
// relative RMSE of the mean of 16 frames (what temporal accumulation reaches), each scene at its own
// noise size; ties go to the faster. A row whose knobs a scene did not measure is not a candidate.
// Timed on one scene, judged on all: a preset must not be chosen for one scene's kind of image.
std::vector<ProposedPreset> proposePresets(const RunInfo& info, const std::vector<Result>& results);

// The fastest row of `method` on `scene` at `noiseSize` (postfx-fog: sweep rows only) whose relative
// RMSE after kAveragedFrames[errorIndex] frames is at most `maxError`; nullptr when there is none.
const Result* fastestWithin(const std::vector<Result>& results, const std::string& scene, Method method,
                            uint32_t noiseSize, size_t errorIndex, double maxError);

// results.md's sections "Presets proposed by this run" and "Targets" (markdown, ends with a blank line).
std::string conclusionsMarkdown(const RunInfo& info, const std::vector<Result>& results);

// A scene named S + kUnskippedSuffix is S with fog.skip_empty_space false (demo/scenes/fog_valley*.json).
inline constexpr const char* kUnskippedSuffix = "_unskipped";
// For each such pair in the run: the section "Empty-space skipping" (every sweep point of S beside the
// same point of its un-skipped twin: time and error); empty without a pair. Part of conclusionsMarkdown.
std::string skippingMarkdown(const RunInfo& info, const std::vector<Result>& results);

// A few lines for stdout: the proposed presets and the targets' status.
std::string conclusionsSummary(const RunInfo& info, const std::vector<Result>& results);

}  // namespace bench
