// The froxel fog's double-precision reference (postfx::reference::renderFroxelFog) against closed forms and
// an independent 1D integral, its settings' checks and the slice distribution. Host only, a few pixels.
#include <postfx/froxel_fog.h>
#include <postfx/reference.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace {

using postfx::FogVolume;
using postfx::FogVolumeShape;
using postfx::FroxelDepthDistribution;
using postfx::FroxelFogSettings;
using postfx::LightType;
using postfx::LocalLight;
using postfx::reference::FroxelFogInputs;
using postfx::reference::henyeyGreenstein;

constexpr double kPi = std::numbers::pi;

// Vulkan perspective projection (clip y down), reversed Z, finite far plane.
glm::mat4 perspective(float fovY, float aspect, float n, float f) {
    const float s = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 m(0.0f);
    m[0][0] = s / aspect;
    m[1][1] = -s;
    m[2][3] = -1.0f;
    m[2][2] = n / (f - n);
    m[3][2] = f * n / (f - n);
    return m;
}

// A frame owning its arrays: by default one pixel looking down -z from the origin at the sky (no
// geometry), so the ray is [0, max_distance] exactly; white color, so with no light the output is T.
struct Frame {
    uint32_t w, h;
    std::vector<float> color, depth;
    std::vector<LocalLight> lights;
    std::vector<FogVolume> volumes;
    FroxelFogInputs in;

    explicit Frame(uint32_t width = 1, uint32_t height = 1) : w(width), h(height) {
        color.assign(size_t(w) * h * 4, 1.0f);
        depth.assign(size_t(w) * h, 0.0f);
        in.width = w;
        in.height = h;
        in.camera.projection = perspective(1.0f, float(w) / float(h), 0.1f, 1000.0f);
        in.sun.illuminance = glm::vec3(0.0f);
        in.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -0.9f));
        in.settings.enabled = true;
        in.settings.density = 0.0f;
        in.settings.heightFalloff = 0.0f;
        in.settings.anisotropy = 0.0f;
        in.settings.albedo = glm::vec3(1.0f);
        in.settings.maxDistance = 20.0f;
        in.settings.analyticTail = false;
        in.stepsPerPixel = 4000;
        in.threads = 1;
    }
    std::vector<float> render() {
        in.color = color;
        in.depth = depth;
        in.lights = lights;
        in.settings.volumes = volumes.data();
        in.settings.volumeCount = uint32_t(volumes.size());
        std::vector<float> out;
        const postfx::Status s = postfx::reference::renderFroxelFog(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
    postfx::Status status() {
        std::vector<float> out;
        in.color = color;
        in.depth = depth;
        in.lights = lights;
        in.settings.volumes = volumes.data();
        in.settings.volumeCount = uint32_t(volumes.size());
        return postfx::reference::renderFroxelFog(in, out);
    }
};

LocalLight pointLight(glm::dvec3 position, glm::vec3 intensity, float radius = 0.05f) {
    LocalLight l;
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    l.sourceRadius = radius;
    l.range = 100.0f;
    return l;
}

// Adaptive Simpson quadrature in double, independent of the reference's midpoint march.
double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
               double whole, double eps, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * eps)
        return left + right + (left + right - whole) / 15.0;
    return simpson(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           simpson(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}
double integrate(const std::function<double(double)>& f, double a, double b) {
    const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
    return simpson(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), 1e-13, 50);
}

// --- (a) Homogeneous sun-lit fog: closed form ----------------------------------------------------------

