// The atmosphere's frame plan (docs/effects/atmosphere.md#frame-plan): the first frame builds the four
// LUTs (the multiple scattering's one pass per order); a still camera and sun record only the apply pass; the
// sun or the camera moving beyond the documented thresholds rebuild the sky-view and aerial-perspective LUTs
// (the camera's height the sky view, its position and frustum the aerial perspective), media changes what
// depends on them; the recorded passes are the plan's; every LUT's bytes.
#include "fog_harness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace test {
namespace {

const std::string kT = "atmosphere.transmittance", kMs = "atmosphere.multiple_scattering",
                  kOrder = "atmosphere.scattering_orders", kSky = "atmosphere.sky_view",
                  kAp = "atmosphere.aerial_perspective", kApply = "atmosphere.apply";

class AtmospherePlanTest : public ReversedZContextTest {
protected:
    void SetUp() override {
        ReversedZContextTest::SetUp();
        frame.atmosphere.enabled = true;
        smallScatteringOrders(frame.atmosphere);
        frame.sun.toSun = {0.8f, 0.6f, 0.0f};
        frame.sun.illuminance = postfx::Vec3(1e5f);
        setCamera({0.0, 10.0, 0.0}, {1.0, 0.0, 0.0});
        im.width = 16;
        im.height = 8;
        im.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        im.color.assign(16 * 8 * 4, 0.0f);
        im.depth.assign(16 * 8, 0.0f);
        im.depth[0] = 0.5f;  // one geometry pixel
    }

    void setCamera(glm::dvec3 position, glm::dvec3 forward) {
        frame.camera = testCamera(position, 60.0f, 2.0f, 0.1f, 1e5f, true);
        frame.camera.view = glm::mat4(glm::lookAt(position, position + forward, glm::dvec3(0.0, 1.0, 0.0)));
    }

    // Plans and records the frame; the recorded passes (timings) must be the plan's.
    std::vector<std::string> planAndRun(
        const std::function<void(const postfx::FrameInfo&)>& beforeRecord = {}) {
        frame.frameIndex = frameIndex++;
        last = planAndRecord(*host, gpu, *context, im, frame, beforeRecord);
        return passNames(last);
    }

    postfx::FrameInfo frame;
    FogHarnessImages im;
    postfx::FramePlan last;
    uint64_t frameIndex = 0;
};

using Passes = std::vector<std::string>;

// `passes` with the scattering orders' passes (4 by default) before them.
Passes withOrders(Passes passes, uint32_t orders = 4) {
    passes.insert(passes.begin(), orders, kOrder);
    return passes;
}

TEST_F(AtmospherePlanTest, StillRecordsOnlyApplyAndChangesRebuildWhatDependsOnThem) {
    // The frames record the small scattering-orders table (SetUp); the LUTs' bytes (rgba16f) and the
    // uniforms are checked on the plan of the same frame at the default sizes, made just before it records:
    // the scattering orders' LUT and its two working images are (32 view nodes × 8 azimuths) × 64 sun nodes
    // × (2 × 16 heights + 1).
    postfx::FramePlan defaults;
    EXPECT_EQ(planAndRun([&](const postfx::FrameInfo& f) {
                  postfx::FrameInfo d = f;
                  d.atmosphere = postfx::AtmosphereSettings{};
                  d.atmosphere.enabled = true;
                  ASSERT_TRUE(context->plan(d, defaults).ok());
              }),
              (Passes{kT, kOrder, kOrder, kOrder, kOrder, kSky, kAp, kApply}));
    const uint64_t orders = 32 * 8 * 64 * 33 * 8;
    for (const auto& [name, bytes] : {std::pair<std::string, uint64_t>{kT, 512 * 128 * 8},
                                      {kMs, orders},
                                      {"atmosphere.scattering_order_a", orders},
                                      {"atmosphere.scattering_order_b", orders},
                                      {kSky, 192 * 108 * 8},
                                      {kAp, 32 * 32 * 32 * 8},
                                      {"atmosphere.aerial_transmittance", 32 * 32 * 32 * 8}}) {
        const postfx::PlannedResource* r = nullptr;
        for (const postfx::PlannedResource& x : defaults.resources)
            if (x.name == name) r = &x;
        ASSERT_TRUE(r) << name;
        EXPECT_EQ(r->bytes, bytes) << name;
    }
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "still";
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "still, again";

    // The sun: below the threshold (1e-3 rad) nothing, beyond it both view LUTs.
    frame.sun.toSun =
        glm::vec3(glm::rotate(glm::mat4(1.0f), 5e-4f, glm::vec3(0, 0, 1)) * glm::vec4(0.8f, 0.6f, 0, 0));
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "sun turned 5e-4 rad";
    frame.sun.toSun = {0.6f, 0.8f, 0.0f};
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "sun moved";
    frame.sun.illuminance = postfx::Vec3(5e4f);
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "the sun's illuminance is applied, not stored";

    // The camera: turning or moving sideways the aerial perspective; rising the sky view too.
    setCamera({0.0, 10.0, 0.0}, {1.0, 0.0, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kAp, kApply})) << "camera turned";
    setCamera({0.5, 10.0, 0.0}, {1.0, 0.0, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "camera moved 0.5 m";
    setCamera({20.0, 10.0, 0.0}, {1.0, 0.0, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kAp, kApply})) << "camera moved 20 m sideways";
    setCamera({20.0, 30.0, 0.0}, {1.0, 0.0, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "camera rose 20 m";

    // Media: the phase and the ground albedo the scattering orders and the view LUTs, the air all four.
    frame.atmosphere.mieAnisotropy = 0.7f;
    EXPECT_EQ(planAndRun(), withOrders({kSky, kAp, kApply})) << "mie_anisotropy";
    frame.atmosphere.groundAlbedo = postfx::Vec3(0.2f);
    EXPECT_EQ(planAndRun(), withOrders({kSky, kAp, kApply})) << "ground_albedo";
    frame.atmosphere.rayleighScaleHeight = 7000.0f;
    Passes all = withOrders({kSky, kAp, kApply});
    all.insert(all.begin(), kT);
    EXPECT_EQ(planAndRun(), all) << "rayleigh_scale_height";
    frame.atmosphere.scatteringOrders = 6;
    EXPECT_EQ(planAndRun(), withOrders({kSky, kAp, kApply}, 6)) << "scattering_orders";
    // Hillaire's model: its one pass, whose isotropic phase does not depend on g.
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
    EXPECT_EQ(planAndRun(), (Passes{kMs, kSky, kAp, kApply})) << "hillaire";
    frame.atmosphere.mieAnisotropy = 0.75f;
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "hillaire, mie_anisotropy";
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "multiple scattering off";
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "still";

    // Near the top, just above it (the sky-view LUT's mapping between the two spans) and in space: the
    // sky-view LUT rebuilt for each camera radius.
    setCamera({20.0, 95e3, 0.0}, {1.0, -0.5, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "at 95 km";
    setCamera({20.0, 105e3, 0.0}, {1.0, -0.5, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "at 105 km";
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "at 105 km, still";
    setCamera({20.0, 2e5, 0.0}, {1.0, -0.5, 0.2});
    EXPECT_EQ(planAndRun(), (Passes{kSky, kAp, kApply})) << "in space";
    EXPECT_EQ(planAndRun(), (Passes{kApply})) << "in space, still";
    // Off: nothing.
    frame.atmosphere.enabled = false;
    EXPECT_TRUE(planAndRun().empty());
}

}  // namespace
}  // namespace test
