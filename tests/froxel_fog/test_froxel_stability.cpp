// The froxel fog's stability cases (docs/stability.md, "Froxel fog"): lights exactly at a froxel's sample
// and on a pixel's ray, 1e9 cd, zero-size and huge fog volumes, a 1×1×1 grid and 512 slices, a near plane
// of 1e-4 m with max distance 1e7 m. Every output: no NaN or Inf, nothing beyond the color format's
// largest finite value (RGBA16F overflow clamped as the ray-marched fog clamps it), and the reference
// (clamped) where the grid can follow it.
#include "froxel_case.h"
#include "local_shadow_maps.h"
#include "stability_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

class FroxelFogStability : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
    }

    std::vector<float> render(const FroxelCase& c) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, c.images, c.prepared(), out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    // No NaN/Inf, nothing out of the format's range; with `tolerance` > 0 also the reference (clamped)
    // within it (relative, of max(|expected|, 1)).
    void expectStable(const FroxelCase& c, const char* what, double tolerance = 0.0) {
        const std::vector<float> out = render(c);
        ASSERT_EQ(out.size(), c.images.color.size());
        std::vector<float> expected = out;
        if (tolerance > 0.0) {
            const postfx::Status s = c.reference(expected);
            ASSERT_TRUE(s.ok()) << s.message;
        }
        const Comparison cmp = compareToExpected(out, expected, c.images.colorFormat, tolerance);
        std::printf("[ froxel_fog ] %s: worst relative %.3g, non-finite %zu, out of range %zu\n", what,
                    cmp.worstRelative, cmp.nonFinite, cmp.outOfRange);
        EXPECT_EQ(cmp.nonFinite, 0u) << what;
        EXPECT_EQ(cmp.outOfRange, 0u) << what;
        EXPECT_EQ(cmp.off, 0u) << what << ": " << cmp.firstOff;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
};

// 9×9 pixels, one froxel per pixel, uniform slices to 20 m: the centre pixel's ray is the view axis.
FroxelCase axisCase() {
    FroxelCase c = froxelCase(9, 9, 0.0, 0, 0.0);
    c.frame.froxelFog.density = 0.02f;
    c.frame.froxelFog.maxDistance = 20.0f;
    c.frame.froxelFog.depthExponent = 1.0f;
    c.frame.froxelFog.grid = {9, 9, 64};
    c.frame.ambient = glm::vec3(1.0f);
    return c;
}

// Where the GPU samples froxel (4, 4, k) of axisCase (jitter off): the slice's middle on the axis.
postfx::DVec3 froxelSample(const FroxelCase& c, uint32_t k) {
    const postfx::FroxelFogSettings& s = c.frame.froxelFog;
    const double near = 0.1, slices = s.grid.z;
    const double start = k == 0 ? 0.0 : postfx::froxelSliceDepth(s, near, k / slices);
    const double end = postfx::froxelSliceDepth(s, near, (k + 1) / slices);
    return {0.0, 0.0, -0.5 * (start + end)};
}

postfx::LocalLight pointLight(postfx::DVec3 position, float intensity, float radius) {
    postfx::LocalLight l;
    l.position = position;
    l.intensity = glm::vec3(intensity);
    l.sourceRadius = radius;
    l.range = 50.0f;
    return l;
}

TEST_F(FroxelFogStability, LightAtFroxelSampleAndOnPixelRay) {
    FroxelCase c = axisCase();
    c.lights = {pointLight(froxelSample(c, 20), 100.0f, 0.01f)};  // at a sample, on the centre ray
    // and one on pixel (2, 6)'s ray between samples
    const glm::dvec3 ray = pixelDirection(c.frame.camera, 2, 6, 9, 9);
    c.lights.push_back(pointLight(postfx::DVec3(ray * 7.3), 100.0f, 0.01f));
    expectStable(c, "lights at a froxel sample and on a pixel ray");
    postfx::LocalLight spot = c.lights[0];
    spot.type = postfx::LightType::Spot;
    spot.innerConeAngle = spot.outerConeAngle = 0.3f;  // a hard cone edge, sampled at its apex
    c.lights = {spot};
    expectStable(c, "spot light's apex at a froxel sample");
}

