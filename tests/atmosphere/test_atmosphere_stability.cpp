// The atmosphere's stability cases (docs/stability.md, "Atmosphere"): the sun at and below the horizon
// (night), the camera below the ground (clamped onto it), at 1e7 m, looking straight up and down, media
// zero and 1000× Earth's, tiny and huge planets, a 1e5 lux sun disk in RGBA16F, and every number of the
// settings table swept over its range (with the CPU reference, the sky's irradiance and the demo's sky
// ambient). Every output: no NaN or Inf, no negative light, nothing beyond the color format's largest finite
// value; where the case has one, the reference (a) within a stated tolerance.
#include "atmosphere/atmosphere_reference.h"
#include "atmosphere_reference_image.h"
#include "fog_harness.h"
#include "host/atmosphere_lighting.h"
#include "image_compare.h"
#include "stability_frame.h"

#include <postfx/reference.h>
#include <postfx/settings_table.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
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
        info.messageCallback = [](postfx::MessageSeverity, const char* text, void* user) {
            static_cast<AtmosphereStability*>(user)->messages.emplace_back(text);
        };
        info.messageUserData = this;
        ASSERT_TRUE(createContext(context, info).ok());
        frame.atmosphere.enabled = true;
        smallScatteringOrders(frame.atmosphere);
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
        harness.onBeforeRecord = beforeRecord;
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    std::vector<float> reference(const FogHarnessImages& im,
                                 const AtmosphereReferenceQuality& quality = {400, 24, 64}) const {
        return atmosphereReferenceImage(frame, im, quality);
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
    std::vector<std::string> messages;  // what postfx said through the message callback
    std::function<void(const postfx::FrameInfo&)> beforeRecord;  // FogHarness::onBeforeRecord
};

TEST_F(AtmosphereStability, SunAtAndBelowTheHorizon) {
    for (double elevation : {0.0, -0.3, -5.0, -90.0}) {
        setSun(elevation);
        const std::string what = "sun at " + std::to_string(elevation) + " deg";
        expectStable(what.c_str(), elevation > -1.0 ? 0.05 : 0.0);
    }
}

// Below the ground the camera is clamped onto it: the image is the one from the ground, and postfx says
// so in one line, in the plan and once through the message callback.
TEST_F(AtmosphereStability, CameraBelowTheGroundIsClamped) {
    const std::string line =
        "atmosphere: FrameInfo.camera.position is below the ground (the planet's surface): "
        "the sky and the aerial perspective are drawn from the ground above it";
    // The plan of each frame as record() gets it, before it records.
    postfx::FramePlan plan;
    beforeRecord = [&](const postfx::FrameInfo& f) { ASSERT_TRUE(context->plan(f, plan).ok()); };
    look({0.0, 0.0, 0.0}, {1.0, 0.05, 0.2});
    const std::vector<float> onGround = expectStable("camera on the ground");
    EXPECT_TRUE(plan.adjusted.empty());
    look({0.0, -500.0, 0.0}, {1.0, 0.05, 0.2});
    const std::vector<float> below = expectStable("camera 500 m below the ground");
    EXPECT_EQ(plan.adjusted, std::vector<std::string>{line});
    const ImageStats stats = compareImages(below, onGround, 16, 8, 0.01, 1e-3);
    EXPECT_LT(stats.relativeRmse, 1e-3) << stats.summary();
    look({0.0, -800.0, 0.0}, {1.0, 0.05, 0.2});
    expectStable("camera 800 m below the ground");
    EXPECT_EQ(messages, std::vector<std::string>{line}) << "said once while the camera stays below";
    look({0.0, 0.0, 0.0}, {1.0, 0.05, 0.2});
    expectStable("camera on the ground again");
    EXPECT_TRUE(plan.adjusted.empty());
    look({0.0, -500.0, 0.0}, {1.0, 0.05, 0.2});
    expectStable("camera below the ground again");
    EXPECT_EQ(messages, (std::vector<std::string>{line, line})) << "said again when it goes below again";
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
    smallScatteringOrders(frame.atmosphere);
    frame.atmosphere.groundRadius = 9.9e7f;
    frame.atmosphere.topRadius = 1e8f;
    look({0.0, 2.0, 0.0}, {1.0, 0.05, 0.2});
    // The LUTs' parameterisations spread over 1e6 m of mostly empty air: 6.5% measured.
    expectStable("planet of 9.9e7 m, atmosphere 1e6 m thick", 0.1);
}

