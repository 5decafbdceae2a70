// Scene files: effects.atmosphere (demo/scene/atmosphere_json.cpp; docs/scene-format.md#effectsatmosphere)
// -- defaults, every key, round trips, unknown keys and bad ranges as errors naming their key path, and the
// committed sky scenes.
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <postfx/atmosphere.h>
#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace {

using demo::Scene;
using json = nlohmann::json;

const std::string kScenesDir = POSTFX_DEMO_SCENES_DIR;

struct Parsed {
    bool ok = false;
    std::string error;
    Scene scene;
};

Parsed parse(const json& j) {
    Parsed p;
    p.ok = demo::parseScene(j.dump(), p.scene, p.error);
    return p;
}

json base() {
    return json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [1000, 1000, 1000], "shadows": true},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]}]
    })");
}

// base() with effects.atmosphere = `atmosphere`.
json withAtmosphere(const json& atmosphere) {
    json j = base();
    j["effects"] = {{"atmosphere", atmosphere}};
    return j;
}

// Every key, each with a valid value different from its default.
json everyKey() {
    return json::parse(R"({
      "enabled": true,
      "ground_radius": 1000000,
      "top_radius": 1050000,
      "rayleigh_scattering": [1e-6, 2e-6, 3e-6],
      "rayleigh_scale_height": 7000,
      "mie_scattering": 2e-6,
      "mie_absorption": 1e-6,
      "mie_scale_height": 1500,
      "mie_anisotropy": -0.25,
      "ozone_absorption": [1e-7, 2e-7, 3e-7],
      "ozone_center_height": 20000,
      "ozone_half_width": 10000,
      "ground_albedo": [0.1, 0.2, 0.4],
      "multiple_scattering": "hillaire",
      "sun_angular_radius_deg": 1.5,
      "ambient_from_sky": true,
      "transmittance_lut_size": [128, 32],
      "transmittance_steps": 60,
      "multiple_scattering_lut_size": [16, 24],
      "multiple_scattering_directions": 49,
      "multiple_scattering_steps": 10,
      "sky_view_lut_size": [96, 54],
      "sky_view_steps": 20,
      "aerial_perspective_lut_size": [16, 24, 48],
      "aerial_perspective_distance": 50000,
      "aerial_perspective_steps_per_slice": 3
    })");
}

// everyKey() with the orders' model: its keys instead of Hillaire's (a key of the model not chosen is an
// error).
json everyOrdersKey() {
    json j = everyKey();
    for (const char* k :
         {"multiple_scattering_lut_size", "multiple_scattering_directions", "multiple_scattering_steps"})
        j.erase(k);
    j["multiple_scattering"] = "orders";
    j["scattering_orders_lut_size"] = {16, 24, 8};
    j["scattering_orders_azimuth_size"] = 4;
    j["scattering_orders_directions"] = 144;
    j["scattering_orders_steps"] = 24;
    j["scattering_orders"] = 5;
    return j;
}

void expectSameAtmosphere(const postfx::AtmosphereSettings& a, const postfx::AtmosphereSettings& b) {
    EXPECT_EQ(demo::sceneToJson([&] {
                  Scene s;
                  s.atmosphere = a;
                  return s;
              }()),
              demo::sceneToJson([&] {
                  Scene s;
                  s.atmosphere = b;
                  return s;
              }()));
}

TEST(DemoSceneAtmosphere, AbsentMeansDisabledDefaults) {
    const Parsed p = parse(base());
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_FALSE(p.scene.atmosphere.enabled);
    expectSameAtmosphere(p.scene.atmosphere, postfx::AtmosphereSettings{});
}

TEST(DemoSceneAtmosphere, EmptyObjectEnablesEarthDefaults) {
    const Parsed p = parse(withAtmosphere(json::object()));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::AtmosphereSettings& a = p.scene.atmosphere;
    EXPECT_TRUE(a.enabled);
    EXPECT_FLOAT_EQ(a.groundRadius, 6360e3f);
    EXPECT_FLOAT_EQ(a.topRadius, 6460e3f);
    EXPECT_FLOAT_EQ(a.rayleighScattering.z, 33.1e-6f);
    EXPECT_FLOAT_EQ(a.mieAnisotropy, 0.8f);
    EXPECT_EQ(a.multipleScattering, postfx::AtmosphereMultipleScattering::Orders);
    EXPECT_FALSE(a.ambientFromSky);
    EXPECT_EQ(a.skyViewLutSize, postfx::UVec2(192, 108));
    postfx::AtmosphereSettings expected;
    expected.enabled = true;
    expectSameAtmosphere(a, expected);
}

