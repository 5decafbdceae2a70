// postfx-bench's "in motion" measurement (docs/accuracy-cost/README.md, "In motion"): the scene state of
// each frame of a sequence (a camera walking and turning, a point light moving, a light switched off),
// the frames measured, and the switched-off light's remaining contribution. Plain C++ over the demo's
// scene description (no Vulkan; tests/bench unit-tests it); the GPU side is Runner::sequence.
#pragma once

#include "bench_types.h"

#include "scene/scene.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct MotionOptions {
    // A sequence starts with a camera cut (frame 0: postfx's temporal history starts anew); the frames
    // warmup + k · frameStep, k = 0 .. frames - 1, are compared with their own CPU references.
    uint32_t warmup = 32;
    uint32_t frames = 8;
    uint32_t frameStep = 4;
    float cameraSpeed = 1.4f;  // [m/s] walking speed, forward (the view direction, horizontal)
    float yawRateDeg = 20.0f;  // [deg/s] turning about +y; positive turns left
    float lightSpeed = 1.4f;   // [m/s] the moving light, along the first frame's camera right (horizontal)
    uint32_t light = 0;        // the index of the light that moves, and that is switched off (froxel)
    // The switched-off light: off from frame F = warmup on (the camera still); frames F - 1 (the last lit)
    // .. F + switchOffFrames - 1 measured.
    uint32_t switchOffFrames = 8;
    // The temporal-on rows' TemporalSettings::blendWeight; 0: the fog's own (its default, or the scene's).
    float temporalBlend = 0.0f;
    // Frame n is at n · frameSeconds [s]: the scene files' default frame_time (60 frames per second). The
    // renderer's own time stays frozen (the bench's RenderOptions::fixedTimeSeconds).
    double frameSeconds = demo::kDefaultFrameTime;
};

// The frames compared with their references: warmup + k · frameStep, ascending.
std::vector<uint32_t> measuredFrames(const MotionOptions& options);
// Frames a sequence renders: the last measured one + 1.
uint32_t sequenceLength(const MotionOptions& options);

// `start` after `seconds` of walking at `speed` [m/s] along its view direction projected onto the
// horizontal plane while turning at `yawRateDeg` [deg/s] about +y (an arc of a circle; positive: left, seen
// from above counter-clockwise): position on the arc, look-at point turned with the view, up unchanged.
demo::Camera walkingCamera(const demo::Camera& start, float speed, float yawRateDeg, double seconds);

// The scene of frame `frame` of each sequence: the camera walking and turning (every light where it is);
// light options.light moving (the camera still; a scene without that light: unchanged). Lights and
// geometry are otherwise the scene's.
demo::Scene cameraMotionScene(const demo::Scene& scene, const MotionOptions& options, uint32_t frame);
demo::Scene lightMotionScene(const demo::Scene& scene, const MotionOptions& options, uint32_t frame);
// The moving light's direction [unit]: the camera's right, horizontal ((1, 0, 0) when it looks straight
// down or up).
glm::vec3 lightMotionDirection(const demo::Camera& camera);
// `scene` with light `light`'s intensity 0 (switched off).
demo::Scene lightOffScene(const demo::Scene& scene, uint32_t light);

// The in-motion sequences.
enum class MotionKind { Camera, Light };
const char* motionKindName(MotionKind kind);  // "camera", "light"

// One setting in motion: timed still, then a sequence measured frame by frame against each frame's
// reference.
struct MotionResult {
    Setting setting;  // scene, method, knobs (a preset row's preset)
    bool temporal = false;
    float blendWeight = 0.0f;  // TemporalSettings::blendWeight (when temporal)
    MotionKind kind = MotionKind::Camera;
    Timing timing;  // the still camera, timed as the sweep
    // The still camera's error of one frame and of the mean of 8 and 16 (measured as the sweep's; with
    // temporal on, a frame is the history's blend after the warm-up and timed frames).
    std::array<ErrorStats, 3> still;
    std::vector<uint32_t> frames;    // the measured frames
    std::vector<ErrorStats> errors;  // each against its frame's reference
    // Frames of the sequence at which the demo's shadow-map fit (which depends on the camera) moved beyond
    // postfx's threshold, each resetting the temporal history (Runner::shadowMatrixChanges).
    uint32_t shadowMatrixChanges = 0;

    double meanError() const;   // mean of the frames' relative RMSE; NaN without frames
    double maxError() const;    // the largest; NaN without frames
    double temporalMs() const;  // the fog.temporal pass's median (ray-marched fog) [ms]; NaN without it
};

// A light switched off at frame F (MotionOptions::warmup; the camera still), each frame F - 1, F, F + 1,
// ... against the references with and without the light, and against the control sequence: the same
// light dimmed to kControlDim of its intensity (on for postfx, invisible) and switched off at F the same
// way, so that postfx rejects the same history in the same frames and the two sequences differ by the
// light alone.
inline constexpr float kControlDim = 1e-9f;
struct SwitchOffResult {
    Setting setting;
    bool temporal = false;
    float blendWeight = 0.0f;
    uint32_t light = 0;
    uint32_t offFrame = 0;
    uint64_t touchedPixels = 0;  // compared pixels the light touches (touchedPixels())
    // Frame F - 1 (the light on): remaining() (about 1 plus the fog's own error) and leftover() (about 1).
    double lastLitRemaining = NAN, lastLitLeftover = NAN;
    // Per frame F + n: remainingContribution(image), the control's, and leftoverContribution(image, control);
    // remainingContribution of a sequence with the light never on (no history rejected: the error a settled
    // history has there, against which the rejection's restart shows).
    std::vector<double> remaining, controlRemaining, leftover, neverLitRemaining;
};
// `scene` with light `light` dimmed to kControlDim of its intensity.
demo::Scene dimmedLightScene(const demo::Scene& scene, uint32_t light);

// A pixel is touched by the light when some channel of (with − without) exceeds `tolerance` times the
// pixel's largest channel with the light (with, without: the same size). 1 per touched pixel.
std::vector<uint8_t> touchedPixels(const std::vector<float>& with, const std::vector<float>& without,
                                   double tolerance);
// Images here are RGBA floats of the same size (the references' layout, demo::ImageF::rgba).
// The light's remaining fog contribution in `image`: Σ|image − without| /
// Σ|with − without| over the RGB channels of the touched pixels; NaN when none is touched.
double remainingContribution(const std::vector<float>& image, const std::vector<float>& with,
                             const std::vector<float>& without, const std::vector<uint8_t>& touched);
// The light's contribution still in `image`, against the control sequence's frame instead of the
// reference without the light: Σ|image − control| / Σ|with − without| over the same channels. The
// fog's own error and its noise, which the two frames share, cancel.
double leftoverContribution(const std::vector<float>& image, const std::vector<float>& control,
                            const std::vector<float>& with, const std::vector<float>& without,
                            const std::vector<uint8_t>& touched);
// The first n from which every values[m], m >= n, is below `limit` (0: all are); values.size() when the
// last is not.
size_t settledAfter(const std::vector<double>& values, double limit);

}  // namespace bench
