// The atmosphere on the device (docs/effects/atmosphere.md, "Tests"): each LUT read back at chosen
// texels against the double-precision model marched finely, closed forms (pure-Rayleigh zenith
// transmittance, an optically thin Rayleigh sky at the zenith), sky and geometry pixels against the
// model per pixel, and the camera crossing the atmosphere's top. Small images on lavapipe.
#include "atmosphere/atmosphere_effect.h"
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_path_tracer.h"
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

#include <algorithm>
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

    // The atmosphere at its defaults but for the small scattering-orders table (smallScatteringOrders),
    // unless `defaultTables`.
    postfx::FrameInfo skyFrame(double sunElevationDeg, bool defaultTables = false) const {
        postfx::FrameInfo frame;
        frame.atmosphere.enabled = true;
        if (!defaultTables) smallScatteringOrders(frame.atmosphere);
        const double e = glm::radians(sunElevationDeg);
        frame.sun.toSun = glm::vec3(float(std::cos(e)), float(std::sin(e)), 0.0f);
        frame.sun.illuminance = glm::vec3(1.0f);
        frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.05, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        return frame;
    }

    void tableViewsAtDefaultSettings(postfx::AtmosphereMultipleScattering model);
};

// The transmittance LUT as its readers sample it (bilinear at transmittanceUvFromParams) against exp(-τ)
// marched with 4096 steps in double, from the ground, 1 km and 10 km, at zenith angles from 0 to the
// horizon (95° from 10 km): within 0.5 % wherever T > 1e-4 (the default size and steps).
TEST_F(AtmosphereGpuTest, TransmittanceLookupsWithinHalfAPercentToTheHorizon) {
    postfx::FrameInfo frame = skyFrame(30.0);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.transmittance");
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    const auto texel = [&](int x, int y) {
        x = std::clamp(x, 0, int(lut.width) - 1);
        y = std::clamp(y, 0, int(lut.height) - 1);
        return glm::dvec3(lut.at(uint32_t(x), uint32_t(y)));
    };
    double worst = 0.0;
    for (const double altitude : {0.0, 1000.0, 10000.0})
        for (double zenith = 0.0; zenith <= 95.0; zenith += 0.5) {
            const double r = m.groundRadius + altitude, mu = std::cos(glm::radians(zenith));
            if (atm::rayIntersectsGround(m, r, mu)) continue;
            const glm::dvec2 uv = atm::transmittanceUvFromParams(m, r, mu, {lut.width, lut.height});
            const glm::dvec2 f = uv * glm::dvec2(lut.width, lut.height) - 0.5;
            const glm::ivec2 i0(glm::floor(f));
            const glm::dvec2 a = f - glm::dvec2(i0);
            const glm::dvec3 lookup =
                glm::mix(glm::mix(texel(i0.x, i0.y), texel(i0.x + 1, i0.y), a.x),
                         glm::mix(texel(i0.x, i0.y + 1), texel(i0.x + 1, i0.y + 1), a.x), a.y);
            const glm::dvec3 dir(std::sqrt(std::max(0.0, 1.0 - mu * mu)), mu, 0.0);
            const glm::dvec3 ref = atm::transmittanceToEdge(m, {0.0, r, 0.0}, dir, 4096);
            for (int c = 0; c < 3; ++c) {
                if (ref[c] < 1e-4) continue;
                const double rel = std::abs(lookup[c] / ref[c] - 1.0);
                worst = std::max(worst, rel);
                EXPECT_LT(rel, 0.005) << altitude << " m, zenith " << zenith << "°, channel " << c;
            }
        }
    std::printf("[ atmosphere ] transmittance lookups, zenith 0-95 deg: largest relative error %.2e\n",
                worst);
}

