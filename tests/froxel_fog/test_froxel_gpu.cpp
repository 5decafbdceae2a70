// The froxel fog on the device against closed forms, a 1D integral computed here in double and the CPU
// reference (docs/effects/froxel-fog.md, "Tests"): small images on lavapipe, a grid of one froxel per
// pixel where the test isolates the depth slices' error.
#include "froxel_case.h"
#include "image_compare.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace test {
namespace {

double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// ∫a^b f by adaptive Simpson to relative `eps`.
double simpson(const std::function<double(double)>& f, double a, double b, double eps, int depth = 40) {
    const double m = 0.5 * (a + b), fa = f(a), fb = f(b), fm = f(m);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    std::function<double(double, double, double, double, double, double, int)> step =
        [&](double a0, double b0, double fa0, double fb0, double fm0, double s, int d) {
            const double m0 = 0.5 * (a0 + b0), lm = 0.5 * (a0 + m0), rm = 0.5 * (m0 + b0);
            const double flm = f(lm), frm = f(rm);
            const double left = (m0 - a0) / 6.0 * (fa0 + 4.0 * flm + fm0);
            const double right = (b0 - m0) / 6.0 * (fm0 + 4.0 * frm + fb0);
            if (d <= 0 || std::abs(left + right - s) <= 15.0 * eps * std::abs(left + right))
                return left + right + (left + right - s) / 15.0;
            return step(a0, m0, fa0, fm0, flm, left, d - 1) + step(m0, b0, fm0, fb0, frm, right, d - 1);
        };
    return step(a, b, fa, fb, fm, whole, depth);
}

class FroxelFogGpuTest : public FroxelGpuFixture {
protected:
    // GPU against the reference: relative RMSE over the image, printed, below `maxRmse`.
    void expectNearReference(const FroxelCase& c, double maxRmse, const char* what) {
        const std::vector<float> gpuImage = render(c);
        std::vector<float> reference;
        const postfx::Status s = c.reference(reference);
        ASSERT_TRUE(s.ok()) << s.message;
        const ImageStats stats =
            compareImages(gpuImage, reference, c.images.width, c.images.height, 0.05, 1e-3);
        std::printf("[ froxel_fog ] %s: GPU vs reference %s\n", what, stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, maxRmse) << what;
    }
};

// Homogeneous medium lit by the sun and ambient light, no shadow: out = color·e^{-σD} + albedo·(E·p(θ) +
// ambient)·(1 - e^{-σD}), D = min(surface, max distance), at every pixel (one froxel per pixel).
TEST_F(FroxelFogGpuTest, HomogeneousSunLitMatchesClosedForm) {
    FroxelCase c = froxelCase(24, 16, 1.5, 12, 12.0);
    c.frame.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
    c.frame.ambient = {10.0f, 20.0f, 30.0f};
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.albedo = {0.9f, 0.5f, 0.7f};
    s.anisotropy = 0.7f;
    s.maxDistance = 30.0f;
    const std::vector<float> out = render(c);
    const uint32_t w = c.images.width, h = c.images.height;
    double worst = 0.0;
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const size_t p = size_t(j) * w + i;
            const glm::dvec3 d = pixelDirection(c.frame.camera, i, j, w, h);
            const double D = i < 12 ? 12.0 : s.maxDistance;
            const double T = std::exp(-double(s.density) * D);
            const double phase = hg(glm::dot(d, glm::dvec3(glm::normalize(c.frame.sun.toSun))), s.anisotropy);
            for (int ch = 0; ch < 3; ++ch) {
                const double light =
                    double(c.frame.sun.illuminance[ch]) * phase + double(c.frame.ambient[ch]);
                const double expected =
                    c.images.color[p * 4 + ch] * T + double(s.albedo[ch]) * light * (1.0 - T);
                const double relative = std::abs(out[p * 4 + ch] - expected) / expected;
                worst = std::max(worst, relative);
                ASSERT_LT(relative, 4e-3) << "pixel " << i << "," << j << " channel " << ch << ": GPU "
                                          << out[p * 4 + ch] << ", closed form " << expected;
            }
            ASSERT_EQ(out[p * 4 + 3], c.images.color[p * 4 + 3]);  // alpha untouched
        }
    std::printf("[ froxel_fog ] homogeneous sun-lit: worst relative error %.3g\n", worst);
}

