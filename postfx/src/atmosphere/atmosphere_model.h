// The atmosphere model (docs/effects/atmosphere.md) in double precision: media, ray–sphere intersections,
// phase functions and the LUTs' parameterisations with their inverses. The effect's GLSL
// (shaders/common/air/model.glsl) mirrors these functions; the CPU reference (atmosphere_reference.h) and the
// unit tests use them.
//
// Positions are planet-centred [m]: the planet's centre at the origin, y up; a world position x (y = 0 on
// the ground) is x + (0, groundRadius, 0). r = |position| is the distance from the centre, μ the cosine of
// a direction's angle to the local zenith (position / r).
#pragma once

#include <postfx/atmosphere.h>
#include "common/ray_sphere.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace postfx::atmosphere {

// AtmosphereSettings' media in double (radii, coefficients [1/m], heights [m]).
struct Model {
    double groundRadius = 6360e3, topRadius = 6460e3;
    glm::dvec3 rayleighScattering{5.802e-6, 13.558e-6, 33.1e-6};
    double rayleighScaleHeight = 8000.0;
    double mieScattering = 3.996e-6, mieAbsorption = 4.4e-6, mieScaleHeight = 1200.0, mieAnisotropy = 0.8;
    glm::dvec3 ozoneAbsorption{0.650e-6, 1.881e-6, 0.085e-6};
    double ozoneCenterHeight = 25000.0, ozoneHalfWidth = 15000.0;
    glm::dvec3 groundAlbedo{0.3};

    bool operator==(const Model&) const = default;
};
Model modelFrom(const AtmosphereSettings& settings);

// Planet-centred position of world position `world` (the ground at y = 0).
inline glm::dvec3 planetCentred(const Model& m, const glm::dvec3& world) {
    return world + glm::dvec3(0.0, m.groundRadius, 0.0);
}

// A camera below the ground is clamped onto it (documented in docs/effects/atmosphere.md): `position`
// moved along its radius to |position| = groundRadius when nearer the centre; unchanged otherwise.
inline glm::dvec3 clampAboveGround(const Model& m, const glm::dvec3& position) {
    const double r = glm::length(position);
    if (r >= m.groundRadius) return position;
    return r > 0.0 ? position * (m.groundRadius / r) : glm::dvec3(0.0, m.groundRadius, 0.0);
}

// Relative density of each constituent at altitude h = r - groundRadius [1]: Rayleigh exp(-h/H_R), Mie
// exp(-h/H_M), ozone max(0, 1 - |h - centre| / halfWidth). Below the ground (h < 0) h is taken as 0.
struct Densities {
    double rayleigh = 0.0, mie = 0.0, ozone = 0.0;
};
Densities densitiesAt(const Model& m, double altitude);

// The medium at altitude h [1/m]: each constituent's coefficient times its density. Rayleigh only
// scatters, ozone only absorbs; Mie does both.
struct Medium {
    glm::dvec3 rayleighScattering{0.0};
    double mieScattering = 0.0;
    glm::dvec3 scattering{0.0};  // σs = rayleigh + mie
    glm::dvec3 extinction{0.0};  // σt = σs + mie absorption + ozone absorption
};
Medium mediumAt(const Model& m, double altitude);

using common::raySphere;
using common::SphereHit;

// The part of the ray from `origin` (t >= 0) inside the atmosphere and before the ground: [tBegin, tEnd],
// empty (tEnd <= tBegin) when the ray never enters it; hitsGround: the segment ends on the ground.
struct AtmosphereSegment {
    double tBegin = 0.0, tEnd = 0.0;
    bool hitsGround = false;
};
AtmosphereSegment atmosphereSegment(const Model& m, const glm::dvec3& origin, const glm::dvec3& dir);

// The view direction at radius r with cosine μ hits the ground: μ < 0 and r²(μ² - 1) + ground² >= 0
// (Bruneton 2017, RayIntersectsGround). r <= ground: every downward ray.
bool rayIntersectsGround(const Model& m, double r, double mu);
// Distance from radius r (<= top) along cosine μ to the top boundary: -rμ + √(r²(μ² - 1) + top²), >= 0.
double distanceToTop(const Model& m, double r, double mu);

// Phase functions of the cosine `cosViewSun` = dot(viewDir, toSun), viewDir from the camera to the sample:
// 1 is forward scattering (looking at the sun). Each integrates to 1 over the sphere [1/sr].
// Rayleigh: 3/(16π)·(1 + cos²θ).
double rayleighPhase(double cosViewSun);
// Cornette–Shanks (1992), the Mie phase: 3/(8π)·(1 - g²)(1 + cos²θ) / ((2 + g²)(1 + g² - 2g·cosθ)^{3/2}).
// g = 0 gives Rayleigh's; g > 0 peaks at cosθ = 1.
double cornetteShanksPhase(double cosViewSun, double g);
inline constexpr double kIsotropicPhase = 0.07957747154594767;  // 1/(4π) [1/sr]