// Transmittance texels against exp(-τ) of their (r, μ) marched with 4096 steps in double: the LUT's
// midpoint steps and its half-float storage.
TEST_F(AtmosphereGpuTest, TransmittanceLutMatchesReference) {
    postfx::FrameInfo frame = skyFrame(30.0);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.transmittance");
    ASSERT_EQ(lut.width, 512u);
    ASSERT_EQ(lut.height, 128u);
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    double worst = 0.0;
    for (uint32_t y : {0u, 14u, 62u, 127u})
        for (uint32_t x : {0u, 100u, 256u, 400u, 500u, 509u}) {
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
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
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

// Scattering-orders LUT texels (a small LUT) against the CPU table of the same nodes, directions, steps and
// orders in double (atmosphere_orders.h): what the GPU adds is float arithmetic, the transmittance LUT
// and half floats. Each node: ΨR and ΨM per channel, and the ground's E≥2.
TEST_F(AtmosphereGpuTest, ScatteringOrdersLutMatchesReference) {
    postfx::FrameInfo frame = skyFrame(30.0);
    render(frame, images(frame.camera, 8, 4));
    const LutImage lut = readLut("atmosphere.multiple_scattering");
    const postfx::UVec3 n = frame.atmosphere.scatteringOrdersLutSize;
    const uint32_t azimuths = frame.atmosphere.scatteringOrdersAzimuthSize;
    ASSERT_EQ(lut.width, n.x * azimuths);
    ASSERT_EQ(lut.depth, 2 * n.z + 1);
    const double scale = atm::ordersStorageScale(frame.atmosphere);
    const atm::Model m = atm::modelFrom(frame.atmosphere);
    atm::OrdersTableOptions o;
    o.viewSize = n.x;
    o.sunSize = n.y;
    o.radiusSize = n.z;
    o.azimuthSize = azimuths;
    o.directions = frame.atmosphere.scatteringOrdersDirections;
    o.steps = frame.atmosphere.scatteringOrdersSteps;
    o.orders = frame.atmosphere.scatteringOrders;
    const atm::OrdersTable table(m, *atm::sharedTransmittanceTable(m), o);
    const auto cosine = [](uint32_t i, uint32_t size) {
        const double u = 2.0 * i / (size - 1) - 1.0;
        return u * std::abs(u);
    };
    // Relative errors against the largest value of the channel (Ψ spans decades; the sky is their sum).
    glm::dvec3 largest(0.0);
    for (uint32_t z = 0; z < 2 * n.z; ++z)
        for (uint32_t y = 0; y < n.y; ++y)
            for (uint32_t x = 0; x < lut.width; ++x)
                largest = glm::max(largest, glm::dvec3(lut.at(x, y, z)) / scale);
    double worst = 0.0, worstGround = 0.0;
    for (uint32_t h = 0; h < n.z; ++h)
        for (uint32_t s = 0; s < n.y; ++s)
            for (uint32_t v = 0; v < n.x; ++v)
                for (uint32_t a = 0; a < azimuths; ++a) {
                    const double y = double(h) / (n.z - 1);
                    const double r = m.groundRadius + y * y * (m.topRadius - m.groundRadius);
                    const double phi = M_PI * a / (azimuths - 1);
                    const atm::OrdersTable::Psi cpu =
                        table.at(r, cosine(v, n.x), cosine(s, n.y), std::cos(phi));
                    const glm::dvec3 gpuR = glm::dvec3(lut.at(v + n.x * a, s, h)) / scale;
                    const glm::dvec3 gpuM = glm::dvec3(lut.at(v + n.x * a, s, h + n.z)) / scale;
                    for (int c = 0; c < 3; ++c) {
                        const double errR = std::abs(gpuR[c] - cpu.rayleigh[c]) /
                                            std::max(std::abs(cpu.rayleigh[c]), 0.01 * largest[c]);
                        const double errM = std::abs(gpuM[c] - cpu.mie[c]) /
                                            std::max(std::abs(cpu.mie[c]), 0.01 * largest[c]);
                        worst = std::max({worst, errR, errM});
                    }
                }
    for (uint32_t s = 0; s < n.y; ++s) {
        const glm::dvec3 cpu = table.groundIrradiance(cosine(s, n.y));
        const glm::dvec3 gpu = glm::dvec3(lut.at(0, s, 2 * n.z)) / scale;
        for (int c = 0; c < 3; ++c)
            worstGround = std::max(worstGround, std::abs(gpu[c] - cpu[c]) /
                                                    std::max(cpu[c], 1e-3 * table.groundIrradiance(1.0)[c]));
    }
    std::printf("[ atmosphere ] scattering-orders LUT: largest relative error %.2e (the ground's E %.2e)\n",
                worst, worstGround);
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(worstGround, 0.02);
}

// Sky-view texels (single scattering, the lit ground) against the view ray marched finely in double, for
// a camera near the ground, just above the top (the sky half's span between Z and αt - β) and in orbit
// (αt - β: only the directions that meet the air).
TEST_F(AtmosphereGpuTest, SkyViewLutMatchesReference) {
    for (double altitude : {100.0, 105e3, 400e3}) {
        postfx::FrameInfo frame = skyFrame(10.0);
        frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
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
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
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
        frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
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

// The same with multiple scattering, each model: Hillaire's LUT Ψ (32×32, 64 directions) and a small
// scattering-orders LUT against the reference's tables, noon and sunset.
TEST_F(AtmosphereGpuTest, SkyWithMultipleScatteringMatchesReference) {
    for (const auto model :
         {postfx::AtmosphereMultipleScattering::Hillaire, postfx::AtmosphereMultipleScattering::Orders})
        for (double elevation : {30.0, 2.0}) {
            postfx::FrameInfo frame = skyFrame(elevation);
            frame.atmosphere.multipleScattering = model;
            frame.atmosphere.sunAngularRadiusDeg = 0.0f;
            frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.1, 0.3}, {0.0, 1.0, 0.0}, 90.0f, 2.0f);
            const FogHarnessImages im = images(frame.camera, 16, 8);
            const std::vector<float> out = render(frame, im);
            const std::vector<float> ref = referenceImage(frame, im);
            const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-6);
            std::printf(
                "[ atmosphere ] sky with multiple scattering (%s), sun at %.0f deg: GPU vs reference %s\n",
                model == postfx::AtmosphereMultipleScattering::Orders ? "orders" : "hillaire", elevation,
                stats.summary().c_str());
            EXPECT_EQ(stats.nonFinite, 0u);
            EXPECT_LT(stats.relativeRmse, 0.03) << "sun elevation " << elevation;
        }
}

// The planet's ground of albedo 0.3 seen from 10 km, 30° down (the sky-view LUT's ground half: the sun's
// light and, with the scattering orders, the sky's E≥2 on it, seen through the air), against the reference,
// sun high and low.
TEST_F(AtmosphereGpuTest, GroundSeenFromTenKilometresMatchesReference) {
    for (double elevation : {40.0, 5.0}) {
        postfx::FrameInfo frame = skyFrame(elevation);
        frame.atmosphere.sunAngularRadiusDeg = 0.0f;
        frame.camera = lookCamera({0.0, 10000.0, 0.0}, {1.0, -0.6, 0.3}, {0.0, 1.0, 0.0}, 40.0f, 2.0f);
        const FogHarnessImages im = images(frame.camera, 16, 8);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> ref = referenceImage(frame, im);
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-6);
        std::printf("[ atmosphere ] ground from 10 km, sun at %.0f deg: GPU vs reference %s\n", elevation,
                    stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.01) << "sun elevation " << elevation;
    }
}

