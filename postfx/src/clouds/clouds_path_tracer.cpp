#include "clouds/clouds_path_tracer.h"

#include "clouds/clouds_settings.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace postfx::clouds {
namespace {

using glm::dvec2;
using glm::dvec3;

// Below this throughput a path (or a shadow ray's transmittance) plays Russian roulette: it survives with
// probability value / kRoulette and then carries kRoulette, which keeps the estimate unbiased.
constexpr double kRoulette = 0.1;

// Delta tracking from x along d over the shape's segment up to `far`: true and the distance `t` of a real
// collision (probability σt/σ̄ at each tentative one), false when the ray leaves the shape first.
bool freeFlight(const Model& m, const dvec3& x, const dvec3& d, double far, Rng& rng, double& t) {
    const dvec2 seg = segment(m, x, d, far);
    if (!(seg.y > seg.x)) return false;
    const double majorant = m.s.density;  // the field is <= 1
    t = std::max(seg.x, 0.0);
    for (;;) {
        t -= std::log1p(-rng.uniform()) / majorant;
        if (t >= seg.y) return false;
        if (rng.uniform() * majorant < extinction(m, x + t * d)) return true;
    }
}

// Ratio tracking from x toward the sun to where that ray leaves the shape: an unbiased estimate of the
// cloud's transmittance, T ×= 1 - σt/σ̄ at each tentative collision.
double sunTransmittance(const Model& m, const dvec3& x, Rng& rng) {
    const dvec2 seg = segment(m, x, m.toSun, kMaxPathLength);
    if (!(seg.y > seg.x)) return 1.0;
    const double majorant = m.s.density;
    double T = 1.0;
    for (double t = std::max(seg.x, 0.0);;) {
        t -= std::log1p(-rng.uniform()) / majorant;
        if (t >= seg.y) return T;
        T *= 1.0 - extinction(m, x + t * m.toSun) / majorant;
        if (T <= 0.0) return 0.0;
        if (T < kRoulette) {
            if (rng.uniform() * kRoulette >= T) return 0.0;
            T = kRoulette;
        }
    }
}

// The sun's light scattered at x toward -d per unit σs: E (times the atmosphere's transmittance when on)
// · phase · the cloud's transmittance toward the sun.
dvec3 sunLight(const Model& m, const dvec3& x, const dvec3& d, Rng& rng) {
    dvec3 sun = m.sunIlluminance;
    if (m.atmosphere) {
        sun *= m.atmosphere->sunTransmittance(m.camera + x, m.toSun, false);
    }
    if (!(std::max(sun.x, std::max(sun.y, sun.z)) > 0.0)) return dvec3(0.0);
    return sun * (phase(m, d, 1.0) * sunTransmittance(m, x, rng));
}

}  // namespace

dvec3 samplePhase(const Model& m, const dvec3& d, Rng& rng) {
    const double lobe = rng.uniform() < m.s.lobeMix ? m.s.anisotropyBack : m.s.anisotropyForward;
    const double g = std::clamp(lobe, -double(kMaxAnisotropy), double(kMaxAnisotropy));
    const double u = rng.uniform();
    double c;  // cos θ to d, HG's inverse CDF
    if (std::abs(g) < 1e-4) {
        c = 1.0 - 2.0 * u;
    } else {
        const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
        c = (1.0 + g * g - s * s) / (2.0 * g);
    }
    c = std::clamp(c, -1.0, 1.0);
    const double sine = std::sqrt(std::max(0.0, 1.0 - c * c));
    const double phi = 2.0 * glm::pi<double>() * rng.uniform();
    // An orthonormal basis around d (Duff et al. 2017).
    const double sign = std::copysign(1.0, d.z);
    const double a = -1.0 / (sign + d.z), b = d.x * d.y * a;
    const dvec3 t1(1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x);
    const dvec3 t2(b, sign + d.y * d.y * a, -d.y);
    return glm::normalize(c * d + sine * (std::cos(phi) * t1 + std::sin(phi) * t2));
}

dvec3 tracePath(const Model& m, const dvec3& origin, const dvec3& d0, double far,
                uint32_t maxScatteringOrders, Rng& rng, bool* truncated) {
    if (truncated) *truncated = false;
    dvec3 L(0.0);
    if (!(m.s.density > 0.0)) return L;
    const uint32_t maxOrder =
        maxScatteringOrders ? maxScatteringOrders : std::numeric_limits<uint32_t>::max();
    dvec3 x = origin, d = d0;
    double throughput = 1.0, limit = far;
    for (uint32_t k = 0;;) {  // k: scattering events so far
        double t;
        if (!freeFlight(m, x, d, limit, rng, t)) {
            if (k > 0) L += throughput * m.ambient;  // left the shape: the ambient from all around
            return L;
        }
        if (k == maxOrder) return L;  // the next event's light is of an order not asked for
        if (k == kMaxScatteringEvents) {
            if (truncated) *truncated = true;
            return L;
        }
        ++k;
        x += t * d;
        throughput *= m.s.albedo;
        L += throughput * sunLight(m, x, d, rng);
        d = samplePhase(m, d, rng);
        limit = kMaxPathLength;  // scattered rays: no geometry, no max_distance
        if (throughput < kRoulette) {
            if (rng.uniform() * kRoulette >= throughput) return L;
            throughput = kRoulette;
        }
    }
}

PathEstimate estimateRadiance(const Model& m, const dvec3& origin, const dvec3& d, double far,
                              const PathOptions& o, uint64_t stream) {
    PathEstimate e;
    dvec3 mean(0.0), m2(0.0);  // Welford's running mean and sum of squared deviations
    for (uint32_t s = 0; s < o.samples; ++s) {
        Rng rng(o.seed, stream, s);
        bool truncated = false;
        const dvec3 L = tracePath(m, origin, d, far, o.maxScatteringOrders, rng, &truncated);
        e.truncated += truncated ? 1u : 0u;
        const dvec3 delta = L - mean;
        mean += delta / double(s + 1);
        m2 += delta * (L - mean);
    }
    e.radiance = mean;
    if (o.samples > 1) e.standardError = glm::sqrt(m2 / (double(o.samples - 1) * o.samples));
    return e;
}

PixelTruth tracePixel(const Model& m, const dvec3& d, double far, uint32_t steps, const PathOptions& o,
                      uint64_t pixel) {
    PixelTruth p;
    // T and D do not depend on the light march: one light step is enough.
    const MarchResult r = march(m, d, far, steps, 0.5, 1);
    p.transmittance = r.transmittance;
    p.meanDistance = r.meanDistance;
    if (r.transmittance < 1.0) p.light = estimateRadiance(m, dvec3(0.0), d, far, o, pixel);
    return p;
}

}  // namespace postfx::clouds
