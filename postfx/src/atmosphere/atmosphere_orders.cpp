// The "orders" multiple-scattering model in double (atmosphere_orders.h).
#include "atmosphere/atmosphere_orders.h"

#include "common/parallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace postfx::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxTailRatio = 0.95;  // q of the geometric tail: at most this (its sum at most 19×)

// (1 + sign(c)·√|c|)/2 and its inverse: the μ and μs axes, finer at the horizon.
double unitFromCosine(double c) {
    return 0.5 + 0.5 * std::copysign(std::sqrt(std::min(1.0, std::abs(c))), c);
}
double cosineFromUnit(double x) {
    const double u = 2.0 * x - 1.0;
    return u * std::abs(u);
}

// Linear interpolation on n >= 2 nodes at unit coordinate x (clamped).
struct Lerp {
    uint32_t i = 0;
    double a = 0.0;
};
Lerp lerpAt(double x, uint32_t n) {
    const double f = std::clamp(x, 0.0, 1.0) * (n - 1);
    const uint32_t i = std::min(uint32_t(f), n - 2);
    return {i, f - i};
}

// Quadratic boundaries of `n` steps from `from` toward `to` (either order), appended to `out` as steps.
void quadraticSteps(double from, double to, uint32_t n, std::vector<MarchStep>& out) {
    double previous = from;
    for (uint32_t i = 1; i <= n; ++i) {
        const double x = double(i) / n;
        const double next = from + (to - from) * x * x;
        out.push_back({0.5 * (previous + next), std::abs(next - previous)});
        previous = next;
    }
}

}  // namespace

void orderMarchSteps(double r, double mu, double tBegin, double tEnd, uint32_t steps,
                     std::vector<MarchStep>& out) {
    out.clear();
    if (!(tEnd > tBegin)) return;
    steps = std::max(1u, steps);
    const double tLow = -r * mu;  // where the ray is nearest the centre
    if (tLow <= tBegin) {
        quadraticSteps(tBegin, tEnd, steps, out);
    } else if (tLow >= tEnd) {
        quadraticSteps(tEnd, tBegin, steps, out);
        std::reverse(out.begin(), out.end());
    } else {
        const auto before =
            uint32_t(std::clamp(std::lround(steps * (tLow - tBegin) / (tEnd - tBegin)), 1l, long(steps)));
        const uint32_t after = std::max(1u, steps > before ? steps - before : 1u);
        quadraticSteps(tLow, tBegin, before, out);
        std::reverse(out.begin(), out.end());
        quadraticSteps(tLow, tEnd, after, out);
    }
}

double cosAzimuthAbout(const glm::dvec3& up, const glm::dvec3& dir, const glm::dvec3& toSun) {
    const glm::dvec3 a = dir - glm::dot(dir, up) * up, b = toSun - glm::dot(toSun, up) * up;
    const double la = glm::length(a), lb = glm::length(b);
    if (la < 1e-9 || lb < 1e-9) return 1.0;
    return std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0);
}

