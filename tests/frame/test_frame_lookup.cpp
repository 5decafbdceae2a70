// The volumetrics lookup for transparent surfaces (postfx/volumetrics_lookup.h): a host's shader calling
// postfxVolumetrics (<postfx/volumetrics.glsl>, shaders/lookup_probe.comp, at binding numbers of its own)
// at a surface's world position gets what postfx's own composite gave that surface drawn opaque (surface·T
// + L, for the froxel fog, the aerial perspective, the ray-marched fog and the clouds), the closed form
// of a homogeneous fog, no clouds in front of a cloud layer; and a frame that does not ask builds nothing.
#include "fog_harness.h"
#include "lookup_probe.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 48, kHeight = 27;

using Probe = LookupProbe;

class FrameLookupTest : public ReversedZContextTest {
protected:
    // The frame's images: pixel (i, j) sees a surface at distance(i, j) of color color(i, j, c); `points`
    // receives each pixel's surface position in the world.
    FogHarnessImages surfaces(const postfx::FrameInfo& f,
                              const std::function<double(uint32_t, uint32_t)>& distance,
                              std::vector<glm::vec4>& points) const {
        points.clear();
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i)
                points.push_back(
                    glm::vec4(glm::vec3(f.camera.position +
                                        pixelDirection(f.camera, i, j, kWidth, kHeight) * distance(i, j)),
                              0.0f));
        return surfaceImages(f.camera, kWidth, kHeight, distance, [](uint32_t i, uint32_t j, int c) {
            return 20.0f + 5.0f * float((i * 7 + j * 3 + c) % 11);
        });
    }

    postfx::Status run(const postfx::FrameInfo& f, const FogHarnessImages& images,
                       const std::vector<glm::vec4>& points, std::vector<float>& color, Probe& probe) {
        return runLookupProbe(*host, gpu, *context, f, images, points, color, probe);
    }

    // The largest |surface·T + L - postfx's output| relative to the output, over every pixel and channel.
    double worstDifference(const FogHarnessImages& images, const std::vector<float>& color,
                           const Probe& probe, const char* what) const {
        double worst = 0.0, mean = 0.0;
        size_t n = 0, worstPixel = 0;
        for (size_t p = 0; p < probe.L.size(); ++p)
            for (int c = 0; c < 3; ++c) {
                const double lookedUp = double(images.color[p * 4 + c]) * probe.T[p][c] + probe.L[p][c];
                const double own = color[p * 4 + c];
                const double d = std::abs(lookedUp - own) / std::max(std::abs(own), 1e-6);
                if (d > worst) worstPixel = p;
                worst = std::max(worst, d);
                mean += d;
                ++n;
            }
        std::printf(
            "[ lookup ] %s: |surface·T + L - composite| / composite: mean %.3g, worst %.3g (pixel %zu, %zu; "
            "T %.4g, L %.4g)\n",
            what, mean / double(n), worst, worstPixel % kWidth, worstPixel / kWidth, probe.T[worstPixel].x,
            probe.L[worstPixel].x);
        return worst;
    }

    static postfx::FrameInfo baseFrame(double upDegrees) {
        postfx::FrameInfo f;
        const double up = upDegrees * 3.14159265358979 / 180.0;
        f.camera = lookCamera({0.0, 1.5, 0.0}, {0.0, std::sin(up), -std::cos(up)}, {0.0, 1.0, 0.0}, 60.0f,
                              float(kWidth) / kHeight);
        f.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.5f, -0.8f));
        f.sun.illuminance = {2000.0f, 1900.0f, 1700.0f};
        f.ambient = {40.0f, 50.0f, 70.0f};
        return f;
    }
};

// Distances from 2 m (left) to 300 m (right), varying down the image too.
double spread(uint32_t i, uint32_t j) {
    return 2.0 * std::pow(150.0, (double(i) + 0.5) / kWidth) * (1.0 + 0.3 * double(j) / kHeight);
}

TEST_F(FrameLookupTest, FroxelFogMatchesItsCompositeWithin1Percent) {
    postfx::FrameInfo f = baseFrame(5.0);
    f.froxelFog.enabled = true;
    f.froxelFog.density = 0.02f;
    f.froxelFog.heightFalloff = 0.05f;
    f.froxelFog.maxDistance = 120.0f;  // the farther surfaces: the analytic tail
    f.froxelFog.noise.enabled = false;
    // The lookup's columns are the froxel grid's; its slices its own.
    f.volumetricsLookup.extent = {f.froxelFog.grid.x, f.froxelFog.grid.y, 128};
    f.volumetricsLookup.nearDistance = 0.5f;
    f.volumetricsLookup.maxDistance = 2000.0f;
    std::vector<glm::vec4> points;
    const FogHarnessImages images = surfaces(f, spread, points);
    std::vector<float> color;
    Probe probe;
    const postfx::Status s = run(f, images, points, color, probe);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_LT(worstDifference(images, color, probe, "froxel fog"), 0.01);
}