TEST_F(FroxelFogStability, Intensity1e9CandelaClampsInBothFormats) {
    for (VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT}) {
        FroxelCase c = axisCase();
        c.images.colorFormat = format;
        c.lights = {pointLight(froxelSample(c, 10), 1e9f, 1e-3f), pointLight({1.0, 0.5, -5.0}, 1e9f, 1e-20f)};
        expectStable(c, format == VK_FORMAT_R16G16B16A16_SFLOAT ? "1e9 cd, rgba16f" : "1e9 cd, rgba32f");
    }
}

TEST_F(FroxelFogStability, ZeroSizeAndHugeVolumes) {
    FroxelCase c = axisCase();
    const std::vector<float> without = render(c);
    c.volumes.resize(2);
    c.volumes[0].halfSize = glm::vec3(0.0f);
    c.volumes[0].density = 1e6f;
    c.volumes[1].shape = postfx::FogVolumeShape::Sphere;
    c.volumes[1].radius = 0.0f;
    c.volumes[1].density = 1e6f;
    c.volumes[1].edgeFalloff = 1e7f;
    EXPECT_EQ(render(c), without) << "zero-size volumes add nothing";

    c.volumes.resize(1);
    c.volumes[0].shape = postfx::FogVolumeShape::Sphere;
    c.volumes[0].radius = 1e7f;
    c.volumes[0].density = 1e6f;
    expectStable(c, "a sphere of radius 1e7 m and density 1e6 around the camera", 2e-3);
    c.volumes[0].shape = postfx::FogVolumeShape::Box;
    c.volumes[0].halfSize = glm::vec3(1e7f);
    c.volumes[0].edgeFalloff = 1e7f;
    c.volumes[0].center = {5e6, 0.0, 0.0};
    expectStable(c, "a box of 1e7 m with an edge falloff of 1e7 m");
}

TEST_F(FroxelFogStability, OneFroxelAnd512Slices) {
    FroxelCase c = froxelCase(8, 6, 1.0, 4, 12.0);
    c.frame.ambient = glm::vec3(3.0f);
    c.lights = {pointLight({0.0, 1.0, -6.0}, 50.0f, 0.1f)};
    c.frame.froxelFog.grid = {1, 1, 1};
    expectStable(c, "1x1x1 grid");
    c.frame.froxelFog.tricubic = true;
    expectStable(c, "1x1x1 grid, tricubic");
    c.frame.froxelFog.tricubic = false;
    c.frame.froxelFog.grid = {8, 6, 512};
    c.lights.clear();
    expectStable(c, "512 slices", 5e-3);
}

TEST_F(FroxelFogStability, NearPlane1em4AndMaxDistance1e7) {
    for (auto distribution : {postfx::FroxelDepthDistribution::Power, postfx::FroxelDepthDistribution::Log}) {
        FroxelCase c = froxelCase(8, 6, 1.0, 4, 12.0);
        c.frame.camera = testCamera({0.0, 1.0, 0.0}, 60.0f, 8.0f / 6.0f, 1e-4f, 1e8f, true);
        for (uint32_t j = 0; j < 6; ++j)
            for (uint32_t i = 0; i < 4; ++i)
                c.images.depth[j * 8 + i] =
                    depthAtDistance(c.frame.camera, pixelDirection(c.frame.camera, i, j, 8, 6), 12.0);
        c.frame.ambient = glm::vec3(3.0f);
        postfx::FroxelFogSettings& s = c.frame.froxelFog;
        s.maxDistance = 1e7f;
        s.density = 0.002f;
        s.depthDistribution = distribution;
        s.grid = {8, 6, 128};
        s.analyticTail = true;
        const bool log = distribution == postfx::FroxelDepthDistribution::Log;
        // Log slices follow the 12 m wall; the power distribution's first slice ends at 610 m, so its
        // linear ramp within that slice is what it can do (docs/effects/froxel-fog.md, "Artefacts").
        expectStable(c, log ? "near 1e-4, far 1e7, log" : "near 1e-4, far 1e7, power", log ? 0.01 : 0.0);
    }
}

