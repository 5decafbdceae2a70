// Sky and atmosphere (Hillaire, "A Scalable and Production Ready Sky and Atmosphere Rendering Technique",
// EGSR 2020): settings (FrameInfo::atmosphere) and the model's CPU evaluations a host may use to light its
// own surfaces consistently. The model and its LUTs are in docs/effects/atmosphere.md.
//
// Every setting: unit, default, valid range. Out-of-range values are rejected (validateAtmosphereSettings)
// with an error naming the field by its C++ path ("FrameInfo.atmosphere.topRadius"); the ranges are
// atmosphereSettingsTable()'s (postfx/settings_table.h).
// Defaults are Earth as in the paper's reference code. World y = 0 is the ground; the planet's centre is at
// (0, -groundRadius, 0): in the host's world frame (ContextCreateInfo::world), its plane up = 0 is the
// ground and the centre is groundRadius metres below its origin along the up axis. Every length here is in
// metres, whatever the host's units.
#pragma once

#include <postfx/export.h>
#include <postfx/result.h>
#include <postfx/types.h>

#include <cstdint>

namespace postfx {

// How the orders of scattering beyond the first are computed (docs/effects/atmosphere.md, "Multiple
// scattering"); scene-file values "off", "hillaire", "orders".
enum class AtmosphereMultipleScattering : uint32_t {
    Off,       // single scattering only
    Hillaire,  // Hillaire 2020's LUT Ψ(μs, r): orders >= 2 isotropic, a geometric series (fast, 2–45% low
               // at the horizon against a path tracer)
    Orders,    // every order computed in turn over (height, view, sun, azimuth), as Bruneton and Neyret
               // 2008, stored as the in-scattered source: within 2% of a path tracer
};

struct AtmosphereSettings {
    bool enabled = false;

    // Planet. Radii of the ground sphere and of the atmosphere's top [m]: ground in [1, 1e8); top greater
    // than ground and at most 1e8.
    float groundRadius = 6360e3f;
    float topRadius = 6460e3f;

    // Rayleigh (air molecules): scattering only, density exp(-h / rayleighScaleHeight), h the altitude.
    // Scattering coefficient at the ground per RGB channel [1/m]; each in [0, 1].
    Vec3 rayleighScattering{5.802e-6f, 13.558e-6f, 33.1e-6f};
    float rayleighScaleHeight = 8000.0f;  // [m]; > 0 and <= 1e7

    // Mie (aerosols): scattering and absorption, density exp(-h / mieScaleHeight), grey.
    float mieScattering = 3.996e-6f;  // at the ground [1/m]; in [0, 1]
    float mieAbsorption = 4.4e-6f;    // at the ground [1/m]; in [0, 1]
    float mieScaleHeight = 1200.0f;   // [m]; > 0 and <= 1e7
    // Cornette–Shanks asymmetry g [1]; in (-1, 1). g > 0 scatters forward: brightest toward the sun.
    float mieAnisotropy = 0.8f;

    // Ozone: absorption only, density max(0, 1 - |h - ozoneCenterHeight| / ozoneHalfWidth) (a tent).
    Vec3 ozoneAbsorption{0.650e-6f, 1.881e-6f, 0.085e-6f};  // at the tent's peak [1/m]; each in [0, 1]
    float ozoneCenterHeight = 25000.0f;                     // altitude of the peak [m]; in [0, 1e7]
    float ozoneHalfWidth = 15000.0f;                        // [m]; > 0 and <= 1e7

    Vec3 groundAlbedo{0.3f};  // Lambertian ground's albedo per RGB channel [1]; each in [0, 1]

    // The multiple-scattering model: its LUT is rebuilt only when the media or its own settings change
    // (a moving sun or camera reuses it).
    AtmosphereMultipleScattering multipleScattering = AtmosphereMultipleScattering::Orders;
    // Angular radius of the sun disk drawn on sky pixels [deg]; in [0, 45]; 0: no disk (the sun still
    // lights). 0.2678 is the sun's as seen from Earth.
    float sunAngularRadiusDeg = 0.2678f;
    // For the host: its ambient should come from the sky (atmosphereSkyIrradiance below, / π) instead of a
    // constant. postfx's effects take FrameInfo::ambient as the host gives it; the demo, with this on,
    // gives them and its surfaces the sky's (docs/effects/atmosphere.md, "The demo").
    bool ambientFromSky = false;