TEST(DemoSceneAtmosphere, EnabledFalseIsKept) {
    const Parsed p = parse(withAtmosphere({{"enabled", false}, {"top_radius", 6500e3}}));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_FALSE(p.scene.atmosphere.enabled);
    EXPECT_FLOAT_EQ(p.scene.atmosphere.topRadius, 6500e3f);
}

TEST(DemoSceneAtmosphere, EveryKeyIsRead) {
    const Parsed p = parse(withAtmosphere(everyKey()));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::AtmosphereSettings& a = p.scene.atmosphere;
    EXPECT_TRUE(a.enabled);
    EXPECT_FLOAT_EQ(a.groundRadius, 1e6f);
    EXPECT_FLOAT_EQ(a.topRadius, 1.05e6f);
    EXPECT_EQ(a.rayleighScattering, postfx::Vec3(1e-6f, 2e-6f, 3e-6f));
    EXPECT_FLOAT_EQ(a.rayleighScaleHeight, 7000.0f);
    EXPECT_FLOAT_EQ(a.mieScattering, 2e-6f);
    EXPECT_FLOAT_EQ(a.mieAbsorption, 1e-6f);
    EXPECT_FLOAT_EQ(a.mieScaleHeight, 1500.0f);
    EXPECT_FLOAT_EQ(a.mieAnisotropy, -0.25f);
    EXPECT_EQ(a.ozoneAbsorption, postfx::Vec3(1e-7f, 2e-7f, 3e-7f));
    EXPECT_FLOAT_EQ(a.ozoneCenterHeight, 20000.0f);
    EXPECT_FLOAT_EQ(a.ozoneHalfWidth, 10000.0f);
    EXPECT_EQ(a.groundAlbedo, postfx::Vec3(0.1f, 0.2f, 0.4f));
    EXPECT_EQ(a.multipleScattering, postfx::AtmosphereMultipleScattering::Hillaire);
    EXPECT_FLOAT_EQ(a.sunAngularRadiusDeg, 1.5f);
    EXPECT_TRUE(a.ambientFromSky);
    EXPECT_EQ(a.transmittanceLutSize, postfx::UVec2(128, 32));
    EXPECT_EQ(a.transmittanceSteps, 60u);
    EXPECT_EQ(a.multipleScatteringLutSize, postfx::UVec2(16, 24));
    EXPECT_EQ(a.multipleScatteringDirections, 49u);
    EXPECT_EQ(a.multipleScatteringSteps, 10u);
    const Parsed orders = parse(withAtmosphere(everyOrdersKey()));
    ASSERT_TRUE(orders.ok) << orders.error;
    const postfx::AtmosphereSettings& o = orders.scene.atmosphere;
    EXPECT_EQ(o.multipleScattering, postfx::AtmosphereMultipleScattering::Orders);
    EXPECT_EQ(o.scatteringOrdersLutSize, postfx::UVec3(16, 24, 8));
    EXPECT_EQ(o.scatteringOrdersAzimuthSize, 4u);
    EXPECT_EQ(o.scatteringOrdersDirections, 144u);
    EXPECT_EQ(o.scatteringOrdersSteps, 24u);
    EXPECT_EQ(o.scatteringOrders, 5u);
    EXPECT_EQ(a.skyViewLutSize, postfx::UVec2(96, 54));
    EXPECT_EQ(a.skyViewSteps, 20u);
    EXPECT_EQ(a.aerialPerspectiveLutSize, postfx::UVec3(16, 24, 48));
    EXPECT_FLOAT_EQ(a.aerialPerspectiveDistance, 50000.0f);
    EXPECT_EQ(a.aerialPerspectiveStepsPerSlice, 3u);
}