// One unshadowed point light 1 m beside the centre pixel's ray in thin isotropic fog, nothing else lit:
// the pixel's in-scattered light is ∫0^D σs·E(x(t))·p·e^{-σt} dt, integrated here in double.
TEST_F(FroxelFogGpuTest, PointLightBesideRayMatches1DIntegral) {
    FroxelCase c = froxelCase(9, 9, 0.0, 0, 0.0);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.density = 0.01f;
    s.albedo = glm::vec3(1.0f);
    s.maxDistance = 20.0f;
    s.depthExponent = 1.0f;  // uniform slices, 20/256 m each
    s.grid = {9, 9, 256};
    const glm::dvec3 ray = pixelDirection(c.frame.camera, 4, 4, 9, 9);
    const glm::dvec3 side = glm::normalize(glm::cross(ray, glm::dvec3(0.0, 1.0, 0.0)));
    postfx::LocalLight light;
    light.position = postfx::DVec3(ray * 8.0 + side);
    light.intensity = {200.0f, 100.0f, 50.0f};
    light.range = 30.0f;
    light.sourceRadius = 0.05f;
    c.lights = {light};
    const std::vector<float> out = render(c);
    const double sigma = s.density, D = s.maxDistance, R = light.range, r = light.sourceRadius;
    const double T = std::exp(-sigma * D);
    for (int ch = 0; ch < 3; ++ch) {
        const double I = light.intensity[ch];
        const double L = simpson(
            [&](double t) {
                const double d = glm::length(ray * t - glm::dvec3(light.position));
                const double q = d / R, window = (1 - q * q * q * q) * (1 - q * q * q * q);
                return sigma * I * window / (d * d + r * r) / (4.0 * glm::pi<double>()) *
                       std::exp(-sigma * t);
            },
            0.0, D, 1e-10);
        const size_t p = 4 * 9 + 4;
        const double expected = c.images.color[p * 4 + ch] * T + L;
        std::printf("[ froxel_fog ] point light channel %d: GPU %.6g, integral %.6g (L %.6g)\n", ch,
                    out[p * 4 + ch], expected, L);
        EXPECT_NEAR(out[p * 4 + ch], expected, 5e-3 * expected);
    }
}

// A spot light pointing down through the view: lit where the rays cross its cone, dark beside it, and the
// whole image near the reference.
TEST_F(FroxelFogGpuTest, SpotConeMatchesReference) {
    FroxelCase c = froxelCase(32, 24, 1.0, 0, 0.0);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.density = 0.03f;
    s.maxDistance = 30.0f;
    s.grid = {32, 24, 128};
    postfx::LocalLight spot;
    spot.type = postfx::LightType::Spot;
    spot.position = {0.0, 4.0, -10.0};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = {500.0f, 400.0f, 300.0f};
    spot.range = 20.0f;
    spot.sourceRadius = 0.1f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.35f;
    c.lights = {spot};
    expectNearReference(c, 0.02, "spot cone");
    // Without fog: the image itself; the cone's column of pixels gains light, the image's corner none.
    const std::vector<float> out = render(c);
    const uint32_t w = 32;
    const auto inScattered = [&](uint32_t i, uint32_t j) {
        const size_t p = size_t(j) * w + i;
        const double T = std::exp(-double(s.density) * s.maxDistance);
        return out[p * 4] - c.images.color[p * 4] * T;
    };
    EXPECT_GT(inScattered(16, 8), 0.1);          // looking through the cone
    EXPECT_NEAR(inScattered(0, 23), 0.0, 1e-3);  // far outside it
}

// A hard-edged sphere of fog in an otherwise empty medium: the centre pixel's transmittance is
// exp(-density·chord) with chord = 2·radius.
TEST_F(FroxelFogGpuTest, SphereVolumeMatchesChord) {
    FroxelCase c = froxelCase(9, 9, 0.0, 0, 0.0);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.density = 0.0f;
    s.maxDistance = 20.0f;
    s.depthExponent = 1.0f;
    s.grid = {9, 9, 128};
    const glm::dvec3 ray = pixelDirection(c.frame.camera, 4, 4, 9, 9);
    postfx::FogVolume sphere;
    sphere.shape = postfx::FogVolumeShape::Sphere;
    sphere.center = postfx::DVec3(ray * 10.0);
    sphere.radius = 3.0f;
    sphere.density = 0.2f;
    c.volumes = {sphere};
    c.frame.ambient = glm::vec3(0.0f);
    const std::vector<float> out = render(c);
    const size_t p = 4 * 9 + 4;
    const double T = std::exp(-0.2 * 6.0);
    EXPECT_NEAR(out[p * 4 + 2], c.images.color[p * 4 + 2] * T, 0.04 * c.images.color[p * 4 + 2] * T);
    expectNearReference(c, 0.03, "sphere volume");
}

