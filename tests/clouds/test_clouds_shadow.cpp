// The clouds' shadows (docs/effects/clouds.md, "Shadows"), on the device: the shadow map of a homogeneous
// box read through cloudShadowTransform at ground points against Beer–Lambert along the sun's direction,
// and both fogs' sunlight under a homogeneous layer dimmed by exactly exp(-σ·H/μ).
#include "clouds_frames.h"
#include "fog_harness.h"

#include <postfx/context.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace test {
namespace {

class CloudsShadowTest : public ReversedZContextTest {
protected:
    // 8×4 pixels of black color, geometry `distance` away on every pixel (0: no geometry).
    FogHarnessImages images(const postfx::CameraInput& camera, double distance) const {
        FogHarnessImages im;
        im.width = 8;
        im.height = 4;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(im.width) * im.height * 4, 0.0f);
        im.depth.assign(size_t(im.width) * im.height, 0.0f);
        if (distance > 0.0)
            for (uint32_t j = 0; j < im.height; ++j)
                for (uint32_t i = 0; i < im.width; ++i)
                    im.depth[size_t(j) * im.width + i] =
                        depthAtDistance(camera, pixelDirection(camera, i, j, im.width, im.height), distance);
        return im;
    }

    std::vector<float> render(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    // The held shadow map, bilinearly filtered at uv (clamp to edge), as the consumers sample it.
    static double sample(const std::vector<float>& map, uint32_t size, double u, double v) {
        const double x = u * size - 0.5, y = v * size - 0.5;
        const double fx = std::floor(x), fy = std::floor(y);
        auto at = [&](double i, double j) {
            const uint32_t ci = uint32_t(std::clamp(i, 0.0, double(size - 1)));
            const uint32_t cj = uint32_t(std::clamp(j, 0.0, double(size - 1)));
            return double(map[size_t(cj) * size + ci]);
        };
        const double a = x - fx, b = y - fy;
        return (1 - a) * (1 - b) * at(fx, fy) + a * (1 - b) * at(fx + 1, fy) + (1 - a) * b * at(fx, fy + 1) +
               a * b * at(fx + 1, fy + 1);
    }
};

// A homogeneous box (noise off, coverage 1) of σt = 0.002 /m between y = 1750 and 2250 m, the sun tilted
// toward +x: a ground point whose ray toward the sun crosses the box's top and bottom faces sees
// exp(-σ·500/μ); one whose ray misses the box sees 1; a point above the box maps outside the map.
TEST_F(CloudsShadowTest, ShadowMapOfABoxIsBeerLambertAlongTheSun) {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.clouds.shape = postfx::CloudShape::Box;
    frame.clouds.box.center = {0.0, 2000.0, 0.0};
    frame.clouds.box.halfSize = {500.0f, 250.0f, 500.0f};
    frame.clouds.shadowMap.size = 256;
    frame.clouds.shadowMap.extent = 6000.0f;
    frame.sun.toSun = glm::vec3(0.5f, 1.0f, 0.0f);
    frame.sun.illuminance = postfx::Vec3(1.0f);
    frame.camera = lookCamera({10.0, 2.0, -20.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
    render(frame, images(frame.camera, 30.0));

    VkExtent3D extent{};
    const std::vector<uint8_t> bytes = readHeldImage(*host, gpu, *context, "clouds.shadow_map", extent);
    ASSERT_EQ(extent.width, 256u);
    std::vector<float> map(bytes.size() / 4);
    std::memcpy(map.data(), bytes.data(), map.size() * 4);

    const postfx::CloudShadowTransform t = postfx::cloudShadowTransform(frame);
    auto shadowAt = [&](glm::dvec3 p) {
        const double u = t.u.x * p.x + t.u.y * p.y + t.u.z * p.z + t.u.w;
        const double v = t.v.x * p.x + t.v.y * p.y + t.v.z * p.z + t.v.w;
        if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return 1.0;
        return sample(map, extent.width, u, v);
    };
    const double mu = 1.0 / std::sqrt(1.25);  // toSun.y once normalised
    const double inside = std::exp(-0.002 * 500.0 / mu);
    // From (x, 0, 0) the ray reaches y = 1750 at x + 875 and y = 2250 at x + 1125: inside the box's
    // |x| < 500 for x in [-1375, -625]; texels sample their centres, so stay a few texels away from the
    // shadow's edge.
    for (double x : {-1300.0, -1000.0, -700.0})
        for (double z : {-400.0, 0.0, 400.0})
            EXPECT_NEAR(shadowAt({x, 0.0, z}), inside, 2e-4) << x << "," << z;
    for (double x : {-2000.0, 0.0, 1000.0})
        EXPECT_NEAR(shadowAt({x, 0.0, 0.0}), 1.0, 1e-6) << x;
    EXPECT_NEAR(shadowAt({-1000.0, 0.0, 700.0}), 1.0, 1e-6);
    std::printf("[ clouds ] box shadow %.6f (closed form %.6f)\n", shadowAt({-1000.0, 0.0, 0.0}), inside);
}

// Both fogs in front of geometry 60 m away, looking level (their rays never reach the layer, so the clouds
// add nothing to the image), lit by the sun alone: under a homogeneous layer of optical depth 2 that casts
// shadows their light is the one without shadows times exp(-2/μ), μ the sun's elevation sine.
TEST_F(CloudsShadowTest, BothFogsAreDimmedUnderTheLayer) {
    for (bool froxel : {false, true}) {
        postfx::FrameInfo frame;
        frame.clouds = homogeneousLayer();
        frame.sun.toSun = glm::vec3(0.3f, 1.0f, 0.2f);
        frame.sun.illuminance = postfx::Vec3(1000.0f);
        frame.camera = lookCamera({0.0, 2.0, 0.0}, {1.0, 0.0, 0.3}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        postfx::FogMedium medium;
        medium.density = 0.01f;
        medium.heightFalloff = 0.0f;
        medium.noise.enabled = false;
        medium.maxDistance = 100.0f;
        if (froxel) {
            static_cast<postfx::FogMedium&>(frame.froxelFog) = medium;
            frame.froxelFog.enabled = true;
            frame.froxelFog.temporal.enabled = false;  // each render its own (the frames repeat index 0)
        } else {
            static_cast<postfx::FogMedium&>(frame.fog) = medium;
            frame.fog.enabled = true;
            frame.fog.temporal.enabled = false;
        }
        const FogHarnessImages im = images(frame.camera, 60.0);
        const std::vector<float> shadowed = render(frame, im);
        frame.clouds.castShadows = false;
        const std::vector<float> lit = render(frame, im);
        const double mu = 1.0 / std::sqrt(0.09 + 1.0 + 0.04);
        const double expected = std::exp(-2.0 / mu);
        const size_t centre = (size_t(2) * im.width + 4) * 4;
        std::printf("[ clouds ] %s under the layer: %.6g of its light (closed form %.6g)\n",
                    froxel ? "froxel fog" : "fog", shadowed[centre] / lit[centre], expected);
        for (size_t p = 0; p < size_t(im.width) * im.height; ++p) {
            ASSERT_GT(lit[p * 4], 0.0f);
            EXPECT_NEAR(shadowed[p * 4] / lit[p * 4], expected, 2e-3 * expected) << p;
        }
    }
}

}  // namespace
}  // namespace test