TEST(FroxelFogReference, HomogeneousSunLitMatchesClosedForm) {
    Frame f(4, 3);
    f.in.settings.density = 0.05f;
    f.in.settings.albedo = {0.9f, 0.5f, 0.2f};
    f.in.settings.anisotropy = 0.6f;
    f.in.sun.illuminance = {3.0f, 2.0f, 1.0f};
    f.in.ambient = {0.1f, 0.2f, 0.3f};
    f.in.stepsPerPixel = 16;  // constant σt and light: every step is exact
    const std::vector<float> out = f.render();
    const glm::dmat4 clipToView = glm::inverse(glm::dmat4(f.in.camera.projection));
    const double T = std::exp(-0.05 * 20.0);
    for (uint32_t j = 0; j < f.h; ++j)
        for (uint32_t i = 0; i < f.w; ++i) {
            const glm::dvec4 p =
                clipToView * glm::dvec4((i + 0.5) / f.w * 2 - 1, (j + 0.5) / f.h * 2 - 1, 0.5, 1);
            const glm::dvec3 d = glm::normalize(glm::dvec3(p) / p.w);
            const double phase =
                henyeyGreenstein(glm::dot(d, glm::normalize(glm::dvec3(f.in.sun.toSun))), 0.6);
            for (int c = 0; c < 3; ++c) {
                const double L =
                    f.in.settings.albedo[c] * (f.in.sun.illuminance[c] * phase + f.in.ambient[c]) * (1 - T);
                EXPECT_NEAR(out[(j * f.w + i) * 4 + c], T + L, 1e-6 * (T + L)) << i << "," << j << " c" << c;
            }
        }
}

// --- (b) A point light beside the view ray: the 1D integral in double ------------------------------------

TEST(FroxelFogReference, PointLightBesideTheRayMatchesTheIntegral) {
    Frame f;
    f.color.assign(4, 0.0f);  // black: the output is L alone
    const double sigma = 1e-3, offset = 1.0, along = 10.0, radius = 0.05, range = 100.0, intensity = 500.0;
    f.in.settings.density = float(sigma);
    f.lights = {pointLight({offset, 0.0, -along}, glm::vec3(float(intensity)), float(radius))};
    const std::vector<float> out = f.render();
    // L = ∫0^D σ·e^{-σt}·I·(1 - (d/range)^4)²/(d² + r²)·(1/4π) dt with d² = offset² + (t - along)².
    const double expected = integrate(
        [&](double t) {
            const double d2 = offset * offset + (t - along) * (t - along);
            const double q2 = d2 / (range * range);
            return sigma * std::exp(-sigma * t) * intensity * (1 - q2 * q2) * (1 - q2 * q2) /
                   (d2 + radius * radius) / (4 * kPi);
        },
        0.0, 20.0);
    EXPECT_NEAR(out[0], expected, 1e-5 * expected);
    EXPECT_FLOAT_EQ(out[0], out[1]);
    EXPECT_EQ(out[3], 0.0f);
}