OrdersTable::OrdersTable(const Model& m, const TransmittanceTable& transmittance, const OrdersTableOptions& o)
    : model_(m), requested_(o), options_(o) {
    OrdersTableOptions& s = options_;
    s.radiusSize = std::max(2u, s.radiusSize);
    s.sunSize = std::max(2u, s.sunSize);
    s.viewSize = std::max(2u, s.viewSize);
    s.azimuthSize = std::max(2u, s.azimuthSize);
    s.steps = std::max(1u, s.steps);
    const auto side = uint32_t(std::max(1l, std::lround(std::sqrt(double(s.directions)))));
    const uint32_t K = side * side;
    const uint32_t outputs = s.viewSize * s.azimuthSize;
    const size_t cells = size_t(s.radiusSize) * s.sunSize;

    // The sample directions and the outputs' normalised phase weights, the same at every node.
    std::vector<glm::dvec3> dirs(K);
    for (uint32_t i = 0; i < side; ++i)
        for (uint32_t j = 0; j < side; ++j) {
            const double a = (i + 0.5) / side, b = (j + 0.5) / side;
            const double phi = 2.0 * kPi * a, cosPolar = 1.0 - 2.0 * b;
            const double sinPolar = std::sqrt(std::max(0.0, 1.0 - cosPolar * cosPolar));
            dirs[i * side + j] = {std::cos(phi) * sinPolar, cosPolar, std::sin(phi) * sinPolar};
        }
    // Azimuth columns i and side - 1 - i (z and -z) see the same light, so only the first (side + 1)/2
    // columns are marched, and each output's weights are folded onto them: half the quadrature's work.
    const uint32_t marched = (side + 1) / 2 * side;
    const auto marchedOf = [&](uint32_t k) {
        const uint32_t column = k / side;
        return (column < (side + 1) / 2 ? column : side - 1 - column) * side + k % side;
    };
    std::vector<double> phaseR(size_t(outputs) * marched, 0.0), phaseM(size_t(outputs) * marched, 0.0);
    for (uint32_t v = 0; v < s.viewSize; ++v)
        for (uint32_t a = 0; a < s.azimuthSize; ++a) {
            const double mu = cosineFromUnit(double(v) / (s.viewSize - 1));
            const double phi = kPi * double(a) / (s.azimuthSize - 1);
            const double sinView = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            const glm::dvec3 w(sinView * std::cos(phi), mu, sinView * std::sin(phi));
            const size_t row = size_t(v * s.azimuthSize + a) * marched;
            double sumR = 0.0, sumM = 0.0;
            for (uint32_t k = 0; k < K; ++k) {
                const double c = glm::dot(w, dirs[k]);
                const double pR = rayleighPhase(c), pM = cornetteShanksPhase(c, m.mieAnisotropy);
                phaseR[row + marchedOf(k)] += pR;
                phaseM[row + marchedOf(k)] += pM;
                sumR += pR;
                sumM += pM;
            }
            for (uint32_t k = 0; k < marched; ++k) {
                phaseR[row + k] /= sumR;
                phaseM[row + k] /= sumM;
            }
        }
    std::vector<double> groundWeight(marched, 0.0);  // max(0, ω_k·up), folded the same way
    for (uint32_t k = 0; k < K; ++k)
        groundWeight[marchedOf(k)] += std::max(0.0, dirs[k].y);

    const size_t size = cells * outputs;
    psi_.assign(size, Psi{});
    ground_.assign(s.sunSize, glm::dvec3(0.0));
    // Order n's tables (read), order n + 1's (written), order n - 1's (the tail's ratio).
    OrdersTable current = *this, next = *this, previous = *this;
    const double groundRadius = m.groundRadius, topRadius = m.topRadius;

    for (uint32_t order = 1; order <= s.orders; ++order) {
        common::parallelFor(uint32_t(cells), s.threads, [&](uint32_t cell) {
            const uint32_t ir = cell / s.sunSize, is = cell % s.sunSize;
            const double y = double(ir) / (s.radiusSize - 1);
            const double r = groundRadius + y * y * (topRadius - groundRadius);
            const double muS = cosineFromUnit(double(is) / (s.sunSize - 1));
            const glm::dvec3 x(0.0, r, 0.0), toSun(std::sqrt(std::max(0.0, 1.0 - muS * muS)), muS, 0.0);
            std::vector<glm::dvec3> L(marched, glm::dvec3(0.0));
            std::vector<MarchStep> steps;
            for (uint32_t k = 0; k < marched; ++k) {
                const glm::dvec3& d = dirs[k];
                const AtmosphereSegment seg = atmosphereSegment(m, x, d);
                if (seg.tEnd <= seg.tBegin && !seg.hitsGround) continue;
                orderMarchSteps(r, d.y, seg.tBegin, seg.tEnd, s.steps, steps);
                const double cosSun = glm::dot(d, toSun);
                const double pR = rayleighPhase(cosSun), pM = cornetteShanksPhase(cosSun, m.mieAnisotropy);
                glm::dvec3 T(1.0), sum(0.0);
                for (const MarchStep& st : steps) {
                    const glm::dvec3 p = x + st.t * d;
                    const double rp = glm::length(p);
                    const Medium md = mediumAt(m, rp - groundRadius);
                    glm::dvec3 J;
                    if (order == 1) {
                        J = transmittance.sun(p, toSun) *
                            (md.rayleighScattering * pR + md.mieScattering * pM);
                    } else {
                        const glm::dvec3 up = p / rp;
                        const Psi psi = current.at(rp, glm::dot(d, up), glm::dot(toSun, up),
                                                   cosAzimuthAbout(up, d, toSun));
                        J = md.rayleighScattering * psi.rayleigh + md.mieScattering * psi.mie;
                    }
                    sum += T * J * stepIntegral(md.extinction, st.dt);
                    T *= expNeg(md.extinction * st.dt);
                }
                if (seg.hitsGround) {
                    const glm::dvec3 g = x + seg.tEnd * d;
                    const double muG = glm::dot(glm::normalize(g), toSun);
                    const glm::dvec3 E = order == 1 ? transmittance.sun(g, toSun) * std::max(0.0, muG)
                                                    : current.groundIrradiance(muG);
                    sum += T * E * m.groundAlbedo / kPi;
                }
                L[k] = sum;
            }
            const size_t base = cell * outputs;
            for (uint32_t out = 0; out < outputs; ++out) {
                const double* wR = &phaseR[size_t(out) * marched];
                const double* wM = &phaseM[size_t(out) * marched];
                glm::dvec3 sR(0.0), sM(0.0);
                for (uint32_t k = 0; k < marched; ++k) {
                    sR += wR[k] * L[k];
                    sM += wM[k] * L[k];
                }
                next.psi_[base + out] = {sR, sM};
            }
            if (ir == 0) {
                glm::dvec3 E(0.0);
                for (uint32_t k = 0; k < marched; ++k)
                    E += L[k] * groundWeight[k];
                next.ground_[is] = E * (4.0 * kPi / K);
            }
        });
        for (size_t i = 0; i < size; ++i) {
            psi_[i].rayleigh += next.psi_[i].rayleigh;
            psi_[i].mie += next.psi_[i].mie;
        }
        for (uint32_t i = 0; i < s.sunSize; ++i)
            ground_[i] += next.ground_[i];
        std::swap(previous, current);
        std::swap(current, next);
    }
    // The geometric tail of the orders not computed: current holds order N + 1, previous order N.
    if (s.orders < 2) return;
    const auto ratio = [](const glm::dvec3& last, const glm::dvec3& before) {
        glm::dvec3 q;
        for (int c = 0; c < 3; ++c)
            q[c] = before[c] > 0.0 ? std::clamp(last[c] / before[c], 0.0, kMaxTailRatio) : 0.0;
        return q / (glm::dvec3(1.0) - q);
    };
    for (size_t cell = 0; cell < cells; ++cell) {
        glm::dvec3 last(0.0), before(0.0);
        for (uint32_t out = 0; out < outputs; ++out) {
            const Psi &c = current.psi_[cell * outputs + out], &p = previous.psi_[cell * outputs + out];
            last += c.rayleigh + c.mie;
            before += p.rayleigh + p.mie;
        }
        const glm::dvec3 tail = ratio(last, before);
        for (uint32_t out = 0; out < outputs; ++out) {
            psi_[cell * outputs + out].rayleigh += current.psi_[cell * outputs + out].rayleigh * tail;
            psi_[cell * outputs + out].mie += current.psi_[cell * outputs + out].mie * tail;
        }
    }
    for (uint32_t i = 0; i < s.sunSize; ++i)
        ground_[i] += current.ground_[i] * ratio(current.ground_[i], previous.ground_[i]);
}

