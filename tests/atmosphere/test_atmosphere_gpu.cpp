// The atmosphere on the device (docs/effects/atmosphere.md, "Tests"): each LUT read back at chosen
// texels against the double-precision model marched finely, closed forms (pure-Rayleigh zenith
// transmittance, an optically thin Rayleigh sky at the zenith), sky and geometry pixels against the
// model per pixel, and the camera crossing the atmosphere's top. Small images on lavapipe.
#include "atmosphere/atmosphere_effect.h"
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_reference.h"
#include "atmosphere_reference_image.h"
#include "core/barriers.h"
#include "core/gpu_resources.h"
#include "fog_harness.h"
#include "image_compare.h"
#include "lut_readback.h"

#include <postfx/reference.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

namespace atm = postfx::atmosphere;

struct LutImage : LutTexels {
    glm::dvec4 at(uint32_t x, uint32_t y, uint32_t z = 0) const {
        const size_t i = ((size_t(z) * height + y) * width + x) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

class AtmosphereGpuTest : public ReversedZContextTest {
protected:
    // A frame of `width`×`height` sky pixels (depth 0: no geometry) over black, or with geometry at
    // `distance` [m] along each pixel's ray when distance > 0.
    FogHarnessImages images(const postfx::CameraInput& camera, uint32_t width, uint32_t height,
                            double distance = 0.0) const {
        FogHarnessImages im;
        im.width = width;
        im.height = height;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(width) * height * 4, 0.0f);
        im.depth.assign(size_t(width) * height, 0.0f);
        for (uint32_t j = 0; distance > 0.0 && j < height; ++j)
            for (uint32_t i = 0; i < width; ++i)
                im.depth[size_t(j) * width + i] =
                    depthAtDistance(camera, pixelDirection(camera, i, j, width, height), distance);
        return im;
    }

    std::vector<float> render(postfx::FrameInfo frame, const FogHarnessImages& im) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    LutImage readLut(const char* name) { return {readLutTexels(*host, gpu, *context, name)}; }

    postfx::FrameInfo skyFrame(double sunElevationDeg) const {
        postfx::FrameInfo frame;
        frame.atmosphere.enabled = true;
        const double e = glm::radians(sunElevationDeg);
        frame.sun.toSun = glm::vec3(float(std::cos(e)), float(std::sin(e)), 0.0f);
        frame.sun.illuminance = glm::vec3(1.0f);
        frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.05, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        return frame;
    }
};

// Each transmittance texel against exp(-τ) of its (r, μ) marched with 4096 steps in double: the LUT's
// 40 midpoint steps and its half-float storage.
TEST_F(AtmosphereGpuTest, TransmittanceLutMatchesReference) {
    postfx::FrameInfo frame = skyFrame(30.0);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.transmittance");
    ASSERT_EQ(lut.width, 256u);
    ASSERT_EQ(lut.height, 64u);
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    double worst = 0.0;
    for (uint32_t y : {0u, 7u, 31u, 63u})
        for (uint32_t x : {0u, 50u, 128u, 200u, 250u, 254u}) {
            const glm::dvec2 uv((x + 0.5) / lut.width, (y + 0.5) / lut.height);
            const atm::RadiusCosine p = atm::transmittanceParamsFromUv(m, uv, {lut.width, lut.height});
            const glm::dvec3 dir(std::sqrt(std::max(0.0, 1.0 - p.mu * p.mu)), p.mu, 0.0);
            const glm::dvec3 ref = atm::transmittanceToEdge(m, {0.0, p.r, 0.0}, dir, 4096);
            for (int c = 0; c < 3; ++c) {
                const double err = std::abs(lut.at(x, y)[c] - ref[c]);
                worst = std::max(worst, err);
                EXPECT_LT(err, 2e-3 + 0.01 * ref[c]) << "texel " << x << "," << y << " channel " << c;
            }
        }
    std::printf("[ atmosphere ] transmittance LUT: largest |LUT - reference| %.2e\n", worst);
}

// Pure Rayleigh at the ground looking straight up: exp(-β·H·(1 - e^{-(top - ground)/H})).
TEST_F(AtmosphereGpuTest, PureRayleighZenithTransmittanceMatchesClosedForm) {
    postfx::FrameInfo frame = skyFrame(30.0);
    frame.atmosphere.mieScattering = 0.0f;
    frame.atmosphere.mieAbsorption = 0.0f;
    frame.atmosphere.ozoneAbsorption = postfx::Vec3(0.0f);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.transmittance");
    const postfx::AtmosphereSettings& s = frame.atmosphere;
    const double H = s.rayleighScaleHeight, thickness = double(s.topRadius) - s.groundRadius;
    for (int c = 0; c < 3; ++c) {
        const double expected =
            std::exp(-double(s.rayleighScattering[c]) * H * (1.0 - std::exp(-thickness / H)));
        EXPECT_NEAR(lut.at(0, 0)[c], expected, 1.5e-3) << "channel " << c;  // texel (μ = 1, r = ground)
    }
}

// Multiple-scattering texels against Ψ (eq. 10) with the same directions and 10× the steps.
TEST_F(AtmosphereGpuTest, MultipleScatteringLutMatchesReference) {
    postfx::FrameInfo frame = skyFrame(30.0);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.multiple_scattering");
    ASSERT_EQ(lut.width, 32u);
    const double scale = atm::lutStorageScale(frame.atmosphere);
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    atm::PsiOptions fine;
    fine.steps = 200;
    fine.transmittanceSteps = 200;
    double worst = 0.0;
    for (uint32_t y : {0u, 16u, 31u})
        for (uint32_t x : {8u, 20u, 31u}) {
            const glm::dvec2 uv((x + 0.5) / lut.width, (y + 0.5) / lut.height);
            const atm::SunCosineRadius p =
                atm::multipleScatteringParamsFromUv(m, uv, {lut.width, lut.height});
            const glm::dvec3 ref = atm::multipleScatteringPsi(m, p.r, p.muS, fine);
            for (int c = 0; c < 3; ++c) {
                const double rel = std::abs(lut.at(x, y)[c] / scale - ref[c]) / std::max(ref[c], 1e-12);
                worst = std::max(worst, rel);
                EXPECT_LT(rel, 0.05) << "texel " << x << "," << y << " channel " << c << ": "
                                     << lut.at(x, y)[c] / scale << " vs " << ref[c];
            }
        }
    std::printf("[ atmosphere ] multiple-scattering LUT: largest relative error %.2e\n", worst);
}

// Sky-view texels (single scattering, the lit ground) against the view ray marched finely in double, for
// a camera near the ground, just above the top (the sky half's span between Z and αt - β) and in orbit
// (αt - β: only the directions that meet the air).
TEST_F(AtmosphereGpuTest, SkyViewLutMatchesReference) {
    for (double altitude : {100.0, 105e3, 400e3}) {
        postfx::FrameInfo frame = skyFrame(10.0);
        frame.atmosphere.multipleScattering = false;
        // From above the top, rays to the planet's limb cross hundreds of km of air: the paper's 30 steps
        // leave 6.5 % on the sunward limb texel (0, 60) at 105 km, 60 steps 1.7 %. There the test checks
        // the mapping and where the march starts, at 60 steps.
        if (altitude > 1e5) frame.atmosphere.skyViewSteps = 60;
        frame.camera = lookCamera({0.0, altitude, 0.0}, {1.0, 0.05, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        frame.frameIndex = uint64_t(altitude);
        render(frame, images(frame.camera, 8, 4));
        const LutImage lut = readLut("atmosphere.sky_view");
        ASSERT_EQ(lut.width, 192u);
        ASSERT_EQ(lut.height, 108u);
        const double scale = atm::lutStorageScale(frame.atmosphere);
        const atm::Model m = atm::modelFrom(frame.atmosphere);
        const double r = m.groundRadius + altitude;
        const double muS = std::sin(glm::radians(10.0));
        atm::Sun sun;
        sun.toSun = {std::sqrt(1.0 - muS * muS), muS, 0.0};
        atm::ViewRayOptions o;
        o.steps = 2000;
        o.transmittanceSteps = 400;
        o.multipleScattering = false;
        o.ground = true;  // the LUT holds the lit ground where a ray ends on it (rows 54 and below)
        double worst = 0.0;
        for (uint32_t y : {2u, 30u, 50u, 53u, 54u, 60u, 100u})
            for (uint32_t x : {0u, 40u, 120u, 191u}) {
                const glm::dvec2 uv((x + 0.5) / lut.width, (y + 0.5) / lut.height);
                const atm::SkyViewParams p = atm::skyViewParamsFromUv(m, r, uv, {lut.width, lut.height});
                const double sinView = std::sqrt(std::max(0.0, 1.0 - p.cosViewZenith * p.cosViewZenith));
                const double sinAz = std::sqrt(std::max(0.0, 1.0 - p.cosAzimuth * p.cosAzimuth));
                const glm::dvec3 dir(sinView * p.cosAzimuth, p.cosViewZenith, sinView * sinAz);
                const glm::dvec3 ref = atm::integrateViewRay(m, {0.0, r, 0.0}, dir, sun, o).luminance;
                for (int c = 0; c < 3; ++c) {
                    const double rel = std::abs(lut.at(x, y)[c] / scale - ref[c]) / std::max(ref[c], 1e-9);
                    worst = std::max(worst, rel);
                    EXPECT_LT(rel, 0.05) << "at " << altitude << " m, texel " << x << "," << y << " channel "
                                         << c << ": " << lut.at(x, y)[c] / scale << " vs " << ref[c];
                }
            }
        std::printf(
            "[ atmosphere ] sky-view LUT (single scattering) at %.0f m: largest relative error %.2e\n",
            altitude, worst);
    }
}

// Aerial-perspective texels (single scattering) against the view ray through each texel's centre marched
// finely in double to its slice's end (through the planet's sphere, as the LUT's and reference (a)'s).
TEST_F(AtmosphereGpuTest, AerialPerspectiveLutMatchesReference) {
    postfx::FrameInfo frame = skyFrame(15.0);
    frame.atmosphere.multipleScattering = false;
    frame.camera = lookCamera({0.0, 800.0, 0.0}, {1.0, -0.05, 0.3}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
    render(frame, images(frame.camera, 8, 4));
    const LutImage scattering = readLut("atmosphere.aerial_perspective");
    const LutImage transmittance = readLut("atmosphere.aerial_transmittance");
    ASSERT_EQ(scattering.depth, 32u);
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    const double scale = atm::lutStorageScale(frame.atmosphere);
    const glm::dvec3 origin = atm::planetCentred(m, frame.camera.position);
    glm::dmat4 rotation(frame.camera.view);
    rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const glm::dmat4 clipToView = glm::inverse(glm::dmat4(frame.camera.projection) * rotation);
    atm::Sun sun;
    sun.toSun = glm::normalize(glm::dvec3(frame.sun.toSun));
    atm::ViewRayOptions o;
    o.steps = 2000;
    o.transmittanceSteps = 300;
    o.multipleScattering = false;
    o.throughGround = true;
    // The sun's transmittance as reference (a) takes it: below the sphere, the ground's (r clamped).
    const auto table = atm::sharedTransmittanceTable(m);
    o.transmittanceTable = table.get();
    double worstL = 0.0, worstT = 0.0;
    for (uint32_t z : {0u, 3u, 15u, 31u})
        for (uint32_t y : {2u, 16u, 29u})
            for (uint32_t x : {0u, 20u}) {
                const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / 32.0 * 2.0 - 1.0;
                const glm::dvec4 p = clipToView * glm::dvec4(ndc, 0.5, 1.0);
                const glm::dvec3 dir = glm::normalize(glm::dvec3(p) / p.w);
                o.maxDistance = (z + 1) / 32.0 * frame.atmosphere.aerialPerspectiveDistance;
                const atm::ViewRayResult ref = atm::integrateViewRay(m, origin, dir, sun, o);
                for (int c = 0; c < 3; ++c) {
                    const double L = scattering.at(x, y, z)[c] / scale, T = transmittance.at(x, y, z)[c];
                    const double relL = std::abs(L - ref.luminance[c]) / std::max(ref.luminance[c], 1e-9);
                    worstL = std::max(worstL, relL);
                    worstT = std::max(worstT, std::abs(T - ref.transmittance[c]));
                    EXPECT_LT(relL, 0.02) << "texel " << x << "," << y << "," << z << " channel " << c;
                    EXPECT_NEAR(T, ref.transmittance[c], 2e-3) << "texel " << x << "," << y << "," << z;
                }
            }
    std::printf(
        "[ atmosphere ] aerial-perspective LUT (single scattering): largest relative error of L %.2e, "
        "largest |dT| %.2e\n",
        worstL, worstT);
}

// An optically thin pure-Rayleigh sky seen straight up, the sun at zenith angle θs, albedo 0: single
// scattering L = E·p_R(cos θs)·β·H·(1 - e^{-(top - ground)/H}) (T ≈ 1 everywhere; multiple scattering
// is of order β² and the ground, black, adds nothing).
TEST_F(AtmosphereGpuTest, ThinRayleighZenithMatchesSingleScatteringClosedForm) {
    postfx::FrameInfo frame = skyFrame(40.0);
    postfx::AtmosphereSettings& s = frame.atmosphere;
    s.rayleighScattering = postfx::Vec3(1e-9f, 2e-9f, 4e-9f);
    s.mieScattering = s.mieAbsorption = 0.0f;
    s.ozoneAbsorption = postfx::Vec3(0.0f);
    s.groundAlbedo = postfx::Vec3(0.0f);
    frame.sun.illuminance = postfx::Vec3(1e5f);
    frame.camera = lookCamera({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, -1.0}, 10.0f, 1.0f);
    const std::vector<float> out = render(frame, images(frame.camera, 8, 8));
    const double H = s.rayleighScaleHeight, thickness = double(s.topRadius) - s.groundRadius;
    const double cosSun = std::sin(glm::radians(40.0));
    const double phase = 3.0 / (16.0 * glm::pi<double>()) * (1.0 + cosSun * cosSun);
    // The four pixels around the image centre look within 0.7° of the zenith.
    for (int c = 0; c < 3; ++c) {
        const double expected = 1e5 * phase * s.rayleighScattering[c] * H * (1.0 - std::exp(-thickness / H));
        double mean = 0.0;
        for (uint32_t j : {3u, 4u})
            for (uint32_t i : {3u, 4u})
                mean += out[(size_t(j) * 8 + i) * 4 + c] / 4.0;
        EXPECT_NEAR(mean, expected, 0.01 * expected) << "channel " << c;
    }
}

// Reference (a) at 600 steps per pixel, a 32×32 Ψ table of 64 directions.
std::vector<float> referenceImage(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
    return atmosphereReferenceImage(frame, im);
}

// Sky pixels (the sky-view LUT, the planet below the horizon, the apply pass) against the model per pixel,
// for the sun from high to below the horizon.
TEST_F(AtmosphereGpuTest, SkyPixelsMatchReferenceAtSunElevations) {
    for (double elevation : {60.0, 10.0, 2.0, 0.0, -2.0}) {
        postfx::FrameInfo frame = skyFrame(elevation);
        frame.atmosphere.multipleScattering = false;
        frame.atmosphere.sunAngularRadiusDeg = 0.0f;
        frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.1, 0.3}, {0.0, 1.0, 0.0}, 90.0f, 2.0f);
        const FogHarnessImages im = images(frame.camera, 16, 8);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> ref = referenceImage(frame, im);
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-6);
        std::printf("[ atmosphere ] sky, sun at %.0f deg: GPU vs reference %s\n", elevation,
                    stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.03) << "sun elevation " << elevation;
    }
}

// The same with multiple scattering: the LUTs' Ψ (32×32, 64 directions) against the reference's fine
// table, noon and sunset.
TEST_F(AtmosphereGpuTest, SkyWithMultipleScatteringMatchesReference) {
    for (double elevation : {30.0, 2.0}) {
        postfx::FrameInfo frame = skyFrame(elevation);
        frame.atmosphere.sunAngularRadiusDeg = 0.0f;
        frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.1, 0.3}, {0.0, 1.0, 0.0}, 90.0f, 2.0f);
        const FogHarnessImages im = images(frame.camera, 16, 8);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> ref = referenceImage(frame, im);
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-6);
        std::printf("[ atmosphere ] sky with multiple scattering, sun at %.0f deg: GPU vs reference %s\n",
                    elevation, stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.03) << "sun elevation " << elevation;
    }
}

