// The atmosphere without LUTs, in double (docs/effects/atmosphere.md, "Reference"): optical depth and
// transmittance to the atmosphere's edge, the multiple-scattering term Ψ (Hillaire eq. 5–10) and the
// luminance along a view ray, each marched with midpoint steps whose count is a parameter. Positions and
// directions are planet-centred (atmosphere_model.h); directions have length 1.
#pragma once

#include "atmosphere/atmosphere_model.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace postfx::atmosphere {

class OrdersTable;  // atmosphere_orders.h

// ∫ over a step of length Δ of e^{-σt·s} ds = (1 - e^{-σtΔ})/σt per channel (Δ where σt = 0), without
// cancellation: the energy-conserving step T·S·(this) every march of the reference uses.
glm::dvec3 stepIntegral(const glm::dvec3& extinction, double delta);
// e^{-τ} per channel.
glm::dvec3 expNeg(const glm::dvec3& tau);

// τ = ∫ σt dt from `origin` along `dir` to where the ray leaves the atmosphere or meets the ground, `steps`
// midpoint steps over that segment [1]; 0 when the ray misses the atmosphere.
glm::dvec3 opticalDepth(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir, uint32_t steps);
// exp(-opticalDepth).
glm::dvec3 transmittanceToEdge(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir,
                               uint32_t steps);
// The sun's transmittance at `position` toward `toSun`: 0 where the planet hides the sun (the ray meets
// the ground), exp(-τ to the top boundary) otherwise (what the transmittance LUT stores).
glm::dvec3 sunTransmittance(const Model& m, const glm::dvec3& position, const glm::dvec3& toSun,
                            uint32_t steps);

// Ψ at radius r for the sun at cosine muS from the zenith, per unit sun illuminance (Hillaire eq. 10,
// what the multiple-scattering LUT stores) [1/sr]: Ψ = min(L2 / (1 - f_ms), kMaxPsi), where over `directions`
// (n×n, stratified uniformly over the sphere) with `steps` midpoint steps each to the atmosphere's edge or
// ground:
//   L2   = (1/N) Σ L'(ω),  L'(ω) = ∫ T(x, x_t)·σs(x_t)·Tsun(x_t)·p_u dt + T(x, p)·Tsun(p)·max(0,
//   n·s)·albedo/π
//          (eq. 5–6: second-order luminance with an isotropic phase p_u = 1/4π, the ground bounce at p),
//   f_ms = (1/N) Σ ∫ T(x, x_t)·σs(x_t) dt  (eq. 7–8: the transfer of a unit isotropic luminance),
// both integrated with the energy-conserving step form (T·S·(1 - e^{-σtΔ})/σt).
// Ψ's bound [1/sr]: 2/π, the GPU's kAtmosphereMaxPsi (atmosphere_shared.h, which says why).
inline constexpr double kMaxPsi = 0.6366197723675814;

struct PsiOptions {
    uint32_t directions = 64;          // a perfect square
    uint32_t steps = 20;               // per direction
    uint32_t transmittanceSteps = 40;  // each sample's sun transmittance
};
glm::dvec3 multipleScatteringPsi(const Model& m, double r, double muS, const PsiOptions& options = {});

// The reference's fine tables (docs/effects/atmosphere.md, "Reference"): caches in double of what the
// reference would otherwise integrate again at every sample, far finer than the GPU's LUTs. Each is built
// once per Model, multithreaded, and looked up bilinearly.

// Optical depth to the top boundary over (x_μ, x_r) of the transmittance LUT's parameterisation
// (transmittanceUnitFromParams), size.x × size.y nodes at x = i/(size - 1), each marched with `steps`
// midpoint steps over [0, distanceToTop(r, μ)]. The lookup interpolates τ, then takes exp(-τ).
struct TransmittanceTableOptions {
    glm::uvec2 size{256, 128};  // each >= 2
    uint32_t steps = 300;
    uint32_t threads = 0;  // 0: all hardware threads
};
class TransmittanceTable {
public:
    explicit TransmittanceTable(const Model& m, const TransmittanceTableOptions& options = {});
    // exp(-τ) from radius r (clamped to [ground, top]) along cosine μ to the top, the ground not tested
    // (directions below the horizon read the horizon's column).
    glm::dvec3 toTop(double r, double mu) const;
    // sunTransmittance's equivalent at planet-centred `position` (|toSun| = 1): 0 where the ray meets the
    // ground; from outside the atmosphere the ray's entry point's value (1 when it misses the atmosphere);
    // a position below the ground is read on it.
    glm::dvec3 sun(const glm::dvec3& position, const glm::dvec3& toSun) const;
    const Model& model() const { return model_; }

private:
    Model model_;
    glm::uvec2 size_;
    std::vector<glm::dvec3> tau_;  // size.x·size.y, x_μ fastest
};