// The views of the path-traced table (tests/atmosphere/data: the camera on the ground, at 1 km, 10 km,
// 100 km and 400 km; the sun 60°, 10°, 2° and −2° up; view zenith 0–120°, azimuth toward, across and away
// from the sun) on the GPU at the default settings (Earth, albedo 0.3, every LUT's default size) against the
// reference at its default quality, each view the centre pixel of a 3×3 image of 0.5°: the orders' within
// the bounds below; Hillaire's model only printed (its discretisation error, docs/effects/atmosphere.md).
void AtmosphereGpuTest::tableViewsAtDefaultSettings(postfx::AtmosphereMultipleScattering model) {
    using Model = postfx::AtmosphereMultipleScattering;
    const char* name = model == Model::Orders ? "orders" : "hillaire";
    double worst = 0.0;
    std::string worstView;
    for (const double altitude : {0.0, 1000.0, 10000.0, 100000.0, 400000.0}) {
        std::string row;
        for (const double sunElevation : {60.0, 10.0, 2.0, -2.0}) {
            double worstHere = 0.0;
            for (const double zenith : {0.0, 45.0, 80.0, 85.0, 89.0, 95.0, 120.0})
                for (const double azimuth : {0.0, 90.0, 180.0}) {
                    if (zenith == 0.0 && azimuth != 0.0) continue;
                    postfx::FrameInfo frame = skyFrame(sunElevation, true);
                    frame.atmosphere.multipleScattering = model;
                    frame.atmosphere.sunAngularRadiusDeg = 0.0f;
                    const atm::ViewSunRay ray =
                        atm::viewSunRay(atm::Model{}, {zenith, sunElevation, azimuth, altitude});
                    frame.sun.toSun = glm::vec3(ray.toSun);
                    const glm::dvec3 up =
                        zenith == 0.0 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
                    frame.camera = lookCamera({0.0, altitude, 0.0}, ray.dir, up, 0.5f, 1.0f);
                    const FogHarnessImages im = images(frame.camera, 3, 3);
                    const std::vector<float> out = render(frame, im);
                    // The reference's own default tables for the orders; for Hillaire's Ψ the GPU's own
                    // directions (its error here is the sky view's and the transmittance's).
                    AtmosphereReferenceQuality quality;
                    quality.ordersView = 0;
                    const std::vector<float> ref = atmosphereReferenceImage(frame, im, quality);
                    for (int c = 0; c < 3; ++c) {
                        const double g = out[4 * 4 + c], r = ref[4 * 4 + c];
                        ASSERT_TRUE(std::isfinite(g));
                        if (r <= 0.0) continue;
                        const double rel = std::abs(g / r - 1.0);
                        worstHere = std::max(worstHere, rel);
                        if (rel > worst) {
                            worst = rel;
                            worstView = std::to_string(int(altitude)) + " m, sun " +
                                        std::to_string(int(sunElevation)) + ", zenith " +
                                        std::to_string(int(zenith)) + ", azimuth " +
                                        std::to_string(int(azimuth)) + ", channel " + std::to_string(c);
                        }
                        // The GPU's default LUTs against the reference as measured
                        // (docs/effects/atmosphere.md, "Against the light"; not yet the 1 % wanted): 2 %
                        // with the sun up and the camera in the air, 3.5 % in twilight, 7 % from orbit at
                        // a low sun; a camera exactly on the top boundary (100 km) is printed only (the
                        // sky view's mapping degenerates there, 17 % with either model).
                        const double bound = altitude > 100000.0 ? 0.07 : sunElevation < 0.0 ? 0.035 : 0.02;
                        if (model == Model::Orders && altitude != 100000.0) {
                            EXPECT_LT(rel, bound)
                                << altitude << " m, sun " << sunElevation << "°, zenith " << zenith
                                << "°, azimuth " << azimuth << "°, channel " << c << ": " << g << " vs " << r;
                        }
                    }
                }
            char cell[32];
            std::snprintf(cell, sizeof cell, " %5.2f %%", 100.0 * worstHere);
            row += cell;
        }
        std::printf(
            "[ atmosphere ] %s, table views at %6.0f m, sun 60 / 10 / 2 / -2 deg: largest GPU vs "
            "reference%s\n",
            name, altitude, row.c_str());
    }
    std::printf("[ atmosphere ] %s, table views: largest GPU vs reference %.2f %% (%s)\n", name,
                100.0 * worst, worstView.c_str());
}

