// The "orders" multiple-scattering model in double (docs/effects/atmosphere.md, "Multiple scattering"):
// every order of scattering computed one after another, as Bruneton and Neyret (2008) do, but stored as the
// in-scattered source of orders >= 2 instead of its integral along rays, so that every effect marches it as
// it marched Hillaire's σs·Ψ:
//   J≥2(x, ω) = σR(x)·ΨR(r, μ, μs, φ) + σM(x)·ΨM(r, μ, μs, φ)   [per unit length, per unit sun illuminance],
// ΨR = ∫ pR(ω·ω')·L≥1(x, ω') dω' and ΨM the same with Cornette–Shanks, L≥1 the radiance that arrives at x
// looking along ω' after one or more events (scattering or the ground's bounce). r the radius, μ the view's
// cos zenith, μs the sun's, φ the azimuth between them (0: the sun's side). The ground's irradiance from the
// sky, E≥2(μs) (orders >= 2 of the ground's light: its bounce of the sky), is a table of its own.
//
// Order n + 1 from order n, at each node (r, μs): over n×n stratified directions ω_k (the same local frame
// at every node: zenith +y, the sun in the x–y plane toward +x),
//   L_n(ω_k) = ∫ T·J_n dt + T·albedo/π·E_n(ground point)        (J_1: single scattering, E_1: the sun's),
//   Ψ_{n+1}(μ, φ) = Σ_k p(ω·ω_k)·L_n(ω_k) / Σ_k p(ω·ω_k)          (a quadrature normalised to the phase's 1),
//   E_{n+1}(μs) = Σ_k L_n(ω_k)·max(0, ω_k·up)·4π/K                (at the ground's nodes),
// each ray marched with `steps` steps crowded toward its lowest point (orderMarchSteps). After `orders`
// orders, the rest is a geometric tail: Ψ_{N+1}·q/(1 - q), q the node's ratio of order N + 1 to order N.
#pragma once

#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_reference.h"

#include <postfx/reference.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace postfx::atmosphere {

// Grid nodes at unit coordinates i/(n - 1) of: r: √((r - ground)/(top - ground)); μs and μ:
// (1 + sign(c)·√|c|)/2 (finer at the horizon); φ: φ/π.
struct OrdersTableOptions {
    uint32_t radiusSize = 24, sunSize = 96, viewSize = 32, azimuthSize = 16;  // each >= 2
    uint32_t directions = 576;                                                // a perfect square
    uint32_t steps = 64;                                                      // per direction
    uint32_t orders = 8;   // computed orders after the first (2 .. orders + 1), then the tail
    uint32_t threads = 0;  // 0: all hardware threads

    bool operator==(const OrdersTableOptions&) const = default;
};

// A ray's march steps, `steps` in all (>= 1), over [tBegin, tEnd] of the ray at radius r with cosine μ:
// split at its lowest point where that lies inside, each part's steps (in proportion to its length, at
// least one) spaced quadratically away from the lowest point (where the air is densest).
struct MarchStep {
    double t = 0.0, dt = 0.0;  // midpoint and length
};
void orderMarchSteps(double r, double mu, double tBegin, double tEnd, uint32_t steps,
                     std::vector<MarchStep>& out);

// The azimuth's cosine between view `dir` and `toSun` about the zenith `up` (1 where either is vertical).
double cosAzimuthAbout(const glm::dvec3& up, const glm::dvec3& dir, const glm::dvec3& toSun);

class OrdersTable {
public:
    OrdersTable(const Model& m, const TransmittanceTable& transmittance, const OrdersTableOptions& o = {});

    struct Psi {
        glm::dvec3 rayleigh{0.0}, mie{0.0};
    };
    // Ψ at (r, μ, μs, cos φ), multilinear, clamped to the grid.
    Psi at(double r, double mu, double muS, double cosAzimuth) const;
    // J≥2 at planet-centred `position` looking along `dir`, the sun toward `toSun`.
    glm::dvec3 source(const glm::dvec3& position, const glm::dvec3& dir, const glm::dvec3& toSun) const;
    // E≥2 at a ground point whose zenith makes cosine μs with the sun [lux per lux].
    glm::dvec3 groundIrradiance(double muS) const;

    const Model& model() const { return model_; }
    const OrdersTableOptions& options() const { return options_; }  // as built (sizes clamped)
    const OrdersTableOptions& requested() const { return requested_; }

private:
    Model model_;
    OrdersTableOptions requested_, options_;
    // Ψ at node (φ fastest, then μ, μs, r), both phases side by side; E at μs nodes.
    std::vector<Psi> psi_;
    std::vector<glm::dvec3> ground_;
};

// The table reference::renderAtmosphere builds from its inputs' orders* fields (and threads).
OrdersTableOptions ordersOptionsFrom(const reference::AtmosphereInputs& inputs);

// A coarse table for what integrates the sky or adds it to something else (the public CPU evaluations'
// sky irradiance, the clouds' reference's air in front of them): about 0.3 s to build on two cores.
OrdersTableOptions coarseOrdersOptions();

// The table for `m` and `o` over the shared transmittance table, built on first use and shared (a few
// recent ones are kept; thread-safe).
std::shared_ptr<const OrdersTable> sharedOrdersTable(const Model& m, const OrdersTableOptions& o = {});

}  // namespace postfx::atmosphere
