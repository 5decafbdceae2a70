// The demo's surface lighting through the atmosphere (demo/host/atmosphere_lighting.h): off leaves the
// scene's sun, ambient and sky; on attenuates the sun by postfx's transmittance at the scene's altitudes,
// blacks the sky, takes the ambient from the sky; each part recomputed only when what it depends on changes.
#include "host/atmosphere_lighting.h"

#include <gtest/gtest.h>
#include <postfx/atmosphere.h>

#include <cmath>

namespace {

using demo::AtmosphereLightingCache;
using demo::Scene;

Scene scene() {
    Scene s;
    s.sun.direction = glm::normalize(glm::vec3(0.3f, 0.5f, -0.8f));
    s.sun.illuminance = glm::vec3(120000.0f);
    s.ambient = glm::vec3(1.0f, 2.0f, 3.0f);
    s.sky = glm::vec3(4.0f, 5.0f, 6.0f);
    demo::Object plane;
    demo::Object box;
    box.type = demo::ObjectType::Box;
    box.position = glm::vec3(0.0f, 300.0f, -1000.0f);
    box.halfSize = glm::vec3(100.0f, 200.0f, 100.0f);
    s.objects = {plane, box};
    return s;
}

TEST(DemoAtmosphereLighting, AltitudeRangeSpansTheObjects) {
    EXPECT_EQ(demo::sceneAltitudeRange(scene()), glm::vec2(0.0f, 500.0f));
    Scene s;
    EXPECT_EQ(demo::sceneAltitudeRange(s), glm::vec2(0.0f, 1.0f));  // none: the ground and 1 m
    demo::Object below;
    below.position.y = -50.0f;
    s.objects = {below};
    EXPECT_EQ(demo::sceneAltitudeRange(s), glm::vec2(0.0f, 1.0f));  // clamped onto the ground
}

TEST(DemoAtmosphereLighting, OffLeavesTheScene) {
    AtmosphereLightingCache cache;
    const Scene s = scene();
    const demo::AtmosphereLighting& l = cache.update(s);
    EXPECT_EQ(l.opticalDepthLow, glm::vec3(0.0f));
    EXPECT_EQ(l.opticalDepthHigh, glm::vec3(0.0f));
    EXPECT_EQ(l.ambient, s.ambient);
    EXPECT_EQ(l.sky, s.sky);
    EXPECT_EQ(cache.transmittanceUpdates(), 0u);
}

TEST(DemoAtmosphereLighting, OnAttenuatesTheSunAndRecomputesOnlyOnChange) {
    AtmosphereLightingCache cache;
    Scene s = scene();
    s.atmosphere.enabled = true;
    const demo::AtmosphereLighting l = cache.update(s);
    EXPECT_EQ(l.sky, glm::vec3(0.0f));
    EXPECT_EQ(l.ambient, s.ambient);  // ambient_from_sky off
    EXPECT_EQ(l.altitudeLow, 0.0f);
    EXPECT_EQ(l.altitudeHigh, 500.0f);
    const postfx::Vec3 t0 =
        postfx::atmosphereSunTransmittance(s.atmosphere, postfx::DVec3(0.0), s.sun.direction);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(l.opticalDepthLow[c], -std::log(t0[c]), 1e-6f);
        EXPECT_GT(l.opticalDepthLow[c], l.opticalDepthHigh[c]);  // less air above the higher point
        EXPECT_GT(l.opticalDepthHigh[c], 0.0f);
    }
    EXPECT_GT(l.opticalDepthLow.z, l.opticalDepthLow.x);  // blue is scattered most
    cache.update(s);
    EXPECT_EQ(cache.transmittanceUpdates(), 1u);
    s.sun.illuminance = glm::vec3(1000.0f);  // the transmittance does not depend on it
    cache.update(s);
    EXPECT_EQ(cache.transmittanceUpdates(), 1u);
    s.sun.direction = glm::normalize(glm::vec3(0.3f, 0.2f, -0.8f));
    const demo::AtmosphereLighting& low = cache.update(s);
    EXPECT_EQ(cache.transmittanceUpdates(), 2u);
    EXPECT_GT(low.opticalDepthLow.x, l.opticalDepthLow.x);  // a lower sun: a longer path
    s.atmosphere.mieScattering *= 2.0f;
    cache.update(s);
    EXPECT_EQ(cache.transmittanceUpdates(), 3u);
    // The sun below the horizon: no light, finite.
    s.sun.direction = glm::normalize(glm::vec3(0.3f, -0.2f, -0.8f));
    const demo::AtmosphereLighting& night = cache.update(s);
    EXPECT_EQ(night.opticalDepthLow, glm::vec3(demo::kMaxOpticalDepth));
}

TEST(DemoAtmosphereLighting, AmbientFromSkyIsTheSkyIrradianceOverPi) {
    AtmosphereLightingCache cache;
    Scene s = scene();
    s.atmosphere.enabled = true;
    s.atmosphere.ambientFromSky = true;
    const glm::vec3 ambient = cache.update(s).ambient;
    const postfx::Vec3 e =
        postfx::atmosphereSkyIrradiance(s.atmosphere, postfx::DVec3(0.0), s.sun.direction, s.sun.illuminance);
    for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(ambient[c], e[c] / 3.14159265f);
    EXPECT_GT(ambient.z, ambient.x);
    cache.update(s);
    EXPECT_EQ(cache.ambientUpdates(), 1u);
    s.sun.illuminance = glm::vec3(60000.0f);
    EXPECT_NEAR(cache.update(s).ambient.x, ambient.x / 2.0f, 1e-3f * ambient.x);
    EXPECT_EQ(cache.ambientUpdates(), 2u);
    s.ambient = glm::vec3(9.0f);  // not used while the sky gives it
    cache.update(s);
    EXPECT_EQ(cache.ambientUpdates(), 2u);
}

}  // namespace
