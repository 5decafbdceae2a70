// AtmosphereSettings' checks (atmosphere_settings.cpp): the defaults pass; every bad value is rejected with
// a message naming its key under effects.atmosphere.
#include "atmosphere/atmosphere_settings.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using postfx::AtmosphereSettings;
using postfx::Result;

// The paper's LUTs, but for a finer transmittance LUT and the scattering orders by default.
TEST(AtmosphereSettings, DefaultsAreValidAndArePapers) {
    const AtmosphereSettings s;
    const postfx::Status st = postfx::validateAtmosphereSettings(s);
    EXPECT_TRUE(st.ok()) << st.message;
    EXPECT_FALSE(s.enabled);
    EXPECT_EQ(s.transmittanceLutSize, postfx::UVec2(512, 128));
    EXPECT_EQ(s.transmittanceSteps, 80u);
    EXPECT_EQ(s.multipleScattering, postfx::AtmosphereMultipleScattering::Orders);
    EXPECT_EQ(s.scatteringOrdersLutSize, postfx::UVec3(32, 64, 16));
    EXPECT_EQ(s.scatteringOrders, 4u);
    EXPECT_EQ(s.multipleScatteringLutSize, postfx::UVec2(32, 32));
    EXPECT_EQ(s.multipleScatteringDirections, 64u);
    EXPECT_EQ(s.multipleScatteringSteps, 20u);
    EXPECT_EQ(s.skyViewLutSize, postfx::UVec2(192, 108));
    EXPECT_EQ(s.skyViewSteps, 30u);
    EXPECT_EQ(s.aerialPerspectiveLutSize, postfx::UVec3(32, 32, 32));
    EXPECT_FLOAT_EQ(s.aerialPerspectiveDistance / float(s.aerialPerspectiveLutSize.z), 1000.0f);
}

struct BadCase {
    const char* key;  // expected at the start of the message
    std::function<void(AtmosphereSettings&)> mutate;
};

TEST(AtmosphereSettings, BadValuesNameTheirKey) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<BadCase> cases = {
        {"atmosphere.ground_radius", [](AtmosphereSettings& s) { s.groundRadius = 0.0f; }},
        {"atmosphere.ground_radius", [&](AtmosphereSettings& s) { s.groundRadius = nan; }},
        {"atmosphere.top_radius", [](AtmosphereSettings& s) { s.topRadius = s.groundRadius; }},
        {"atmosphere.top_radius", [](AtmosphereSettings& s) { s.topRadius = 1e9f; }},
        {"atmosphere.rayleigh_scattering", [](AtmosphereSettings& s) { s.rayleighScattering.y = -1e-6f; }},
        {"atmosphere.rayleigh_scattering", [&](AtmosphereSettings& s) { s.rayleighScattering.z = inf; }},
        {"atmosphere.rayleigh_scale_height", [](AtmosphereSettings& s) { s.rayleighScaleHeight = 0.0f; }},
        {"atmosphere.mie_scattering", [&](AtmosphereSettings& s) { s.mieScattering = nan; }},
        {"atmosphere.mie_absorption", [](AtmosphereSettings& s) { s.mieAbsorption = -1.0f; }},
        {"atmosphere.mie_scale_height", [](AtmosphereSettings& s) { s.mieScaleHeight = -5.0f; }},
        {"atmosphere.mie_anisotropy", [](AtmosphereSettings& s) { s.mieAnisotropy = 1.0f; }},
        {"atmosphere.mie_anisotropy", [](AtmosphereSettings& s) { s.mieAnisotropy = -1.0f; }},
        {"atmosphere.mie_anisotropy", [&](AtmosphereSettings& s) { s.mieAnisotropy = nan; }},
        {"atmosphere.ozone_absorption", [](AtmosphereSettings& s) { s.ozoneAbsorption.x = -1e-9f; }},
        {"atmosphere.ozone_center_height", [&](AtmosphereSettings& s) { s.ozoneCenterHeight = inf; }},
        {"atmosphere.ozone_half_width", [](AtmosphereSettings& s) { s.ozoneHalfWidth = 0.0f; }},
        {"atmosphere.ground_albedo", [](AtmosphereSettings& s) { s.groundAlbedo.y = 1.5f; }},
        {"atmosphere.sun_angular_radius_deg", [](AtmosphereSettings& s) { s.sunAngularRadiusDeg = 90.0f; }},
        {"atmosphere.transmittance_lut_size", [](AtmosphereSettings& s) { s.transmittanceLutSize.y = 2; }},
        {"atmosphere.transmittance_steps", [](AtmosphereSettings& s) { s.transmittanceSteps = 0; }},
        {"atmosphere.multiple_scattering_lut_size",
         [](AtmosphereSettings& s) { s.multipleScatteringLutSize.x = 2000; }},
        {"atmosphere.multiple_scattering_directions",
         [](AtmosphereSettings& s) { s.multipleScatteringDirections = 60; }},
        {"atmosphere.multiple_scattering_steps",
         [](AtmosphereSettings& s) { s.multipleScatteringSteps = 5000; }},
        {"atmosphere.multiple_scattering",
         [](AtmosphereSettings& s) { s.multipleScattering = postfx::AtmosphereMultipleScattering(7); }},
        {"atmosphere.scattering_orders_lut_size",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.x = 65; }},
        {"atmosphere.scattering_orders_lut_size",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.y = 129; }},
        {"atmosphere.scattering_orders_lut_size",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.z = 3; }},
        {"atmosphere.scattering_orders_azimuth_size",
         [](AtmosphereSettings& s) { s.scatteringOrdersAzimuthSize = 17; }},
        {"atmosphere.scattering_orders_directions",
         [](AtmosphereSettings& s) { s.scatteringOrdersDirections = 100 + 1; }},
        {"atmosphere.scattering_orders_directions",
         [](AtmosphereSettings& s) { s.scatteringOrdersDirections = 625; }},
        {"atmosphere.scattering_orders_steps", [](AtmosphereSettings& s) { s.scatteringOrdersSteps = 0; }},
        {"atmosphere.scattering_orders", [](AtmosphereSettings& s) { s.scatteringOrders = 33; }},
        {"atmosphere.sky_view_lut_size", [](AtmosphereSettings& s) { s.skyViewLutSize.x = 0; }},
        {"atmosphere.sky_view_steps", [](AtmosphereSettings& s) { s.skyViewSteps = 0; }},
        {"atmosphere.aerial_perspective_lut_size",
         [](AtmosphereSettings& s) { s.aerialPerspectiveLutSize.z = 512; }},
        {"atmosphere.aerial_perspective_distance",
         [](AtmosphereSettings& s) { s.aerialPerspectiveDistance = 0.0f; }},
        {"atmosphere.aerial_perspective_steps_per_slice",
         [](AtmosphereSettings& s) { s.aerialPerspectiveStepsPerSlice = 0; }},
    };
    for (const BadCase& c : cases) {
        AtmosphereSettings s;
        c.mutate(s);
        const postfx::Status st = postfx::validateAtmosphereSettings(s);
        EXPECT_EQ(st.code, Result::InvalidArgument) << c.key;
        EXPECT_EQ(st.message.rfind(std::string(c.key) + ":", 0), 0u) << c.key << " -> " << st.message;
    }
}

TEST(AtmosphereSettings, TopRadiusMessageSaysWhy) {
    AtmosphereSettings s;
    s.topRadius = 6000e3f;
    const postfx::Status st = postfx::validateAtmosphereSettings(s);
    EXPECT_EQ(st.message, "atmosphere.top_radius: 6e+06 must be greater than ground_radius (6.36e+06)");
}

}  // namespace
