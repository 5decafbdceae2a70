// reference::renderAtmosphere (reference (a), docs/effects/atmosphere.md, "Reference"): its pixels against
// integrateViewRay, the sun disk, the ground hiding the host color, geometry pixels, the camera below the
// ground and in space, its input checks; and the fog references' sun through the atmosphere.
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_reference.h"

#include <postfx/reference.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace postfx;
using namespace postfx::atmosphere;

glm::mat4 perspective(float fovY, float aspect, float n, float f) {  // Vulkan, reversed Z
    const float s = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 m(0.0f);
    m[0][0] = s / aspect;
    m[1][1] = -s;
    m[2][3] = -1.0f;
    m[2][2] = n / (f - n);
    m[3][2] = f * n / (f - n);
    return m;
}

struct Frame {
    uint32_t w = 5, h = 5;
    std::vector<float> color, depth;
    reference::AtmosphereInputs in;
    Frame() {
        color.assign(size_t(w) * h * 4, 0.0f);
        for (size_t p = 0; p < size_t(w) * h; ++p) {
            color[p * 4 + 0] = 1.0f;
            color[p * 4 + 1] = 2.0f;
            color[p * 4 + 2] = 3.0f;
            color[p * 4 + 3] = 0.5f;
        }
        depth.assign(size_t(w) * h, 0.0f);  // reversed Z: no geometry
        in.width = w;
        in.height = h;
        in.depthConvention.reversedZ = true;
        in.camera.position = DVec3(0.0, 2.0, 0.0);
        in.camera.projection = perspective(0.5f, 1.0f, 0.1f, 1e5f);
        in.sun.toSun = glm::normalize(glm::vec3(0.0f, 0.5f, -1.0f));
        in.sun.illuminance = Vec3(100000.0f);
        in.settings.enabled = true;
        in.stepsPerPixel = 128;
        in.psiDirections = 16;
        in.psiSteps = 10;
        in.psiTableMuS = 16;
        in.psiTableHeights = 16;
        // A small scattering-orders table (the default model), built once for every test here.
        in.ordersViewNodes = 16;
        in.ordersSunNodes = 16;
        in.ordersHeightNodes = 8;
        in.ordersAzimuthNodes = 4;
        in.ordersDirections = 144;
        in.ordersSteps = 32;
        in.ordersCount = 4;
        in.threads = 2;
    }
    // Looking along `forward` (world), up +y unless forward is vertical.
    void look(const glm::vec3& forward) {
        const glm::vec3 up = std::abs(forward.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        in.camera.view = glm::lookAt(glm::vec3(0.0f), forward, up);
    }
    std::vector<float> render() {
        in.color = color;
        in.depth = depth;
        std::vector<float> out;
        const Status s = reference::renderAtmosphere(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
    size_t centre() const { return (size_t(h / 2) * w + w / 2) * 4; }
};

// The same ray through integrateViewRay with the renderer's tables (shared: the same ones).
ViewRayResult expectedRay(const Frame& f, const glm::dvec3& dir, bool ground, double maxDistance) {
    const Model m = modelFrom(f.in.settings);
    const auto transmittance = sharedTransmittanceTable(m);
    PsiTableOptions po;
    po.muSSize = f.in.psiTableMuS;
    po.heightSize = f.in.psiTableHeights;
    po.psi.directions = f.in.psiDirections;
    po.psi.steps = f.in.psiSteps;
    const auto psi = sharedPsiTable(m, po);
    const auto orders = sharedOrdersTable(m, ordersOptionsFrom(f.in));
    ViewRayOptions o;
    o.steps = f.in.stepsPerPixel;
    o.transmittanceTable = transmittance.get();
    o.psiTable = psi.get();
    if (f.in.settings.multipleScattering == postfx::AtmosphereMultipleScattering::Orders)
        o.ordersTable = orders.get();
    o.ground = ground;
    o.maxDistance = maxDistance;
    Sun sun;
    sun.toSun = glm::normalize(glm::dvec3(f.in.sun.toSun));
    sun.illuminance = glm::dvec3(f.in.sun.illuminance);
    const glm::dvec3 origin = clampAboveGround(m, planetCentred(m, glm::dvec3(f.in.camera.position)));
    return integrateViewRay(m, origin, dir, sun, o);
}

TEST(AtmosphereReferenceImage, SkyPixelIsSkyPlusHostThroughTransmittance) {
    Frame f;
    f.look({1.0f, 0.2f, 0.0f});
    const std::vector<float> out = f.render();
    const ViewRayResult r = expectedRay(f, glm::normalize(glm::dvec3(1.0, 0.2, 0.0)), true, INFINITY);
    const size_t p = f.centre();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out[p + c], r.luminance[c] + f.color[p + c] * r.transmittance[c], 1e-4 * out[p + c]);
    EXPECT_EQ(out[p + 3], 0.5f);
}

TEST(AtmosphereReferenceImage, GroundHidesHostColorAndIsLit) {
    Frame f;
    f.look({1.0f, -0.3f, 0.0f});
    const std::vector<float> out = f.render();
    const ViewRayResult r = expectedRay(f, glm::normalize(glm::dvec3(1.0, -0.3, 0.0)), true, INFINITY);
    const size_t p = f.centre();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out[p + c], r.luminance[c], 1e-4 * out[p + c]);  // no host color
    EXPECT_GT(out[p], 0.0f);
}

TEST(AtmosphereReferenceImage, GeometryPixelIsAttenuatedAndInScattered) {
    Frame f;
    f.look({1.0f, 0.0f, 0.0f});
    // Reversed Z: z = n(f - d)/(d(f - n)) at view depth d = 5 km (the centre pixel's ray is the axis).
    const double n = 0.1, far = 1e5, d = 5000.0;
    f.depth.assign(f.depth.size(), float(n * (far - d) / (d * (far - n))));
    const std::vector<float> out = f.render();
    const size_t p = f.centre();
    const ViewRayResult r = expectedRay(f, glm::dvec3(1.0, 0.0, 0.0), false, d);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out[p + c], f.color[p + c] * r.transmittance[c] + r.luminance[c], 2e-3 * out[p + c]);
    EXPECT_LT(r.transmittance.z, 0.99);
    EXPECT_GT(r.luminance.z, 0.0);
}

