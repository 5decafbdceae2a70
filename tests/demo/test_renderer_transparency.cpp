// The demo renderer's forward pass (transparent objects and particles, drawn after postfx through its
// volumetrics lookup; demo/host/forward_pass.*): an object drawn forward at opacity 1 equals the same object
// drawn opaque (no effects; postfx's froxel fog, ray-marched fog and aerial perspective), a half-transparent
// quad in homogeneous fog against the closed form, a quad in front of the clouds gets none of them, and the
// transparent scenes render under the validation layer.
// The tests that need postfx's volumetrics lookup are  until the library builds it (until then
// the forward pass draws unfogged): enable them then.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace test {
namespace {

const std::string kScenesDir = POSTFX_DEMO_SCENES_DIR;
constexpr uint32_t kW = 96, kH = 54;

// The quad: a thin box facing +z, its front face at z = centre.z + kHalfDepth.
constexpr float kHalfDepth = 0.05f;

struct QuadStats {
    size_t pixels = 0;
    double meanRelative = 0.0;  // over the quad's pixels and RGB
    double maxRelative = 0.0;
};

// A camera at `eye` looking along -z (up +y), fov 60°.
demo::Camera cameraAlongMinusZ(glm::vec3 eye, float far) {
    demo::Camera c;
    c.position = eye;
    c.lookAt = eye + glm::vec3(0.0f, 0.0f, -1.0f);
    c.fovYDeg = 60.0f;
    c.nearPlane = 0.1f;
    c.farPlane = far;
    return c;
}

demo::Object quad(glm::vec3 centre, glm::vec2 half, glm::vec3 albedo) {
    demo::Object o;
    o.type = demo::ObjectType::Box;
    o.position = centre;
    o.halfSize = {half.x, half.y, kHalfDepth};
    o.albedo = albedo;
    return o;
}

// Whether pixel (x, y) of a camera along -z sees the front face of `q` within 80 % of its half sizes
// (away from its edges, where pixels straddle the quad and the background).
bool insideQuad(const demo::Camera& camera, const demo::Object& q, uint32_t x, uint32_t y) {
    const double tanHalf = std::tan(glm::radians(double(camera.fovYDeg)) / 2.0);
    const double aspect = double(kW) / kH;
    const double nx = (x + 0.5) / kW * 2.0 - 1.0, ny = (y + 0.5) / kH * 2.0 - 1.0;
    const glm::dvec3 dir(nx * tanHalf * aspect, -ny * tanHalf, -1.0);
    const double s = double(camera.position.z) - (double(q.position.z) + q.halfSize.z);
    const glm::dvec3 p = glm::dvec3(camera.position) + dir * s;
    return std::abs(p.x - q.position.x) < 0.8 * q.halfSize.x &&
           std::abs(p.y - q.position.y) < 0.8 * q.halfSize.y;
}

QuadStats compareOnQuad(const demo::ImageF& a, const demo::ImageF& b, const demo::Camera& camera,
                        const demo::Object& q) {
    QuadStats s;
    for (uint32_t y = 0; y < kH; ++y) {
        for (uint32_t x = 0; x < kW; ++x) {
            if (!insideQuad(camera, q, x, y)) continue;
            ++s.pixels;
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * kW + x) * 4 + c;
                const double r =
                    std::abs(double(a.rgba[i]) - b.rgba[i]) / std::max(std::abs(double(b.rgba[i])), 1e-9);
                s.meanRelative += r / 3.0;
                s.maxRelative = std::max(s.maxRelative, r);
            }
        }
    }
    if (s.pixels) s.meanRelative /= double(s.pixels);
    return s;
}

class DemoRendererTransparency : public GpuTest {
protected:
    demo::ImageF render(const demo::Scene& scene) {
        demo::RenderOptions o;
        o.width = kW;
        o.height = kH;
        o.shadowMapSize = 512;
        std::string error;
        auto renderer = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(renderer) << error;
        demo::ImageF image;
        if (renderer) {
            EXPECT_TRUE(renderer->render(scene, image, error)) << error;
        }
        return image;
    }

