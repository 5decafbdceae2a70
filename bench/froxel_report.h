// postfx-bench --froxel's report (docs/accuracy-cost/README.md, "Froxel fog"): results.csv (every
// number) and results.md (the targets, the light lists, the froxel fog against the ray-marched fog at
// equal error, every row), each with the run's device, driver, date and command line. What it concludes
// is computed from the rows here, never written by hand.
#pragma once

#include "bench_types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

// The froxel fog's targets, for the NVIDIA H100 at 1920×1080: postfx's default grid
// (FroxelFogSettings::grid, power slices, trilinear) on a scene with sun shadows and noise.
constexpr double kFroxelTargetMs = 0.10;        // all froxel passes [ms]
constexpr uint32_t kFroxelTargetLights = 64;    // ... with this many point lights
constexpr double kFroxelLightsTargetMs = 0.20;  // ... all froxel passes [ms]
constexpr uint32_t kFroxelTargetShadowed = 16;  // ... of them this many shadowed: the same limit
constexpr double kApplyFloorTarget = 2.0;       // the apply pass within this multiple of its floor

// The froxel fog's pass names (Context::readPassTimings), in recording order.
inline constexpr const char* kFroxelPasses[] = {"froxel_fog.light_lists", "froxel_fog.scatter",
                                                "froxel_fog.integrate", "froxel_fog.apply"};

// The bytes the apply pass cannot avoid moving per frame: each pixel's colour read and written
// (RGBA16F, 8 + 8 bytes) and its depth read (D32, 4 bytes). The integrated volume it samples is not
// counted (a pixel reads the 2 slices about its depth, and neighbours share them: far less than the
// volume), so the floor is a lower bound.
uint64_t applyFloorBytes(uint32_t width, uint32_t height);
// applyFloorBytes / bandwidth [ms]; NaN without a bandwidth.
double applyFloorMs(uint32_t width, uint32_t height, double gbPerSecond);

// The median of pass `name` in r's timing [ms]; NaN when the frames did not record it.
double passMs(const Result& r, const std::string& name);

// Marks pareto1 / pareto16 per scene and method (postfx-froxel's sweep rows, light-count rows left
// out; postfx-fog's rows): each method's own front of (time, error).
void markFroxelFronts(std::vector<Result>& results);

// The light-count sweep at one light count: the row without light lists (every froxel loops over every
// light) and the row with them.
struct LightListPoint {
    uint32_t lights = 0;
    const Result* loop = nullptr;
    const Result* lists = nullptr;
    double loopMs = NAN;   // loop's scatter pass
    double listsMs = NAN;  // lists' light-list pass + scatter pass
};
// The light counts > 0 with both rows, ascending.
std::vector<LightListPoint> lightListPoints(const std::vector<Result>& results);
// The rule for FroxelFogSettings::lightListMinLights: the smallest measured light count from which the
// lists are never slower (listsMs <= loopMs there and at every larger count measured); 257 (never) when
// they are slower at the largest; 0 without points.
uint32_t recommendedLightListMin(const std::vector<LightListPoint>& points);

// One point of `method`'s Pareto front on a scene (time against the error after
// kAveragedFrames[errorIndex] frames; light-count rows left out) and the cheapest row of the other
// method at no more error (nullptr: none gets that low).
struct EqualErrorPoint {
    const Result* front = nullptr;
    const Result* other = nullptr;
};
std::vector<EqualErrorPoint> equalErrorPoints(const std::vector<Result>& results, const std::string& scene,
                                              Method method, Method other, size_t errorIndex);

// One of the targets above, measured in the run's rows.
struct FroxelTarget {
    std::string name;             // "all passes ≤ 0.1 ms"
    const Result* row = nullptr;  // nullptr: not measured
    double measured = NAN;        // [ms], or × floor for the apply pass
    double limit = NAN;
    std::string unit;  // "ms" or "× floor"
    bool met() const { return measured <= limit; }
};
// The target row: info.froxelTargetScene's postfx-froxel sweep row at postfx's default grid, power
// slices, trilinear, with the scene's own lights (nullptr when the run has none).
const Result* froxelTargetRow(const RunInfo& info, const std::vector<Result>& results);
// The four targets: the target row's time; the light-count row with kFroxelTargetLights lights and
// the light lists as info.lightListDefault decides; the target row's apply pass over its floor; the
// shadow sweep's row with kFroxelTargetShadowed of those lights shadowed.
std::vector<FroxelTarget> froxelTargets(const RunInfo& info, const std::vector<Result>& results);

// The froxel report's CSV columns, in order (tests/bench parses them by name).
const std::vector<std::string>& froxelCsvColumns();
bool writeFroxelCsv(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                    std::string& error);
// results.md; `sections` (markdown: the in-motion section) follows the conclusions.
bool writeFroxelMarkdown(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
                         std::string& error, const std::string& sections = "");
// results.md's sections "Targets", "Light lists" and "Froxel fog against the ray-marched fog at equal
// error" (markdown, ends with a blank line): part of writeFroxelMarkdown.
std::string froxelConclusionsMarkdown(const RunInfo& info, const std::vector<Result>& results);
// A few lines for stdout: the targets and the light-list rule's answer.
std::string froxelSummary(const RunInfo& info, const std::vector<Result>& results);

}  // namespace bench