// Local lights' shadows (docs/stability.md, "Froxel fog"): a light inside its caster and exactly on its
// surface, a 1×1-texel map, ranges of 1e-3 m and 1e6 m, depth biases of 0 and 1e3, 256 lights each with a
// cube shadow; compared with the reference where the grid can follow it.
TEST_F(FroxelFogStability, LocalLightShadowsAtTheirExtremes) {
    FroxelCase base = axisCase();
    base.frame.ambient = glm::vec3(0.0f);
    const glm::dvec3 caster(0.0, 0.0, -8.0);
    const auto shadowedPoint = [&](FroxelCase& c, const glm::dvec3& position, float range, float bias,
                                   uint32_t size, const std::vector<ShadowSphere>& spheres) {
        postfx::LocalLight l = pointLight(postfx::DVec3(position), 500.0f, std::min(0.05f, range));
        l.range = range;
        l.shadow = 0;
        c.lights = {l};
        ShadowAtlas atlas(3 * size, 2 * size);
        c.localShadows = {atlas.point(position, {0, 0}, size, std::min(0.01, 0.5 * range), range, spheres)};
        c.localShadows[0].depthBias = bias;
        c.images.localShadow = atlas.texels;
        c.images.localShadowWidth = atlas.width;
        c.images.localShadowHeight = atlas.height;
    };
    FroxelCase c = base;
    shadowedPoint(c, caster, 30.0f, 1e-4f, 32, {{caster, 1.0}});
    expectStable(c, "a light inside its caster");
    shadowedPoint(c, caster + glm::dvec3(1.0, 0.0, 0.0), 30.0f, 1e-4f, 32, {{caster, 1.0}});
    expectStable(c, "a light on its caster's surface");
    shadowedPoint(c, caster + glm::dvec3(1.5, 0.0, 0.0), 30.0f, 1e-4f, 1, {{caster, 1.0}});
    expectStable(c, "a cube of 1x1-texel faces");
    for (float range : {1e-3f, 1e6f}) {
        shadowedPoint(c, caster + glm::dvec3(1.5, 0.0, 0.0), range, 1e-4f, 16, {{caster, 1.0}});
        expectStable(c, range < 1.0f ? "range 1e-3 m" : "range 1e6 m");
    }
    for (float bias : {0.0f, 1e3f}) {
        shadowedPoint(c, caster + glm::dvec3(1.5, 0.0, 0.0), 30.0f, bias, 16, {{caster, 1.0}});
        expectStable(c, bias == 0.0f ? "depth bias 0" : "depth bias 1e3");
    }
    // 256 point lights along the view, each with its own cube of 4×4-texel faces.
    c = base;
    ShadowAtlas atlas(256 * 12, 8);
    for (uint32_t i = 0; i < postfx::kMaxLocalLights; ++i) {
        const glm::dvec3 p(0.3 * std::sin(double(i)), 0.3 * std::cos(double(i)), -0.07 * i);
        postfx::LocalLight l = pointLight(postfx::DVec3(p), 5.0f, 0.05f);
        l.range = 5.0f;
        l.shadow = i;
        c.lights.push_back(l);
        c.localShadows.push_back(atlas.point(p, {i * 12, 0}, 4, 0.01, 5.0, {{caster, 1.0}}));
    }
    c.images.localShadow = atlas.texels;
    c.images.localShadowWidth = atlas.width;
    c.images.localShadowHeight = atlas.height;
    expectStable(c, "256 lights, each shadowed");
}

}  // namespace
}  // namespace test
