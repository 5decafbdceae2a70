// The clouds' model in double (docs/effects/clouds.md): the shape, the density field and the light at a
// sample, as shaders/clouds/density.glsl and lighting.glsl evaluate them, for the CPU reference
// (clouds_reference_image.cpp) and the tests. Positions are camera-relative [m] unless said otherwise.
#pragma once

#include <postfx/clouds.h>
#include <postfx/context.h>

#include "common/air.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <span>

namespace postfx::clouds {

// A repeat-tileable size³ texture of values in [0, 1], sampled as the GPU's trilinear REPEAT sampler.
struct NoiseVolume {
    std::span<const float> texels;  // x fastest, then y, then z
    uint32_t size = 0;
    double sample(const glm::dvec3& uvw) const;
};

// A repeat-tileable width×height map of values in [0, 1], sampled as the GPU's bilinear REPEAT sampler.
struct CoverageMapTexels {
    std::span<const float> texels;  // row-major, v = 0 row first
    uint32_t width = 0, height = 0;
    bool present() const { return !texels.empty(); }
    double sample(const glm::dvec2& uv) const;
};

// The slab model's δ-scaled medium (Joseph, Wiscombe and Weinman 1976): the phase's first and second
// moments g and f of the dual lobe, ω' = ω(1 - f)/(1 - ωf), g' = (g - f)/(1 - f), τ' = (1 - ωf)·τ.
struct SlabMedium {
    double g = 0.0, f = 0.0;
    double albedo = 0.0, asymmetry = 0.0, depthScale = 1.0;  // ω', g', 1 - ωf
};
SlabMedium slabMedium(const CloudSettings& settings);

struct Model {
    CloudSettings s;
    glm::dvec3 camera{0.0};  // world [m]
    bool curved = false;     // the layer follows the planet (atmosphere on, Layer shape)
    double groundRadius = 0.0;
    double bottom = 0.0, top = 1.0;  // altitudes of the layer, or the box's -half.y, half.y [m]
    glm::dmat3 worldToBox{1.0};
    glm::dvec3 boxCenter{0.0};
    double topFalloff = 1.0;      // fraction of the layer the profile falls to 0 over at its top
    glm::dvec3 noiseOrigin{0.0};  // world position - wind·t of the camera [m]
    NoiseVolume base, detail;
    CoverageMapTexels coverageMap;  // the host's coverage map; empty: none
    glm::dvec3 toSun{0.0, 1.0, 0.0}, sunIlluminance{0.0}, ambient{0.0};
    SlabMedium slab;  // slabMedium(s), for the slab model
    // The air, for the sun's transmittance through it; null with the atmosphere off.
    std::shared_ptr<const common::Air> atmosphere;
};

// Whether the layer follows the planet (a Layer with the atmosphere on: spheres around its centre).
bool followsPlanet(const FrameInfo& frame);
// The shape's bottom and top along its height: the layer's altitudes, or -half.y, half.y in the box's frame
// [m].
glm::dvec2 heightRange(const CloudSettings& settings);
// The box's rotation from world to its own axes: the inverse of yaw about world y, then pitch about its x.
glm::dmat3 worldToBox(const CloudBox& box);
// The fraction of the layer over which the height profile falls to 0 at its top, for a cloud type in
// [0, 1]: from kCloudTopFalloffStratus (0) to kCloudTopFalloffCumulus (1), linearly.
double topFalloff(double cloudType);

// The model of `frame`'s clouds (settings validated), reading the noise from `base` and `detail` and the
// coverage map from `coverageMap` (empty: none).
Model modelFrom(const FrameInfo& frame, NoiseVolume base, NoiseVolume detail,
                CoverageMapTexels coverageMap = {});

// The part of ray x0 + t·d inside the shape, t in [0, far]: (begin, end), end <= begin when none.
glm::dvec2 segment(const Model& m, const glm::dvec3& x0, const glm::dvec3& d, double far);
// The height fraction at x: 0 at the shape's bottom, 1 at its top.
double heightFraction(const Model& m, const glm::dvec3& x);
double heightProfile(const Model& m, double h);
double field(const Model& m, const glm::dvec3& x, double h);  // in [0, 1]
double extinction(const Model& m, const glm::dvec3& x);       // σt [1/m]
// Optical depth toward the sun from x over the light path (the shape's exit, at most light_distance),
// with `steps` midpoint samples, step k spanning [(k/n)², ((k+1)/n)²] of the path (lighting.glsl).
double sunOpticalDepth(const Model& m, const glm::dvec3& x, uint32_t steps);
// The δ-Eddington diffuse fluence U and net flux F away from the sunlit face, per unit sun illuminance, at
// scaled optical depth tt from the sunlit face of a slab with tb beyond, the sun at cosine mu0, the
// scaled beam `beam` at the point and `farBeam` at the far face (lighting.glsl, cloudSlabDiffuse).
glm::dvec2 slabDiffuse(const SlabMedium& medium, double tt, double tb, double mu0, double beam,
                       double farBeam);
// The slab model's ambient term per unit ambient radiance toward -d at a sample whose slab normal is n
// (lighting.glsl, cloudSlabAmbient): the δ-Eddington slab lit by uniform diffuse radiance on both faces,
// optical depths σ·(1 - h)·H above the sample and σ·h·H below.
double slabAmbientTerm(const Model& m, const glm::dvec3& n, const glm::dvec3& d, double sigma, double h);
// The slab model's sun term per unit illuminance toward -d at a sample whose slab normal is n
// (lighting.glsl, cloudSlabSunTerm): τ the sun's optical depth, σ the extinction and h the height
// fraction there.
double slabSunTerm(const Model& m, glm::dvec3 n, const glm::dvec3& d, double sigma, double h, double tau);
// The slab's unit normal at x: up (flat layer), the planet's radial direction (curved), the box's y.
glm::dvec3 slabNormal(const Model& m, const glm::dvec3& x);
// The dual-lobe phase for view direction d, asymmetries times `scale` [1/sr].
double phase(const Model& m, const glm::dvec3& d, double scale);
// The radiance per unit scattering coefficient at x toward -d (lighting.glsl, cloudInScattered), the sun's
// optical depth from `lightSteps` samples.
glm::dvec3 inScattered(const Model& m, const glm::dvec3& x, const glm::dvec3& d, double sigma, double h,
                       uint32_t lightSteps);

struct MarchResult {
    glm::dvec3 luminance{0.0};
    double transmittance = 1.0;
    double meanDistance = 0.0;  // the extinction-weighted mean distance, 0 when T = 1
};
// The view ray from the camera along d to `far` with `steps` samples at offset `offset` in [0, 1) of
// each step (0.5: midpoints) and `lightSteps` samples toward the sun.
MarchResult march(const Model& m, const glm::dvec3& d, double far, uint32_t steps, double offset,
                  uint32_t lightSteps);

}  // namespace postfx::clouds