TEST(FroxelFogReference, PointLightIsFiniteAtTheLightAndZeroBeyondRange) {
    const LocalLight l = pointLight({1.0, 2.0, 3.0}, glm::vec3(1e9f), 0.05f);
    const glm::vec3 atLight = postfx::reference::localLightIlluminance(l, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_FLOAT_EQ(atLight.x, float(1e9 / (0.05 * 0.05)));  // I / r² at d = 0
    EXPECT_EQ(postfx::reference::localLightIlluminance(l, glm::dvec3(1.0, 2.0, 103.0)).x, 0.0f);
    // Far from the source radius (and from range) the falloff is I/d².
    const glm::vec3 at5 = postfx::reference::localLightIlluminance(l, glm::dvec3(1.0, 2.0, 8.0));
    EXPECT_NEAR(at5.x / (1e9 / 25.0), 1.0, 2e-4);
}

TEST(FroxelFogReference, ForwardScatteringPeaksLookingTowardTheLight) {
    // Light ahead at 25 m or behind at 5 m: the samples on [0, 20] see the same distances, so with g = 0
    // the two agree (up to the thin fog's own attenuation), with g > 0 the light ahead is brighter.
    auto render = [](double z, float g) {
        Frame f;
        f.color.assign(4, 0.0f);
        f.in.settings.density = 1e-4f;
        f.in.settings.anisotropy = g;
        f.lights = {pointLight({0.5, 0.0, z}, glm::vec3(100.0f))};
        return double(f.render()[0]);
    };
    EXPECT_NEAR(render(-25.0, 0.0f) / render(5.0, 0.0f), 1.0, 3e-3);
    EXPECT_GT(render(-25.0, 0.6f), 3.0 * render(5.0, 0.6f));
}

// --- (c) Spot cone ------------------------------------------------------------------------------------

TEST(FroxelFogReference, SpotConeIsBrightInsideZeroOutsideAndSmoothBetween) {
    LocalLight l = pointLight({0.0, 5.0, 0.0}, glm::vec3(100.0f));
    l.type = LightType::Spot;
    l.direction = {0.0f, -2.0f, 0.0f};  // normalised by the model
    l.innerConeAngle = float(20.0 * kPi / 180.0);
    l.outerConeAngle = float(30.0 * kPi / 180.0);
    auto at = [&](double deg) {  // at 5 m from the light, `deg` off its axis
        const double a = deg * kPi / 180.0;
        return double(
            postfx::reference::localLightIlluminance(l, glm::dvec3(5 * std::sin(a), 5 - 5 * std::cos(a), 0))
                .x);
    };
    const double q4 = std::pow(5.0 / 100.0, 4.0);
    const double full = 100.0 * (1 - q4) * (1 - q4) / (25.0 + 0.05 * 0.05);  // the point light's at 5 m
    EXPECT_NEAR(at(0.0), full, 1e-6 * full);
    EXPECT_NEAR(at(19.0), full, 1e-6 * full);
    EXPECT_EQ(at(31.0), 0.0);
    EXPECT_EQ(at(90.0), 0.0);
    EXPECT_EQ(at(150.0), 0.0);
    double previous = at(20.0);
    for (double deg = 20.5; deg <= 30.0; deg += 0.5) {  // strictly falling between the angles
        const double v = at(deg);
        EXPECT_LT(v, previous) << deg;
        EXPECT_GE(v, 0.0);
        previous = v;
    }
    EXPECT_GT(at(25.0), 0.2 * full);
    EXPECT_LT(at(25.0), 0.8 * full);

    // Through the fog: a ray passing below the light inside its cone is lit, one outside is not.
    auto render = [&](glm::vec3 direction) {
        Frame f;
        f.color.assign(4, 0.0f);
        f.in.settings.density = 0.01f;
        LocalLight s = l;
        s.position = {0.0, 1.0, -10.0};
        s.direction = direction;
        f.lights = {s};
        return f.render()[0];
    };
    EXPECT_GT(render({0.0f, -1.0f, 0.0f}), 0.0f);
    EXPECT_EQ(render({0.0f, 1.0f, 0.0f}), 0.0f);
}

// --- (d) Local volumes: T = exp(-σ·chord) -------------------------------------------------------------

double volumeTransmittance(const FogVolume& v) {
    Frame f;
    f.volumes = {v};
    return f.render()[0];
}

TEST(FroxelFogReference, HardVolumesMatchTheirChord) {
    FogVolume sphere;
    sphere.shape = FogVolumeShape::Sphere;
    sphere.center = {0.0, 0.0, -10.0};
    sphere.radius = 2.0f;
    sphere.density = 0.5f;
    // 4000 steps over 20 m: the surfaces at 8 m and 12 m fall between midpoints, the chord is exact.
    EXPECT_NEAR(volumeTransmittance(sphere), std::exp(-0.5 * 4.0), 1e-6);
    sphere.center = {1.0, 0.0, -10.0};  // off the ray by 1 m: chord 2·sqrt(r² - 1)
    EXPECT_NEAR(std::log(volumeTransmittance(sphere)), -0.5 * 2.0 * std::sqrt(3.0), 0.5 * 0.005);

    FogVolume box;
    box.shape = FogVolumeShape::Box;
    box.center = {0.3, -0.5, -10.0};
    box.halfSize = {1.0f, 2.0f, 1.5f};
    box.density = 0.25f;
    EXPECT_NEAR(volumeTransmittance(box), std::exp(-0.25 * 3.0), 1e-6);
    box.center = {1.5, 0.0, -10.0};  // beside the ray: no extinction
    EXPECT_EQ(volumeTransmittance(box), 1.0f);

    // Zero-size volumes add nothing; two overlapping volumes add their densities.
    sphere.center = {0.0, 0.0, -10.0};
    sphere.radius = 0.0f;
    EXPECT_EQ(volumeTransmittance(sphere), 1.0f);
    Frame f;
    box.center = {0.0, 0.0, -10.0};
    f.volumes = {box, box};
    EXPECT_NEAR(f.render()[0], std::exp(-2 * 0.25 * 3.0), 1e-6);
}

TEST(FroxelFogReference, VolumeEdgeFalloffRampsFromTheSurface) {
    FogVolume v;
    v.shape = FogVolumeShape::Sphere;
    v.center = {1.0, 2.0, 3.0};
    v.radius = 4.0f;
    v.edgeFalloff = 2.0f;
    using postfx::reference::fogVolumeWeight;
    EXPECT_EQ(fogVolumeWeight(v, glm::dvec3(1.0, 2.0, 3.0)), 1.0);
    EXPECT_EQ(fogVolumeWeight(v, glm::dvec3(1.0, 2.0, 7.5)), 0.0);
    EXPECT_NEAR(fogVolumeWeight(v, glm::dvec3(1.0, 2.0, 6.0)), 0.5, 1e-12);  // 1 m inside: smoothstep(0.5)
    EXPECT_EQ(fogVolumeWeight(v, glm::dvec3(1.0, 2.0, 4.5)), 1.0);
    v.shape = FogVolumeShape::Box;
    v.halfSize = {4.0f, 1.0f, 4.0f};
    // 0.5 m below the top face (the nearest): t = 1/4, 3t² - 2t³ = 0.15625
    EXPECT_NEAR(fogVolumeWeight(v, glm::dvec3(1.0, 2.5, 3.0)), 0.15625, 1e-12);
}

// --- (e) The same height fog as the ray-marched fog's reference ------------------------------------------

TEST(FroxelFogReference, AgreesWithTheRayMarchedFogOnTheSameHeightFog) {
    Frame f(6, 4);
    f.in.camera.position = {100.0, 3.0, -50.0};
    f.in.camera.view = glm::mat4(glm::mat3(glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(1.0f, 0.3f, 0.0f))));
    for (uint32_t p = 0; p < f.w * f.h; p += 3)
        f.depth[p] = 0.002f + 0.0005f * p;  // some surfaces, the rest sky
    f.in.sun.illuminance = {3.0f, 2.0f, 1.0f};
    f.in.ambient = {0.2f, 0.2f, 0.3f};
    postfx::FogMedium medium;
    medium.density = 0.05f;
    medium.heightFalloff = 0.2f;
    medium.baseHeight = 1.0f;
    medium.anisotropy = 0.5f;
    medium.albedo = {0.8f, 0.7f, 0.6f};
    medium.maxDistance = 80.0f;
    medium.selfShadow = true;
    medium.analyticTail = true;
    static_cast<postfx::FogMedium&>(f.in.settings) = medium;
    f.in.stepsPerPixel = 512;
    const std::vector<float> froxel = f.render();

    postfx::reference::FogInputs fog;
    fog.width = f.w;
    fog.height = f.h;
    fog.color = f.color;
    fog.depth = f.depth;
    fog.camera = f.in.camera;
    fog.sun = f.in.sun;
    fog.ambient = f.in.ambient;
    static_cast<postfx::FogMedium&>(fog.settings) = medium;
    fog.settings.enabled = true;
    fog.settings.skipEmptySpace = false;  // the same steps over the same interval
    fog.stepsPerPixel = 512;
    fog.threads = 1;
    std::vector<float> marched;
    ASSERT_TRUE(postfx::reference::renderFog(fog, marched).ok());
    ASSERT_EQ(froxel.size(), marched.size());
    for (size_t i = 0; i < froxel.size(); ++i)
        EXPECT_NEAR(froxel[i], marched[i], 1e-6 * std::abs(marched[i]) + 1e-7) << i;
    EXPECT_LT(froxel[0], 0.99f);  // the fog is there
}

