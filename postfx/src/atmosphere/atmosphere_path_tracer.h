// Reference (b) of the atmosphere (docs/effects/atmosphere.md, "The multiple-scattering approximation
// against a path tracer"): a Monte Carlo path tracer in double of the same media, every order of
// scattering, to measure what Hillaire's Ψ (an isotropic, infinite-layer approximation of orders >= 2)
// leaves out. Positions and directions are planet-centred (atmosphere_model.h).
//
// The media: Rayleigh with its phase, Mie with Cornette–Shanks (sampled exactly by rejection from
// Henyey–Greenstein of the same g: CS/HG = 3(1 + cos²θ)/(2(2 + g²)), accepted with probability
// (1 + cos²θ)/2), Mie and ozone absorption; a Lambertian ground of the model's albedo; the sun a directional
// light outside the atmosphere, seen through next-event estimation at every scattering event and ground
// hit (shadow ray: the transmittance to the top, 0 where the planet blocks it, from a TransmittanceTable).
//
// Spectral choice: each RGB channel is traced on its own (a grey medium per channel, its own paths and
// random numbers): no spectral MIS is needed, and each channel's standard error is its own.
// Free paths: delta tracking with one majorant per channel (σt of Rayleigh and Mie at the ground plus ozone
// at its peak, each density <= 1), except the first segment along the view ray, which forces a collision:
// the collision's optical depth is drawn from the exponential truncated to the segment's τ (tabulated
// along it, kViewNodes cells) and the path's weight takes (1 - e^{-τ}); where the view ray ends on the
// ground, the ground's branch (weight e^{-τ}) is added to the same sample. At a real collision the weight
// takes the single-scattering albedo σs/σt (absorption by weight). Russian roulette from the third event
// on, with survival probability min(1, weight).
#pragma once

#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_reference.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace postfx::atmosphere {

struct PathTracerOptions {
    uint64_t paths = 100000;  // per channel
    uint64_t seed = 1;
    uint32_t threads = 0;  // 0: all hardware threads; the result does not depend on it
};

struct PathTracerResult {
    glm::dvec3 luminance{0.0};      // [cd/m² for illuminance in lux]
    glm::dvec3 standardError{0.0};  // of the mean, per channel
};

// Luminance reaching `origin` along `dir` (|dir| = 1) from the sun `sun` scattered any number of times by
// the atmosphere and the ground. The sun's direct beam is not included (it is a delta: the disk is drawn
// apart). `origin` must be on or above the ground.
PathTracerResult pathTraceViewRay(const Model& m, const TransmittanceTable& transmittance,
                                  const glm::dvec3& origin, const glm::dvec3& dir, const Sun& sun,
                                  const PathTracerOptions& options = {});

// A view and sun configuration as the paper's figure: camera at `altitude` [m] above the ground, view at
// `viewZenithDeg` from the zenith, sun at `sunElevationDeg` above the horizon, `relativeAzimuthDeg`
// between the view's and the sun's horizontal directions (0: facing the sun's side).
struct ViewSunAngles {
    double viewZenithDeg = 0.0, sunElevationDeg = 90.0, relativeAzimuthDeg = 0.0, altitude = 0.0;
};
struct ViewSunRay {
    glm::dvec3 origin, dir, toSun;
};
ViewSunRay viewSunRay(const Model& m, const ViewSunAngles& angles);

}  // namespace postfx::atmosphere
