// postfx-bench --clouds (docs/accuracy-cost/README.md, "Clouds (--clouds)"): the views it measures, the
// settings it sweeps (steps, light steps, resolution scale, noise sizes, the quality presets), its targets
// and its report (results.csv, results.md). Plain C++ (no Vulkan): tests/bench unit-tests it.
#pragma once

#include "bench_types.h"

#include <postfx/clouds.h>
#include <postfx/inputs.h>

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

// A view of the cloud layer (postfx's default: 1500–4000 m, coverage 0.5, noise on) with the atmosphere on.
struct CloudsView {
    std::string name;
    double altitude = 0;  // camera height above the ground (y) [m]
    double pitchDeg = 0;  // camera pitch above the horizon [deg]; the camera looks along +x
    double sunElevationDeg = 0;
    double sunAzimuthDeg = 0;  // from the view direction (+x) toward +z [deg]
};

// ground_noon (camera 100 m up looking 20° up into the layer, the sun at 60°), ground_sunset (the same,
// the sun at 5° ahead), above (camera 6 km up, above the layer, looking 10° down at it, the sun at 60°).
std::vector<CloudsView> cloudsViews();

constexpr float kCloudsFovYDeg = 60.0f;
constexpr float kCloudsNear = 0.1f;  // [m]
constexpr float kCloudsFar = 1e6f;   // [m]
// The view's camera for a w×h image: vertical field of view kCloudsFovYDeg, reversed Z; `yawOffset`
// [rad] turns it about +y.
postfx::CameraInput cloudsCamera(const CloudsView& view, uint32_t width, uint32_t height,
                                 double yawOffset = 0.0);
postfx::Vec3 cloudsToSun(const CloudsView& view);

// The motion of the "in motion" error: the camera panning this much every frame [deg].
constexpr double kCloudsPanDegPerFrame = 0.1;

// One row of the sweep: the clouds' settings (the Medium preset's values and one knob changed, or a
// preset).
struct CloudsPoint {
    std::string knob;   // "default", one of cloudsKnobs(), or "preset"
    std::string value;  // "32", "0.5", "low", ... ("" for default)
    postfx::CloudSettings settings;
};

// The knobs swept, in order: model (multiple_scattering.model: slab, or octaves at their defaults), steps,
// light_steps, resolution_scale, base_size (noise.baseSize), detail_size (noise.detailSize), temporal
// (on/off), preset (low, medium, high, ultra: applyCloudQuality).
const std::vector<std::string>& cloudsKnobs();
struct CloudsSweepOptions {
    std::vector<std::pair<std::string, std::vector<std::string>>> values;
};
CloudsSweepOptions defaultCloudsSweep(bool quick);
// The settings every row starts from: postfx's defaults (the Medium preset's values), the clouds on.
postfx::CloudSettings cloudsBaseSettings();
bool applyCloudsKnob(postfx::CloudSettings& settings, const std::string& knob, const std::string& value,
                     std::string& error);
std::string cloudsKnobValue(const postfx::CloudSettings& settings, const std::string& knob);
// "default" first, then each knob's values that differ from the default (presets always: a preset row
// names its preset), knob by knob. False with `error` for a bad value, an unknown knob or invalid settings.
bool cloudsSweep(const CloudsSweepOptions& options, std::vector<CloudsPoint>& out, std::string& error);

// The clouds' passes (Context::readPassTimings), in recording order; a frame's time is the sum of the
// clouds.* passes it recorded.
inline constexpr const char* kCloudsPasses[] = {"clouds.base_noise", "clouds.detail_noise",
                                                "clouds.shadow",     "clouds.march",
                                                "clouds.temporal",   "clouds.upsample"};
bool isCloudsPass(const std::string& name);  // "clouds." followed by anything

// The targets on the H100 at 1920×1080: the Medium preset (temporal on), the sum of the clouds.*
// passes with camera and sun still, on the slowest view; its converged still error on the worst view.
constexpr double kCloudsMediumTargetMs = 0.5;
constexpr double kCloudsMediumTargetError = 0.015;
// Published anchors (not targets): Horizon Zero Dawn on a PS4 (Schneider 2015) and a public implementation
// on an RTX 4080 [ms].
constexpr double kCloudsAnchorPs4Ms = 2.0;
constexpr double kCloudsAnchorRtx4080Ms = 0.76;

// Error of an image against the reference: relative RMSE over RGB (ErrorStats, tests' image_compare) and
// the mean over pixels of |Y - Y_ref| / Y_ref (luminance).
struct CloudsError {
    ErrorStats stats;
    double meanRelativeLuminance = NAN;
};

// Against the path-traced truth (reference::renderClouds' path-traced mode, every scattering order) at
// every truth-stride-th pixel: the relative RMSE (the truth's own noise included: CloudsInfo's
// truthStandardError) and the bias, (mean luminance / the truth's - 1) over the pixels the clouds change.
struct CloudsTruthError {
    double relativeRmse = NAN;
    double bias = NAN;
};

struct CloudsRow {
    std::string view;
    CloudsPoint point;
    Timing timing;  // still frames: the clouds.* passes, median of the sums and each pass's median
    std::vector<std::pair<std::string, uint32_t>> passFrames;
    // Still: the last of convergedFrames still frames (temporal on; 1 frame without temporal). Motion: the
    // last of motionFrames panning frames, against its own view's reference.
    CloudsError still, motion;
    uint32_t stillFrames = 0, motionFrames = 0;
    // The still error split against the truth: the model (the row's CPU reference, no discretisation)
    // and the GPU's (model + discretisation). NaN without --clouds-truth.
    CloudsTruthError model, total;
};

struct CloudsInfo {
    RunInfo run;  // referenceSteps: the reference's view steps
    uint32_t referenceLightSteps = 0;
    uint32_t convergedFrames = 0, motionFrames = 0;
    std::vector<std::pair<std::string, double>> referenceSeconds;  // "view noise" -> seconds
    // The path-traced truth: paths per pixel, stride, and per view its mean relative standard error (the
    // luminance's, over the pixels the clouds change) and seconds. truthPaths 0: not run.
    uint32_t truthPaths = 0, truthStride = 0;
    std::vector<std::pair<std::string, double>> truthStandardError, truthSeconds;
};

double cloudsPassMs(const CloudsRow& row, const std::string& pass);  // NaN when not recorded

struct CloudsTarget {
    std::string name;
    const CloudsRow* row = nullptr;  // the worst Medium row; nullptr: none measured
    double limit = NAN;
    bool error = false;  // the converged still error (else the GPU time)
    double measured() const;
    bool met() const { return measured() <= limit; }
};
// Whether a row runs the Medium preset's settings: the "default" row and the "preset=medium" row.
bool isCloudsMediumRow(const CloudsRow& row);
// Medium ≤ kCloudsMediumTargetMs on the slowest view; Medium's converged still error ≤
// kCloudsMediumTargetError on the worst view.
std::vector<CloudsTarget> cloudsTargets(const std::vector<CloudsRow>& rows);

const std::vector<std::string>& cloudsCsvColumns();
bool writeCloudsCsv(const std::string& path, const CloudsInfo& info, const std::vector<CloudsRow>& rows,
                    std::string& error);
bool writeCloudsMarkdown(const std::string& path, const CloudsInfo& info, const std::vector<CloudsRow>& rows,
                         std::string& error);
std::string cloudsSummary(const CloudsInfo& info, const std::vector<CloudsRow>& rows);

}  // namespace bench