// --- (f) Validation ----------------------------------------------------------------------------------

TEST(FroxelFogSettings, DefaultsAreValidAndEveryFieldIsChecked) {
    EXPECT_TRUE(postfx::validateFroxelFogSettings(FroxelFogSettings{}).ok());
    FogVolume goodVolume;
    struct Row {
        std::function<void(FroxelFogSettings&, FogVolume&)> change;
        std::string field;
    };
    const float nan = std::nanf("");
    const std::vector<Row> rows = {
        {[](FroxelFogSettings& s, FogVolume&) { s.density = -1.0f; }, "FrameInfo.froxelFog.density"},
        {[&](FroxelFogSettings& s, FogVolume&) { s.albedo.y = nan; }, "FrameInfo.froxelFog.albedo[1]"},
        {[](FroxelFogSettings& s, FogVolume&) { s.anisotropy = 1.5f; }, "FrameInfo.froxelFog.anisotropy"},
        {[](FroxelFogSettings& s, FogVolume&) { s.heightFalloff = 11.0f; },
         "FrameInfo.froxelFog.heightFalloff"},
        {[](FroxelFogSettings& s, FogVolume&) { s.baseHeight = INFINITY; }, "FrameInfo.froxelFog.baseHeight"},
        {[](FroxelFogSettings& s, FogVolume&) { s.maxDistance = 0.0f; }, "FrameInfo.froxelFog.maxDistance"},
        {[](FroxelFogSettings& s, FogVolume&) {
             s.noise.enabled = true;
             s.noise.tiling = 0.0f;
         },
         "FrameInfo.froxelFog.noise.tiling"},
        {[](FroxelFogSettings& s, FogVolume&) {
             s.grid = {0, 90, 128};
         },
         "FrameInfo.froxelFog.grid[0]"},
        {[](FroxelFogSettings& s, FogVolume&) {
             s.grid = {160, 90, 513};
         },
         "FrameInfo.froxelFog.grid[2]"},
        {[](FroxelFogSettings& s, FogVolume&) { s.tileSizePx = 5000; }, "FrameInfo.froxelFog.tileSizePx"},
        {[](FroxelFogSettings& s, FogVolume&) { s.depthDistribution = FroxelDepthDistribution(7); },
         "FrameInfo.froxelFog.depthDistribution"},
        {[](FroxelFogSettings& s, FogVolume&) { s.depthExponent = 0.5f; },
         "FrameInfo.froxelFog.depthExponent"},
        {[](FroxelFogSettings& s, FogVolume&) { s.volumeCount = postfx::kMaxFogVolumes + 1; },
         "FrameInfo.froxelFog.volumeCount"},
        {[](FroxelFogSettings& s, FogVolume&) { s.volumes = nullptr; }, "FrameInfo.froxelFog.volumes"},
        {[](FroxelFogSettings&, FogVolume& v) { v.shape = FogVolumeShape(9); },
         "FrameInfo.froxelFog.volumes[0].shape"},
        {[](FroxelFogSettings&, FogVolume& v) { v.center.z = 2e9; },
         "FrameInfo.froxelFog.volumes[0].center[2]"},
        {[](FroxelFogSettings&, FogVolume& v) { v.halfSize.x = -1.0f; },
         "FrameInfo.froxelFog.volumes[0].halfSize[0]"},
        {[&](FroxelFogSettings&, FogVolume& v) { v.radius = nan; }, "FrameInfo.froxelFog.volumes[0].radius"},
        {[](FroxelFogSettings&, FogVolume& v) { v.density = -0.1f; },
         "FrameInfo.froxelFog.volumes[0].density"},
        {[](FroxelFogSettings&, FogVolume& v) { v.edgeFalloff = -1.0f; },
         "FrameInfo.froxelFog.volumes[0].edgeFalloff"},
    };
    for (const Row& row : rows) {
        FogVolume volume = goodVolume;
        FroxelFogSettings s;
        s.volumes = &volume;
        s.volumeCount = 1;
        row.change(s, volume);
        const postfx::Status status = postfx::validateFroxelFogSettings(s);
        EXPECT_EQ(status.code, postfx::Result::InvalidArgument) << row.field;
        EXPECT_EQ(status.message.rfind(row.field + ":", 0), 0u) << status.message;
    }
    // The limits themselves are valid: grid 1×1×1, 512 along each axis, kMaxFroxels in all, 64 volumes;
    // one froxel more is not.
    FroxelFogSettings s;
    s.grid = {1, 1, 1};
    EXPECT_TRUE(postfx::validateFroxelFogSettings(s).ok());
    s.grid = {512, 512, 33};
    EXPECT_EQ(postfx::validateFroxelFogSettings(s).code, postfx::Result::InvalidArgument);
    s.grid = {32, 512, 512};
    EXPECT_TRUE(postfx::validateFroxelFogSettings(s).ok());
    s.grid = {512, 512, 32};
    std::vector<FogVolume> many(postfx::kMaxFogVolumes);
    s.volumes = many.data();
    s.volumeCount = uint32_t(many.size());
    EXPECT_TRUE(postfx::validateFroxelFogSettings(s).ok());
}

