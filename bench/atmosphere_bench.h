// postfx-bench --atmosphere (docs/accuracy-cost/README.md, "Atmosphere (--atmosphere)"): the sky
// scenes it measures, the LUT sizes and sample counts it sweeps, the situations it times (what a frame
// rebuilds), and its report (results.csv, results.md, the targets). Plain C++ (no Vulkan): tests/bench
// unit-tests it.
#pragma once

#include "bench_types.h"

#include <postfx/atmosphere.h>
#include <postfx/inputs.h>

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

// A sky scene: the camera, the sun, and geometry (a terrain plane) in part of the image.
struct AtmosphereView {
    std::string name;
    double altitude = 0;  // camera height above the ground (y) [m]
    double pitchDeg = 0;  // camera pitch above the horizon [deg]; the camera looks along +x
    double sunElevationDeg = 0;
    double sunAzimuthDeg = 0;  // from the view direction (+x) toward +z [deg]
    // The ground plane y = 0 as geometry up to this distance along each pixel's ray [m]; 0: no geometry
    // (every pixel shows the sky, or the planet's ground as the model draws it).
    double terrainDistance = 0;
};

// ground_sun30 (camera 300 m up, the sun at 30° off to the side), ground_sunset (sun at 5° ahead), both
// with the ground plane as geometry up to 30 km (inside the aerial-perspective LUT's default 32 km),
// space_sun30 (camera 105 km up, just above the top, looking down at the horizon, no geometry: the planet
// fills half the image; the sky-view LUT's sky half between its two spans), orbit_sun30 (400 km up: the sky
// half spans only the directions that meet the air).
std::vector<AtmosphereView> atmosphereViews();

// The view's camera for a w×h image: vertical field of view kAtmosphereFovYDeg, reversed Z, near
// kAtmosphereNear, far kAtmosphereFar; `yawOffset` [rad] turns it about +y.
constexpr float kAtmosphereFovYDeg = 60.0f;
constexpr float kAtmosphereNear = 1.0f;    // [m]
constexpr float kAtmosphereFar = 1e6f;     // [m]
constexpr float kTerrainRadiance = 0.03f;  // the terrain's colour before the atmosphere, per unit sun
postfx::CameraInput atmosphereCamera(const AtmosphereView& view, uint32_t width, uint32_t height,
                                     double yawOffset = 0.0);
// Direction toward the sun, `elevationOffset` [rad] added to the view's elevation.
postfx::Vec3 atmosphereToSun(const AtmosphereView& view, double elevationOffset = 0.0);
// Unit world direction through the centre of pixel (i, j) of a w×h image.
postfx::DVec3 atmospherePixelDirection(const postfx::CameraInput& camera, double i, double j, uint32_t width,
                                       uint32_t height);
// The image's depth (reversed Z, as the GPU samples it: 0 = no geometry) and colour (RGBA: the terrain's
// kTerrainRadiance on geometry, 0 on the sky; alpha 1).
void atmosphereImages(const AtmosphereView& view, const postfx::CameraInput& camera, uint32_t width,
                      uint32_t height, std::vector<float>& depth, std::vector<float>& color);

// What a frame rebuilds (docs/effects/atmosphere.md, frame plan), frame n of a timed run:
//   still:  camera and sun still: atmosphere.apply only;
//   camera: the camera turning (yaw alternating by kAtmosphereMotion each frame): aerial perspective +
//           apply;
//   sun:    the sun moving (elevation alternating by kAtmosphereMotion): sky view + aerial perspective +
//           apply;
//   media:  a media change (Mie scattering alternating by a factor 1 + kAtmosphereMediaChange): every LUT
//           (transmittance, multiple scattering, sky view, aerial perspective) + apply.
enum class AtmosphereSituation { Still, Camera, Sun, Media };
const char* situationName(AtmosphereSituation situation);  // "still", "camera", "sun", "media"
constexpr double kAtmosphereMotion = 0.01;                 // [rad], 10× the rebuild threshold
constexpr float kAtmosphereMediaChange = 1e-3f;

// One point of the sweep: the sweep's base settings (postfx's defaults) with one knob changed.
struct AtmospherePoint {
    std::string knob;   // "default" or one of atmosphereKnobs()
    std::string value;  // "256x64", "40", ... ("" for default)
    postfx::AtmosphereSettings settings;
};