// The default lookup (1 m to 10 km in 64 slices) for surfaces from 100 m to 10 km: within 1%. To 40 km,
// past the aerial-perspective LUT's depth (32 km, beyond which the apply pass holds L and T at the LUT's
// last slice): the lookup's slice across that kink interpolates over it, 1.6% at 128 slices to 100 km
// (0.36% at 512), within 2%.
TEST_F(FrameLookupTest, AerialPerspectiveMatchesItsCompositeWithin1Percent) {
    postfx::FrameInfo f = baseFrame(3.0);
    f.sun.illuminance = {1e5f, 1e5f, 1e5f};
    f.preExposure = 1e-3f;
    f.atmosphere.enabled = true;
    smallScatteringOrders(f.atmosphere);
    for (const double farthest : {10000.0, 40000.0}) {
        if (farthest > 10000.0) {
            f.volumetricsLookup.extent.z = 128;
            f.volumetricsLookup.maxDistance = 100000.0f;
        }
        std::vector<glm::vec4> points;
        const FogHarnessImages images = surfaces(
            f,
            [&](uint32_t i, uint32_t j) {
                return 100.0 * std::pow(farthest / 100.0, (double(i) + 0.5) / kWidth) *
                       (1.0 - 0.2 * j / kHeight);
            },
            points);
        std::vector<float> color;
        Probe probe;
        const postfx::Status s = run(f, images, points, color, probe);
        ASSERT_TRUE(s.ok()) << s.message;
        const std::string what = "aerial perspective to " + std::to_string(int(farthest / 1000.0)) + " km";
        EXPECT_LT(worstDifference(images, color, probe, what.c_str()), farthest > 10000.0 ? 0.02 : 0.01);
    }
}

TEST_F(FrameLookupTest, RayMarchedFogMatchesItsCompositeWithin2Percent) {
    postfx::FrameInfo f = baseFrame(5.0);
    f.fog.enabled = true;
    f.fog.density = 0.02f;
    f.fog.heightFalloff = 0.05f;
    f.fog.maxDistance = 150.0f;
    f.fog.noise.enabled = false;
    // Against the march's integral: many steps, no jitter (whose noise is the march's, not the lookup's).
    f.fog.quality = postfx::FogQuality::Custom;
    f.fog.steps = 512;
    f.fog.jitter = false;
    // The default lookup: 160 × 90 × 64 from 1 m to 10 km.
    std::vector<glm::vec4> points;
    const FogHarnessImages images = surfaces(f, spread, points);
    std::vector<float> color;
    Probe probe;
    const postfx::Status s = run(f, images, points, color, probe);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_LT(worstDifference(images, color, probe, "ray-marched fog, 160x90x64"), 0.02);
}

// A homogeneous fog lit by the ambient alone: L = albedo·ambient·(1 - e^{-σd}), T = e^{-σd} at distance d.
TEST_F(FrameLookupTest, HomogeneousFogMatchesTheClosedForm) {
    for (const bool froxel : {false, true}) {
        postfx::FrameInfo f = baseFrame(0.0);
        f.sun.illuminance = {0.0f, 0.0f, 0.0f};
        const float sigma = 0.01f;
        const glm::vec3 albedo{0.9f, 0.8f, 0.7f};
        (froxel ? f.froxelFog.enabled : f.fog.enabled) = true;
        // The medium both fogs share (FogMedium), set once.
        postfx::FogMedium& medium = froxel ? static_cast<postfx::FogMedium&>(f.froxelFog) : f.fog;
        medium.density = sigma;
        medium.heightFalloff = 0.0f;
        medium.albedo = albedo;
        medium.maxDistance = 500.0f;
        medium.noise.enabled = false;
        std::vector<glm::vec4> points;
        const double d = 80.0;
        const FogHarnessImages images = surfaces(
            f, [&](uint32_t, uint32_t) { return d; }, points);
        std::vector<float> color;
        Probe probe;
        const postfx::Status s = run(f, images, points, color, probe);
        ASSERT_TRUE(s.ok()) << s.message;
        double worst = 0.0;
        for (size_t p = 0; p < points.size(); ++p) {
            const double T = std::exp(-double(sigma) * d);
            for (int c = 0; c < 3; ++c) {
                const double L = double(albedo[c]) * f.ambient[c] * (1.0 - T);
                worst = std::max({worst, std::abs(probe.T[p][c] - T) / T, std::abs(probe.L[p][c] - L) / L});
            }
        }
        std::printf("[ lookup ] %s, homogeneous, d = %.0f m: worst relative error %.3g\n",
                    froxel ? "froxel fog" : "ray-marched fog", d, worst);
        EXPECT_LT(worst, 0.01);
    }
}