// Geometry pixels: the aerial-perspective LUT over a grey surface at 3 km and 25 km.
TEST_F(AtmosphereGpuTest, AerialPerspectiveMatchesReference) {
    for (double distance : {3000.0, 25000.0}) {
        postfx::FrameInfo frame = skyFrame(20.0);
        frame.atmosphere.multipleScattering = false;
        frame.camera = lookCamera({0.0, 500.0, 0.0}, {1.0, 0.0, 0.5}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        FogHarnessImages im = images(frame.camera, 16, 8, distance);
        std::fill(im.color.begin(), im.color.end(), 0.2f);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> ref = referenceImage(frame, im);
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.02, 1e-3);
        std::printf("[ atmosphere ] aerial perspective at %.0f m: GPU vs reference %s\n", distance,
                    stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.01) << distance << " m";
    }
}

// A flat world's ground plane y = 0 seen from 300 m, out to 60 km (beyond the LUT's 32 km: its last slice):
// far pixels lie below the planet's sphere, whose curvature drops 280 m at 60 km, and still get their
// aerial perspective (the march goes on below the sphere, as the reference's).
TEST_F(AtmosphereGpuTest, AerialPerspectiveOfAFlatGroundPlane) {
    postfx::FrameInfo frame = skyFrame(25.0);
    frame.atmosphere.multipleScattering = false;
    frame.atmosphere.aerialPerspectiveDistance = 64000.0f;
    frame.camera = lookCamera({0.0, 300.0, 0.0}, {1.0, -0.08, 0.3}, {0.0, 1.0, 0.0}, 40.0f, 2.0f);
    FogHarnessImages im = images(frame.camera, 16, 8);
    for (uint32_t j = 0; j < im.height; ++j)
        for (uint32_t i = 0; i < im.width; ++i) {
            const glm::dvec3 d = pixelDirection(frame.camera, i, j, im.width, im.height);
            const double t = d.y < 0.0 ? 300.0 / -d.y : 0.0;
            if (t <= 0.0 || t > 6e4) continue;
            im.depth[size_t(j) * im.width + i] = depthAtDistance(frame.camera, d, t);
            for (int c = 0; c < 3; ++c)
                im.color[(size_t(j) * im.width + i) * 4 + c] = 0.05f;
        }
    const std::vector<float> out = render(frame, im);
    const std::vector<float> ref = referenceImage(frame, im);
    const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.03, 1e-3);
    std::printf("[ atmosphere ] flat ground plane to 60 km: GPU vs reference %s\n", stats.summary().c_str());
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_LT(stats.relativeRmse, 0.02);
}

