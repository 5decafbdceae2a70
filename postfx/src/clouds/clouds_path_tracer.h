// A Monte Carlo volumetric path tracer through the clouds' model (docs/effects/clouds.md, "Path-traced
// truth"): every scattering order, in double, through the same density field (clouds::extinction), the same
// phase function (clouds::phase) and the same sun and ambient as clouds_model.cpp, with no approximation
// but Monte Carlo noise (and the event cap below). The physically exact counterpart of clouds::march.
// Positions are camera-relative [m].
#pragma once

#include "clouds/clouds_model.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace postfx::clouds {

// SplitMix64 (Steele, Lea, Flood 2014): a counter-based stream, seeded per path from (seed, stream,
// sample) so that a pixel's estimate does not depend on which thread computes it or in which order.
class Rng {
public:
    explicit Rng(uint64_t state) : state_(state) {}
    Rng(uint64_t seed, uint64_t stream, uint64_t sample) : state_(mix(mix(mix(seed) ^ stream) ^ sample)) {}
    uint64_t next() { return mix(state_ += kGamma); }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // in [0, 1)

private:
    static constexpr uint64_t kGamma = 0x9e3779b97f4a7c15ull;
    static uint64_t mix(uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    uint64_t state_;
};

// Scattering events per path at most: a path still inside after this many is ended there, its light so
// far kept (the light of the orders beyond is lost; at albedo 1 the mean number of events grows as τ² in a
// thick cloud, ~1e4 at optical depth 100). Keeps optical depth 1e4 finite.
constexpr uint32_t kMaxScatteringEvents = 100000;
// Rays are followed at most this far [m] (a ray parallel to an infinite flat layer never leaves it).
constexpr double kMaxPathLength = 1e7;

struct PathOptions {
    uint32_t samples = 256;            // paths per estimate; >= 1
    uint32_t maxScatteringOrders = 0;  // 0: all; k: the light of at most k scattering events
    uint64_t seed = 1;
};

struct PathEstimate {
    glm::dvec3 radiance{0.0};       // mean in-scattered radiance toward the eye (no background)
    glm::dvec3 standardError{0.0};  // per channel: the paths' sample standard deviation / sqrt(n)
    uint32_t truncated = 0;         // paths ended by kMaxScatteringEvents
};

// One path's in-scattered radiance arriving at `origin` from along `d` (unit, from the eye), the ray
// ending at `far` (geometry or max_distance) as far as the view ray goes: delta tracking with the majorant
// σ̄ = density over the shape's segments; at each real collision the throughput is multiplied by the albedo,
// the sun is added by next-event estimation (its illuminance, times the atmosphere's transmittance to x
// when on, times phase(d, toSun), times the cloud's transmittance to where the sun's ray leaves the shape
// by ratio tracking), and a new direction is drawn from the dual-lobe HG; a path that leaves the shape
// after k >= 1 events adds the throughput times the ambient radiance. Russian roulette below throughput
// 0.1. `truncated` (may be null) is set when the event cap ended the path.
glm::dvec3 tracePath(const Model& m, const glm::dvec3& origin, const glm::dvec3& d, double far,
                     uint32_t maxScatteringOrders, Rng& rng, bool* truncated = nullptr);

// The mean of `options.samples` paths from `origin` along `d`, path s seeded by (options.seed, stream, s).
PathEstimate estimateRadiance(const Model& m, const glm::dvec3& origin, const glm::dvec3& d, double far,
                              const PathOptions& options, uint64_t stream);

// A pixel's truth: the path-traced radiance along the view ray d (from the camera, to `far`) and the
// transmittance T and extinction-weighted mean distance D the composite uses, from the deterministic fine
// march (clouds::march with `steps` midpoint samples; its light march does not change T or D). A ray whose
// march meets no density (T = 1) is not traced (radiance 0), as the reference leaves such pixels alone.
struct PixelTruth {
    PathEstimate light;
    double transmittance = 1.0;
    double meanDistance = 0.0;
};
PixelTruth tracePixel(const Model& m, const glm::dvec3& d, double far, uint32_t steps,
                      const PathOptions& options, uint64_t pixel);

// Samples the dual-lobe phase function around the direction of travel `d` (the lobe by lobe_mix, then
// that lobe's HG): the pdf is clouds::phase's, so a path's throughput does not change.
glm::dvec3 samplePhase(const Model& m, const glm::dvec3& d, Rng& rng);

}  // namespace postfx::clouds