OrdersTable::Psi OrdersTable::at(double r, double mu, double muS, double cosAzimuth) const {
    const OrdersTableOptions& s = options_;
    const double h =
        std::clamp((r - model_.groundRadius) / (model_.topRadius - model_.groundRadius), 0.0, 1.0);
    const Lerp lr = lerpAt(std::sqrt(h), s.radiusSize), ls = lerpAt(unitFromCosine(muS), s.sunSize);
    const Lerp lv = lerpAt(unitFromCosine(mu), s.viewSize);
    const Lerp la = lerpAt(std::acos(std::clamp(cosAzimuth, -1.0, 1.0)) / kPi, s.azimuthSize);
    // The two azimuth nodes of each (r, μs, μ) corner lie side by side.
    const double wa[2] = {1.0 - la.a, la.a};
    Psi out;
    for (int dr = 0; dr < 2; ++dr)
        for (int ds = 0; ds < 2; ++ds)
            for (int dv = 0; dv < 2; ++dv) {
                const double w =
                    (dr ? lr.a : 1.0 - lr.a) * (ds ? ls.a : 1.0 - ls.a) * (dv ? lv.a : 1.0 - lv.a);
                if (w == 0.0) continue;
                const Psi* node =
                    &psi_[((size_t(lr.i + dr) * s.sunSize + ls.i + ds) * s.viewSize + lv.i + dv) *
                              s.azimuthSize +
                          la.i];
                for (int da = 0; da < 2; ++da) {
                    out.rayleigh += (w * wa[da]) * node[da].rayleigh;
                    out.mie += (w * wa[da]) * node[da].mie;
                }
            }
    return out;
}

