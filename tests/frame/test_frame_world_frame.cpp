// The host's world frame (ContextCreateInfo::world; docs/integration.md, "World frame and units"): one
// scene handed to postfx by hosts each in its own frame and units: y up right-handed in metres (postfx's
// own, the reference), y up left-handed in metres, z up right-handed in 1/128 m, z up right-handed and z up
// left-handed (Unreal's) in centimetres. Each builds its camera with its own lookAt and perspective in its
// units (a left-handed one looks down +z, its clip is its units' multiple of the metre host's), and gives
// the sun, the sun's and the spot light's shadow matrices, the lights, the fog volumes, the fogs' and the
// clouds' wind, the clouds' box and coverage map in its frame. Each gets the reference's image, and the
// same volumetrics lookup at the same points given in its frame:
//   - exactly (image difference 0) where its units are a power of two, so that its numbers are the
//     reference's scaled without rounding and the conversion rounds nothing either (the lookup's GLSL then
//     works in the host's units: within 1e-5);
//   - within float round-off amplified by the scene in centimetres: the host's own numbers (its projection
//     built in its units, then postfx's P·diag(u, u, u, 1)) round at 6e-8 relative, and the view rays'
//     intersections with the clouds' layer around the planet (a 6360 km sphere in float) turn that into
//     up to 1e-3 in a few cloud pixels (measured 1.0e-3, 1.9% of the channels above 1e-5; the scene without
//     clouds, atmosphere and noise: 6e-7): each pixel within 3e-3, under 5% of the channels above 1e-5.
// The checks name the host's fields; the clouds' shadow transform and the atmosphere's CPU evaluations take
// the host's positions.
#include "fog_harness.h"
#include "lookup_probe.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 64, kHeight = 36;
constexpr double kPi = 3.14159265358979323846;

// A host's frame, and where postfx's y-up metre scene lies in it: the host's coordinates of postfx's
// point p are u·T·p, T the signed permutation whose columns are the host's coordinates of postfx's x,
// y (up) and z (docs/integration.md's table, inverted).
struct TestHost {
    const char* name;
    postfx::WorldFrame world;
    glm::dmat3 axes;

    double units() const { return world.unitsPerMetre; }
    bool left() const { return world.handedness == postfx::Handedness::Left; }
    bool exact() const { return std::exp2(std::round(std::log2(units()))) == units(); }  // a power of two
    glm::dvec3 position(const glm::dvec3& p) const { return units() * (axes * p); }
    glm::dvec3 direction(const glm::dvec3& d) const { return axes * d; }
    glm::dvec3 extent(const glm::dvec3& h) const { return units() * glm::abs(axes * h); }
    double length(double d) const { return units() * d; }
    // A world -> clip matrix of postfx's frame as the host's: W · (host -> postfx).
    glm::dmat4 worldToClip(const glm::dmat4& w) const {
        glm::dmat4 toPostfx(glm::transpose(axes) / units());
        toPostfx[3][3] = 1.0;
        return w * toPostfx;
    }
    // Its other horizontal axis runs along postfx's -z: a map laid on it is postfx's mirrored in v.
    bool vFlipped() const {
        const glm::dvec3 z = axes * glm::dvec3(0.0, 0.0, 1.0);  // one of y, z nonzero: the host's horizontal
        return z.y + z.z < 0.0;
    }
};

const TestHost kHosts[] = {
    {"y up, right-handed, m", {postfx::UpAxis::Y, postfx::Handedness::Right, 1.0}, glm::dmat3(1.0)},
    {"y up, left-handed, m",
     {postfx::UpAxis::Y, postfx::Handedness::Left, 1.0},
     glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1))},
    {"z up, right-handed, 1/128 m",
     {postfx::UpAxis::Z, postfx::Handedness::Right, 128.0},
     glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0))},
    {"z up, right-handed, cm",
     {postfx::UpAxis::Z, postfx::Handedness::Right, 100.0},
     glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0))},
    {"z up, left-handed, cm (Unreal)",
     {postfx::UpAxis::Z, postfx::Handedness::Left, 100.0},
     glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0))},
};