TEST(DemoSceneAtmosphere, EveryKeyRoundTrips) {
    for (const json& in : {everyKey(), everyOrdersKey()}) {
        const Parsed first = parse(withAtmosphere(in));
        ASSERT_TRUE(first.ok) << first.error;
        const json out = demo::sceneToJson(first.scene);
        const json& written = out["effects"]["atmosphere"];
        EXPECT_EQ(written.size(), in.size());
        for (const auto& [key, value] : in.items()) {
            if (value.is_number_float() || (value.is_array() && value[0].is_number_float())) {
                // Floats are written in their shortest form as floats: compare as floats.
                const json w = written[key];
                if (value.is_array()) {
                    for (std::size_t i = 0; i < value.size(); ++i)
                        EXPECT_EQ(float(w[i].get<double>()), float(value[i].get<double>())) << key;
                } else {
                    EXPECT_EQ(float(w.get<double>()), float(value.get<double>())) << key;
                }
            } else if (value.is_number()) {
                EXPECT_EQ(written[key].get<double>(), value.get<double>()) << key;
            } else {
                EXPECT_EQ(written[key], value) << key;
            }
        }
        const Parsed second = parse(json::parse(out.dump(2)));
        ASSERT_TRUE(second.ok) << second.error;
        expectSameAtmosphere(second.scene.atmosphere, first.scene.atmosphere);
        EXPECT_EQ(demo::sceneToJson(second.scene), out);
    }
}

TEST(DemoSceneAtmosphere, DefaultsRoundTrip) {
    for (const json& atmosphere : {json(nullptr), json::object()}) {
        const Parsed first = parse(atmosphere.is_null() ? base() : withAtmosphere(atmosphere));
        ASSERT_TRUE(first.ok) << first.error;
        const json out = demo::sceneToJson(first.scene);
        EXPECT_EQ(out["effects"]["atmosphere"]["enabled"], !atmosphere.is_null());
        EXPECT_EQ(out["effects"]["atmosphere"]["aerial_perspective_lut_size"], json({32, 32, 32}));
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << second.error;
        EXPECT_EQ(demo::sceneToJson(second.scene), out);
    }
}

// Each key alone at its range's ends (and odd floats) reads back exactly.
TEST(DemoSceneAtmosphere, EachKeyRoundTripsAtItsBounds) {
    const std::vector<std::pair<std::string, json>> cases = {
        {"/ground_radius", 1},
        {"/top_radius", 1e8},
        {"/rayleigh_scattering", {0, 1, 0.1}},
        {"/rayleigh_scale_height", 1e7},
        {"/mie_scattering", 1},
        {"/mie_absorption", 0},
        {"/mie_scale_height", 1e-3},
        {"/mie_anisotropy", -0.999},
        {"/mie_anisotropy", 0.999},
        {"/ozone_absorption", {1, 0, 0.3}},
        {"/ozone_center_height", 0},
        {"/ozone_center_height", 1e7},
        {"/ozone_half_width", 1e7},
        {"/ground_albedo", {0, 1, 0.3}},
        {"/sun_angular_radius_deg", 0},
        {"/sun_angular_radius_deg", 45},
        {"/transmittance_lut_size", {4, 512}},
        {"/transmittance_steps", 1},
        {"/transmittance_steps", 128},
        {"/multiple_scattering_lut_size", {64, 4}},
        {"/multiple_scattering_directions", 4},
        {"/multiple_scattering_directions", 256},
        {"/multiple_scattering_steps", 128},
        {"/scattering_orders_lut_size", {4, 128, 4}},
        {"/scattering_orders_lut_size", {64, 4, 64}},
        {"/scattering_orders_azimuth_size", 2},
        {"/scattering_orders_azimuth_size", 16},
        {"/scattering_orders_directions", 4},
        {"/scattering_orders_directions", 576},
        {"/scattering_orders_steps", 128},
        {"/scattering_orders", 1},
        {"/scattering_orders", 16},
        {"/multiple_scattering", "off"},
        {"/multiple_scattering", "hillaire"},
        {"/multiple_scattering", true},
        {"/sky_view_lut_size", {512, 4}},
        {"/sky_view_steps", 1},
        {"/aerial_perspective_lut_size", {4, 64, 4}},
        {"/aerial_perspective_distance", 1e7},
        {"/aerial_perspective_steps_per_slice", 8},
    };
    for (const auto& [pointer, value] : cases) {
        json atmosphere = json::object();
        atmosphere[json::json_pointer(pointer)] = value;
        if (pointer == "/ground_radius") atmosphere["top_radius"] = 2;
        if (pointer.rfind("/scattering_orders", 0) == 0) atmosphere["multiple_scattering"] = "orders";
        if (pointer.rfind("/multiple_scattering_", 0) == 0) atmosphere["multiple_scattering"] = "hillaire";
        const Parsed first = parse(withAtmosphere(atmosphere));
        ASSERT_TRUE(first.ok) << pointer << " = " << value << ": " << first.error;
        const json out = demo::sceneToJson(first.scene);
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << pointer << ": " << second.error;
        EXPECT_EQ(demo::sceneToJson(second.scene), out) << pointer;
    }
}

