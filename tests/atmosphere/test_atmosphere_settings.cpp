// AtmosphereSettings' checks (atmosphere_settings.cpp): the defaults pass; every bad value is rejected with
// a message naming its key under effects.atmosphere.
#include "atmosphere/atmosphere_settings.h"

#include <gtest/gtest.h>

#include <cstring>
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
        {"FrameInfo.atmosphere.groundRadius", [](AtmosphereSettings& s) { s.groundRadius = 0.0f; }},
        {"FrameInfo.atmosphere.groundRadius", [&](AtmosphereSettings& s) { s.groundRadius = nan; }},
        {"FrameInfo.atmosphere.topRadius", [](AtmosphereSettings& s) { s.topRadius = s.groundRadius; }},
        {"FrameInfo.atmosphere.topRadius", [](AtmosphereSettings& s) { s.topRadius = 1e9f; }},
        {"FrameInfo.atmosphere.rayleighScattering",
         [](AtmosphereSettings& s) { s.rayleighScattering.y = -1e-6f; }},
        {"FrameInfo.atmosphere.rayleighScattering",
         [&](AtmosphereSettings& s) { s.rayleighScattering.z = inf; }},
        {"FrameInfo.atmosphere.rayleighScaleHeight",
         [](AtmosphereSettings& s) { s.rayleighScaleHeight = 0.0f; }},
        {"FrameInfo.atmosphere.mieScattering", [&](AtmosphereSettings& s) { s.mieScattering = nan; }},
        {"FrameInfo.atmosphere.mieAbsorption", [](AtmosphereSettings& s) { s.mieAbsorption = -1.0f; }},
        {"FrameInfo.atmosphere.mieScaleHeight", [](AtmosphereSettings& s) { s.mieScaleHeight = -5.0f; }},
        {"FrameInfo.atmosphere.mieAnisotropy", [](AtmosphereSettings& s) { s.mieAnisotropy = 1.0f; }},
        {"FrameInfo.atmosphere.mieAnisotropy", [](AtmosphereSettings& s) { s.mieAnisotropy = -1.0f; }},
        {"FrameInfo.atmosphere.mieAnisotropy", [&](AtmosphereSettings& s) { s.mieAnisotropy = nan; }},
        {"FrameInfo.atmosphere.ozoneAbsorption", [](AtmosphereSettings& s) { s.ozoneAbsorption.x = -1e-9f; }},
        {"FrameInfo.atmosphere.ozoneCenterHeight", [&](AtmosphereSettings& s) { s.ozoneCenterHeight = inf; }},
        {"FrameInfo.atmosphere.ozoneHalfWidth", [](AtmosphereSettings& s) { s.ozoneHalfWidth = 0.0f; }},
        {"FrameInfo.atmosphere.groundAlbedo", [](AtmosphereSettings& s) { s.groundAlbedo.y = 1.5f; }},
        {"FrameInfo.atmosphere.sunAngularRadiusDeg",
         [](AtmosphereSettings& s) { s.sunAngularRadiusDeg = 90.0f; }},
        {"FrameInfo.atmosphere.transmittanceLutSize",
         [](AtmosphereSettings& s) { s.transmittanceLutSize.y = 2; }},
        {"FrameInfo.atmosphere.transmittanceSteps", [](AtmosphereSettings& s) { s.transmittanceSteps = 0; }},
        {"FrameInfo.atmosphere.multipleScatteringLutSize",
         [](AtmosphereSettings& s) { s.multipleScatteringLutSize.x = 2000; }},
        {"FrameInfo.atmosphere.multipleScatteringDirections",
         [](AtmosphereSettings& s) { s.multipleScatteringDirections = 60; }},
        {"FrameInfo.atmosphere.multipleScatteringSteps",
         [](AtmosphereSettings& s) { s.multipleScatteringSteps = 5000; }},
        {"FrameInfo.atmosphere.multipleScattering",
         [](AtmosphereSettings& s) { s.multipleScattering = postfx::AtmosphereMultipleScattering(7); }},
        {"FrameInfo.atmosphere.scatteringOrdersLutSize",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.x = 65; }},
        {"FrameInfo.atmosphere.scatteringOrdersLutSize",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.y = 129; }},
        {"FrameInfo.atmosphere.scatteringOrdersLutSize",
         [](AtmosphereSettings& s) { s.scatteringOrdersLutSize.z = 3; }},
        {"FrameInfo.atmosphere.scatteringOrdersAzimuthSize",
         [](AtmosphereSettings& s) { s.scatteringOrdersAzimuthSize = 17; }},
        {"FrameInfo.atmosphere.scatteringOrdersDirections",
         [](AtmosphereSettings& s) { s.scatteringOrdersDirections = 100 + 1; }},
        {"FrameInfo.atmosphere.scatteringOrdersDirections",
         [](AtmosphereSettings& s) { s.scatteringOrdersDirections = 625; }},
        {"FrameInfo.atmosphere.scatteringOrdersSteps",
         [](AtmosphereSettings& s) { s.scatteringOrdersSteps = 0; }},
        {"FrameInfo.atmosphere.scatteringOrders", [](AtmosphereSettings& s) { s.scatteringOrders = 33; }},
        {"FrameInfo.atmosphere.skyViewLutSize", [](AtmosphereSettings& s) { s.skyViewLutSize.x = 0; }},
        {"FrameInfo.atmosphere.skyViewSteps", [](AtmosphereSettings& s) { s.skyViewSteps = 0; }},
        {"FrameInfo.atmosphere.aerialPerspectiveLutSize",
         [](AtmosphereSettings& s) { s.aerialPerspectiveLutSize.z = 512; }},
        {"FrameInfo.atmosphere.aerialPerspectiveDistance",
         [](AtmosphereSettings& s) { s.aerialPerspectiveDistance = 0.0f; }},
        {"FrameInfo.atmosphere.aerialPerspectiveStepsPerSlice",
         [](AtmosphereSettings& s) { s.aerialPerspectiveStepsPerSlice = 0; }},
    };
    for (const BadCase& c : cases) {
        AtmosphereSettings s;
        c.mutate(s);
        const postfx::Status st = postfx::validateAtmosphereSettings(s);
        EXPECT_EQ(st.code, Result::InvalidArgument) << c.key;
        // The field, a vector's component ("[1]") at most, then the reason.
        EXPECT_EQ(st.message.rfind(c.key, 0), 0u) << c.key << " -> " << st.message;
        EXPECT_NE(std::string(":[").find(st.message[std::strlen(c.key)]), std::string::npos) << st.message;
    }
}

