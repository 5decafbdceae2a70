#include "motion.h"

#include <algorithm>
#include <cmath>

namespace bench {
namespace {

// (x, z) turned by `angle` [rad] about +y: positive turns -z toward -x (left for a camera looking along -z).
glm::vec3 turned(const glm::vec3& v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return glm::vec3(float(v.x * c + v.z * s), v.y, float(-v.x * s + v.z * c));
}

// The view direction projected onto the horizontal plane, unit; (0, 0, -1) when it is vertical.
glm::dvec3 horizontalForward(const demo::Camera& camera) {
    const glm::dvec3 f = glm::dvec3(camera.lookAt) - glm::dvec3(camera.position);
    const glm::dvec3 h(f.x, 0.0, f.z);
    const double length = glm::length(h);
    return length > 1e-9 * glm::length(f) ? h / length : glm::dvec3(0.0, 0.0, -1.0);
}

}  // namespace

std::vector<uint32_t> measuredFrames(const MotionOptions& options) {
    std::vector<uint32_t> frames;
    for (uint32_t k = 0; k < options.frames; ++k)
        frames.push_back(options.warmup + k * std::max(options.frameStep, 1u));
    return frames;
}

uint32_t sequenceLength(const MotionOptions& options) {
    const std::vector<uint32_t> frames = measuredFrames(options);
    return frames.empty() ? options.warmup : frames.back() + 1;
}

demo::Camera walkingCamera(const demo::Camera& start, float speed, float yawRateDeg, double seconds) {
    const double omega = glm::radians(double(yawRateDeg));
    const double angle = omega * seconds;
    // ∫₀ᵗ R(ω s) ds applied to the horizontal forward direction h: R turns (x, z) by ω s, so the integral is
    // (h.x S + h.z C, -h.x C + h.z S) with S = sin(ωt)/ω, C = (1 - cos(ωt))/ω (S = t, C = 0 without turning).
    const bool straight = std::abs(angle) < 1e-12;
    const double S = straight ? seconds : std::sin(angle) / omega;
    const double C = straight ? 0.0 : (1.0 - std::cos(angle)) / omega;
    const glm::dvec3 h = horizontalForward(start);
    const glm::dvec3 travelled = double(speed) * glm::dvec3(h.x * S + h.z * C, 0.0, -h.x * C + h.z * S);
    demo::Camera camera = start;
    camera.position = glm::vec3(glm::dvec3(start.position) + travelled);
    camera.lookAt = camera.position + turned(start.lookAt - start.position, angle);
    camera.up = turned(start.up, angle);
    return camera;
}

demo::Scene cameraMotionScene(const demo::Scene& scene, const MotionOptions& options, uint32_t frame) {
    demo::Scene s = scene;
    s.camera = walkingCamera(scene.camera, options.cameraSpeed, options.yawRateDeg,
                             double(frame) * options.frameSeconds);
    return s;
}

glm::vec3 lightMotionDirection(const demo::Camera& camera) {
    const glm::dvec3 h = horizontalForward(camera);
    return glm::vec3(glm::normalize(glm::cross(h, glm::dvec3(0.0, 1.0, 0.0))));
}

demo::Scene lightMotionScene(const demo::Scene& scene, const MotionOptions& options, uint32_t frame) {
    demo::Scene s = scene;
    if (options.light < s.lights.size()) {
        const double distance = double(options.lightSpeed) * double(frame) * options.frameSeconds;
        glm::vec3& p = s.lights[options.light].position;
        p = glm::vec3(glm::dvec3(p) + distance * glm::dvec3(lightMotionDirection(scene.camera)));
    }
    return s;
}

demo::Scene lightOffScene(const demo::Scene& scene, uint32_t light) {
    demo::Scene s = scene;
    if (light < s.lights.size()) s.lights[light].intensity = glm::vec3(0.0f);
    return s;
}

demo::Scene dimmedLightScene(const demo::Scene& scene, uint32_t light) {
    demo::Scene s = scene;
    if (light < s.lights.size()) s.lights[light].intensity *= kControlDim;
    return s;
}

const char* motionKindName(MotionKind kind) {
    return kind == MotionKind::Camera ? "camera" : "light";
}

double MotionResult::meanError() const {
    if (errors.empty()) return NAN;
    double sum = 0.0;
    for (const ErrorStats& e : errors)
        sum += e.relativeRmse;
    return sum / double(errors.size());
}

double MotionResult::maxError() const {
    if (errors.empty()) return NAN;
    double m = -INFINITY;
    for (const ErrorStats& e : errors)
        m = std::isnan(e.relativeRmse) ? NAN : std::max(m, e.relativeRmse);
    return m;
}

double MotionResult::temporalMs() const {
    for (const auto& [name, ms] : timing.passMedians)
        if (name == "fog.temporal") return ms;
    return NAN;
}

std::vector<uint8_t> touchedPixels(const std::vector<float>& with, const std::vector<float>& without,
                                   double tolerance) {
    std::vector<uint8_t> touched(std::min(with.size(), without.size()) / 4, 0);
    for (size_t p = 0; p < touched.size(); ++p) {
        double magnitude = 0.0, difference = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            magnitude = std::max(magnitude, std::abs(double(with[p * 4 + c])));
            difference = std::max(difference, double(with[p * 4 + c]) - double(without[p * 4 + c]));
        }
        touched[p] = difference > tolerance * magnitude && difference > 0.0;
    }
    return touched;
}

double remainingContribution(const std::vector<float>& image, const std::vector<float>& with,
                             const std::vector<float>& without, const std::vector<uint8_t>& touched) {
    double left = 0.0, contribution = 0.0;
    for (size_t p = 0; p < touched.size(); ++p) {
        if (!touched[p]) continue;
        for (size_t c = 0; c < 3; ++c) {
            const size_t i = p * 4 + c;
            left += std::abs(double(image[i]) - double(without[i]));
            contribution += std::abs(double(with[i]) - double(without[i]));
        }
    }
    return contribution > 0.0 ? left / contribution : NAN;
}

double leftoverContribution(const std::vector<float>& image, const std::vector<float>& control,
                            const std::vector<float>& with, const std::vector<float>& without,
                            const std::vector<uint8_t>& touched) {
    double left = 0.0, contribution = 0.0;
    for (size_t p = 0; p < touched.size(); ++p) {
        if (!touched[p]) continue;
        for (size_t c = 0; c < 3; ++c) {
            const size_t i = p * 4 + c;
            left += std::abs(double(image[i]) - double(control[i]));
            contribution += std::abs(double(with[i]) - double(without[i]));
        }
    }
    return contribution > 0.0 ? left / contribution : NAN;
}

size_t settledAfter(const std::vector<double>& values, double limit) {
    size_t n = values.size();
    while (n > 0 && values[n - 1] < limit)
        --n;
    return n;
}

}  // namespace bench