    // `scene` with its object `index` drawn opaque and drawn forward at opacity 1, compared on its pixels.
    QuadStats forwardAgainstOpaque(demo::Scene scene, size_t index) {
        const demo::ImageF opaque = render(scene);
        scene.objects[index].forward = true;
        const demo::ImageF forward = render(scene);
        EXPECT_EQ(opaque.rgba.size(), size_t(kW) * kH * 4);
        EXPECT_EQ(forward.rgba.size(), opaque.rgba.size());
        if (forward.rgba.size() != opaque.rgba.size() || opaque.rgba.empty()) return {};
        const QuadStats s = compareOnQuad(forward, opaque, scene.camera, scene.objects[index]);
        EXPECT_GT(s.pixels, 50u);
        return s;
    }
};

// A lit quad 40 m ahead over a ground plane, sun (with its shadow map) from behind the camera, ambient, and
// a shadowed spot light on the quad.
demo::Scene quadScene() {
    demo::Scene s;
    s.camera = cameraAlongMinusZ({0.0f, 2.0f, 0.0f}, 1000.0f);
    s.camera.ev100 = 13.0f;
    s.sun.direction = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    s.sun.illuminance = glm::vec3(20000.0f);
    s.sun.shadows = true;
    s.ambient = glm::vec3(500.0f, 600.0f, 800.0f);
    s.sky = glm::vec3(2000.0f, 3000.0f, 5000.0f);
    demo::Object ground;
    ground.albedo = glm::vec3(0.3f);
    s.objects.push_back(ground);
    s.objects.push_back(quad({0.0f, 4.0f, -40.0f}, {8.0f, 4.0f}, {0.6f, 0.5f, 0.4f}));
    demo::Light spot;
    spot.kind = demo::LightKind::Spot;
    spot.position = {2.0f, 6.0f, -30.0f};
    spot.direction = glm::normalize(glm::vec3(-0.2f, -0.2f, -1.0f));
    spot.intensity = glm::vec3(2e5f);
    spot.range = 40.0f;
    spot.outerAngleDeg = 25.0f;
    spot.shadows = true;
    s.lights.push_back(spot);
    return s;
}

// Without effects the lookup is the identity (T = 1, L = 0): the forward pass lights a surface exactly as
// the deferred lighting does.
TEST_F(DemoRendererTransparency, ForwardQuadLitAsTheGBufferWithoutEffects) {
    const QuadStats s = forwardAgainstOpaque(quadScene(), 1);
    EXPECT_LT(s.meanRelative, 1e-3) << "max " << s.maxRelative;
    EXPECT_LT(s.maxRelative, 1e-2);
}

// The froxel fog (grid 160x90x128, the lookup's x, y matching it: 160x90x128, near 0.5 m, max 200 m).
TEST_F(DemoRendererTransparency, ForwardQuadMatchesTheFroxelFog) {
    demo::Scene scene = quadScene();
    scene.froxelFog.enabled = true;
    scene.froxelFog.density = 0.03f;
    scene.froxelFog.heightFalloff = 0.0f;
    scene.froxelFog.noise.enabled = false;
    scene.froxelFog.maxDistance = 150.0f;
    scene.froxelFog.grid = {160, 90, 128};
    scene.volumetricsLookup.extent = {160, 90, 128};
    scene.volumetricsLookup.nearDistance = 0.5f;
    scene.volumetricsLookup.maxDistance = 200.0f;
    const QuadStats s = forwardAgainstOpaque(scene, 1);
    std::printf("froxel fog: %zu pixels, mean %.4f%%, max %.4f%%\n", s.pixels, 100 * s.meanRelative,
                100 * s.maxRelative);
    EXPECT_LT(s.meanRelative, 0.005);
    EXPECT_LT(s.maxRelative, 0.01);  // the bound for the froxel fog, at every pixel
}

// The ray-marched fog, integrated by the lookup at 160x90x128 (near 0.5 m, max 200 m).
TEST_F(DemoRendererTransparency, ForwardQuadMatchesTheRayMarchedFog) {
    demo::Scene scene = quadScene();
    scene.fog.enabled = true;
    scene.fog.density = 0.03f;
    scene.fog.heightFalloff = 0.0f;
    scene.fog.noise.enabled = false;
    scene.fog.maxDistance = 150.0f;
    scene.volumetricsLookup.extent = {160, 90, 128};
    scene.volumetricsLookup.nearDistance = 0.5f;
    scene.volumetricsLookup.maxDistance = 200.0f;
    const QuadStats s = forwardAgainstOpaque(scene, 1);
    std::printf("ray-marched fog: %zu pixels, mean %.4f%%, max %.4f%%\n", s.pixels, 100 * s.meanRelative,
                100 * s.maxRelative);
    EXPECT_LT(s.meanRelative, 0.01);
    EXPECT_LT(s.maxRelative, 0.02);  // the bound for the ray-marched fog's volume
}

