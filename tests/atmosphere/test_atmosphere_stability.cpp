// The atmosphere's stability cases (docs/stability.md, "Atmosphere"): the sun at and below the horizon
// (night), the camera below the ground (clamped onto it), at 1e7 m, looking straight up and down, media
// zero and 1000× Earth's, tiny and huge planets, a 1e5 lux sun disk in RGBA16F. Every output: no NaN or
// Inf, no negative light, nothing beyond the color format's largest finite value; where the case has
// one, the reference (a) within a stated tolerance.
#include "atmosphere_reference_image.h"
#include "fog_harness.h"
#include "image_compare.h"
#include "stability_frame.h"

#include <postfx/reference.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

class AtmosphereStability : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
        frame.atmosphere.enabled = true;
        frame.sun.illuminance = postfx::Vec3(1e5f);
        setSun(30.0);
        look({0.0, 2.0, 0.0}, {1.0, 0.05, 0.2});
    }

    void setSun(double elevationDeg) {
        const double e = glm::radians(elevationDeg);
        frame.sun.toSun = glm::vec3(float(std::cos(e)), float(std::sin(e)), 0.3f * float(std::cos(e)));
    }

    void look(glm::dvec3 position, glm::dvec3 forward, glm::dvec3 up = {0.0, 1.0, 0.0}) {
        frame.camera = testCamera(position, 70.0f, 2.0f, 0.1f, 1e6f, true);
        frame.camera.view = glm::mat4(glm::lookAt(position, position + forward, up));
    }

    // 16×8 pixels: the left half a surface at `distance` [m] (grey 0.1), the right half no geometry
    // (black: space).
    FogHarnessImages images(double distance = 1000.0) const {
        FogHarnessImages im;
        im.width = 16;
        im.height = 8;
        im.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        im.color.assign(16 * 8 * 4, 0.0f);
        im.depth.assign(16 * 8, 0.0f);
        for (uint32_t j = 0; j < 8; ++j)
            for (uint32_t i = 0; i < 8; ++i) {
                im.depth[j * 16 + i] =
                    depthAtDistance(frame.camera, pixelDirection(frame.camera, i, j, 16, 8), distance);
                for (int c = 0; c < 3; ++c)
                    im.color[(j * 16 + i) * 4 + c] = 0.1f;
                im.color[(j * 16 + i) * 4 + 3] = 1.0f;
            }
        return im;
    }

    std::vector<float> render(const FogHarnessImages& im) {
        frame.frameIndex = frameIndex++;
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    std::vector<float> reference(const FogHarnessImages& im) const {
        return atmosphereReferenceImage(frame, im, {400, 24, 64});
    }

    // Finite, not negative, within RGBA16F; with tolerance > 0 the reference's (clamped to the format)
    // within that relative RMSE.
    std::vector<float> expectStable(const char* what, double tolerance = 0.0,
                                    const FogHarnessImages* given = nullptr) {
        const FogHarnessImages im = given ? *given : images();
        const std::vector<float> out = render(im);
        size_t nonFinite = 0, negative = 0, beyond = 0;
        for (float v : out) {
            nonFinite += !std::isfinite(v);
            negative += v < 0.0f;
            beyond += std::abs(v) > 65504.0f;
        }
        double rmse = 0.0;
        if (tolerance > 0.0) {
            std::vector<float> ref = reference(im);
            for (float& v : ref)
                v = std::min(v, 65504.0f);
            rmse = compareImages(out, ref, im.width, im.height, 0.05, 1e-3).relativeRmse;
            EXPECT_LT(rmse, tolerance) << what;
        }
        std::printf("[ atmosphere ] %s: non-finite %zu, negative %zu, beyond half %zu, vs reference %.3g\n",
                    what, nonFinite, negative, beyond, rmse);
        EXPECT_EQ(nonFinite, 0u) << what;
        EXPECT_EQ(negative, 0u) << what;
        EXPECT_EQ(beyond, 0u) << what;
        return out;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
    postfx::FrameInfo frame;
    uint64_t frameIndex = 0;
};

TEST_F(AtmosphereStability, SunAtAndBelowTheHorizon) {
    for (double elevation : {0.0, -0.3, -5.0, -90.0}) {
        setSun(elevation);
        const std::string what = "sun at " + std::to_string(elevation) + " deg";
        expectStable(what.c_str(), elevation > -1.0 ? 0.05 : 0.0);
    }
}

// Below the ground the camera is clamped onto it: the image is the one from the ground.
TEST_F(AtmosphereStability, CameraBelowTheGroundIsClamped) {
    look({0.0, 0.0, 0.0}, {1.0, 0.05, 0.2});
    const std::vector<float> onGround = expectStable("camera on the ground");
    look({0.0, -500.0, 0.0}, {1.0, 0.05, 0.2});
    const std::vector<float> below = expectStable("camera 500 m below the ground");
    const ImageStats stats = compareImages(below, onGround, 16, 8, 0.01, 1e-3);
    EXPECT_LT(stats.relativeRmse, 1e-3) << stats.summary();
}

TEST_F(AtmosphereStability, CameraFarOutAndLookingStraightUpOrDown) {
    look({0.0, 1e7, 0.0}, {0.0, -1.0, 0.0}, {0.0, 0.0, -1.0});
    expectStable("camera at 1e7 m looking down", 0.05);
    look({0.0, 1e7, 0.0}, {0.42, -0.91, 0.0});  // the limb: 23° from the nadir
    expectStable("camera at 1e7 m toward the limb", 0.05);
    look({0.0, 2.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, -1.0});
    expectStable("looking straight up", 0.05);
    look({0.0, 2.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, 0.0, -1.0});
    expectStable("looking straight down", 0.05);
}

TEST_F(AtmosphereStability, EmptyAndDenseMedia) {
    postfx::AtmosphereSettings& s = frame.atmosphere;
    const postfx::AtmosphereSettings earth = s;
    s.rayleighScattering = postfx::Vec3(0.0f);
    s.mieScattering = s.mieAbsorption = 0.0f;
    s.ozoneAbsorption = postfx::Vec3(0.0f);
    s.sunAngularRadiusDeg = 0.0f;
    const FogHarnessImages im = images();
    const std::vector<float> empty = expectStable("media zero", 0.0, &im);
    // Nothing scatters or absorbs: the host's color as it was, the planet's lit ground below the horizon.
    for (uint32_t j = 0; j < 8; ++j)
        for (uint32_t i = 0; i < 8; ++i)
            EXPECT_NEAR(empty[(j * 16 + i) * 4], 0.1f, 1e-3f);
    s = earth;
    s.rayleighScattering = s.rayleighScattering * 1000.0f;
    s.mieScattering *= 1000.0f;
    s.mieAbsorption *= 1000.0f;
    s.ozoneAbsorption = s.ozoneAbsorption * 1000.0f;
    // Optical depths of ~260: stable with the scattering orders (the default), compared with Hillaire's
    // model, whose reference agrees with the GPU (the LUTs' default steps do not resolve such media: 15 %
    // measured; finer steps do). The orders' reference is not comparable here: its table's linear
    // interpolation between height nodes leaks light down past e^-250, order after order
    // (docs/effects/atmosphere.md, "Stability").
    expectStable("media 1000x Earth's, scattering orders");
    s.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
    expectStable("media 1000x Earth's, Hillaire's model", 0.25);
}

// Earth scaled by 1e-4 (a planet of 636 m, every length 1e4 times shorter, every coefficient 1e4 times
// larger: the same optical depths) and a planet of 9.9e7 m under an atmosphere 1e6 m thick.
TEST_F(AtmosphereStability, TinyAndHugePlanets) {
    postfx::AtmosphereSettings& s = frame.atmosphere;
    const float k = 1e-4f;
    s.groundRadius *= k;
    s.topRadius *= k;
    s.rayleighScaleHeight *= k;
    s.mieScaleHeight *= k;
    s.ozoneCenterHeight *= k;
    s.ozoneHalfWidth *= k;
    s.rayleighScattering = s.rayleighScattering / k;
    s.mieScattering /= k;
    s.mieAbsorption /= k;
    s.ozoneAbsorption = s.ozoneAbsorption / k;
    s.aerialPerspectiveDistance *= k;
    const glm::dvec3 eye(0.0, 0.01, 0.0);
    frame.camera = testCamera(eye, 70.0f, 2.0f, 1e-4f, 100.0f, true);
    frame.camera.view =
        glm::mat4(glm::lookAt(eye, eye + glm::dvec3(1.0, 0.05, 0.2), glm::dvec3(0.0, 1.0, 0.0)));
    const FogHarnessImages tiny = images(0.1);
    expectStable("planet of 636 m (Earth scaled by 1e-4)", 0.05, &tiny);
    frame.atmosphere = postfx::AtmosphereSettings{};
    frame.atmosphere.enabled = true;
    frame.atmosphere.groundRadius = 9.9e7f;
    frame.atmosphere.topRadius = 1e8f;
    look({0.0, 2.0, 0.0}, {1.0, 0.05, 0.2});
    // The LUTs' parameterisations spread over 1e6 m of mostly empty air: 6.5% measured.
    expectStable("planet of 9.9e7 m, atmosphere 1e6 m thick", 0.1);
}

// A 1e5 lux sun disk in view (about 1.5e9 cd/m², beyond half floats): clamped to 65504, never Inf.
TEST_F(AtmosphereStability, SunDiskInRgba16fIsClamped) {
    look({0.0, 2.0, 0.0}, {1.0, 0.1, 0.0});
    frame.sun.toSun = glm::vec3(pixelDirection(frame.camera, 12, 4, 16, 8));  // a sky pixel's centre
    const std::vector<float> out = expectStable("sun disk in view");
    float brightest = 0.0f;
    for (float v : out)
        brightest = std::max(brightest, v);
    EXPECT_EQ(brightest, 65504.0f);
}

}  // namespace
}  // namespace test