TEST(FroxelFogReference, RefusesBadLightsAndInputsNamingThem) {
    Frame f;
    f.lights = {pointLight({0, 0, -5}, glm::vec3(1.0f)), pointLight({0, 0, -5}, glm::vec3(-1.0f))};
    postfx::Status s = f.status();
    EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
    EXPECT_NE(s.message.find("FroxelFogInputs.lights[1].intensity"), std::string::npos) << s.message;
    f.lights.assign(postfx::kMaxLocalLights + 1, pointLight({0, 0, -5}, glm::vec3(1.0f)));
    EXPECT_NE(f.status().message.find("FroxelFogInputs.lights"), std::string::npos);
    f.lights.clear();
    f.in.settings.density = -1.0f;
    EXPECT_NE(f.status().message.find("FrameInfo.froxelFog.density"), std::string::npos);
    f.in.settings.density = 0.1f;
    f.depth.clear();
    EXPECT_NE(f.status().message.find("FroxelFogInputs.depth"), std::string::npos);
}

TEST(FroxelFogSettings, RayMarchedFogKeepsItsKeyNames) {
    postfx::FogSettings s;
    s.density = -1.0f;
    EXPECT_EQ(postfx::validateFogSettings(s).message.rfind("FrameInfo.fog.density:", 0), 0u);
}