// The aerial perspective: a quad 2 km away through the atmosphere (lookup 160x90x64, near 1 m, max 10 km).
TEST_F(DemoRendererTransparency, ForwardQuadMatchesTheAerialPerspective) {
    demo::Scene scene = quadScene();
    scene.lights.clear();
    scene.camera.farPlane = 100000.0f;
    scene.camera.ev100 = 14.0f;
    scene.sun.illuminance = glm::vec3(120000.0f);
    scene.objects[1] = quad({0.0f, 300.0f, -2000.0f}, {400.0f, 250.0f}, {0.6f, 0.5f, 0.4f});
    scene.atmosphere.enabled = true;
    smallScatteringOrders(scene.atmosphere);
    const QuadStats s = forwardAgainstOpaque(scene, 1);
    std::printf("aerial perspective: %zu pixels, mean %.4f%%, max %.4f%%\n", s.pixels, 100 * s.meanRelative,
                100 * s.maxRelative);
    EXPECT_LT(s.meanRelative, 0.005);
    EXPECT_LT(s.maxRelative, 0.01);
}

// A half-transparent quad at d = 20 m in homogeneous fog lit by the ambient only (sun off), in front of a
// black wall at D = 60 m: L(t) = L∞ (1 - e^{-σ t}), T(t) = e^{-σ t}, L∞ = albedo · ambient; the pixel is
// (Q · T(d) + L(d)) · α + L(D) · (1 - α) with Q = albedo_q · ambient.
TEST_F(DemoRendererTransparency, HalfTransparentQuadInHomogeneousFogIsTheClosedForm) {
    constexpr double kSigma = 0.04, kD = 20.0, kWall = 60.0, kAlpha = 0.5, kFogAlbedo = 0.9,
                     kQuadAlbedo = 0.7;
    const glm::dvec3 ambient(400.0, 500.0, 600.0);
    demo::Scene scene;
    scene.camera = cameraAlongMinusZ({0.0f, 2.0f, 0.0f}, 500.0f);
    scene.camera.ev100 = 9.0f;
    scene.sun.illuminance = glm::vec3(0.0f);
    scene.sun.shadows = false;
    scene.ambient = glm::vec3(ambient);
    scene.objects.push_back(
        quad({0.0f, 2.0f, float(-kWall) - kHalfDepth}, {200.0f, 200.0f}, glm::vec3(0.0f)));
    demo::Object glass =
        quad({0.0f, 2.0f, float(-kD) - kHalfDepth}, {4.0f, 3.0f}, glm::vec3(float(kQuadAlbedo)));
    glass.opacity = float(kAlpha);
    scene.objects.push_back(glass);
    scene.fog.enabled = true;
    scene.fog.density = float(kSigma);
    scene.fog.albedo = glm::vec3(float(kFogAlbedo));
    scene.fog.heightFalloff = 0.0f;
    scene.fog.noise.enabled = false;
    scene.fog.maxDistance = 400.0f;
    scene.volumetricsLookup.extent = {96, 54, 128};
    scene.volumetricsLookup.maxDistance = 200.0f;
    const demo::ImageF image = render(scene);
    ASSERT_EQ(image.rgba.size(), size_t(kW) * kH * 4);

    size_t pixels = 0;
    double worst = 0.0, mean = 0.0;
    for (uint32_t y = 0; y < kH; ++y) {
        for (uint32_t x = 0; x < kW; ++x) {
            if (!insideQuad(scene.camera, glass, x, y)) continue;
            // Distances along the pixel's ray to the quad's and the wall's planes.
            const double tanHalf = std::tan(glm::radians(30.0));
            const double nx = (x + 0.5) / kW * 2.0 - 1.0, ny = (y + 0.5) / kH * 2.0 - 1.0;
            const double stretch = glm::length(glm::dvec3(nx * tanHalf * kW / kH, ny * tanHalf, 1.0));
            const double d = kD * stretch, wall = kWall * stretch;
            ++pixels;
            for (int c = 0; c < 3; ++c) {
                const double lInf = kFogAlbedo * ambient[c];
                const double t = std::exp(-kSigma * d);
                const double surface = kQuadAlbedo * ambient[c] * t + lInf * (1.0 - t);
                const double background = lInf * (1.0 - std::exp(-kSigma * wall));
                const double expected = surface * kAlpha + background * (1.0 - kAlpha);
                const double r = std::abs(image.rgba[(size_t(y) * kW + x) * 4 + c] - expected) / expected;
                worst = std::max(worst, r);
                mean += r / 3.0;
            }
        }
    }
    ASSERT_GT(pixels, 50u);
    mean /= double(pixels);
    std::printf("closed form: %zu pixels, mean %.4f%%, max %.4f%%\n", pixels, 100 * mean, 100 * worst);
    EXPECT_LT(mean, 0.005);
    EXPECT_LT(worst, 0.01);
}

