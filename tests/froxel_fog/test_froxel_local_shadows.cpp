// Local lights' volumetric shadows in the froxel fog (docs/effects/froxel-fog.md, "Local light shadows"):
// the GPU and the CPU reference against a 1D integral with the occluded interval removed (a sphere between
// a point light and the view ray, on a cube face and across a seam of two faces), a spot light's shadow
// against the reference (one tap and filtered), and a moving occluder with temporal accumulation.
#include "froxel_case.h"
#include "local_shadow_maps.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace test {
namespace {

// ∫a^b f (smooth on [a, b]) by composite Simpson with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n = 2000) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i)
        sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

// ∫0^D f over the t where `visible(t)`: the transitions found on a fine scan and bisected, f integrated
// on each visible piece (f is smooth there).
double integrateVisible(const std::function<double(double)>& f, const std::function<bool(double)>& visible,
                        double D) {
    std::vector<double> edges = {0.0};
    const int scan = 20000;
    for (int k = 0; k < scan; ++k) {
        double a = D * k / scan, b = D * (k + 1) / scan;
        if (visible(a) == visible(b)) continue;
        const bool va = visible(a);
        for (int it = 0; it < 60; ++it) {
            const double m = 0.5 * (a + b);
            (visible(m) == va ? a : b) = m;
        }
        edges.push_back(0.5 * (a + b));
    }
    edges.push_back(D);
    double sum = 0.0;
    for (size_t i = 0; i + 1 < edges.size(); ++i)
        if (visible(0.5 * (edges[i] + edges[i + 1]))) sum += simpson(f, edges[i], edges[i + 1]);
    return sum;
}

// 32×24 pixels of fog (density 0.03 /m to 30 m, `slices` slices) under a spot 4 m up, 10 m ahead, pointing
// down through the view, its cone's half angles `inner` and `outer` [rad].
FroxelCase spotCase(uint32_t slices, float inner, float outer) {
    FroxelCase c = froxelCase(32, 24, 1.0, 0, 0.0);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.density = 0.03f;
    s.maxDistance = 30.0f;
    s.grid = {32, 24, slices};
    postfx::LocalLight spot;
    spot.type = postfx::LightType::Spot;
    spot.position = {0.0, 4.0, -10.0};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = {500.0f, 400.0f, 300.0f};
    spot.range = 20.0f;
    spot.sourceRadius = 0.1f;
    spot.innerConeAngle = inner;
    spot.outerConeAngle = outer;
    c.lights = {spot};
    return c;
}

class FroxelFogLocalShadowTest : public FroxelGpuFixture {
protected:
    static void setAtlas(FroxelCase& c, const ShadowAtlas& atlas) {
        c.images.localShadow = atlas.texels;
        c.images.localShadowWidth = atlas.width;
        c.images.localShadowHeight = atlas.height;
    }