TEST_F(AtmosphereGpuTest, TableViewsAtDefaultSettingsMatchTheReference) {
    tableViewsAtDefaultSettings(postfx::AtmosphereMultipleScattering::Orders);
}

// Hillaire's model on the same views: it asserts nothing (the model is kept for comparison), so it runs
// by hand: gpu_tests --gtest_also_run_disabled_tests --gtest_filter='*HillaireTableViews*'.
TEST_F(AtmosphereGpuTest, DISABLED_HillaireTableViewsPrintTheirError) {
    tableViewsAtDefaultSettings(postfx::AtmosphereMultipleScattering::Hillaire);
}

// A sunset: the sun from 10° to 4° below the horizon in 0.5° steps, the view LUTs rebuilt each frame and
// the scattering orders' LUT kept. No NaN, and no pixel changes between two frames by more than the
// reference changes it for the same two suns (the sun's own change) plus 4 % of the frame's brightest
// (measured 2.9 %, near the horizon toward the sun just after it sets: the sky view's 30 steps sample where
// the planet's shadow begins; the reference's 600 do it finely).
TEST_F(AtmosphereGpuTest, SunsetSequenceChangesOnlyAsTheSunDoes) {
    postfx::FrameInfo frame = skyFrame(10.0);
    frame.atmosphere.sunAngularRadiusDeg = 0.0f;
    frame.camera = lookCamera({0.0, 100.0, 0.0}, {1.0, 0.15, 0.4}, {0.0, 1.0, 0.0}, 90.0f, 2.0f);
    const FogHarnessImages im = images(frame.camera, 16, 8);
    std::vector<float> lastOut, lastRef;
    double worst = 0.0;
    for (double elevation = 10.0; elevation >= -4.0; elevation -= 0.5) {
        const double e = glm::radians(elevation);
        frame.sun.toSun = glm::vec3(float(std::cos(e)), float(std::sin(e)), 0.0f);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> ref = referenceImage(frame, im);
        float peak = 0.0f;
        for (size_t i = 0; i < out.size(); ++i) {
            ASSERT_TRUE(std::isfinite(out[i])) << "sun " << elevation << "°, value " << i;
            if (i % 4 != 3) peak = std::max(peak, ref[i]);
        }
        if (!lastOut.empty())
            for (size_t i = 0; i < out.size(); ++i) {
                if (i % 4 == 3) continue;
                const double jump = std::abs(out[i] - lastOut[i]), own = std::abs(ref[i] - lastRef[i]);
                worst = std::max(worst, (jump - own) / peak);
                EXPECT_LE(jump, own + 0.04 * peak) << "sun " << elevation << "°, value " << i;
            }
        lastOut = out;
        lastRef = ref;
    }
    std::printf(
        "[ atmosphere ] sunset 10 to -4 deg: largest frame-to-frame change beyond the reference's %.2e "
        "of the frame's peak\n",
        worst);
}

// Geometry pixels: the aerial-perspective LUT over a grey surface at 3 km and 25 km.
TEST_F(AtmosphereGpuTest, AerialPerspectiveMatchesReference) {
    for (double distance : {3000.0, 25000.0}) {
        postfx::FrameInfo frame = skyFrame(20.0);
        frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
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
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
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