// Ψ (multipleScatteringPsi) over (μ_s, altitude): muSSize × heightSize nodes at x = (1 + sign(μ_s)·√|μ_s|)/2
// = i/(n - 1) and y = √((r - ground)/(top - ground)) = j/(n - 1): finer than the LUT's linear mapping where
// Ψ changes fastest (the sun near the horizon, the ground), each from `psi`'s directions and steps with every
// sample's sun transmittance read from a TransmittanceTable (psi.transmittanceSteps is not used). Bilinear
// lookup, clamped to the grid.
struct PsiTableOptions {
    uint32_t muSSize = 64, heightSize = 64;  // each >= 2
    PsiOptions psi{256, 100, 0};
    uint32_t threads = 0;  // 0: all hardware threads
};
class PsiTable {
public:
    PsiTable(const Model& m, const TransmittanceTable& transmittance, const PsiTableOptions& options = {});
    glm::dvec3 at(double r, double muS) const;
    const Model& model() const { return model_; }
    // Whether the table was built with the same grid, directions and steps as `o` asks for.
    bool builtWith(const PsiTableOptions& o) const;

private:
    Model model_;
    PsiTableOptions options_;
    uint32_t muSSize_, heightSize_;
    std::vector<glm::dvec3> psi_;  // muSSize·heightSize, μ_s fastest
};

// A few recent tables of one kind, keyed by what they were built from (their model): get() returns the
// kept table that `matches`, or builds one (thread-safe). The shared tables below and the public CPU
// evaluations' (atmosphere_public.cpp) keep theirs in one each.
template <class Table>
struct TableCache {
    std::mutex mutex;
    std::vector<std::shared_ptr<const Table>> recent;  // most recent last
    static constexpr size_t kKept = 4;

    template <class Matches, class Build>
    std::shared_ptr<const Table> get(const Matches& matches, const Build& build) {
        const std::lock_guard<std::mutex> lock(mutex);
        for (size_t i = 0; i < recent.size(); ++i)
            if (matches(*recent[i])) {
                std::shared_ptr<const Table> t = recent[i];
                recent.erase(recent.begin() + std::ptrdiff_t(i));
                recent.push_back(t);
                return t;
            }
        std::shared_ptr<const Table> t = build();
        if (recent.size() >= kKept) recent.erase(recent.begin());
        recent.push_back(t);
        return t;
    }
};

// Tables for `m` (the transmittance table with its default options), built on first use and shared (a few
// recent ones are kept; thread-safe).
std::shared_ptr<const TransmittanceTable> sharedTransmittanceTable(const Model& m);
std::shared_ptr<const PsiTable> sharedPsiTable(const Model& m, const PsiTableOptions& options = {});

// The sun: a directional light of illuminance `illuminance` [lux] outside the atmosphere.
struct Sun {
    glm::dvec3 toSun{0.0, 1.0, 0.0};
    glm::dvec3 illuminance{1.0};
};

struct ViewRayOptions {
    uint32_t steps = 256;               // over the segment [begin, min(end, maxDistance)]
    uint32_t transmittanceSteps = 256;  // each sample's sun transmittance
    double maxDistance = std::numeric_limits<double>::infinity();  // [m] from the origin
    bool multipleScattering = true;  // add σs·Ψ·E at each sample, Ψ from multipleScatteringPsi
    PsiOptions psi;
    // Add the lit ground where the ray ends on it (within maxDistance): T·Tsun·max(0, n·s)·albedo/π·E.
    bool ground = false;
    // The ray ends at maxDistance (a host's surface), not on the planet's sphere: it goes on below the
    // ground, in the ground's medium, to where it leaves the top (the aerial perspective of geometry).
    bool throughGround = false;
    // Fine tables instead of the per-sample integrals (the exact path when null): each sample's Tsun from
    // `transmittanceTable` (transmittanceSteps unused), Ψ from `psiTable` (psi unused). Not owned.
    const TransmittanceTable* transmittanceTable = nullptr;
    const PsiTable* psiTable = nullptr;
    // The "orders" model instead of Ψ (multipleScattering on): J≥2 from `ordersTable` at each sample, and
    // the ground lit by the sky (its E≥2) where the ray ends on it. Not owned.
    const OrdersTable* ordersTable = nullptr;
};

// Luminance reaching `origin` along `dir` [cd/m² for illuminance in lux] and the transmittance of the
// segment. Single scattering: L = ∫ T(0, t)·σs... summed per constituent with its phase, the Rayleigh phase
// and Cornette–Shanks of cos = dir·toSun, times Tsun; each step adds T·S·(1 - e^{-σtΔ})/σt with S the
// in-scattered radiance per unit length at the step's midpoint.
struct ViewRayResult {
    glm::dvec3 luminance{0.0};
    glm::dvec3 transmittance{1.0};
};
ViewRayResult integrateViewRay(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir,
                               const Sun& sun, const ViewRayOptions& options = {});

}  // namespace postfx::atmosphere