// Looking up at a cloud layer 300–600 m above: a surface at 100 m has no cloud in front of it; one 5 km
// away, beyond the layer, has postfx's clouds over it.
TEST_F(FrameLookupTest, CloudsOnlyInFrontOfTheirLayer) {
    postfx::FrameInfo f = baseFrame(40.0);
    f.clouds.enabled = true;
    f.clouds.bottomHeight = 300.0f;
    f.clouds.topHeight = 600.0f;
    f.clouds.coverage = 0.7f;
    f.clouds.density = 0.01f;
    f.clouds.noise.enabled = false;
    f.clouds.castShadows = false;
    for (const double d : {100.0, 5000.0}) {
        std::vector<glm::vec4> points;
        const FogHarnessImages images = surfaces(
            f, [&](uint32_t, uint32_t) { return d; }, points);
        std::vector<float> color;
        Probe probe;
        const postfx::Status s = run(f, images, points, color, probe);
        ASSERT_TRUE(s.ok()) << s.message;
        if (d < 300.0) {
            double largest = 0.0;
            for (size_t p = 0; p < points.size(); ++p)
                for (int c = 0; c < 3; ++c)
                    largest = std::max({largest, 1.0 - double(probe.T[p][c]), double(probe.L[p][c])});
            // What the march met before the surface (the layer's thin lower edge), as postfx's own composite.
            std::printf("[ lookup ] clouds, surface at %.0f m: largest 1 - T or L %.3g\n", d, largest);
            EXPECT_LT(largest, 1e-3);
            EXPECT_LT(worstDifference(images, color, probe, "clouds, surface at 100 m"), 1e-3);
        } else {
            double lowest = 1.0;
            for (const glm::vec3& t : probe.T)
                lowest = std::min(lowest, double(t.x));
            EXPECT_LT(lowest, 0.5);  // the layer is in front
            EXPECT_LT(worstDifference(images, color, probe, "clouds, surface at 5 km"), 0.02);
        }
    }
}

// All off: postfx.lookup_clear gives (L, T) = (0, 1); not asked: no pass, no resource, and the API
// refuses to hand out what was not built.
TEST_F(FrameLookupTest, BuildsNothingUnlessAsked) {
    postfx::FrameInfo f = baseFrame(0.0);
    f.fog.density = 0.02f;
    std::vector<glm::vec4> points;
    const FogHarnessImages images = surfaces(
        f, [](uint32_t, uint32_t) { return 50.0; }, points);
    std::vector<float> color;
    Probe probe;
    postfx::Status s = run(f, images, points, color, probe);
    ASSERT_TRUE(s.ok()) << s.message;
    for (size_t p = 0; p < points.size(); ++p) {
        EXPECT_EQ(probe.L[p], glm::vec3(0.0f));
        EXPECT_EQ(probe.T[p], glm::vec3(1.0f));
    }
    f.volumetricsLookup.enabled = true;
    const postfx::FramePlan cleared = planAndRecord(*host, gpu, *context, images, f);
    EXPECT_EQ(passNames(cleared), std::vector<std::string>{"postfx.lookup_clear"});

    f.fog.enabled = true;
    const postfx::FramePlan asked = planAndRecord(*host, gpu, *context, images, f);
    EXPECT_EQ(passNames(asked), (std::vector<std::string>{"fog.lookup", "fog.raymarch"}));
    std::vector<std::string> held;
    for (const postfx::PlannedResource& r : asked.resources)
        held.push_back(r.name);
    EXPECT_NE(std::find(held.begin(), held.end(), "postfx.lookup_scattering"), held.end());
    postfx::VolumetricsLookup lookup;
    EXPECT_TRUE(context->volumetricsLookup(lookup).ok());
    EXPECT_EQ(lookup.extent.depth, 64u);

    f.volumetricsLookup.enabled = false;
    const postfx::FramePlan notAsked = planAndRecord(*host, gpu, *context, images, f);
    EXPECT_EQ(passNames(notAsked), std::vector<std::string>{"fog.raymarch"});
    for (const postfx::PlannedResource& r : notAsked.resources)
        EXPECT_EQ(r.name.find("lookup"), std::string::npos) << r.name;
    s = context->volumetricsLookup(lookup);
    EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
    EXPECT_NE(s.message.find("FrameInfo.volumetricsLookup.enabled"), std::string::npos) << s.message;
}

TEST_F(FrameLookupTest, RefusesSettingsOutsideTheirRanges) {
    postfx::FrameInfo f = baseFrame(0.0);
    std::vector<glm::vec4> points;
    const FogHarnessImages images = surfaces(
        f, [](uint32_t, uint32_t) { return 50.0; }, points);
    const auto refused = [&](const postfx::VolumetricsLookupSettings& settings, const char* field) {
        postfx::FrameInfo g = f;
        g.volumetricsLookup = settings;
        std::vector<float> color;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, images, g, color);
        EXPECT_EQ(s.code, postfx::Result::InvalidArgument) << field;
        EXPECT_NE(s.message.find(field), std::string::npos) << s.message;
    };
    postfx::VolumetricsLookupSettings s;
    s.enabled = true;
    s.extent = {0, 90, 64};
    refused(s, "volumetricsLookup.extent.x");
    s.extent = {160, 90, 1};
    refused(s, "volumetricsLookup.extent.z");
    s.extent = {1024, 1024, 512};
    refused(s, "volumetricsLookup.extent");
    s.extent = {160, 90, 64};
    s.nearDistance = 0.0f;
    refused(s, "volumetricsLookup.nearDistance");
    s.nearDistance = 10.0f;
    s.maxDistance = 5.0f;
    refused(s, "volumetricsLookup.maxDistance");
}

}  // namespace