// Height fog with the analytic tail, the sun and ambient light: near the reference.
TEST_F(FroxelFogGpuTest, HeightFogMatchesReference) {
    FroxelCase c = froxelCase(32, 24, 2.0, 16, 25.0);
    c.frame.sun.illuminance = {100.0f, 90.0f, 80.0f};
    c.frame.ambient = {2.0f, 3.0f, 4.0f};
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.heightFalloff = 0.2f;
    s.anisotropy = 0.5f;
    s.analyticTail = true;
    s.selfShadow = true;
    s.grid = {16, 12, 64};
    expectNearReference(c, 0.01, "height fog");
}

// Noise (the generated texture, reproduced on the CPU for the reference).
TEST_F(FroxelFogGpuTest, NoiseMatchesReference) {
    FroxelCase c = froxelCase(32, 24, 2.0, 16, 25.0);
    c.frame.ambient = {5.0f, 5.0f, 5.0f};
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.noise.enabled = true;
    s.noise.textureSize = 32;
    s.noise.tiling = 5.0f;
    s.grid = {32, 24, 128};
    expectNearReference(c, 0.03, "noise");
}

// Enough lights for light lists (lights in and out of the view, some far): near the reference, so the
// lists drop no light a froxel needs.
TEST_F(FroxelFogGpuTest, ManyLightsWithListsMatchReference) {
    FroxelCase c = froxelCase(32, 24, 1.0, 16, 15.0);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.density = 0.02f;
    s.grid = {32, 24, 64};
    for (int k = 0; k < 40; ++k) {
        postfx::LocalLight l;
        l.type = k % 5 == 0 ? postfx::LightType::Spot : postfx::LightType::Point;
        l.position = {-12.0 + 0.6 * k, 0.5 + (k % 3), -2.0 - 0.9 * k};
        l.intensity = {float(20 + k), float(60 - k), 30.0f};
        l.range = 4.0f + float(k % 4);
        l.sourceRadius = 0.1f;
        l.outerConeAngle = 0.6f;
        l.innerConeAngle = 0.3f;
        c.lights.push_back(l);
    }
    expectNearReference(c, 0.04, "40 lights");
    // Light lists change the work, not the image: every froxel looping over all 40 lights agrees.
    c.frame.froxelFog.lightListMinLights = 1;
    const std::vector<float> withLists = render(c);
    c.frame.froxelFog.lightListMinLights = postfx::kMaxLocalLights + 1;
    const std::vector<float> withoutLists = render(c);
    const ImageStats stats = compareImages(withLists, withoutLists, 32, 24, 1e-3, 1e-3);
    EXPECT_LT(stats.relativeRmse, 1e-6) << stats.summary();
}

// The froxel fog and the ray-marched fog on the same height fog agree (both against the same medium).
TEST_F(FroxelFogGpuTest, AgreesWithRayMarchedFog) {
    FroxelCase c = froxelCase(32, 24, 2.0, 16, 25.0);
    c.frame.sun.illuminance = {50.0f, 50.0f, 50.0f};
    c.frame.ambient = {2.0f, 3.0f, 4.0f};
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.heightFalloff = 0.15f;
    s.analyticTail = true;
    s.grid = {16, 12, 128};
    const std::vector<float> froxel = render(c);
    FroxelCase r = c;
    r.frame.froxelFog.enabled = false;
    postfx::FogSettings& fog = r.frame.fog;
    static_cast<postfx::FogMedium&>(fog) = s;
    fog.enabled = true;
    fog.steps = 256;
    fog.jitter = false;
    fog.transmittanceCutoff = 0.0f;
    const std::vector<float> marched = render(r);
    const ImageStats stats = compareImages(froxel, marched, 32, 24, 0.05, 1e-3);
    std::printf("[ froxel_fog ] froxel vs ray-marched fog: %s\n", stats.summary().c_str());
    EXPECT_LT(stats.relativeRmse, 0.01);
}

TEST_F(FroxelFogGpuTest, BothFogsInOneFrameIsAnError) {
    FroxelCase c = froxelCase(8, 8, 1.0, 0, 0.0);
    c.frame.fog.enabled = true;
    std::vector<float> out;
    FogHarness harness(*host, gpu);
    const postfx::Status s = harness.run(*context, c.images, c.prepared(), out);
    EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
    EXPECT_NE(s.message.find("FrameInfo.fog.enabled and FrameInfo.froxelFog.enabled"), std::string::npos)
        << s.message;
}

}  // namespace
}  // namespace test