// The camera rising through the top of the atmosphere, looking at the horizon: the images just below
// and just above the top (where the sky-view LUT's sky half starts to narrow), and either side of 110 % of
// the thickness (where it reaches αt - β), differ by about what moving the camera by that much changes.
TEST_F(AtmosphereGpuTest, CrossingTheTopShowsNoSeam) {
    postfx::FrameInfo frame = skyFrame(15.0);
    const postfx::AtmosphereSettings& s = frame.atmosphere;
    const double thickness = double(s.topRadius) - s.groundRadius;
    auto renderAt = [&](double altitude) {
        frame.camera = lookCamera({0.0, altitude, 0.0}, {1.0, -0.3, 0.2}, {0.0, 1.0, 0.0}, 90.0f, 2.0f);
        frame.frameIndex++;
        return render(frame, images(frame.camera, 24, 12));
    };
    for (double altitude : {thickness, 1.05 * thickness, 1.1 * thickness}) {
        const std::vector<float> below = renderAt(altitude - 10.0), above = renderAt(altitude + 10.0);
        const ImageStats stats = compareImages(above, below, 24, 12, 0.05, 1e-4);
        std::printf("[ atmosphere ] crossing %.0f m: images 20 m apart differ by %s\n", altitude,
                    stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.01) << "at " << altitude << " m";
    }
}