// LUTs of a few hundred texels and steps: the sweep's frames in tens of ms on lavapipe.
void smallLuts(postfx::AtmosphereSettings& s) {
    s.transmittanceLutSize = {32, 16};
    s.transmittanceSteps = 16;
    s.multipleScatteringLutSize = {8, 8};
    s.multipleScatteringDirections = 16;
    s.multipleScatteringSteps = 8;
    s.scatteringOrdersLutSize = {8, 8, 4};
    s.scatteringOrdersAzimuthSize = 2;
    s.scatteringOrdersDirections = 16;
    s.scatteringOrdersSteps = 8;
    s.scatteringOrders = 2;
    s.skyViewLutSize = {16, 8};
    s.skyViewSteps = 8;
    s.aerialPerspectiveLutSize = {8, 8, 8};
}

// A Float or Vec3 key's sweep: its ends (the nearest float inside an open one) and the value between,
// log-spaced over a positive range (from 1e-6 of the top for a range from 0), linear over one through 0.
std::vector<float> sweepValues(const postfx::SettingField& f) {
    float lo = float(f.min), hi = float(f.max);
    if (f.minOpen) lo = std::nextafter(lo, hi);
    if (f.maxOpen) hi = std::nextafter(hi, lo);
    const float middle =
        lo < 0.0f ? 0.5f * (lo + hi) : float(std::sqrt(std::max(double(lo), 1e-6 * hi) * hi));
    return {lo, middle, hi};
}

struct SweepCase {
    std::string name;
    postfx::AtmosphereSettings settings;
    bool ambient = true;  // check the demo's sky ambient too (its orders table: ~0.5 s a case)
};

// Keys that change Hillaire's Ψ (its LUT's geometry, the media, the ground's bounce).
bool changesPsi(const char* key) {
    for (const char* k :
         {"mie_anisotropy", "ozone_center_height", "sun_angular_radius_deg", "aerial_perspective_distance"})
        if (std::strcmp(key, k) == 0) return false;
    return true;
}

// Sets `key` (a Float or Vec3 row of the table) to `value`, keeping the radii valid: a ground radius keeps
// 100 km of air above it (up to the largest top), a top radius stays above the ground.
void setKey(postfx::AtmosphereSettings& s, const postfx::SettingField& f, float value) {
    if (std::strcmp(f.key, "top_radius") == 0) value = std::max(value, std::nextafter(s.groundRadius, 2e8f));
    void* at = f.address(&s);
    if (f.kind == postfx::SettingKind::Vec3)
        *static_cast<postfx::Vec3*>(at) = postfx::Vec3(value);
    else
        *static_cast<float*>(at) = value;
    if (std::strcmp(f.key, "ground_radius") == 0)
        s.topRadius = std::max(std::min(value + 1e5f, float(f.max)), std::nextafter(value, 2e8f));
}

// Every Float and Vec3 key at each of its sweep's values (the scattering orders, the default), again at its
// ends with Hillaire's model where it changes Ψ, and the combinations that once gave NaN or Inf
// (docs/stability.md). The demo's sky ambient at the ends and in the combinations.
std::vector<SweepCase> sweepCases() {
    using M = postfx::AtmosphereMultipleScattering;
    postfx::AtmosphereSettings base;
    base.enabled = true;
    base.ambientFromSky = true;
    smallLuts(base);
    std::vector<SweepCase> cases;
    for (const postfx::SettingField& f : postfx::atmosphereSettingsTable()) {
        if (f.kind != postfx::SettingKind::Float && f.kind != postfx::SettingKind::Vec3) continue;
        const std::vector<float> values = sweepValues(f);
        for (size_t i = 0; i < values.size(); ++i)
            for (M model : {M::Orders, M::Hillaire}) {
                const bool end = i == 0 || i + 1 == values.size();
                if (model == M::Hillaire && (!end || !changesPsi(f.key))) continue;
                char name[96];
                std::snprintf(name, sizeof name, "%s = %g%s", f.key, double(values[i]),
                              model == M::Hillaire ? ", hillaire" : "");
                SweepCase c{name, base, end};
                c.settings.multipleScattering = model;
                setKey(c.settings, f, values[i]);
                cases.push_back(c);
            }
    }
    const auto named = [&](const char* name, M model, auto&& change) {
        SweepCase c{std::string(name) + (model == M::Hillaire ? ", hillaire" : ""), base};
        c.settings.multipleScattering = model;
        change(c.settings);
        cases.push_back(c);
    };
    for (M model : {M::Orders, M::Hillaire}) {
        named("rayleigh 1e-3 /m, scale height 1e7 m, planet of 1e5 m under 1e8 m", model, [](auto& s) {
            s.rayleighScattering = postfx::Vec3(1e-3f);
            s.rayleighScaleHeight = 1e7f;
            s.groundRadius = 1e5f;
            s.topRadius = 1e8f;
        });
        named("Mie only at its largest scattering, no absorption", model, [](auto& s) {
            s.rayleighScattering = s.ozoneAbsorption = postfx::Vec3(0.0f);
            s.mieScattering = 1.0f;
            s.mieAbsorption = 0.0f;
        });
        named("planet of 1 m under 1e8 m of air, rayleigh 1 /m, scale height 1e7 m", model, [](auto& s) {
            s.groundRadius = 1.0f;
            s.topRadius = 1e8f;
            s.rayleighScattering = postfx::Vec3(1.0f);
            s.rayleighScaleHeight = 1e7f;
        });
        named("rayleigh 0.01 /m over a ground of albedo 1, nothing absorbs", model, [](auto& s) {
            s.rayleighScattering = postfx::Vec3(0.01f);
            s.groundAlbedo = postfx::Vec3(1.0f);
            s.mieAbsorption = 0.0f;
            s.ozoneAbsorption = postfx::Vec3(0.0f);
        });
    }
    return cases;
}

