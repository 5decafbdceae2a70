// Depth linearised once: with two or more effects in the frame, postfx.view_distance turns the
// host's depth into surface distances once and every effect reads those; with one effect, that effect
// unprojects the depth itself (no extra pass). Either way each effect sees the same surface: the clouds and
// the ray-marched fog rendered together (one shared distance image) equal the two rendered one after the
// other in separate contexts (each unprojecting the depth itself), on surfaces from 0.5 m to 5 km and sky.
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 24, kHeight = 16;

class FrameViewDistanceTest : public ReversedZContextTest {
protected:
    postfx::FrameInfo frame() const {
        postfx::FrameInfo f;
        f.cameraCut = true;
        f.camera =
            lookCamera({0.0, 1.7, 0.0}, {0.2, 0.35, -1.0}, {0.0, 1.0, 0.0}, 70.0f, float(kWidth) / kHeight);
        f.sun.toSun = glm::normalize(glm::vec3(0.4f, 0.3f, -0.8f));
        f.sun.illuminance = {1e5f, 1e5f, 1e5f};
        f.ambient = {300.0f, 400.0f, 600.0f};
        f.fog.density = 0.002f;
        f.fog.heightFalloff = 0.01f;
        f.fog.anisotropy = 0.6f;
        f.fog.maxDistance = 800.0f;
        f.fog.noise.enabled = false;
        // A layer from 300 m to 600 m that casts no shadow (the fog alone would not see it); reduced
        // resolution and temporal at their defaults, so the upsample reads the distances too.
        f.clouds.bottomHeight = 300.0f;
        f.clouds.topHeight = 600.0f;
        f.clouds.coverage = 0.6f;
        f.clouds.density = 0.004f;
        f.clouds.castShadows = false;
        f.clouds.noise.baseSize = 32;
        f.clouds.noise.detailSize = 16;
        return f;
    }

    // Surfaces from 0.5 m to 5 km, one column in six with no geometry.
    FogHarnessImages images(const postfx::FrameInfo& f) const {
        return surfaceImages(
            f.camera, kWidth, kHeight,
            [](uint32_t i, uint32_t j) {
                return i % 6 == 5 ? std::numeric_limits<double>::infinity()
                                  : 0.5 * std::pow(1e4, double((i * 5 + j * 3) % 17) / 16.0);
            },
            [](uint32_t i, uint32_t j, int c) { return 50.0f + 10.0f * float((i * 7 + j * 3 + c) % 11); });
    }

    // `f` in a new context over `im`'s color; the plan it recorded in `plan`.
    std::vector<float> render(const postfx::FrameInfo& f, const FogHarnessImages& im,
                              postfx::FramePlan& plan) {
        std::unique_ptr<postfx::Context> c;
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        EXPECT_TRUE(createContext(c, info).ok());
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& g) { EXPECT_TRUE(c->plan(g, plan).ok()); };
        std::vector<float> out;
        const postfx::Status s = harness.run(*c, im, f, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
};

bool reads(const postfx::FramePlan& plan, const char* pass, const char* resource) {
    const postfx::PlannedPass* p = plan.pass(pass);
    return p && std::find(p->reads.begin(), p->reads.end(), resource) != p->reads.end();
}

}  // namespace

TEST_F(FrameViewDistanceTest, OneEffectReadsTheDepthItselfTwoShareOneDistancePass) {
    const postfx::FrameInfo base = frame();
    FogHarnessImages im = images(base);
    postfx::FrameInfo cloudsAlone = base, fogAlone = base, both = base;
    cloudsAlone.clouds.enabled = true;
    fogAlone.fog.enabled = true;
    both.clouds.enabled = both.fog.enabled = true;

    postfx::FramePlan planClouds, planFog, planBoth;
    const std::vector<float> afterClouds = render(cloudsAlone, im, planClouds);
    EXPECT_TRUE(reads(planClouds, "clouds.march", "host.depth"));
    EXPECT_TRUE(reads(planClouds, "clouds.upsample", "host.depth"));
    EXPECT_FALSE(planClouds.pass("postfx.view_distance"));
    FogHarnessImages chained = im;
    chained.color = afterClouds;
    const std::vector<float> oneAfterTheOther = render(fogAlone, chained, planFog);
    EXPECT_TRUE(reads(planFog, "fog.raymarch", "host.depth"));
    EXPECT_FALSE(planFog.pass("postfx.view_distance"));

    const std::vector<float> together = render(both, im, planBoth);
    ASSERT_TRUE(planBoth.pass("postfx.view_distance"));
    const std::vector<std::string> order = passNames(planBoth);
    const auto at = [&](const char* name) {
        return std::find(order.begin(), order.end(), name) - order.begin();
    };
    EXPECT_LT(at("postfx.view_distance"), at("clouds.march"));  // made before its first reader
    for (const postfx::PlannedPass& p : planBoth.passes)
        EXPECT_EQ(reads(planBoth, p.name.c_str(), "host.depth"), p.name == "postfx.view_distance") << p.name;
    for (const char* reader : {"clouds.march", "clouds.upsample", "fog.raymarch"})
        EXPECT_TRUE(reads(planBoth, reader, "postfx.view_distance")) << reader;

    ASSERT_EQ(together.size(), oneAfterTheOther.size());
    double worst = 0.0, largestChange = 0.0;
    for (size_t k = 0; k < together.size(); ++k) {
        if (k % 4 == 3) continue;
        const double expected = oneAfterTheOther[k];
        ASSERT_TRUE(std::isfinite(together[k])) << k;
        worst =
            std::max(worst, std::abs(double(together[k]) - expected) / std::max(std::abs(expected), 1e-3));
        largestChange =
            std::max(largestChange, std::abs(expected - double(im.color[k])) / double(im.color[k]));
    }
    std::printf(
        "[ frame ] shared distances against each effect's own unprojection: worst relative "
        "difference %.3g (the effects change the color by up to %.3g)\n",
        worst, largestChange);
    EXPECT_GT(largestChange, 0.1);  // the effects do change the image
    EXPECT_LT(worst, 1e-4);         // float rounding of the ray's direction and distance
}