// The fogs lit through the atmosphere: with it on, every fog sample's sun is the illuminance outside the
// atmosphere times the transmittance LUT's T at the sample. Frame: the atmosphere (sky, aerial
// perspective) then the fog, against reference (a) then the fog's reference with the same atmosphere,
// for the sun low (10°, reddened) and the ray-marched and froxel fogs.
TEST_F(AtmosphereGpuTest, FogsLitThroughTheAtmosphereMatchTheirReferences) {
    for (bool froxel : {false, true}) {
        postfx::FrameInfo frame = skyFrame(10.0);
        frame.sun.illuminance = postfx::Vec3(1e4f);
        frame.camera = lookCamera({0.0, 20.0, 0.0}, {1.0, 0.05, 0.4}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        FogHarnessImages im = images(frame.camera, 16, 8, 0.0);
        for (uint32_t j = 0; j < 8; ++j)  // the lower half a wall at 40 m
            for (uint32_t i = 0; j >= 4 && i < 16; ++i) {
                im.depth[j * 16 + i] =
                    depthAtDistance(frame.camera, pixelDirection(frame.camera, i, j, 16, 8), 40.0);
                for (int c = 0; c < 3; ++c)
                    im.color[(j * 16 + i) * 4 + c] = 0.2f;
            }
        postfx::FogMedium medium;
        medium.density = 0.02f;
        medium.heightFalloff = 0.0f;
        medium.anisotropy = 0.3f;
        medium.maxDistance = 60.0f;
        medium.analyticTail = false;
        if (froxel) {
            static_cast<postfx::FogMedium&>(frame.froxelFog) = medium;
            frame.froxelFog.enabled = true;
            frame.froxelFog.grid = {16, 8, 64};
            frame.froxelFog.temporal.enabled = false;
            frame.froxelFog.jitter = false;
        } else {
            static_cast<postfx::FogMedium&>(frame.fog) = medium;
            frame.fog.enabled = true;
            frame.fog.steps = 128;
            frame.fog.jitter = false;
            frame.fog.transmittanceCutoff = 0.0f;
            frame.fog.temporal.enabled = false;
        }
        const std::vector<float> out = render(frame, im);

        FogHarnessImages afterSky = im;
        afterSky.color = referenceImage(frame, im);
        // The fog's reference over reference (a)'s image, its sun through the atmosphere (or not).
        auto fogReference = [&](bool throughAtmosphere, std::vector<float>& result) {
            postfx::AtmosphereSettings atmosphere = frame.atmosphere;
            atmosphere.enabled = throughAtmosphere;
            if (froxel) {
                postfx::reference::FroxelFogInputs in;
                setReferenceImages(in, frame, im, afterSky.color);
                in.settings = frame.froxelFog;
                in.atmosphere = atmosphere;
                return postfx::reference::renderFroxelFog(in, result);
            }
            postfx::reference::FogInputs in;
            setReferenceImages(in, frame, im, afterSky.color);
            in.settings = frame.fog;
            in.atmosphere = atmosphere;
            return postfx::reference::renderFog(in, result);
        };
        std::vector<float> ref, unattenuated;
        const postfx::Status s = fogReference(true, ref);
        ASSERT_TRUE(fogReference(false, unattenuated).ok());
        // The sun 10° up crosses ~5.6 air masses: without the atmosphere's T the fog is far brighter.
        EXPECT_GT(compareImages(out, unattenuated, im.width, im.height, 0.05, 1e-3).relativeRmse, 0.2);
        ASSERT_TRUE(s.ok()) << s.message;
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-3);
        std::printf("[ atmosphere ] %s fog lit through the atmosphere: GPU vs references %s\n",
                    froxel ? "froxel" : "ray-marched", stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, froxel ? 0.03 : 0.01);
    }
}
}  // namespace
}  // namespace test
