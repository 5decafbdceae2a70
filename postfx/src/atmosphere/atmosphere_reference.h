// The atmosphere without LUTs, in double (docs/effects/atmosphere.md, "Reference"): optical depth and
// transmittance to the atmosphere's edge, the multiple-scattering term Ψ (Hillaire eq. 5–10) and the
// luminance along a view ray, each marched with midpoint steps whose count is a parameter. Positions and
// directions are planet-centred (atmosphere_model.h); directions have length 1.
#pragma once

#include "atmosphere/atmosphere_model.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>

namespace postfx::atmosphere {

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
// what the multiple-scattering LUT stores) [1/sr]: Ψ = L2 / (1 - f_ms), where over `directions` (n×n,
// stratified uniformly over the sphere) with `steps` midpoint steps each to the atmosphere's edge or ground:
//   L2   = (1/N) Σ L'(ω),  L'(ω) = ∫ T(x, x_t)·σs(x_t)·Tsun(x_t)·p_u dt + T(x, p)·Tsun(p)·max(0,
//   n·s)·albedo/π
//          (eq. 5–6: second-order luminance with an isotropic phase p_u = 1/4π, the ground bounce at p),
//   f_ms = (1/N) Σ ∫ T(x, x_t)·σs(x_t) dt  (eq. 7–8: the transfer of a unit isotropic luminance),
// both integrated with the energy-conserving step form (T·S·(1 - e^{-σtΔ})/σt).
struct PsiOptions {
    uint32_t directions = 64;          // a perfect square
    uint32_t steps = 20;               // per direction
    uint32_t transmittanceSteps = 40;  // each sample's sun transmittance
};
glm::dvec3 multipleScatteringPsi(const Model& m, double r, double muS, const PsiOptions& options = {});

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