// Texel-centre mapping of a unit coordinate x in [0, 1] onto a LUT side of n texels (Bruneton 2017,
// GetTextureCoordFromUnitRange): x = 0 at the first texel's centre, 1 at the last's, so the stored range's
// ends are sampled exactly: u = 0.5/n + x·(1 - 1/n); and its inverse. (Hillaire's fromUnitToSubUvs /
// fromSubUvsToUnit are not each other's inverse; these are.)
double unitToTexelUv(double x, uint32_t n);
double texelUvToUnit(double u, uint32_t n);

// Transmittance LUT (Bruneton's horizon-distance mapping, Hillaire's LutTransmittanceParamsToUv):
// H = √(top² - ground²), ρ = √(r² - ground²), d = distanceToTop(r, μ), d_min = top - r, d_max = ρ + H,
// x_μ = (d - d_min)/(d_max - d_min), x_r = ρ/H. x_μ = 0 is the zenith, 1 the horizon: directions below the
// horizon are not stored (they give x_μ > 1; the caller tests the ground first). r is clamped to
// [ground, top].
struct RadiusCosine {
    double r = 0.0, mu = 0.0;
};
glm::dvec2 transmittanceUnitFromParams(const Model& m, double r, double mu);  // (x_μ, x_r)
RadiusCosine transmittanceParamsFromUnit(const Model& m, const glm::dvec2& unit);
// The same through the texel-centre mapping of a w×h LUT: uv in [0.5/n, 1 - 0.5/n].
glm::dvec2 transmittanceUvFromParams(const Model& m, double r, double mu, const glm::uvec2& size);
RadiusCosine transmittanceParamsFromUv(const Model& m, const glm::dvec2& uv, const glm::uvec2& size);

// Multiple-scattering LUT (Hillaire's GetMultipleScattering): x = (μ_s + 1)/2, μ_s the cosine of the
// sun's zenith angle; y = (r - ground)/(top - ground); both clamped to [0, 1]; then texel centres.
struct SunCosineRadius {
    double muS = 0.0, r = 0.0;
};
glm::dvec2 multipleScatteringUvFromParams(const Model& m, double muS, double r, const glm::uvec2& size);
SunCosineRadius multipleScatteringParamsFromUv(const Model& m, const glm::dvec2& uv, const glm::uvec2& size);

// Sky-view LUT at radius r (Hillaire's SkyViewLutParamsToUv, NONLINEARSKYVIEWLUT). β = acos(√(r² -
// ground²)/r) is the angle between the nadir and the horizon, Z = π - β the horizon's zenith angle, θ the
// view's zenith angle. Above the horizon (θ < Z): v = (1 - √(min(1, (Z - θ)/D)))/2; at or below it:
// v = (1 + √((θ - Z)/β))/2: half the texels each side, crowded toward the horizon (v = 0.5). D is the sky
// half's span of zenith angles (skyViewSkySpan): Z inside the atmosphere (the paper's mapping); from above
// the top only directions within αt = asin(top/r) of the nadir meet the air, so D falls to αt - β
// (atmosphere.md#high-up-and-in-space). Azimuth φ between the view's and the sun's horizontal directions,
// cos φ: u = √((1 - cos φ)/2) (sun side at u = 0). r is clamped to >= ground. Then texel centres.
double skyViewHorizonBeta(const Model& m, double r);
// The weight of the space span in D: 0 up to the top, 1 from kAtmosphereSpaceViewMinAltitude of the
// thickness up, linear in the altitude between. D = (1 - w)·Z + w·(αt - β).
double skyViewSpaceWeight(const Model& m, double r);
double skyViewSkySpan(const Model& m, double r);
struct SkyViewParams {
    double cosViewZenith = 0.0, cosAzimuth = 0.0;
};
glm::dvec2 skyViewUnitFromParams(const Model& m, double r, const SkyViewParams& p);
SkyViewParams skyViewParamsFromUnit(const Model& m, double r, const glm::dvec2& unit);
glm::dvec2 skyViewUvFromParams(const Model& m, double r, const SkyViewParams& p, const glm::uvec2& size);
SkyViewParams skyViewParamsFromUv(const Model& m, double r, const glm::dvec2& uv, const glm::uvec2& size);

}  // namespace postfx::atmosphere
