// The atmosphere's Monte Carlo path tracer (atmosphere_path_tracer.h).
#include "atmosphere/atmosphere_path_tracer.h"
#include "common/parallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace postfx::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr uint32_t kViewNodes = 8192;  // cells of the view segment's optical-depth table
constexpr uint64_t kChunk = 1024;      // paths per random stream
constexpr uint32_t kRouletteFrom = 3;  // events before Russian roulette starts
constexpr uint32_t kMaxEvents = 100000;

// splitmix64 seeds xoshiro256**; one stream per (seed, channel, chunk).
uint64_t splitmix(uint64_t& s) {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

struct Rng {
    uint64_t s[4];
    explicit Rng(uint64_t seed) {
        for (uint64_t& v : s)
            v = splitmix(seed);
    }
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t next() {
        const uint64_t result = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = rotl(s[3], 45);
        return result;
    }
    // Uniform in [0, 1).
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    // Uniform in (0, 1]: safe under a logarithm.
    double open() { return 1.0 - uniform(); }
};

// A unit vector with cosine `cosTheta` to `axis` and uniform azimuth.
glm::dvec3 around(const glm::dvec3& axis, double cosTheta, Rng& rng) {
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * rng.uniform();
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, axis)), v = glm::cross(axis, u);
    return glm::normalize(sinTheta * std::cos(phi) * u + sinTheta * std::sin(phi) * v + cosTheta * axis);
}

// cos θ from the Rayleigh phase: uniform, accepted with probability (1 + cos²θ)/2.
double sampleRayleigh(Rng& rng) {
    for (;;) {
        const double c = 2.0 * rng.uniform() - 1.0;
        if (2.0 * rng.uniform() <= 1.0 + c * c) return c;
    }
}

// cos θ from Cornette–Shanks: Henyey–Greenstein of the same g, accepted with probability (1 + cos²θ)/2.
double sampleCornetteShanks(double g, Rng& rng) {
    for (;;) {
        double c;
        if (std::abs(g) < 1e-4) {
            c = 2.0 * rng.uniform() - 1.0;
        } else {
            const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * rng.uniform());
            c = std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
        }
        if (2.0 * rng.uniform() <= 1.0 + c * c) return c;
    }
}

struct Tracer {
    const Model& m;
    const TransmittanceTable& transmittance;
    glm::dvec3 toSun;
    int c;            // channel
    double majorant;  // >= σt anywhere, this channel

    double sunT(const glm::dvec3& p) const { return transmittance.sun(p, toSun)[c]; }

    // Radiance per unit sun illuminance carried back along the path from a real collision at `x` (the path
    // arriving along `dir`) with weight `w`, or from the ground at `x` when `onGround`.
    double continuePath(glm::dvec3 x, glm::dvec3 dir, double w, bool onGround, Rng& rng) const {
        double sum = 0.0;
        for (uint32_t event = 0; event < kMaxEvents; ++event) {
            glm::dvec3 next;
            if (onGround) {
                const glm::dvec3 n = glm::normalize(x);
                const double nDotL = glm::dot(n, toSun);
                const double albedo = m.groundAlbedo[c];
                if (nDotL > 0.0) sum += w * albedo / kPi * nDotL * sunT(x);
                w *= albedo;
                x = n * (m.groundRadius + 1e-4);                  // off the surface
                next = around(n, std::sqrt(rng.uniform()), rng);  // cosine-weighted: weight albedo
            } else {
                const Medium md = mediumAt(m, glm::length(x) - m.groundRadius);
                const double sigmaS = md.scattering[c], sigmaT = md.extinction[c];
                if (!(sigmaS > 0.0)) return sum;
                w *= sigmaS / sigmaT;
                const double cosSun = glm::dot(dir, toSun);
                const double sigmaR = md.rayleighScattering[c], sigmaM = md.mieScattering;
                const double phase =
                    (sigmaR * rayleighPhase(cosSun) + sigmaM * cornetteShanksPhase(cosSun, m.mieAnisotropy)) /
                    sigmaS;
                sum += w * phase * sunT(x);
                const double cosTheta = rng.uniform() * sigmaS < sigmaR
                                            ? sampleRayleigh(rng)
                                            : sampleCornetteShanks(m.mieAnisotropy, rng);
                next = around(dir, cosTheta, rng);
            }
            if (!(w > 0.0)) return sum;
            if (event + 1 >= kRouletteFrom) {
                const double q = std::min(1.0, w);
                if (rng.uniform() >= q) return sum;
                w /= q;
            }
            // Delta tracking to the next real collision, the ground or out of the atmosphere.
            const AtmosphereSegment seg = atmosphereSegment(m, x, next);
            double t = seg.tBegin;
            for (;;) {
                t -= std::log(rng.open()) / majorant;
                if (t >= seg.tEnd) break;
                const glm::dvec3 p = x + t * next;
                const double sigmaT = mediumAt(m, glm::length(p) - m.groundRadius).extinction[c];
                if (rng.uniform() * majorant < sigmaT) break;
            }
            if (t >= seg.tEnd) {
                if (!seg.hitsGround) return sum;  // escaped
                x += seg.tEnd * next;
                onGround = true;
            } else {
                x += t * next;
                onGround = false;
            }
            dir = next;
        }
        return sum;
    }
};

}  // namespace