    // A point light 1 m beside the centre pixel's ray at 8 m (offset along `side`, unit, perpendicular
    // to the ray), a sphere of radius 0.2 m halfway between them; uniform slices of 12/512 m. The GPU's
    // and the reference's in-scattered light at the centre pixel against the 1D integral with the
    // occluded interval removed, within 1% (and the shadow removes a good part of the light).
    void expectShadowedPointLightMatchesIntegral(const glm::dvec3& side, const glm::dmat3& cubeRotation,
                                                 const char* what) {
        FroxelCase c = froxelCase(9, 9, 0.0, 0, 0.0);
        postfx::FroxelFogSettings& s = c.frame.froxelFog;
        s.density = 0.01f;
        s.albedo = glm::vec3(1.0f);
        s.maxDistance = 12.0f;
        s.depthExponent = 1.0f;
        s.grid = {9, 9, 512};
        const glm::dvec3 ray = pixelDirection(c.frame.camera, 4, 4, 9, 9);
        const glm::dvec3 lightPosition = ray * 8.0 + side;
        const std::vector<ShadowSphere> spheres = {{lightPosition - 0.5 * side, 0.2}};
        postfx::LocalLight light;
        light.position = postfx::DVec3(lightPosition);
        light.intensity = {200.0f, 100.0f, 50.0f};
        light.range = 30.0f;
        light.sourceRadius = 0.05f;
        light.shadow = 0;
        c.lights = {light};
        ShadowAtlas atlas(3 * 256, 2 * 256);
        c.localShadows = {atlas.point(lightPosition, {0, 0}, 256, 0.05, 30.0, spheres, cubeRotation)};
        setAtlas(c, atlas);
        const std::vector<float> out = render(c);
        std::vector<float> reference;
        const postfx::Status rs = c.reference(reference, 8192);
        ASSERT_TRUE(rs.ok()) << rs.message;

        const double sigma = s.density, D = s.maxDistance, R = light.range, r = light.sourceRadius;
        const double T = std::exp(-sigma * D);
        const size_t p = 4 * 9 + 4;
        for (int ch = 0; ch < 3; ++ch) {
            const double I = light.intensity[ch];
            const auto f = [&](double t) {
                const double d = glm::length(ray * t - lightPosition);
                const double q = d / R, window = (1 - q * q * q * q) * (1 - q * q * q * q);
                return sigma * I * window / (d * d + r * r) / (4.0 * glm::pi<double>()) *
                       std::exp(-sigma * t);
            };
            const double lit = integrateVisible(
                f, [&](double t) { return !occluded(ray * t, lightPosition, spheres); }, D);
            const double unshadowed = simpson(f, 0.0, D, 20000);
            const double gpuL = out[p * 4 + ch] - c.images.color[p * 4 + ch] * T;
            const double refL = reference[p * 4 + ch] - c.images.color[p * 4 + ch] * T;
            std::printf(
                "[ froxel_fog ] %s channel %d: GPU %.6g, reference %.6g, integral %.6g (unshadowed %.6g)\n",
                what, ch, gpuL, refL, lit, unshadowed);
            EXPECT_LT(lit, 0.9 * unshadowed) << what;  // the shadow matters
            EXPECT_NEAR(gpuL, lit, 0.01 * lit) << what;
            EXPECT_NEAR(refL, lit, 0.002 * lit) << what;
        }
    }
};

// The sphere's shadow inside one cube face (the -X face's centre).
TEST_F(FroxelFogLocalShadowTest, PointLightShadowMatches1DIntegral) {
    expectShadowedPointLightMatchesIntegral(glm::dvec3(1.0, 0.0, 0.0), glm::dmat3(1.0),
                                            "point light, one face");
}

// The cube turned 45° about y: the sphere's shadow straddles the seam of two faces. A gap would leave lit
// light in the shadow, a double count add it twice; either fails the integral.
TEST_F(FroxelFogLocalShadowTest, ShadowAcrossACubeSeamMatches1DIntegral) {
    const glm::dmat3 turn =
        glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(45.0), glm::dvec3(0.0, 1.0, 0.0)));
    expectShadowedPointLightMatchesIntegral(glm::dvec3(1.0, 0.0, 0.0), turn, "point light, across a seam");
}

// A shadowed point light whose atlas holds no caster is the unshadowed light, at every pixel and so on
// every face and seam the rays cross.
TEST_F(FroxelFogLocalShadowTest, EmptyCubeShadowIsTheUnshadowedLight) {
    FroxelCase c = froxelCase(16, 12, 1.0, 6, 5.0);
    c.frame.froxelFog.grid = {16, 12, 64};
    postfx::LocalLight light;
    light.position = {0.5, 1.2, -4.0};
    light.intensity = {80.0f, 60.0f, 40.0f};
    light.range = 20.0f;
    c.lights = {light};
    const std::vector<float> unshadowed = render(c);
    ShadowAtlas atlas(3 * 64, 2 * 64);
    c.localShadows = {atlas.point(glm::dvec3(light.position), {0, 0}, 64, 0.05, 20.0, {})};
    c.lights[0].shadow = 0;
    setAtlas(c, atlas);
    const std::vector<float> shadowed = render(c);
    ASSERT_EQ(shadowed.size(), unshadowed.size());
    for (size_t i = 0; i < shadowed.size(); ++i)
        ASSERT_NEAR(shadowed[i], unshadowed[i], 1e-5 * std::abs(unshadowed[i]) + 1e-6) << "value " << i;
}