TEST(AtmosphereReferenceImage, SunDiskIsDrawnWithItsRadiance) {
    Frame f;
    f.in.settings.sunAngularRadiusDeg = 5.0f;  // wide enough for the centre pixel
    f.in.sun.toSun = glm::vec3(1.0f, 0.3f, 0.0f);
    f.look(f.in.sun.toSun);
    const std::vector<float> withDisk = f.render();
    f.in.settings.sunAngularRadiusDeg = 0.0f;
    const std::vector<float> without = f.render();
    const size_t p = f.centre();
    const double alpha = 5.0 * 3.14159265358979 / 180.0;
    const ViewRayResult r = expectedRay(f, glm::normalize(glm::dvec3(1.0, 0.3, 0.0)), true, INFINITY);
    for (int c = 0; c < 3; ++c) {
        const double disk =
            100000.0 / (2.0 * 3.14159265358979 * (1.0 - std::cos(alpha))) * r.transmittance[c];
        EXPECT_NEAR(withDisk[p + c] - without[p + c], disk, 1e-3 * disk);
    }
    EXPECT_EQ(withDisk[0], without[0]);  // a corner outside the disk
}

TEST(AtmosphereReferenceImage, CameraBelowGroundInSpaceAndDisabled) {
    Frame f;
    f.look({1.0f, 0.1f, 0.0f});
    f.in.camera.position = DVec3(0.0, -500.0, 0.0);  // clamped onto the ground: as at y = 0
    const std::vector<float> below = f.render();
    f.in.camera.position = DVec3(0.0, 0.0, 0.0);
    const std::vector<float> ground = f.render();
    EXPECT_EQ(below, ground);
    f.in.camera.position = DVec3(0.0, 1e7, 0.0);
    f.look({0.0f, -1.0f, 0.0f});  // the planet from space
    for (float v : f.render())
        EXPECT_TRUE(std::isfinite(v) && v >= 0.0f);
    f.look({0.0f, 1.0f, 0.0f});  // away from it: the host color
    const std::vector<float> away = f.render();
    EXPECT_EQ(away, f.color);
    f.in.settings.enabled = false;
    EXPECT_EQ(f.render(), f.color);
}