PathTracerResult pathTraceViewRay(const Model& m, const TransmittanceTable& transmittance,
                                  const glm::dvec3& origin, const glm::dvec3& dir, const Sun& sun,
                                  const PathTracerOptions& o) {
    PathTracerResult result;
    const AtmosphereSegment seg = atmosphereSegment(m, origin, dir);
    if (seg.tEnd <= seg.tBegin && !seg.hitsGround) return result;
    const uint64_t paths = std::max<uint64_t>(o.paths, 2);
    const uint64_t chunks = (paths + kChunk - 1) / kChunk;
    const glm::dvec3 toSun = glm::normalize(sun.toSun);

    // Optical depth along the view segment per channel: cumulative over kViewNodes midpoint cells.
    const double length = std::max(0.0, seg.tEnd - seg.tBegin), dt = length / kViewNodes;
    std::vector<glm::dvec3> sigma(kViewNodes), tau(kViewNodes + 1, glm::dvec3(0.0));
    for (uint32_t k = 0; k < kViewNodes; ++k) {
        const glm::dvec3 p = origin + (seg.tBegin + (k + 0.5) * dt) * dir;
        sigma[k] = mediumAt(m, glm::length(p) - m.groundRadius).extinction;
        tau[k + 1] = tau[k] + sigma[k] * dt;
    }
    const glm::dvec3 tauTotal = tau[kViewNodes];

    for (int c = 0; c < 3; ++c) {
        const double majorant =
            m.rayleighScattering[c] + m.mieScattering + m.mieAbsorption + m.ozoneAbsorption[c];
        const Tracer tracer{m, transmittance, toSun, c, majorant};
        const double collide = -std::expm1(-tauTotal[c]);  // probability of a collision on the view segment
        const double reachGround = std::exp(-tauTotal[c]);
        std::vector<double> sums(chunks), squares(chunks);
        common::parallelFor(chunks, o.threads, [&](uint64_t chunk) {
            uint64_t seed = o.seed * 0x9e3779b97f4a7c15ull + uint64_t(c) * 0x632be59bd9b4e019ull + chunk;
            Rng rng(splitmix(seed));
            const uint64_t begin = chunk * kChunk, end = std::min(paths, begin + kChunk);
            double s = 0.0, s2 = 0.0;
            for (uint64_t i = begin; i < end; ++i) {
                double x = 0.0;
                if (collide > 0.0) {
                    // Forced collision: τ* from the exponential truncated to [0, τ], then t from the table.
                    const double target = -std::log1p(-rng.uniform() * collide);
                    const auto it = std::upper_bound(tau.begin(), tau.end(), target,
                                                     [c](double v, const glm::dvec3& e) { return v < e[c]; });
                    const auto k =
                        uint32_t(std::clamp<std::ptrdiff_t>(it - tau.begin() - 1, 0, kViewNodes - 1));
                    const double f = sigma[k][c] > 0.0
                                         ? std::clamp((target - tau[k][c]) / (sigma[k][c] * dt), 0.0, 1.0)
                                         : 0.5;
                    const glm::dvec3 p = origin + (seg.tBegin + (k + f) * dt) * dir;
                    x += tracer.continuePath(p, dir, collide, false, rng);
                }
                if (seg.hitsGround)
                    x += tracer.continuePath(origin + seg.tEnd * dir, dir, reachGround, true, rng);
                s += x;
                s2 += x * x;
            }
            sums[chunk] = s;
            squares[chunk] = s2;
        });
        double s = 0.0, s2 = 0.0;
        for (uint64_t k = 0; k < chunks; ++k) {
            s += sums[k];
            s2 += squares[k];
        }
        const double n = double(paths), mean = s / n;
        const double variance = std::max(0.0, (s2 / n - mean * mean) * n / (n - 1.0));
        result.luminance[c] = mean * sun.illuminance[c];
        result.standardError[c] = std::sqrt(variance / n) * sun.illuminance[c];
    }
    return result;
}

ViewSunRay viewSunRay(const Model& m, const ViewSunAngles& a) {
    const double deg = kPi / 180.0;
    const double theta = a.viewZenithDeg * deg, phi = a.relativeAzimuthDeg * deg;
    const double sunZenith = (90.0 - a.sunElevationDeg) * deg;
    ViewSunRay r;
    r.origin = glm::dvec3(0.0, m.groundRadius + a.altitude, 0.0);
    r.dir = glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    r.toSun = glm::dvec3(std::sin(sunZenith), std::cos(sunZenith), 0.0);
    return r;
}

}  // namespace postfx::atmosphere