glm::dvec3 OrdersTable::source(const glm::dvec3& position, const glm::dvec3& dir,
                               const glm::dvec3& toSun) const {
    const double r = glm::length(position);
    const glm::dvec3 up = position / r;
    const Psi psi = at(r, glm::dot(dir, up), glm::dot(toSun, up), cosAzimuthAbout(up, dir, toSun));
    const Medium md = mediumAt(model_, r - model_.groundRadius);
    return md.rayleighScattering * psi.rayleigh + md.mieScattering * psi.mie;
}

glm::dvec3 OrdersTable::groundIrradiance(double muS) const {
    const Lerp l = lerpAt(unitFromCosine(muS), options_.sunSize);
    return (1.0 - l.a) * ground_[l.i] + l.a * ground_[l.i + 1];
}

OrdersTableOptions ordersOptionsFrom(const reference::AtmosphereInputs& in) {
    OrdersTableOptions o;
    o.viewSize = in.ordersViewNodes;
    o.sunSize = in.ordersSunNodes;
    o.radiusSize = in.ordersHeightNodes;
    o.azimuthSize = in.ordersAzimuthNodes;
    o.directions = in.ordersDirections;
    o.steps = in.ordersSteps;
    o.orders = in.ordersCount;
    o.threads = in.threads;
    return o;
}

OrdersTableOptions coarseOrdersOptions() {
    OrdersTableOptions o;
    o.radiusSize = 8;
    o.sunSize = 24;
    o.viewSize = 16;
    o.azimuthSize = 4;
    o.directions = 144;
    o.steps = 32;
    o.orders = 6;
    return o;
}

std::shared_ptr<const OrdersTable> sharedOrdersTable(const Model& m, const OrdersTableOptions& o) {
    static TableCache<OrdersTable> cache;
    return cache.get([&](const OrdersTable& t) { return t.model() == m && t.requested() == o; },
                     [&] {
                         const std::shared_ptr<const TransmittanceTable> t = sharedTransmittanceTable(m);
                         return std::make_shared<const OrdersTable>(m, *t, o);
                     });
}

}  // namespace postfx::atmosphere