// The scene in postfx's frame [m].
const glm::dvec3 kEye{0.0, 1.7, 0.0}, kTarget{0.0, 3.0, -20.0};
const glm::dvec3 kToSun = glm::normalize(glm::dvec3(0.4, 0.45, -0.8));
const glm::dvec3 kSunShadowCentre{0.0, 0.0, -30.0};
const glm::dvec3 kSpot{-3.0, 5.0, -14.0}, kSpotAxis = glm::normalize(glm::dvec3(0.2, -1.0, -0.3));

// A right-handed view (looking down -z) to reversed-Z Vulkan clip, near and far in the view's units.
glm::mat4 projection(double nearPlane, double farPlane, bool left) {
    const double f = 1.0 / std::tan(0.5 * 60.0 * kPi / 180.0), aspect = double(kWidth) / kHeight;
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0;
    p[2][2] = nearPlane / (farPlane - nearPlane);
    p[3][2] = farPlane * nearPlane / (farPlane - nearPlane);
    if (left) p[2] = -p[2];  // a left-handed view looks down +z
    return glm::mat4(p);
}

// The host's camera, built from its own lookAt in its own coordinates and units.
postfx::CameraInput hostCamera(const TestHost& h) {
    postfx::CameraInput c;
    const glm::dvec3 eye = h.position(kEye), target = h.position(kTarget), up = h.direction({0.0, 1.0, 0.0});
    c.position = eye;
    c.view = glm::mat4(h.left() ? glm::lookAtLH(eye, target, up) : glm::lookAtRH(eye, target, up));
    c.projection = projection(h.length(0.1), h.length(1e4), h.left());
    return c;
}

// Orthographic world -> clip of the sun's shadow map in postfx's frame: 80 m across, depth 0 at 100 m
// toward the sun from `kSunShadowCentre`, 1 at 100 m beyond it.
glm::dmat4 sunShadowMatrix() {
    const glm::dvec3 eye = kSunShadowCentre + 100.0 * kToSun;
    const glm::dmat4 view = glm::lookAtRH(eye, kSunShadowCentre, glm::dvec3(0.0, 0.0, -1.0));
    glm::dmat4 clip(1.0);
    clip[0][0] = clip[1][1] = 1.0 / 40.0;
    clip[2][2] = -1.0 / 200.0;  // depth (-z_view) / 200
    return clip * view;
}

// The spot light's shadow face: perspective along its axis, 70° across, standard Z from 0.5 m to 40 m.
glm::dmat4 spotShadowMatrix() {
    const glm::dmat4 view = glm::lookAtRH(kSpot, kSpot + kSpotAxis, glm::dvec3(0.0, 0.0, -1.0));
    const double f = 1.0 / std::tan(0.5 * 70.0 * kPi / 180.0), n = 0.5, far = 40.0;
    glm::dmat4 p(0.0);
    p[0][0] = f;
    p[1][1] = f;
    p[2][2] = -far / (far - n);
    p[2][3] = -1.0;
    p[3][2] = -far * n / (far - n);
    return p * view;
}

// A 32 × 32 depth map: a square caster at depth `caster` over texels [10, 22)², cleared to 1 elsewhere.
std::vector<float> squareCaster(float caster) {
    std::vector<float> t(32 * 32, 1.0f);
    for (uint32_t j = 10; j < 22; ++j)
        for (uint32_t i = 10; i < 22; ++i)
            t[j * 32 + i] = caster;
    return t;
}

// What a host hands postfx for one frame, with the arrays its pointers name.
struct HostFrame {
    postfx::FrameInfo frame;
    std::vector<postfx::LocalLight> lights;
    std::vector<postfx::LocalShadow> shadows;
    std::vector<postfx::FogVolume> volumes;
};

class FrameWorldFrameTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        // The clouds' coverage map (4 × 4), and the same map with its rows reversed: a host whose map's v
        // runs along postfx's -z lays the mirrored texture down for the same clouds.
        const uint8_t texels[16] = {255, 200, 90, 30, 180, 255, 140, 60, 40, 120, 255, 200, 0, 70, 160, 255};
        uint8_t flipped[16];
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                flipped[j * 4 + i] = texels[(3 - j) * 4 + i];
        postfx::core::ImageDesc desc;
        desc.format = VK_FORMAT_R8_UNORM;
        desc.extent = {4, 4, 1};
        coverage = uploadSampledImage(*host, gpu, desc, texels, sizeof texels);
        coverageFlipped = uploadSampledImage(*host, gpu, desc, flipped, sizeof flipped);
    }
    void TearDown() override {
        coverage.reset();
        coverageFlipped.reset();
        GpuTest::TearDown();
    }

    // The scene as host `h` hands it over: with the froxel fog (its lights and volumes, the clouds in a
    // box) or the ray-marched fog (the clouds in a layer over the coverage map).
    HostFrame frameFor(const TestHost& h, bool froxel) const {
        HostFrame out;
        postfx::FrameInfo& f = out.frame;
        f.camera = hostCamera(h);
        f.sun.toSun = glm::vec3(h.direction(kToSun));
        f.sun.illuminance = {1.2e5f, 1.15e5f, 1.1e5f};
        f.ambient = {2000.0f, 2500.0f, 3500.0f};
        f.preExposure = 1.0f / 4096.0f;
        f.timeSeconds = 12.5;
        f.shadowMap.worldToClip = h.worldToClip(sunShadowMatrix());
        f.shadowMap.depthBias = 0.002f;

        f.atmosphere.enabled = true;  // small LUTs: lavapipe
        f.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
        f.atmosphere.transmittanceLutSize = {64, 16};
        f.atmosphere.multipleScatteringLutSize = {8, 8};
        f.atmosphere.multipleScatteringDirections = 16;
        f.atmosphere.skyViewLutSize = {32, 18};
        f.atmosphere.aerialPerspectiveLutSize = {8, 8, 16};

        postfx::CloudSettings& c = f.clouds;
        c.enabled = true;
        c.steps = 24;
        c.lightSteps = 4;
        c.temporal.enabled = false;
        c.noise.baseSize = 32;
        c.noise.detailSize = 16;
        c.noise.tiling = 3000.0f;
        c.shadowMap.size = 64;
        c.shadowMap.extent = 8000.0f;
        c.wind = glm::vec3(h.direction({12.0, 0.0, 4.0}));  // [m/s] along the host's axes
        if (froxel) {
            c.shape = postfx::CloudShape::Box;
            c.box.center = h.position({300.0, 1200.0, -2500.0});
            c.box.halfSize = glm::vec3(h.extent({1500.0, 300.0, 800.0}));
            // R_up(yaw)·R_x(pitch) on the host's axes is postfx's box when both angles carry the mirror's
            // sign.
            const float det = float(glm::determinant(h.axes));
            c.box.yawDeg = 30.0f * det;
            c.box.pitchDeg = 8.0f * det;
            c.density = 0.01f;
        } else {
            c.bottomHeight = 900.0f;  // heights stay metres
            c.topHeight = 1600.0f;
            c.coverage = 0.7f;
            c.coverageMap.texture = h.vFlipped() ? coverageFlipped.view() : coverage.view();
            c.coverageMap.size = float(h.length(3000.0));
            c.coverageMap.originX = h.length(-700.0);
            // The map's v = 0 edge at postfx's z = 1234.5 m, on the host's other horizontal axis.
            c.coverageMap.originZ = h.vFlipped() ? -h.length(1234.5) : h.length(1234.5);
        }

        postfx::FogMedium& m = froxel ? static_cast<postfx::FogMedium&>(f.froxelFog) : f.fog;
        m.density = 0.015f;
        m.heightFalloff = 0.08f;
        m.baseHeight = 0.5f;  // [m] above the host's up = 0
        m.maxDistance = 150.0f;
        m.selfShadow = true;
        m.noise.enabled = true;
        m.noise.textureSize = 32;
        m.noise.tiling = 3.0f;
        m.noise.wind = glm::vec3(h.direction({1.5, 0.2, -0.8}));
        if (!froxel) {
            f.fog.enabled = true;
            f.fog.steps = 32;
            f.fog.shadowKernel = 3;
            return out;
        }
        postfx::FroxelFogSettings& x = f.froxelFog;
        x.enabled = true;
        x.grid = {16, 9, 32};
        x.temporal.enabled = false;
        x.localShadowFilter = true;
        postfx::FogVolume box;
        box.center = h.position({-2.0, 1.0, -12.0});
        box.halfSize = glm::vec3(h.extent({3.0, 1.5, 2.0}));
        box.density = 0.2f;
        box.edgeFalloff = float(h.length(0.5));
        postfx::FogVolume sphere;
        sphere.shape = postfx::FogVolumeShape::Sphere;
        sphere.center = h.position({4.0, 2.0, -18.0});
        sphere.radius = float(h.length(3.0));
        sphere.density = 0.3f;
        sphere.edgeFalloff = float(h.length(1.0));
        out.volumes = {box, sphere};
        x.volumes = out.volumes.data();
        x.volumeCount = 2;

        postfx::LocalLight point;
        point.position = h.position({1.0, 2.5, -8.0});
        point.intensity = {300.0f, 250.0f, 200.0f};
        point.range = float(h.length(25.0));
        point.sourceRadius = float(h.length(0.2));
        postfx::LocalLight spot;
        spot.type = postfx::LightType::Spot;
        spot.position = h.position(kSpot);
        spot.direction = glm::vec3(h.direction(kSpotAxis));
        spot.intensity = {3000.0f, 3000.0f, 2600.0f};
        spot.range = float(h.length(30.0));
        spot.sourceRadius = float(h.length(0.1));
        spot.innerConeAngle = 0.3f;
        spot.outerConeAngle = 0.55f;
        spot.shadow = 0;
        out.lights = {point, spot};
        f.lights = out.lights.data();
        f.lightCount = 2;
        postfx::LocalShadow shadow;
        shadow.faces[0].extent = {32, 32};
        shadow.faces[0].worldToClip = h.worldToClip(spotShadowMatrix());
        shadow.depthBias = 0.001f;
        out.shadows = {shadow};
        f.localShadows.shadows = out.shadows.data();
        f.localShadows.shadowCount = 1;
        return out;
    }

    // The images every host draws (the y-up metre host's camera): ground below the horizon, a tower 90 m
    // away, sky elsewhere; and each pixel's surface point for the lookup (3 km along the ray for the sky).
    FogHarnessImages images(bool froxel, std::vector<glm::dvec3>& points) const {
        const postfx::CameraInput camera = hostCamera(kHosts[0]);
        const auto distance = [&](uint32_t i, uint32_t j) {
            const glm::dvec3 d = pixelDirection(camera, i, j, kWidth, kHeight);
            if (d.y < -1e-3) return std::min(kEye.y / -d.y, 4000.0);
            if (i >= 40 && i < 48) return 90.0;
            return std::numeric_limits<double>::infinity();
        };
        points.clear();
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const double d = distance(i, j);
                points.push_back(kEye + pixelDirection(camera, i, j, kWidth, kHeight) *
                                            (std::isinf(d) ? 3000.0 : d));
            }
        FogHarnessImages im = surfaceImages(
            camera, kWidth, kHeight, distance,
            [](uint32_t i, uint32_t j, int c) { return 10.0f + 2.0f * float((i * 7 + j * 3 + c) % 11); });
        im.shadow = squareCaster(0.4f);
        im.shadowWidth = im.shadowHeight = 32;
        if (froxel) {
            im.localShadow = squareCaster(0.6f);
            im.localShadowWidth = im.localShadowHeight = 32;
        }
        return im;
    }

    struct Rendered {
        std::vector<float> color;
        LookupProbe probe;
    };

    // Host `h`'s frame rendered in a context of its world frame, and the lookup at `points` (postfx's frame)
    // given in its frame.
    Rendered render(const TestHost& h, bool froxel, const FogHarnessImages& im,
                    const std::vector<glm::dvec3>& points) {
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        info.depth.infiniteFar = false;
        info.world = h.world;
        std::unique_ptr<postfx::Context> context;
        Rendered r;
        EXPECT_TRUE(createContext(context, info).ok());
        if (!context) return r;
        HostFrame hf = frameFor(h, froxel);
        hf.frame.volumetricsLookup.extent = {32, 18, 32};
        hf.frame.volumetricsLookup.nearDistance = 0.5f;
        hf.frame.volumetricsLookup.maxDistance = 5000.0f;
        std::vector<glm::vec4> hostPoints;
        for (const glm::dvec3& p : points)
            hostPoints.push_back(glm::vec4(glm::vec3(h.position(p)), 0.0f));
        const postfx::Status s =
            runLookupProbe(*host, gpu, *context, hf.frame, im, hostPoints, r.color, r.probe);
        EXPECT_TRUE(s.ok()) << h.name << ": " << s.message;
        return r;
    }

    // Every host's image and lookup against the y-up metre host's: the largest difference relative to
    // the value (radiance: to at least 1e-3 of the image's mean; transmittance absolute), within the file
    // comment's bounds.
    void expectTheSameImage(bool froxel) {
        std::vector<glm::dvec3> points;
        const FogHarnessImages im = images(froxel, points);
        const Rendered reference = render(kHosts[0], froxel, im, points);
        ASSERT_EQ(reference.color.size(), im.color.size());
        double mean = 0.0, changed = 0.0;
        for (size_t k = 0; k < reference.color.size(); ++k) {
            mean += reference.color[k] / double(reference.color.size());
            changed = std::max(changed, std::abs(double(reference.color[k]) - im.color[k]) / im.color[k]);
        }
        EXPECT_GT(changed, 0.5);  // the effects do something
        const double floor = 1e-3 * mean;
        for (size_t k = 1; k < std::size(kHosts); ++k) {
            const TestHost& h = kHosts[k];
            const Rendered r = render(h, froxel, im, points);
            ASSERT_EQ(r.color.size(), reference.color.size()) << h.name;
            double image = 0.0, radiance = 0.0, transmittance = 0.0;
            size_t above = 0;
            for (size_t p = 0; p < reference.color.size(); ++p) {
                if (p % 4 == 3) continue;
                const double a = r.color[p], b = reference.color[p];
                const double d = std::abs(a - b) / std::max(std::abs(b), floor);
                image = std::max(image, d);
                above += d > 1e-5 ? 1 : 0;
            }
            const double aboveShare = double(above) / double(reference.color.size() / 4 * 3);
            for (size_t p = 0; p < points.size(); ++p)
                for (int c = 0; c < 3; ++c) {
                    const double a = r.probe.L[p][c], b = reference.probe.L[p][c];
                    radiance = std::max(radiance, std::abs(a - b) / std::max(std::abs(b), floor));
                    transmittance =
                        std::max(transmittance, double(std::abs(r.probe.T[p][c] - reference.probe.T[p][c])));
                }
            std::printf(
                "[ world frame ] %s, %s: largest differences image %.3g (%.2g%% of channels above 1e-5), "
                "lookup L %.3g, T %.3g\n",
                froxel ? "froxel fog" : "ray-marched fog", h.name, image, 100.0 * aboveShare, radiance,
                transmittance);
            if (h.exact()) {
                EXPECT_EQ(image, 0.0) << h.name;
                EXPECT_LT(radiance, 1e-5) << h.name;
                EXPECT_LT(transmittance, 1e-5) << h.name;
            } else {
                EXPECT_LT(image, 3e-3) << h.name;
                EXPECT_LT(aboveShare, 0.05) << h.name;
                EXPECT_LT(radiance, 3e-3) << h.name;
                EXPECT_LT(transmittance, 1e-3) << h.name;
            }
        }
    }

    postfx::core::Gpu gpu;
    postfx::core::GpuImage coverage, coverageFlipped;
};