size_t countNot(const std::vector<float>& v, bool (*ok)(float)) {
    size_t n = 0;
    for (size_t i = 0; i < v.size(); ++i)
        n += i % 4 != 3 && !ok(v[i]);
    return n;
}

double meanRgb(const std::vector<float>& v) {
    double sum = 0.0;
    for (size_t i = 0; i < v.size(); ++i)
        if (i % 4 != 3) sum += v[i];
    return sum / (v.size() * 3 / 4);
}

// The largest vertical optical depth of the air over the RGB channels, from the ground to the top [1].
double verticalOpticalDepth(const postfx::AtmosphereSettings& s) {
    const postfx::atmosphere::Model m = postfx::atmosphere::modelFrom(s);
    const glm::dvec3 tau = postfx::atmosphere::opticalDepth(m, glm::dvec3(0.0, m.groundRadius, 0.0),
                                                            glm::dvec3(0.0, 1.0, 0.0), 4096);
    return std::max(tau.x, std::max(tau.y, tau.z));
}

// Each case: the GPU frame (16×8, small LUTs) finite, >= 0, within RGBA16F; the CPU reference finite and
// >= 0; the demo's sky ambient (AtmosphereLightingCache: atmosphereSkyIrradiance / π at the ground, in the
// cases that ask for it) finite and within FrameInfo::ambient's [0, 1e7]. Where the air's vertical optical
// depth is at most 1 the GPU's LUTs resolve it: the image's mean within 20 % of the reference's (12 %
// measured, a planet of 1 m under 100 km of air). Thicker air is checked for finiteness only:
// its light lies in the top few kilometres, between the small LUTs' height nodes (docs/effects/atmosphere.md,
// "Stability").
TEST_F(AtmosphereStability, EveryNumberAcrossItsRange) {
    const auto start = std::chrono::steady_clock::now();
    const AtmosphereReferenceQuality quality{64, 8, 16, 8, 8, 4, 2, 16, 8, 2};
    size_t compared = 0;
    for (const SweepCase& c : sweepCases()) {
        SCOPED_TRACE(c.name);
        ASSERT_TRUE(postfx::validateAtmosphereSettings(c.settings).ok()) << c.name;
        frame.atmosphere = c.settings;
        const FogHarnessImages im = images();
        const std::vector<float> gpuOut = render(im);
        const std::vector<float> ref = reference(im, quality);
        const auto finiteNonNegative = [](float v) { return std::isfinite(v) && v >= 0.0f; };
        const auto inHalf = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 65504.0f; };
        EXPECT_EQ(countNot(gpuOut, inHalf), 0u);
        EXPECT_EQ(countNot(ref, finiteNonNegative), 0u);
        glm::vec3 ambient(0.0f);
        if (c.ambient) {
            demo::Scene scene;
            scene.atmosphere = c.settings;
            scene.sun.direction = glm::vec3(frame.sun.toSun);
            scene.sun.illuminance = glm::vec3(frame.sun.illuminance);
            demo::AtmosphereLightingCache lighting;
            ambient = lighting.update(scene).ambient;
            for (int k = 0; k < 3; ++k)
                EXPECT_TRUE(ambient[k] >= 0.0f && ambient[k] <= 1e7f) << ambient[k];
        }
        const double tau = verticalOpticalDepth(c.settings);
        const double gpuMean = meanRgb(gpuOut), refMean = meanRgb(ref);
        if (tau <= 1.0) {
            EXPECT_NEAR(gpuMean, refMean, 0.2 * refMean) << "vertical optical depth " << tau;
            ++compared;
        }
        std::printf("[ sweep ] %-72s tau %-9.3g gpu mean %-9.4g reference %-9.4g ambient %.4g\n",
                    c.name.c_str(), tau, gpuMean, refMean, double(ambient.y));
    }
    std::printf("[ sweep ] %zu compared with the reference, %.1f s\n", compared,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
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