// A spot light shining down through the view with a sphere under it: the shaft's shadow against the
// reference (relative RMSE of the in-scattered light), one tap and filtered, and darker than unshadowed.
TEST_F(FroxelFogLocalShadowTest, SpotShadowEdgeMatchesReference) {
    FroxelCase c = spotCase(128, 0.2f, 0.35f);
    const postfx::FroxelFogSettings& s = c.frame.froxelFog;
    const postfx::LocalLight spot = c.lights[0];
    const std::vector<float> unshadowed = render(c);
    ShadowAtlas atlas(256, 256);
    c.localShadows = {atlas.spot(glm::dvec3(spot.position), glm::dvec3(spot.direction), 0.8, {0, 0}, 256,
                                 0.05, 20.0, {{glm::dvec3(0.3, 2.5, -10.0), 0.35}})};
    c.localShadows[0].depthBias = 1e-4f;
    c.lights[0].shadow = 0;
    setAtlas(c, atlas);
    const double T = std::exp(-double(s.density) * s.maxDistance);
    const auto inScattered = [&](const std::vector<float>& image) {
        std::vector<double> l;
        for (size_t i = 0; i < image.size(); ++i)
            if (i % 4 != 3) l.push_back(image[i] - c.images.color[i] * T);
        return l;
    };
    for (bool filtered : {false, true}) {
        c.frame.froxelFog.localShadowFilter = filtered;
        const std::vector<float> out = render(c);
        std::vector<float> reference;
        const postfx::Status rs = c.reference(reference);
        ASSERT_TRUE(rs.ok()) << rs.message;
        const std::vector<double> a = inScattered(out), b = inScattered(reference),
                                  u = inScattered(unshadowed);
        double err = 0.0, norm = 0.0, removed = 0.0, total = 0.0;
        for (size_t i = 0; i < a.size(); ++i) {
            err += (a[i] - b[i]) * (a[i] - b[i]);
            norm += b[i] * b[i];
            removed += u[i] - a[i];
            total += u[i];
        }
        const double rmse = std::sqrt(err / norm);
        std::printf(
            "[ froxel_fog ] spot shadow (%s): in-scattered relative RMSE %.4f, shadow removes %.1f%%\n",
            filtered ? "filtered" : "one tap", rmse, 100.0 * removed / total);
        // The unshadowed cone's error alone (froxels sampled at their centres against a continuous
        // integral) is 6.1% here; the shadow's edges add theirs.
        EXPECT_LT(rmse, 0.1);
        EXPECT_GT(removed, 0.05 * total);  // the sphere's shaft is dark
    }
}

// An occluder that jumps with temporal accumulation on: the first frame after the jump drops the history
// where the shadowed light changed, so the image is near the converged one of the new place at once
// (froxel-fog.md#temporal), not the old shadow fading at 5% per frame.
TEST_F(FroxelFogLocalShadowTest, MovingOccluderLeavesNoGhost) {
    FroxelCase c = spotCase(64, 0.3f, 0.5f);
    postfx::FroxelFogSettings& s = c.frame.froxelFog;
    s.jitter = false;  // each frame alike: the converged image is any one frame's, so what differs is history
    s.temporal.enabled = true;
    c.lights[0].shadow = 0;
    const postfx::LocalLight spot = c.lights[0];
    const auto place = [&](const glm::dvec3& centre) {
        ShadowAtlas atlas(128, 128);
        c.localShadows = {atlas.spot(glm::dvec3(spot.position), glm::dvec3(spot.direction), 1.1, {0, 0}, 128,
                                     0.05, 20.0, {{centre, 0.5}})};
        setAtlas(c, atlas);
    };
    const glm::dvec3 a(-0.8, 2.5, -10.0), b(0.8, 2.5, -10.0);
    place(a);
    uint64_t frame = 0;
    std::vector<float> atA;
    for (int n = 0; n < 40; ++n)
        atA = render(c, frame++);
    place(b);
    const std::vector<float> firstAtB = render(c, frame++);
    std::vector<float> convergedAtB = firstAtB;
    for (int n = 0; n < 40; ++n)
        convergedAtB = render(c, frame++);
    // RMS over RGB of the differences to the converged image at the new place: the first frame after the
    // move (a ghost of the old shadow would keep 95% of the old difference) and the old place's image.
    double ghost = 0.0, change = 0.0;
    for (size_t i = 0; i < firstAtB.size(); ++i) {
        if (i % 4 == 3) continue;
        ghost += (double(firstAtB[i]) - convergedAtB[i]) * (double(firstAtB[i]) - convergedAtB[i]);
        change += (double(atA[i]) - convergedAtB[i]) * (double(atA[i]) - convergedAtB[i]);
    }
    ghost = std::sqrt(ghost / (firstAtB.size() * 3 / 4));
    change = std::sqrt(change / (firstAtB.size() * 3 / 4));
    std::printf("[ froxel_fog ] moving occluder: RMS change %.4g, first frame after the move off by %.4g\n",
                change, ghost);
    EXPECT_GT(change, 0.01);
    EXPECT_LT(ghost, 0.01 * change);
}

}  // namespace
}  // namespace test
