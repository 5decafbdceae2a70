// The benchmark's GPU side: the demo renderer driven frame by frame into the bench's own command buffers
// (two frames in flight), postfx's pass timings (Context::readPassTimings) or the baselines' own
// timestamp queries, and the error of 1, 8 and 16 jittered frames against the CPU reference.
#pragma once

#include "bench_types.h"
#include "calibration.h"

#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace bench {

struct RunnerOptions {
    uint32_t width = 1920, height = 1080;
    uint32_t warmup = 5;  // frames recorded before timing, at least
    // ... and for at least this long [ms] (wall clock), so that the GPU's clocks have ramped up after the
    // CPU reference or a lighter setting.
    double warmupMs = 200.0;
    // ... or this long after the GPU sat idle for seconds (the CPU reference): 200 ms was not always
    // enough on the H100 (a bimodal median, 2.7× its p10, in the setting measured next).
    double coldWarmupMs = 1000.0;
    uint32_t frames = 30;            // frames timed
    bool validation = false;         // Khronos validation with synchronization validation
    CalibrationOptions calibration;  // the calibration around each row's timed frames
};

// The report header's run fields common to every mode: device, Vulkan API, date, command, image size,
// error stride, reference steps, warm-up and timed frames.
void fillRunHeader(RunInfo& info, const demo::VulkanHost& host, const RunnerOptions& options,
                   uint32_t errorStride, uint32_t referenceSteps, const std::string& date,
                   const std::string& commandLine);

class Runner {
public:
    static std::unique_ptr<Runner> create(const RunnerOptions& options, std::string& error);
    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

    const demo::VulkanHost& host() const;
    // The demo renderer's postfx context (what quality Auto and the frame budget chose).
    const postfx::Context& postfxContext() const;
    // Whether the baselines (bench/baseline.h) were built in.
    static bool hasBaselines();

    // Brackets every timed row of measure() from now on with the calibration (bench/calibration.h),
    // recording into `log` (which outlives the runner); takes the run's reference first unless `log` has
    // one. Without it, measure() times each row once and leaves Timing::calibration NaN.
    bool calibrate(CalibrationLog& log, std::string& error);

    // Uploads the scene's geometry (once per scene, before reference() and measure()).
    bool setScene(const demo::Scene& scene, std::string& error);
    // Whether the frames of `scene` give postfx a shadow map (sun.shadows and a caster).
    bool hasShadowMap(const demo::Scene& scene) const;
    // Whether the demo's forward pass fogs its transparent surfaces through postfx's lookup in the timed
    // frames (default true); false times the pass without it (the lookup still built), so that the
    // difference of two rows is the lookup's share of host.forward.
    void setForwardLookup(bool lookup);

    // The CPU reference of `scene`'s frame (Renderer::renderReference: its fog as given, `steps` midpoint
    // steps, no jitter) at every `stride`-th pixel in x and y. Time is frozen, so it fits every frame.
    bool reference(const demo::Scene& scene, uint32_t steps, uint32_t stride, demo::ImageF& out,
                   std::string& error);

    // Times `method` on `scene` (warm-up, then the timed frames, bracketed by the calibration and timed
    // again while it drifts: Timing::calibration) and measures the error of one frame and
    // of the mean of 8 and 16 frames (consecutive frame indices from a multiple of 1024: only the jitter
    // differs; the ray-marched fog's IGN pattern repeats every 64 frames, the froxel fog's Halton
    // samples every 1024) against `reference` (from reference() with the same stride); an empty
    // `reference` (width 0) measures no error (`error` keeps NaN). Ours and Froxel: postfx with
    // scene.fog and scene.froxelFog as given. Baselines: `stepLength` [m] over the un-fogged frame with
    // scene.fog's medium.
    bool measure(const demo::Scene& scene, Method method, float stepLength, const demo::ImageF& reference,
                 uint32_t stride, Timing& timing, std::array<ErrorStats, 3>& error, std::string& message);

    // Renders a sequence of `frames` frames with frame indices 0 .. frames - 1 (index 0 is a camera cut,
    // demo::Renderer's FrameInfo::cameraCut: postfx's temporal histories start anew), frame n being
    // sceneAt(n) (camera, lights, fog; the geometry of the last setScene), two in flight, and hands each
    // frame of `readback` (ascending, each < frames) to onFrame(n, rgba): its radiance at every `stride`-th
    // pixel in x and y, the layout of reference() with that stride. Nothing is timed. The frames after it
    // continue above the indices measure() used before.
    bool sequence(uint32_t frames, const std::function<demo::Scene(uint32_t)>& sceneAt,
                  const std::vector<uint32_t>& readback, uint32_t stride,
                  const std::function<bool(uint32_t, const std::vector<float>&)>& onFrame,
                  std::string& error);

    // The frames n of a sequence (1 .. frames - 1, sceneAt(n) as for sequence()) at which the demo's shadow
    // map matrix (demo::fitShadowMap, which follows the camera) differs from the one of the last such frame
    // (at first frame 0's) by postfx's rule (an element by more than 1e-6 of the largest): postfx resets
    // its temporal histories there. 0 when the frames have no shadow map.
    uint32_t shadowMatrixChanges(const std::function<demo::Scene(uint32_t)>& sceneAt, uint32_t frames) const;

    // The error of `image` (RGBA floats in a reference's layout) against `reference`, as measure() computes
    // it.
    static ErrorStats compare(const std::vector<float>& image, const demo::ImageF& reference);

    // The device's memory bandwidth as a copy of `bytes` between two device-local buffers moves it,
    // (bytes read + bytes written) / time [GB/s], the median of `repeats` timed copies after copies for
    // RunnerOptions::coldWarmupMs (the clocks ramp up): `transfer` by vkCmdCopyBuffer, `compute` by a
    // compute pass (bench/shaders/copy_bandwidth.comp, 16-byte words). NaN when the queue has no
    // timestamps.
    bool copyBandwidth(uint64_t bytes, uint32_t repeats, double& transfer, double& compute,
                       std::string& error);

    // Validation messages so far (with RunnerOptions::validation).
    std::vector<std::string> validationMessages() const;

    struct Impl;

private:
    explicit Runner(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bench