TEST_F(FrameWorldFrameTest, EveryHostGetsTheRayMarchedFogsImage) {
    expectTheSameImage(false);
}

TEST_F(FrameWorldFrameTest, EveryHostGetsTheFroxelFogsImage) {
    expectTheSameImage(true);
}

// A centimetre z-up host's bad input is named by its own field, with its own value.
TEST_F(FrameWorldFrameTest, ChecksNameTheHostsFields) {
    const TestHost& h = kHosts[4];
    postfx::ContextCreateInfo info;
    info.world = h.world;
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context, info).ok());
    std::vector<glm::dvec3> points;
    const FogHarnessImages im = images(true, points);
    HostFrame hf = frameFor(h, true);
    hf.lights[1].sourceRadius = 3001.0f;  // beyond its range, 3000 cm
    FogHarness harness(*host, gpu);
    std::vector<float> color;
    const postfx::Status s = harness.run(*context, im, hf.frame, color);
    EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
    EXPECT_NE(s.message.find("FrameInfo.lights[1].sourceRadius: 3001"), std::string::npos) << s.message;
}

// The clouds' shadow transform of a host's frame reads the host's positions: the same uv as postfx's
// frame at the same point; the atmosphere's CPU evaluations the same.
TEST(FrameWorldFrameCpu, CloudShadowAndAtmosphereTakeTheHostsPositions) {
    postfx::FrameInfo f;
    f.clouds.enabled = true;
    f.clouds.shape = postfx::CloudShape::Box;
    f.clouds.box.yawDeg = 20.0f;
    const glm::dvec3 x{120.0, 35.0, -410.0};
    for (const TestHost& h : kHosts) {
        postfx::FrameInfo g = f;
        g.camera = hostCamera(h);
        g.sun.toSun = glm::vec3(h.direction(kToSun));
        g.clouds.box.center = h.position(f.clouds.box.center);
        g.clouds.box.halfSize = glm::vec3(h.extent(f.clouds.box.halfSize));
        g.clouds.box.yawDeg = f.clouds.box.yawDeg * float(glm::determinant(h.axes));
        postfx::FrameInfo y = f;
        y.camera = hostCamera(kHosts[0]);
        y.sun.toSun = glm::vec3(kToSun);
        const postfx::CloudShadowTransform a = postfx::cloudShadowTransform(g, h.world);
        const postfx::CloudShadowTransform b = postfx::cloudShadowTransform(y);
        const glm::dvec3 p = h.position(x);
        const auto uv = [](const postfx::CloudShadowTransform& t, const glm::dvec3& q) {
            return glm::dvec2(glm::dot(glm::dvec3(t.u), q) + t.u.w, glm::dot(glm::dvec3(t.v), q) + t.v.w);
        };
        const glm::dvec2 hostUv = uv(a, p), uv0 = uv(b, x);
        EXPECT_NEAR(hostUv.x, uv0.x, 1e-12) << h.name;
        EXPECT_NEAR(hostUv.y, uv0.y, 1e-12) << h.name;
        EXPECT_GT(uv0.x, 0.0);
        EXPECT_LT(uv0.x, 1.0);

        const postfx::AtmosphereSettings air;
        const glm::vec3 t0 = postfx::atmosphereSunTransmittance(air, x, glm::vec3(kToSun));
        const glm::vec3 t =
            postfx::atmosphereSunTransmittance(air, p, glm::vec3(h.direction(kToSun)), h.world);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(t[c], t0[c], 1e-6) << h.name;
    }
}

}  // namespace