// --- (g) Slice distribution -------------------------------------------------------------------------

TEST(FroxelFogSettings, SliceDepthAndItsInverse) {
    FroxelFogSettings s;
    s.maxDistance = 200.0f;
    const double n = 0.5;
    EXPECT_DOUBLE_EQ(postfx::froxelSliceDepth(s, n, 0.0), n);
    EXPECT_DOUBLE_EQ(postfx::froxelSliceDepth(s, n, 1.0), 200.0);
    EXPECT_DOUBLE_EQ(postfx::froxelSliceDepth(s, n, 0.5), n + (200.0 - n) * 0.25);  // k = 2
    s.depthExponent = 3.0f;
    EXPECT_DOUBLE_EQ(postfx::froxelSliceDepth(s, n, 0.5), n + (200.0 - n) * 0.125);
    s.depthDistribution = FroxelDepthDistribution::Log;
    EXPECT_NEAR(postfx::froxelSliceDepth(s, n, 0.5), std::sqrt(n * 200.0), 1e-12);
    EXPECT_NEAR(postfx::froxelSliceDepth(s, n, 1.0), 200.0, 1e-12);
    for (FroxelDepthDistribution d : {FroxelDepthDistribution::Power, FroxelDepthDistribution::Log}) {
        s.depthDistribution = d;
        double previous = -1.0;
        for (int k = 0; k <= 64; ++k) {
            const double z = k / 64.0, depth = postfx::froxelSliceDepth(s, n, z);
            EXPECT_GT(depth, previous);
            previous = depth;
            EXPECT_NEAR(postfx::froxelSliceCoordinate(s, n, depth), z, 1e-12);
        }
        // Clamped outside [0, 1] and [near, far]; extremes stay finite.
        EXPECT_DOUBLE_EQ(postfx::froxelSliceDepth(s, n, 2.0), postfx::froxelSliceDepth(s, n, 1.0));
        EXPECT_EQ(postfx::froxelSliceCoordinate(s, n, 1e9), 1.0);
        EXPECT_EQ(postfx::froxelSliceCoordinate(s, n, 0.0), 0.0);
        FroxelFogSettings wide = s;
        wide.maxDistance = 1e7f;
        EXPECT_TRUE(std::isfinite(postfx::froxelSliceDepth(wide, 1e-4, 0.001)));
        EXPECT_NEAR(postfx::froxelSliceCoordinate(wide, 1e-4, postfx::froxelSliceDepth(wide, 1e-4, 0.3)), 0.3,
                    1e-9);
    }
}

}  // namespace