// The knobs swept, in order: transmittance_size (WxH), transmittance_steps, ms_size (N: N×N), ms_directions
// (a perfect square), ms_steps, sky_view_size (WxH), sky_view_steps, ap_size (N: N×N×N),
// ap_steps_per_slice.
const std::vector<std::string>& atmosphereKnobs();
// Each knob's values (text as on the command line); a knob absent or empty is not swept.
struct AtmosphereSweepOptions {
    std::vector<std::pair<std::string, std::vector<std::string>>> values;
    // The settings every point starts from: postfx's defaults (--quick: test::smallScatteringOrders).
    postfx::AtmosphereSettings base;
};
AtmosphereSweepOptions defaultAtmosphereSweep(bool quick);
// `settings` with `knob` set to `value`; false with `error` for a bad value (the settings' own ranges are
// checked by postfx::validateAtmosphereSettings).
bool applyAtmosphereKnob(postfx::AtmosphereSettings& settings, const std::string& knob,
                         const std::string& value, std::string& error);
// The value `knob` has in `settings`, as text ("256x64").
std::string atmosphereKnobValue(const postfx::AtmosphereSettings& settings, const std::string& knob);
// "default" first, then each knob's values that differ from the default, knob by knob. False with `error`
// for a bad value or invalid settings.
bool atmosphereSweep(const AtmosphereSweepOptions& options, std::vector<AtmospherePoint>& out,
                     std::string& error);

// The atmosphere's passes (Context::readPassTimings), in recording order.
// atmosphere.scattering_orders runs once per order: its time is their sum.
inline constexpr const char* kAtmospherePasses[] = {
    "atmosphere.transmittance", "atmosphere.multiple_scattering", "atmosphere.scattering_orders",
    "atmosphere.sky_view",      "atmosphere.aerial_perspective",  "atmosphere.apply"};

// The targets on the H100 at 1920×1080 (the sum of the atmosphere.* passes a frame records): a still view,
// a moving camera or sun, and a change of the media (rare: every LUT rebuilt, the scattering orders too).
constexpr double kAtmosphereStillTargetMs = 0.02;
constexpr double kAtmosphereMovingTargetMs = 0.06;
constexpr double kAtmosphereRebuildTargetMs = 2.0;

struct AtmosphereRow {
    std::string view;
    AtmosphereSituation situation = AtmosphereSituation::Media;
    AtmospherePoint point;
    Timing timing;  // the frame's atmosphere.* passes: median of the sums, and each pass's median
    // Per pass: in how many timed frames it was recorded (the plan: which LUTs a frame rebuilds).
    std::vector<std::pair<std::string, uint32_t>> passFrames;
    // Against reference (a) at the error stride: sky pixels (no geometry, the sun disk's pixels left
    // out), geometry pixels, and both.
    ErrorStats sky, geometry, all;
    uint64_t skyPixels = 0, geometryPixels = 0;
};

// The run's header (RunInfo: device, driver, date, command, size, stride, reference steps, warm-up).
struct AtmosphereInfo {
    RunInfo run;
    uint32_t psiDirections = 0, psiSteps = 0;                      // the reference's Ψ table
    std::vector<std::pair<std::string, double>> referenceSeconds;  // per view
};

double atmospherePassMs(const AtmosphereRow& row, const std::string& pass);  // NaN when not recorded
uint32_t atmospherePassFrames(const AtmosphereRow& row, const std::string& pass);

struct AtmosphereTarget {
    std::string name;                    // "still camera and sun ≤ 0.02 ms"
    const AtmosphereRow* row = nullptr;  // the worst default row of those situations; nullptr: none
    double limit = NAN;
    double measured() const { return row ? row->timing.median : NAN; }
    bool met() const { return measured() <= limit; }
};
// Still; moving (camera and sun rows); full rebuild (media rows): each the slowest view's default row.
std::vector<AtmosphereTarget> atmosphereTargets(const std::vector<AtmosphereRow>& rows);

const std::vector<std::string>& atmosphereCsvColumns();
bool writeAtmosphereCsv(const std::string& path, const AtmosphereInfo& info,
                        const std::vector<AtmosphereRow>& rows, std::string& error);
bool writeAtmosphereMarkdown(const std::string& path, const AtmosphereInfo& info,
                             const std::vector<AtmosphereRow>& rows, std::string& error);
// A few lines for stdout: the targets.
std::string atmosphereSummary(const AtmosphereInfo& info, const std::vector<AtmosphereRow>& rows);

}  // namespace bench