TEST(AtmosphereSettings, TopRadiusMessageSaysWhy) {
    AtmosphereSettings s;
    s.topRadius = 6000e3f;
    const postfx::Status st = postfx::validateAtmosphereSettings(s);
    EXPECT_EQ(st.message,
              "FrameInfo.atmosphere.topRadius: 6e+06 must be greater than groundRadius (6.36e+06)");
}

}  // namespace

namespace test {
namespace {

// The orders' work together is bounded (kMaxOrdersWork): the defaults and each setting alone at its
// maximum fit; all at their maxima are refused naming scatteringOrders; Hillaire's model is not bound by it.
TEST(AtmosphereSettings, ScatteringOrdersWorkIsBounded) {
    using postfx::atmosphere::kMaxOrdersWork;
    using postfx::atmosphere::scatteringOrdersWork;
    postfx::AtmosphereSettings s;
    s.multipleScattering = postfx::AtmosphereMultipleScattering::Orders;
    EXPECT_NEAR(scatteringOrdersWork(s), 4.0 * 64 * 33 * 256 * (24 + 32 * 8), 1.0);
    const std::function<void(postfx::AtmosphereSettings&)> alone[] = {
        [](auto& a) { a.scatteringOrders = postfx::atmosphere::kMaxScatteringOrders; },
        [](auto& a) { a.scatteringOrdersSteps = postfx::atmosphere::kMaxSteps; },
        [](auto& a) { a.scatteringOrdersDirections = postfx::atmosphere::kMaxOrdersDirections; },
        [](auto& a) { a.scatteringOrdersAzimuthSize = postfx::atmosphere::kMaxOrdersAzimuths; },
        [](auto& a) {
            a.scatteringOrdersLutSize = {postfx::atmosphere::kMaxOrdersViewSide,
                                         postfx::atmosphere::kMaxOrdersSunSide,
                                         postfx::atmosphere::kMaxOrdersHeightSide};
        },
    };
    for (const auto& edit : alone) {
        postfx::AtmosphereSettings a = s;
        edit(a);
        EXPECT_LE(scatteringOrdersWork(a), kMaxOrdersWork);
        EXPECT_TRUE(postfx::validateAtmosphereSettings(a).ok())
            << postfx::validateAtmosphereSettings(a).message;
    }
    postfx::AtmosphereSettings all = s;
    for (const auto& edit : alone)
        edit(all);
    const postfx::Status refused = postfx::validateAtmosphereSettings(all);
    EXPECT_EQ(refused.code, postfx::Result::InvalidArgument);
    EXPECT_EQ(refused.message.rfind("FrameInfo.atmosphere.scatteringOrders: 16 orders with ", 0), 0u)
        << refused.message;
    EXPECT_NE(refused.message.find("more than 1.71799e+10"), std::string::npos) << refused.message;
    all.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
    EXPECT_TRUE(postfx::validateAtmosphereSettings(all).ok());
}

}  // namespace
}  // namespace test