TEST(AtmosphereReferenceImage, BadInputsNameTheField) {
    const auto message = [](Frame& f) {
        f.in.color = f.color;
        f.in.depth = f.depth;
        std::vector<float> out;
        const Status s = reference::renderAtmosphere(f.in, out);
        EXPECT_FALSE(s.ok());
        return s.message;
    };
    Frame a;
    a.depth.pop_back();
    EXPECT_NE(message(a).find("AtmosphereInputs.depth"), std::string::npos);
    Frame b;
    b.in.settings.topRadius = 1.0f;
    EXPECT_NE(message(b).find("FrameInfo.atmosphere.topRadius"), std::string::npos);
    Frame c;
    c.in.stepsPerPixel = 0;
    EXPECT_NE(message(c).find("AtmosphereInputs.stepsPerPixel"), std::string::npos);
    Frame d;
    d.in.psiDirections = 15;
    EXPECT_NE(message(d).find("AtmosphereInputs.psiDirections"), std::string::npos);
    Frame e;
    e.in.sun.toSun = Vec3(0.0f);
    EXPECT_NE(message(e).find("sun.toSun"), std::string::npos);
}

// The fog reference with the atmosphere on, the sun at noon, the camera on the ground looking horizontally
// through homogeneous fog (no ambient, no self-shadowing): every sample's sun is attenuated by the zenith
// transmittance from the ground (the samples stay within millimetres of it), so the fog's light is the
// atmosphere-off light times T_zenith per channel; with the sun below the horizon the fog gets none.
TEST(AtmosphereFogReference, SunAtNoonIsAttenuatedByTheZenithTransmittance) {
    const uint32_t w = 3, h = 3;
    std::vector<float> color(w * h * 4, 0.0f), depth(w * h, 0.0f);
    reference::FogInputs in;
    in.width = w;
    in.height = h;
    in.color = color;
    in.depth = depth;
    in.depthConvention.reversedZ = true;
    in.camera.projection = perspective(0.5f, 1.0f, 0.1f, 1000.0f);
    in.sun.toSun = Vec3(0.0f, 1.0f, 0.0f);
    in.sun.illuminance = Vec3(1000.0f);
    in.settings.enabled = true;
    in.settings.density = 0.01f;
    in.settings.heightFalloff = 0.0f;
    in.settings.selfShadow = false;
    in.settings.maxDistance = 200.0f;
    in.stepsPerPixel = 64;
    in.threads = 2;
    std::vector<float> off, on;
    ASSERT_TRUE(reference::renderFog(in, off).ok());
    in.atmosphere.enabled = true;
    ASSERT_TRUE(reference::renderFog(in, on).ok());
    const Model m;
    const glm::dvec3 T = sunTransmittance(m, {0.0, m.groundRadius, 0.0}, {0.0, 1.0, 0.0}, 4000);
    const size_t p = (1 * w + 1) * 4;
    for (int c = 0; c < 3; ++c) {
        ASSERT_GT(off[p + c], 0.0f);
        EXPECT_NEAR(on[p + c] / off[p + c], T[c], 2e-4) << "channel " << c;
    }
    // The froxel fog's reference likewise.
    reference::FroxelFogInputs fin;
    fin.width = w;
    fin.height = h;
    fin.color = color;
    fin.depth = depth;
    fin.depthConvention.reversedZ = true;
    fin.camera = in.camera;
    fin.sun = in.sun;
    fin.settings.enabled = true;
    fin.settings.density = 0.01f;
    fin.settings.heightFalloff = 0.0f;
    fin.settings.selfShadow = false;
    fin.settings.maxDistance = 200.0f;
    fin.stepsPerPixel = 64;
    fin.threads = 2;
    std::vector<float> froxelOff, froxelOn;
    ASSERT_TRUE(reference::renderFroxelFog(fin, froxelOff).ok());
    fin.atmosphere.enabled = true;
    ASSERT_TRUE(reference::renderFroxelFog(fin, froxelOn).ok());
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(froxelOn[p + c] / froxelOff[p + c], T[c], 2e-4) << "froxel channel " << c;
    // Night: the planet hides the sun from every sample.
    in.sun.toSun = Vec3(0.0f, -0.2f, 1.0f);
    std::vector<float> night;
    ASSERT_TRUE(reference::renderFog(in, night).ok());
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(night[p + c], 0.0f);
    // A bad atmosphere is named.
    in.atmosphere.mieAnisotropy = 1.0f;
    std::vector<float> bad;
    const Status s = reference::renderFog(in, bad);
    EXPECT_NE(s.message.find("FrameInfo.atmosphere.mieAnisotropy"), std::string::npos) << s.message;
}

}  // namespace