struct ErrorCase {
    const char* name;
    json atmosphere;
    const char* expected;  // the error starts with this
};

TEST(DemoSceneAtmosphere, ErrorsNameTheKeyPath) {
    const std::vector<ErrorCase> cases = {
        {"UnknownKey",
         {{"rayleigh_height", 8000}},
         "effects.atmosphere.rayleigh_height: unknown key (expected enabled, "},
        {"NotObject", true, "effects.atmosphere: expected an object, got true"},
        {"EnabledNumber", {{"enabled", 1}}, "effects.atmosphere.enabled: expected true or false, got 1"},
        {"GroundString",
         {{"ground_radius", "6360e3"}},
         "effects.atmosphere.ground_radius: expected a number"},
        {"TopBelowGround", {{"top_radius", 6000e3}}, "effects.atmosphere.top_radius: "},
        {"GroundZero", {{"ground_radius", 0}}, "effects.atmosphere.ground_radius: "},
        {"RayleighTwo", {{"rayleigh_scattering", {1e-6, 2e-6}}}, "effects.atmosphere.rayleigh_scattering: "},
        {"RayleighNegative",
         {{"rayleigh_scattering", {1e-6, -2e-6, 0}}},
         "effects.atmosphere.rayleigh_scattering"},
        {"RayleighHeightZero", {{"rayleigh_scale_height", 0}}, "effects.atmosphere.rayleigh_scale_height: "},
        {"MieOver", {{"mie_scattering", 2}}, "effects.atmosphere.mie_scattering: "},
        {"MieAbsorptionNegative", {{"mie_absorption", -1e-6}}, "effects.atmosphere.mie_absorption: "},
        {"MieHeightOver", {{"mie_scale_height", 2e7}}, "effects.atmosphere.mie_scale_height: "},
        {"AnisotropyOne", {{"mie_anisotropy", 1}}, "effects.atmosphere.mie_anisotropy: "},
        {"OzoneOver", {{"ozone_absorption", {0, 0, 1.5}}}, "effects.atmosphere.ozone_absorption"},
        {"OzoneCenterNegative", {{"ozone_center_height", -1}}, "effects.atmosphere.ozone_center_height: "},
        {"OzoneWidthZero", {{"ozone_half_width", 0}}, "effects.atmosphere.ozone_half_width: "},
        {"AlbedoOver", {{"ground_albedo", {0.3, 1.2, 0.3}}}, "effects.atmosphere.ground_albedo"},
        {"MultipleScatteringString",
         {{"multiple_scattering", "yes"}},
         "effects.atmosphere.multiple_scattering: expected \"off\", \"hillaire\" or \"orders\""},
        {"OrdersDirectionsNotSquare",
         {{"scattering_orders_directions", 50}},
         "effects.atmosphere.scattering_orders_directions: 50 is not a perfect square"},
        {"OrdersDirectionsOver",
         {{"scattering_orders_directions", 625}},
         "effects.atmosphere.scattering_orders_directions: 625 is outside [4, 576]"},
        {"OrdersHeightOver",
         {{"scattering_orders_lut_size", {32, 32, 65}}},
         "effects.atmosphere.scattering_orders_lut_size[2]: 65 is outside [4, 64]"},
        {"OrdersAzimuthOne",
         {{"scattering_orders_azimuth_size", 1}},
         "effects.atmosphere.scattering_orders_azimuth_size: 1 is outside [2, 16]"},
        {"OrdersZero",
         {{"scattering_orders", 0}},
         "effects.atmosphere.scattering_orders: 0 is outside [1, 16]"},
        {"OrdersKeyWithHillaire",
         {{"multiple_scattering", "hillaire"}, {"multiple_scattering_steps", 8}, {"scattering_orders", 4}},
         "effects.atmosphere.scattering_orders: ignored with multiple_scattering \"hillaire\" (used with "
         "\"orders\")"},
        {"SunRadiusOver", {{"sun_angular_radius_deg", 46}}, "effects.atmosphere.sun_angular_radius_deg: "},
        {"AmbientNumber",
         {{"ambient_from_sky", 0}},
         "effects.atmosphere.ambient_from_sky: expected true or false"},
        {"TransmittanceSizeThree",
         {{"transmittance_lut_size", {256, 64, 1}}},
         "effects.atmosphere.transmittance_lut_size: expected an array of 2 integers"},
        {"TransmittanceSizeSmall",
         {{"transmittance_lut_size", {256, 3}}},
         "effects.atmosphere.transmittance_lut_size[1]: 3 is outside [4, 512]"},
        {"TransmittanceSizeFraction",
         {{"transmittance_lut_size", {256, 6.5}}},
         "effects.atmosphere.transmittance_lut_size[1]: expected an integer"},
        {"TransmittanceStepsZero", {{"transmittance_steps", 0}}, "effects.atmosphere.transmittance_steps: "},
        {"DirectionsNotSquare",
         {{"multiple_scattering_directions", 50}},
         "effects.atmosphere.multiple_scattering_directions: 50 is not a perfect square"},
        {"MsStepsOver",
         {{"multiple_scattering_steps", 1025}},
         "effects.atmosphere.multiple_scattering_steps: "},
        {"SkyViewSizeOver",
         {{"sky_view_lut_size", {4097, 108}}},
         "effects.atmosphere.sky_view_lut_size[0]: "},
        {"SkyViewStepsNegative", {{"sky_view_steps", -1}}, "effects.atmosphere.sky_view_steps"},
        {"ApSizeTwo",
         {{"aerial_perspective_lut_size", {32, 32}}},
         "effects.atmosphere.aerial_perspective_lut_size: expected an array of 3 integers"},
        {"ApSizeOver",
         {{"aerial_perspective_lut_size", {32, 257, 32}}},
         "effects.atmosphere.aerial_perspective_lut_size[1]: "},
        {"ApDistanceZero",
         {{"aerial_perspective_distance", 0}},
         "effects.atmosphere.aerial_perspective_distance: "},
        {"ApStepsOver",
         {{"aerial_perspective_steps_per_slice", 65}},
         "effects.atmosphere.aerial_perspective_steps_per_slice: "},
        // Checked while disabled too: turning it on cannot make a file invalid.
        {"CheckedWhileDisabled",
         {{"enabled", false}, {"mie_anisotropy", -1}},
         "effects.atmosphere.mie_anisotropy: "},
    };
    for (const ErrorCase& c : cases) {
        json atmosphere = c.atmosphere;
        // A model's own keys with their model, unless the case chooses one.
        if (atmosphere.is_object() && !atmosphere.contains("multiple_scattering")) {
            for (const auto& [key, value] : c.atmosphere.items()) {
                if (key.rfind("scattering_orders", 0) == 0) atmosphere["multiple_scattering"] = "orders";
                if (key.rfind("multiple_scattering_", 0) == 0) atmosphere["multiple_scattering"] = "hillaire";
            }
        }
        const Parsed p = parse(withAtmosphere(atmosphere));
        EXPECT_FALSE(p.ok) << c.name;
        EXPECT_EQ(p.error.rfind(c.expected, 0), 0u) << c.name << ": " << p.error;
        EXPECT_EQ(p.error.find('\n'), std::string::npos) << c.name;
    }
}

// The committed sky scenes load, with the atmosphere on.
TEST(DemoSceneAtmosphereFiles, SkyScenesLoad) {
    for (const char* name : {"sky_noon.json", "sky_sunset.json", "sky_space.json"}) {
        Scene s;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/" + name, s, error)) << name << ": " << error;
        EXPECT_TRUE(s.atmosphere.enabled) << name;
        EXPECT_FALSE(s.fog.enabled && s.froxelFog.enabled) << name;
    }
}

}  // namespace