    // LUTs: sizes [texels] and march steps (the transmittance's finer than the paper's 256×64 and 40 steps:
    // within 0.5 % of the exact T to the horizon).
    // Transmittance LUT: (view height, cos view zenith), Bruneton's horizon mapping. Each side in [4, 512].
    UVec2 transmittanceLutSize{512, 128};
    uint32_t transmittanceSteps = 80;  // in [1, 128]
    // Multiple-scattering LUT: (cos sun zenith, height). Each side in [4, 64].
    UVec2 multipleScatteringLutSize{32, 32};
    // Directions integrated per texel: a perfect square (stratified n×n over the sphere) in [4, 256].
    uint32_t multipleScatteringDirections = 64;
    uint32_t multipleScatteringSteps = 20;  // per direction; in [1, 128]
    // Scattering-orders LUT ("orders"): the source of orders >= 2 at nodes of (cos view zenith, cos sun
    // zenith, height) [nodes], each in [4, 64] (the sun's in [4, 128]), times this many azimuths from the
    // sun's side to the opposite one, in [2, 16].
    UVec3 scatteringOrdersLutSize{32, 64, 16};
    uint32_t scatteringOrdersAzimuthSize = 8;
    // Directions integrated at each (sun, height) node: a perfect square (stratified n×n) in [4, 576].
    uint32_t scatteringOrdersDirections = 256;
    uint32_t scatteringOrdersSteps = 24;  // per direction; in [1, 128]
    // Orders computed after the first, in [1, 16]; the rest is a geometric tail from the last two.
    uint32_t scatteringOrders = 4;
    // Sky-view LUT: (azimuth relative to the sun, view zenith), non-linear around the horizon. Each side in
    // [4, 512].
    UVec2 skyViewLutSize{192, 108};
    uint32_t skyViewSteps = 30;  // in [1, 128]
    // Aerial-perspective LUT: froxels over the camera frustum (x, y across the view; z slices of equal
    // depth). Each side in [4, 64].
    UVec3 aerialPerspectiveLutSize{32, 32, 32};
    // Depth the slices cover from the camera [m]; > 0 and <= 1e7. 32 km: 1 km a slice as in the paper (the
    // reference code uses 4 km a slice).
    float aerialPerspectiveDistance = 32000.0f;
    // March steps per slice of depth: slice k (0-based) is marched with (k + 1) · this steps from the camera,
    // as the reference code's 2 per slice; in [1, 8].
    uint32_t aerialPerspectiveStepsPerSlice = 2;
};

// The atmosphere's LUTs, for Context::imageView and Context::recordImageReadback (a host that lights its own
// surfaces through the atmosphere samples the transmittance LUT as postfx's effects do; docs/effects/
// atmosphere.md, "Parameterisations"): held while the atmosphere runs, each RGBA16F. The luminance LUTs hold
// luminance per unit sun illuminance times a storage scale (docs/effects/atmosphere.md, "Passes").
inline constexpr ResourceName kAtmosphereTransmittanceLut{"atmosphere.transmittance"};
inline constexpr ResourceName kAtmosphereMultipleScatteringLut{"atmosphere.multiple_scattering"};
// The transmittance and multiple-scattering LUTs and the sky-view LUT are 2D images; the aerial
// perspective's in-scattering is a 3D image and its transmittance a 2D array of a layer per slice (slice k's
// end in layer k).
inline constexpr ResourceName kAtmosphereSkyViewLut{"atmosphere.sky_view"};
inline constexpr ResourceName kAtmosphereAerialPerspectiveLut{"atmosphere.aerial_perspective"};
inline constexpr ResourceName kAtmosphereAerialTransmittanceLut{"atmosphere.aerial_transmittance"};

// Checks every setting against its documented range: InvalidArgument naming the first bad field with its
// C++ path ("FrameInfo.atmosphere.topRadius: 6e+06 must be greater than groundRadius (6.36e+06)"). Checked
// whether or not `enabled` is set.
POSTFX_API Status validateAtmosphereSettings(const AtmosphereSettings& settings);

// The sun's transmittance through the atmosphere from world position `worldPosition` toward `toSun`
// (normalised here) [1] per RGB channel, evaluated in double without LUTs: 0 where the planet hides the sun,
// exp(-optical depth to the top boundary) otherwise. A position below the ground is clamped onto it.
// Position and direction are in `world`, the host's world frame (ContextCreateInfo::world; the position in
// its units). Settings must be valid (validateAtmosphereSettings); `enabled` is ignored.
POSTFX_API Vec3 atmosphereSunTransmittance(const AtmosphereSettings& settings, const DVec3& worldPosition,
                                           const Vec3& toSun, const WorldFrame& world = {});

// Irradiance the sky (the atmosphere's scattered light, not the sun's direct beam) gives a surface at
// `worldPosition` facing the local zenith [lux], for a sun of `sunIlluminance` [lux] outside the atmosphere
// toward `toSun`: ∫ L_sky(ω)·cos θ dω over the upper hemisphere, L_sky with single and (settings'
// multipleScattering) multiple scattering (Hillaire's or the orders', as the settings say). A Lambertian
// surface's ambient radiance is this / π. Position and direction in `world`, as above. Settings must be
// valid; `enabled` is ignored.
POSTFX_API Vec3 atmosphereSkyIrradiance(const AtmosphereSettings& settings, const DVec3& worldPosition,
                                        const Vec3& toSun, const Vec3& sunIlluminance,
                                        const WorldFrame& world = {});

}  // namespace postfx