// A quad 50 m ahead, looking up at the clouds (its visible faces turned from the sun: lit by the ambient
// only, so the clouds' shadow does not touch it): with the clouds on it is as without them, while the sky
// around it changes.
TEST_F(DemoRendererTransparency, QuadInFrontOfTheCloudsGetsNoCloud) {
    demo::Scene scene;
    scene.camera.position = {0.0f, 2.0f, 0.0f};
    scene.camera.lookAt = {0.0f, 2.7f, -1.0f};
    scene.camera.fovYDeg = 60.0f;
    scene.camera.farPlane = 100000.0f;
    scene.camera.ev100 = 14.0f;
    scene.sun.direction = glm::normalize(glm::vec3(0.0f, 0.6f, -0.8f));
    scene.sun.illuminance = glm::vec3(120000.0f);
    scene.sun.shadows = true;
    scene.ambient = glm::vec3(3000.0f);
    demo::Object q;
    q.type = demo::ObjectType::Box;
    q.position = {0.0f, 37.0f, -50.0f};
    q.halfSize = {10.0f, 8.0f, kHalfDepth};
    q.albedo = glm::vec3(0.5f);
    q.forward = true;
    scene.objects.push_back(q);
    scene.atmosphere.enabled = true;
    smallScatteringOrders(scene.atmosphere);
    demo::Scene clouds = scene;
    clouds.clouds.enabled = true;
    clouds.clouds.coverage = 0.8f;
    const demo::ImageF without = render(scene);
    const demo::ImageF with = render(clouds);
    ASSERT_EQ(without.rgba.size(), size_t(kW) * kH * 4);
    ASSERT_EQ(with.rgba.size(), without.rgba.size());
    // The quad covers the middle of the image; its corners are sky.
    const auto at = [&](const demo::ImageF& im, uint32_t x, uint32_t y, int c) {
        return double(im.rgba[(size_t(y) * kW + x) * 4 + c]);
    };
    double quadWorst = 0.0, skyChange = 0.0;
    for (uint32_t y = kH / 2 - 4; y < kH / 2 + 4; ++y)
        for (uint32_t x = kW / 2 - 6; x < kW / 2 + 6; ++x)
            for (int c = 0; c < 3; ++c)
                quadWorst = std::max(
                    quadWorst, std::abs(at(with, x, y, c) - at(without, x, y, c)) / at(without, x, y, c));
    for (uint32_t y = 0; y < 6; ++y)
        for (uint32_t x = 0; x < kW; ++x)
            skyChange +=
                std::abs(at(with, x, y, 1) - at(without, x, y, 1)) / at(without, x, y, 1) / (6.0 * kW);
    std::printf("clouds: quad max %.4f%%, sky mean change %.2f%%\n", 100 * quadWorst, 100 * skyChange);
    EXPECT_LT(quadWorst, 0.005);
    EXPECT_GT(skyChange, 0.05);  // the clouds are there around it
}

// The committed transparent scenes render (validation layer clean) and their forward pass draws: the glass
// pane differs from the same scene without it.
TEST_F(DemoRendererTransparency, TransparentScenesRender) {
    for (const char* name : {"transparent_noon.json", "transparent_sunset.json"}) {
        demo::Scene scene;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/" + name, scene, error)) << error;
        smallScatteringOrders(scene.atmosphere);
        ASSERT_TRUE(demo::hasForwardDraws(scene));
        const demo::ImageF image = render(scene);
        ASSERT_EQ(image.rgba.size(), size_t(kW) * kH * 4) << name;
        for (float v : image.rgba)
            ASSERT_TRUE(std::isfinite(v)) << name;
    }
}

}  // namespace
}  // namespace test
