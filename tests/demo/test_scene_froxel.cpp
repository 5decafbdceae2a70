// Scene files: effects.froxel_fog (demo/scene/froxel_fog_json.cpp, the medium keys it shares with
// effects.fog, from the settings tables: demo/scene/settings_json.cpp;
// docs/scene-format.md#effectsfroxel_fog) -- defaults, every key, round trips, errors naming their key path,
// the fog volumes' limit, the two fogs never both on, and the committed froxel scenes.
#include "scene/json_text.h"
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <postfx/froxel_fog.h>
#include <nlohmann/json.hpp>

#include <ostream>
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

// base() with effects.froxel_fog = `froxel`.
json withFroxel(const json& froxel) {
    json j = base();
    j["effects"] = {{"froxel_fog", froxel}};
    return j;
}

json box() {
    return {{"shape", "box"}, {"center", {1, 2, 3}}, {"half_size", {4, 5, 6}}};
}
json sphere() {
    return {{"shape", "sphere"}, {"center", {-1, 0.5, -2}}, {"radius", 3}};
}

// The medium keys both fogs share, each with a value different from its default.
json mediumKeys() {
    return json::parse(R"({
      "density": 0.125,
      "albedo": [0.25, 0.5, 0.75],
      "anisotropy": -0.3,
      "height_falloff": 0.05,
      "base_height": -12.5,
      "max_distance": 321,
      "self_shadow": true,
      "analytic_tail": false,
      "noise": {
        "enabled": true,
        "texture_size": 64,
        "seed": 4000000000,
        "tiling": 2.5,
        "threshold": 0.3,
        "multiplier": 4,
        "wind": [1, -2, 0.5]
      }
    })");
}

// Every key with a value different from its default.
json everyKey() {
    json j = mediumKeys();
    j["enabled"] = false;
    j["grid"] = {64, 32, 200};
    j["tile_size_px"] = 16;
    j["depth_distribution"] = "power";
    j["depth_exponent"] = 3.5;
    j["tricubic"] = true;
    j["jitter"] = false;
    j["local_shadow_filter"] = true;
    j["light_list_min_lights"] = 257;
    j["temporal"] = {{"enabled", false}, {"blend_weight", 0.5}};
    json b = box();
    b["density"] = 0.5;
    b["edge_falloff"] = 0.25;
    json s = sphere();
    s["density"] = 2;
    s["edge_falloff"] = 1;
    j["volumes"] = {b, s};
    return j;
}

void expectSameMedium(const postfx::FogMedium& a, const postfx::FogMedium& b) {
    EXPECT_EQ(a.density, b.density);
    EXPECT_EQ(a.albedo, b.albedo);
    EXPECT_EQ(a.anisotropy, b.anisotropy);
    EXPECT_EQ(a.heightFalloff, b.heightFalloff);
    EXPECT_EQ(a.baseHeight, b.baseHeight);
    EXPECT_EQ(a.maxDistance, b.maxDistance);
    EXPECT_EQ(a.selfShadow, b.selfShadow);
    EXPECT_EQ(a.analyticTail, b.analyticTail);
    EXPECT_EQ(a.noise.enabled, b.noise.enabled);
    EXPECT_EQ(a.noise.textureSize, b.noise.textureSize);
    EXPECT_EQ(a.noise.seed, b.noise.seed);
    EXPECT_EQ(a.noise.tiling, b.noise.tiling);
    EXPECT_EQ(a.noise.threshold, b.noise.threshold);
    EXPECT_EQ(a.noise.multiplier, b.noise.multiplier);
    EXPECT_EQ(a.noise.wind, b.noise.wind);
}

void expectSameVolume(const postfx::FogVolume& a, const postfx::FogVolume& b) {
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.center, b.center);
    if (a.shape == postfx::FogVolumeShape::Box)
        EXPECT_EQ(a.halfSize, b.halfSize);
    else
        EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.density, b.density);
    EXPECT_EQ(a.edgeFalloff, b.edgeFalloff);
}

void expectSameFroxel(const Scene& a, const Scene& b) {
    const postfx::FroxelFogSettings &x = a.froxelFog, &y = b.froxelFog;
    EXPECT_EQ(x.enabled, y.enabled);
    expectSameMedium(x, y);
    EXPECT_EQ(x.grid, y.grid);
    EXPECT_EQ(x.tileSizePx, y.tileSizePx);
    EXPECT_EQ(x.depthDistribution, y.depthDistribution);
    EXPECT_EQ(x.depthExponent, y.depthExponent);
    EXPECT_EQ(x.tricubic, y.tricubic);
    EXPECT_EQ(x.jitter, y.jitter);
    EXPECT_EQ(x.localShadowFilter, y.localShadowFilter);
    EXPECT_EQ(x.lightListMinLights, y.lightListMinLights);
    EXPECT_EQ(x.temporal.enabled, y.temporal.enabled);
    EXPECT_EQ(x.temporal.blendWeight, y.temporal.blendWeight);
    ASSERT_EQ(a.froxelVolumes.size(), b.froxelVolumes.size());
    for (size_t i = 0; i < a.froxelVolumes.size(); ++i)
        expectSameVolume(a.froxelVolumes[i], b.froxelVolumes[i]);
}

// ---- defaults ------------------------------------------------------------------------------------

TEST(DemoSceneFroxel, AbsentMeansDisabledDefaults) {
    json empty = base();
    empty["effects"] = json::object();
    for (const json& j : {base(), empty}) {
        const Parsed p = parse(j);
        ASSERT_TRUE(p.ok) << p.error;
        Scene defaults;
        expectSameFroxel(p.scene, defaults);
        EXPECT_FALSE(p.scene.froxelFog.enabled);
        EXPECT_TRUE(p.scene.froxelVolumes.empty());
        // Written anyway, off, with every key (as effects.fog).
        const json out = demo::sceneToJson(p.scene);
        EXPECT_EQ(out["effects"]["froxel_fog"]["enabled"], false);
        EXPECT_EQ(out["effects"]["froxel_fog"].size(), everyKey().size());
    }
}

TEST(DemoSceneFroxel, EmptyObjectEnablesFroxelFogWithDefaults) {
    const Parsed p = parse(withFroxel(json::object()));
    ASSERT_TRUE(p.ok) << p.error;
    Scene expected;
    expected.froxelFog.enabled = true;
    expectSameFroxel(p.scene, expected);
    EXPECT_EQ(p.scene.froxelFog.grid, postfx::UVec3(160, 90, 128));
    EXPECT_FALSE(p.scene.fog.enabled);
}

TEST(DemoSceneFroxel, EmptyNoiseObjectEnablesNoiseWithDefaults) {
    const Parsed p = parse(withFroxel({{"noise", json::object()}}));
    ASSERT_TRUE(p.ok) << p.error;
    Scene expected;
    expected.froxelFog.enabled = true;
    expected.froxelFog.noise.enabled = true;
    expectSameFroxel(p.scene, expected);
}

TEST(DemoSceneFroxel, EnabledFalseIsKept) {
    const Parsed p = parse(withFroxel({{"enabled", false}, {"noise", {{"enabled", false}}}}));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_FALSE(p.scene.froxelFog.enabled);
    EXPECT_FALSE(p.scene.froxelFog.noise.enabled);
}

// ---- every key -----------------------------------------------------------------------------------

TEST(DemoSceneFroxel, EveryKeyIsRead) {
    const Parsed p = parse(withFroxel(everyKey()));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::FroxelFogSettings& f = p.scene.froxelFog;
    EXPECT_FALSE(f.enabled);
    EXPECT_EQ(f.density, 0.125f);
    EXPECT_EQ(f.albedo, glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(f.anisotropy, -0.3f);
    EXPECT_EQ(f.heightFalloff, 0.05f);
    EXPECT_EQ(f.baseHeight, -12.5f);
    EXPECT_EQ(f.maxDistance, 321.0f);
    EXPECT_TRUE(f.selfShadow);
    EXPECT_FALSE(f.analyticTail);
    EXPECT_TRUE(f.noise.enabled);
    EXPECT_EQ(f.noise.textureSize, 64u);
    EXPECT_EQ(f.noise.seed, 4000000000u);
    EXPECT_EQ(f.noise.tiling, 2.5f);
    EXPECT_EQ(f.noise.threshold, 0.3f);
    EXPECT_EQ(f.noise.multiplier, 4.0f);
    EXPECT_EQ(f.noise.wind, glm::vec3(1.0f, -2.0f, 0.5f));
    EXPECT_EQ(f.grid, postfx::UVec3(64, 32, 200));
    EXPECT_EQ(f.tileSizePx, 16u);
    EXPECT_EQ(f.depthDistribution, postfx::FroxelDepthDistribution::Power);
    EXPECT_EQ(f.depthExponent, 3.5f);
    EXPECT_TRUE(f.tricubic);
    EXPECT_FALSE(f.jitter);
    EXPECT_TRUE(f.localShadowFilter);
    EXPECT_EQ(f.lightListMinLights, 257u);
    // The settings never point anywhere: the volumes are the scene's.
    EXPECT_EQ(f.volumes, nullptr);
    EXPECT_EQ(f.volumeCount, 0u);
    ASSERT_EQ(p.scene.froxelVolumes.size(), 2u);
    const postfx::FogVolume& b = p.scene.froxelVolumes[0];
    EXPECT_EQ(b.shape, postfx::FogVolumeShape::Box);
    EXPECT_EQ(b.center, postfx::DVec3(1, 2, 3));
    EXPECT_EQ(b.halfSize, postfx::Vec3(4, 5, 6));
    EXPECT_EQ(b.density, 0.5f);
    EXPECT_EQ(b.edgeFalloff, 0.25f);
    const postfx::FogVolume& s = p.scene.froxelVolumes[1];
    EXPECT_EQ(s.shape, postfx::FogVolumeShape::Sphere);
    EXPECT_EQ(s.center, postfx::DVec3(-1, 0.5, -2));
    EXPECT_EQ(s.radius, 3.0f);
    EXPECT_EQ(s.density, 2.0f);
    EXPECT_EQ(s.edgeFalloff, 1.0f);
}

TEST(DemoSceneFroxel, VolumeDefaults) {
    const Parsed p = parse(withFroxel({{"volumes", {box(), sphere()}}}));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::FogVolume defaults;
    for (const postfx::FogVolume& v : p.scene.froxelVolumes) {
        EXPECT_EQ(v.density, defaults.density);
        EXPECT_EQ(v.edgeFalloff, defaults.edgeFalloff);
    }
}

// The medium keys are read by the one function both fogs use: the same object gives the same FogMedium.
TEST(DemoSceneFroxel, MediumKeysReadAsEffectsFog) {
    json j = base();
    json fog = mediumKeys();
    fog["enabled"] = false;
    j["effects"] = {{"fog", fog}, {"froxel_fog", mediumKeys()}};
    const Parsed p = parse(j);
    ASSERT_TRUE(p.ok) << p.error;
    expectSameMedium(p.scene.froxelFog, p.scene.fog);
    const json out = demo::sceneToJson(p.scene);
    const json medium = mediumKeys();
    for (const auto& [key, value] : medium.items())
        EXPECT_EQ(out["effects"]["froxel_fog"][key], out["effects"]["fog"][key]) << key;
}

TEST(DemoSceneFroxel, GridAndTileSizeMayBeWrittenAsWholeDecimals) {
    const Parsed p = parse(withFroxel({{"grid", {8.0, 4.0, 2.0}}, {"tile_size_px", 8.0}}));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.scene.froxelFog.grid, postfx::UVec3(8, 4, 2));
    EXPECT_EQ(p.scene.froxelFog.tileSizePx, 8u);
}

// The renderer's settings for a frame point at the scene's volumes (FrameInfo::froxelFog).
TEST(DemoSceneFroxel, FrameSettingsPointIntoTheScene) {
    const Parsed p = parse(withFroxel({{"volumes", {box(), sphere(), box()}}}));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::FroxelFogSettings s = demo::froxelFogSettings(p.scene);
    EXPECT_EQ(s.volumes, p.scene.froxelVolumes.data());
    EXPECT_EQ(s.volumeCount, 3u);
    EXPECT_TRUE(s.enabled);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(s).ok());
    const Parsed none = parse(withFroxel(json::object()));
    ASSERT_TRUE(none.ok) << none.error;
    EXPECT_EQ(demo::froxelFogSettings(none.scene).volumes, nullptr);
    EXPECT_EQ(demo::froxelFogSettings(none.scene).volumeCount, 0u);
}

// ---- round trips ---------------------------------------------------------------------------------

TEST(DemoSceneFroxel, EveryKeyRoundTrips) {
    const Parsed first = parse(withFroxel(everyKey()));
    ASSERT_TRUE(first.ok) << first.error;
    const json out = demo::sceneToJson(first.scene);
    // Every key is written, with the value read.
    const json& froxel = out["effects"]["froxel_fog"];
    const json in = everyKey();
    EXPECT_EQ(out["effects"].size(), 4u);  // fog, froxel_fog, atmosphere and clouds
    EXPECT_EQ(froxel.size(), in.size());
    for (const auto& [key, value] : in.items()) {
        if (key == "noise" || key == "volumes") continue;
        EXPECT_EQ(froxel[key], value) << key;
    }
    for (const auto& [key, value] : in["noise"].items())
        EXPECT_EQ(froxel["noise"][key], value) << "noise." << key;
    EXPECT_EQ(froxel["volumes"], in["volumes"]);

    const Parsed second = parse(json::parse(out.dump(2)));
    ASSERT_TRUE(second.ok) << second.error;
    expectSameFroxel(second.scene, first.scene);
    EXPECT_EQ(demo::sceneToJson(second.scene), out);
}

TEST(DemoSceneFroxel, DefaultsRoundTrip) {
    for (const json& froxel : {json(nullptr), json::object()}) {
        const Parsed first = parse(froxel.is_null() ? base() : withFroxel(froxel));
        ASSERT_TRUE(first.ok) << first.error;
        const json out = demo::sceneToJson(first.scene);
        EXPECT_EQ(out["effects"]["froxel_fog"]["enabled"], !froxel.is_null());
        EXPECT_EQ(out["effects"]["froxel_fog"]["grid"], json({160, 90, 128}));
        EXPECT_EQ(out["effects"]["froxel_fog"]["depth_distribution"], "power");
        EXPECT_EQ(out["effects"]["froxel_fog"]["volumes"], json::array());
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << second.error;
        expectSameFroxel(second.scene, first.scene);
        EXPECT_EQ(demo::sceneToJson(second.scene), out);
    }
}

// Each key alone, at a few values including its range's ends, reads back exactly.
TEST(DemoSceneFroxel, EachKeyRoundTripsAtItsBounds) {
    const std::vector<std::pair<std::string, json>> cases = {
        {"/density", 0},
        {"/density", 1e6},
        {"/albedo", {0, 1, 0.1}},
        {"/anisotropy", -0.999},
        {"/anisotropy", 0.999},
        {"/height_falloff", 0},
        {"/height_falloff", 10},
        {"/base_height", -3e38},
        {"/max_distance", 1e-3},
        {"/max_distance", 1e7},
        {"/self_shadow", true},
        {"/analytic_tail", false},
        {"/noise/texture_size", 16},
        {"/noise/texture_size", 256},
        {"/noise/seed", 4294967295u},
        {"/noise/tiling", 1e-6},
        {"/noise/tiling", 1000},
        {"/noise/threshold", 1},
        {"/noise/multiplier", 1000},
        {"/noise/wind", {-1000, 0, 1000}},
        {"/grid", {1, 1, 1}},
        {"/grid", {512, 512, 32}},  // 512 along each axis, x·y·z within kMaxFroxels
        {"/grid", {32, 512, 512}},
        {"/tile_size_px", 0},
        {"/tile_size_px", 4096},
        {"/depth_distribution", "power"},
        {"/depth_distribution", "log"},
        {"/depth_exponent", 1},
        {"/depth_exponent", 8},
        {"/tricubic", true},
        {"/jitter", false},
        {"/local_shadow_filter", true},
        {"/volumes/0", {{"shape", "box"}, {"center", {-1e9, 0, 1e9}}, {"half_size", {0, 1e7, 0.1}}}},
        {"/volumes/0", {{"shape", "sphere"}, {"center", {0.1, 0.2, 0.3}}, {"radius", 0}}},
        {"/volumes/0", {{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1e7}, {"density", 1e6}}},
        {"/volumes/0", {{"shape", "box"}, {"center", {0, 0, 0}}, {"half_size", {1, 1, 1}}, {"density", 0}}},
        {"/volumes/0",
         {{"shape", "box"}, {"center", {0, 0, 0}}, {"half_size", {1, 1, 1}}, {"edge_falloff", 1e7}}},
    };
    for (const auto& [pointer, value] : cases) {
        json froxel = json::object();
        froxel[json::json_pointer(pointer)] = value;
        const Parsed first = parse(withFroxel(froxel));
        ASSERT_TRUE(first.ok) << pointer << " = " << value << ": " << first.error;
        const json out = demo::sceneToJson(first.scene);
        const json& written = out["effects"]["froxel_fog"][json::json_pointer(pointer)];
        if (value.is_number()) {
            EXPECT_EQ(float(written.get<double>()), float(value.get<double>()))
                << pointer << ": wrote " << written;
        } else if (!value.is_object()) {
            EXPECT_EQ(written, value) << pointer;
        }
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << pointer << ": " << second.error;
        expectSameFroxel(second.scene, first.scene);
        EXPECT_EQ(demo::sceneToJson(second.scene), out) << pointer;
    }
}

// ---- the fog volumes' limit and the two fogs -------------------------------------------------------

TEST(DemoSceneFroxel, VolumeLimitIsKMaxFogVolumes) {
    json many = json::array();
    for (uint32_t i = 0; i < postfx::kMaxFogVolumes; ++i)
        many.push_back(i % 2 ? box() : sphere());
    const Parsed full = parse(withFroxel({{"volumes", many}}));
    ASSERT_TRUE(full.ok) << full.error;
    EXPECT_EQ(full.scene.froxelVolumes.size(), postfx::kMaxFogVolumes);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(demo::froxelFogSettings(full.scene)).ok());
    many.push_back(box());
    const Parsed over = parse(withFroxel({{"volumes", many}}));
    ASSERT_FALSE(over.ok);
    EXPECT_EQ(over.error, "effects.froxel_fog.volumes: 65 volumes are more than the limit of 64");
    EXPECT_TRUE(parse(withFroxel({{"volumes", json::array()}})).ok);
}

TEST(DemoSceneFroxel, BothFogsEnabledIsAnErrorNamingBoth) {
    json j = base();
    j["effects"] = {{"fog", json::object()}, {"froxel_fog", json::object()}};
    const Parsed both = parse(j);
    ASSERT_FALSE(both.ok);
    EXPECT_EQ(both.error.rfind("effects: ", 0), 0u) << both.error;
    EXPECT_NE(both.error.find("effects.fog"), std::string::npos) << both.error;
    EXPECT_NE(both.error.find("effects.froxel_fog"), std::string::npos) << both.error;
    EXPECT_EQ(demo::json_text::oneLine(both.error), both.error);

    // Either one off: fine, whichever.
    for (const char* off : {"fog", "froxel_fog"}) {
        json k = j;
        k["effects"][off]["enabled"] = false;
        const Parsed p = parse(k);
        ASSERT_TRUE(p.ok) << off << ": " << p.error;
        EXPECT_NE(p.scene.fog.enabled, p.scene.froxelFog.enabled);
    }
}

// Every froxel fog that loads is accepted by postfx (its boundary values included).
TEST(DemoSceneFroxel, BoundaryValuesAreAcceptedByPostfx) {
    json froxel = everyKey();
    froxel["enabled"] = true;
    froxel["grid"] = {512, 1, 512};
    froxel["tile_size_px"] = 4096;
    froxel["depth_exponent"] = 8;
    froxel["max_distance"] = 1e7;
    froxel["volumes"] = {{{"shape", "box"},
                          {"center", {1e9, -1e9, 0}},
                          {"half_size", {1e7, 0, 1e7}},
                          {"density", 1e6},
                          {"edge_falloff", 1e7}},
                         {{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0}, {"density", 0}}};
    const Parsed p = parse(withFroxel(froxel));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::Status s = postfx::validateFroxelFogSettings(demo::froxelFogSettings(p.scene));
    EXPECT_TRUE(s.ok()) << s.message;
}

// ---- errors --------------------------------------------------------------------------------------

struct FroxelRejection {
    const char* name;
    json effects;
    std::string message;  // the error starts with this
};

void PrintTo(const FroxelRejection& r, std::ostream* os) {
    *os << r.name;
}

std::vector<FroxelRejection> froxelRejections() {
    const auto froxel = [](const char* pointer, const json& value) {
        json f = json::object();
        f[json::json_pointer(pointer)] = value;
        return json{{"froxel_fog", f}};
    };
    // volumes [box, sphere, <v>]: the error names volumes[2]
    const auto volume = [](const json& v) {
        return json{{"froxel_fog", {{"volumes", {box(), sphere(), v}}}}};
    };
    const auto edit = [](json v, const char* key, const json& value) {
        v[key] = value;
        return v;
    };
    const auto drop = [](json v, const char* key) {
        v.erase(key);
        return v;
    };
    return {
        // unknown keys, at every level
        {"UnknownFroxelKey", froxel("/steps", 32),
         "effects.froxel_fog.steps: unknown key (expected enabled, density, albedo, anisotropy, "
         "height_falloff, "
         "base_height, max_distance, self_shadow, analytic_tail, noise, grid, tile_size_px, "
         "depth_distribution, "
         "depth_exponent, tricubic, jitter, local_shadow_filter, light_list_min_lights, temporal or "
         "volumes)"},
        {"UnknownNoiseKey", froxel("/noise/octaves", 4),
         "effects.froxel_fog.noise.octaves: unknown key (expected enabled, texture_size, seed, tiling, "
         "threshold, multiplier or wind)"},
        {"UnknownVolumeKey", volume(edit(box(), "colour", {1, 1, 1})),
         "effects.froxel_fog.volumes[2].colour: unknown key for a box volume (expected shape, center, "
         "half_size, "
         "density or edge_falloff)"},
        {"RadiusOnBox", volume(edit(box(), "radius", 1)),
         "effects.froxel_fog.volumes[2].radius: unknown key for a box volume"},
        {"HalfSizeOnSphere", volume(edit(sphere(), "half_size", {1, 1, 1})),
         "effects.froxel_fog.volumes[2].half_size: unknown key for a sphere volume"},
        {"VolumeCountIsNoKey", froxel("/volume_count", 1), "effects.froxel_fog.volume_count: unknown key"},
        // types and required keys
        {"FroxelNotObject", {{"froxel_fog", true}}, "effects.froxel_fog: expected an object, got true"},
        {"EnabledNumber", froxel("/enabled", 1), "effects.froxel_fog.enabled: expected true or false, got 1"},
        {"DensityString", froxel("/density", "0.1"),
         "effects.froxel_fog.density: expected a number, got the string"},
        {"AlbedoElement", froxel("/albedo", {0.5, 0.5, 1.5}),
         "effects.froxel_fog.albedo[2]: expected a number in [0, 1], got 1.5"},
        {"GridTwoNumbers", froxel("/grid", {8, 8}),
         "effects.froxel_fog.grid: expected an array of 3 integers"},
        {"GridFraction", froxel("/grid", {8, 8.5, 8}),
         "effects.froxel_fog.grid[1]: expected an integer, got 8.5"},
        {"GridNegative", froxel("/grid", {8, 8, -1}),
         "effects.froxel_fog.grid[2]: expected an integer in [0, 4294967295], got -1"},
        {"TileSizeString", froxel("/tile_size_px", "8"),
         "effects.froxel_fog.tile_size_px: expected an integer"},
        {"DistributionUnknown", froxel("/depth_distribution", "linear"),
         "effects.froxel_fog.depth_distribution: expected \"power\" or \"log\", got the string \"linear\""},
        {"DistributionUpperCase", froxel("/depth_distribution", "Log"),
         "effects.froxel_fog.depth_distribution: expected \"power\" or \"log\""},
        {"DistributionNumber", froxel("/depth_distribution", 1),
         "effects.froxel_fog.depth_distribution: expected \"power\" or \"log\", got 1"},
        {"ExponentString", froxel("/depth_exponent", "2"),
         "effects.froxel_fog.depth_exponent: expected a number"},
        {"TricubicNull", froxel("/tricubic", nullptr), "effects.froxel_fog.tricubic: expected true or false"},
        {"JitterNumber", froxel("/jitter", 0), "effects.froxel_fog.jitter: expected true or false"},
        {"VolumesNotArray", froxel("/volumes", json::object()),
         "effects.froxel_fog.volumes: expected an array of volumes"},
        {"VolumeNotObject", volume(3), "effects.froxel_fog.volumes[2]: expected an object, got 3"},
        {"ShapeMissing", volume(drop(box(), "shape")), "effects.froxel_fog.volumes[2].shape: missing"},
        {"ShapeUnknown", volume(edit(box(), "shape", "cone")),
         "effects.froxel_fog.volumes[2].shape: unknown volume shape \"cone\" (expected box or sphere)"},
        {"ShapeNotString", volume(edit(box(), "shape", 0)),
         "effects.froxel_fog.volumes[2].shape: expected a string (box or sphere)"},
        {"CenterMissing", volume(drop(sphere(), "center")), "effects.froxel_fog.volumes[2].center: missing"},
        {"HalfSizeMissing", volume(drop(box(), "half_size")),
         "effects.froxel_fog.volumes[2].half_size: missing"},
        {"RadiusMissing", volume(drop(sphere(), "radius")), "effects.froxel_fog.volumes[2].radius: missing"},
        {"CenterElement", volume(edit(box(), "center", {0, "x", 0})),
         "effects.froxel_fog.volumes[2].center[1]: expected a number"},
        {"RadiusOverflow", volume(edit(sphere(), "radius", 1e39)),
         "effects.froxel_fog.volumes[2].radius: expected a number of magnitude"},
        // ranges, from postfx::validateFroxelFogSettings
        {"DensityNegative", froxel("/density", -1), "effects.froxel_fog.density: -1 is outside [0, 1e+06]"},
        {"AnisotropyTwo", froxel("/anisotropy", 2),
         "effects.froxel_fog.anisotropy: 2 is outside [-0.999, 0.999]"},
        {"HeightFalloffNegative", froxel("/height_falloff", -0.1), "effects.froxel_fog.height_falloff: "},
        {"MaxDistanceZero", froxel("/max_distance", 0), "effects.froxel_fog.max_distance: "},
        {"GridZero", froxel("/grid", {160, 90, 0}), "effects.froxel_fog.grid[2]: 0 is outside [1, 512]"},
        {"GridTooFine", froxel("/grid", {513, 90, 128}),
         "effects.froxel_fog.grid[0]: 513 is outside [1, 512]"},
        {"TileSizeTooLarge", froxel("/tile_size_px", 4097),
         "effects.froxel_fog.tile_size_px: 4097 is outside [0, 4096]"},
        {"LightListMinLightsZero", froxel("/light_list_min_lights", 0),
         "effects.froxel_fog.light_list_min_lights: 0 is outside [1, 257]"},
        {"ExponentBelowOne", froxel("/depth_exponent", 0.5),
         "effects.froxel_fog.depth_exponent: 0.5 is outside"},
        {"ExponentAboveEight", froxel("/depth_exponent", 9),
         "effects.froxel_fog.depth_exponent: 9 is outside"},
        {"TextureSizeNotPowerOfTwo", froxel("/noise/texture_size", 100),
         "effects.froxel_fog.noise.texture_size: "},
        {"WindTooFast", froxel("/noise/wind", {0, 2000, 0}), "effects.froxel_fog.noise.wind[1]: "},
        {"VolumeRadiusNegative", volume(edit(sphere(), "radius", -1)),
         "effects.froxel_fog.volumes[2].radius: -1 is outside [0, 1e+07]"},
        {"VolumeRadiusHuge", volume(edit(sphere(), "radius", 2e7)), "effects.froxel_fog.volumes[2].radius: "},
        {"VolumeHalfSizeNegative", volume(edit(box(), "half_size", {1, -1, 1})),
         "effects.froxel_fog.volumes[2].half_size[1]: "},
        {"VolumeCenterTooFar", volume(edit(box(), "center", {0, 0, 2e9})),
         "effects.froxel_fog.volumes[2].center[2]: "},
        {"VolumeDensityNegative", volume(edit(box(), "density", -0.5)),
         "effects.froxel_fog.volumes[2].density: "},
        {"VolumeDensityHuge", volume(edit(box(), "density", 2e6)), "effects.froxel_fog.volumes[2].density: "},
        {"VolumeEdgeFalloffNegative", volume(edit(sphere(), "edge_falloff", -1)),
         "effects.froxel_fog.volumes[2].edge_falloff: "},
        // noise keys are range-checked even while the noise (or the froxel fog) is off
        {"TilingZeroNoiseOff",
         {{"froxel_fog", {{"enabled", false}, {"noise", {{"enabled", false}, {"tiling", 0}}}}}},
         "effects.froxel_fog.noise.tiling: "},
        // both fogs
        {"BothFogs",
         {{"fog", json::object()}, {"froxel_fog", json::object()}},
         "effects: effects.fog and effects.froxel_fog are both enabled"},
    };
}

class DemoSceneFroxelRejects : public ::testing::TestWithParam<FroxelRejection> {};

TEST_P(DemoSceneFroxelRejects, WithOneLineNamingTheKeyPath) {
    const FroxelRejection& r = GetParam();
    json j = base();
    j["effects"] = r.effects;
    Scene scene = demo::defaultScene();
    std::string error;
    EXPECT_FALSE(demo::parseScene(j.dump(2), scene, error));
    EXPECT_EQ(error.rfind(r.message, 0), 0u)
        << "error: " << error << "\nexpected to start with: " << r.message;
    EXPECT_EQ(demo::json_text::oneLine(error), error);
    EXPECT_EQ(demo::sceneToJson(scene), demo::sceneToJson(demo::defaultScene()));  // left unchanged
}

INSTANTIATE_TEST_SUITE_P(Cases, DemoSceneFroxelRejects, ::testing::ValuesIn(froxelRejections()),
                         [](const ::testing::TestParamInfo<FroxelRejection>& info) {
                             return info.param.name;
                         });

// ---- committed froxel scenes ---------------------------------------------------------------------

Scene load(const std::string& name) {
    Scene s;
    std::string error;
    EXPECT_TRUE(demo::loadSceneFile(kScenesDir + "/" + name + ".json", s, error)) << error;
    return s;
}

// lights.json in thin froxel fog with two lit fog volumes.
TEST(DemoSceneFroxelFiles, FroxelLights) {
    const Scene s = load("froxel_lights");
    EXPECT_TRUE(s.froxelFog.enabled);
    EXPECT_FALSE(s.fog.enabled);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(demo::froxelFogSettings(s)).ok());
    EXPECT_LE(s.froxelFog.density, 0.05f);  // thin
    EXPECT_GT(s.froxelFog.heightFalloff, 0.0f);
    EXPECT_GE(s.lights.size(), 4u);
    bool spot = false;
    for (const demo::Light& l : s.lights)
        spot = spot || l.kind == demo::LightKind::Spot;
    EXPECT_TRUE(spot);
    bool boxVolume = false, sphereVolume = false;
    for (const postfx::FogVolume& v : s.froxelVolumes) {
        boxVolume = boxVolume || v.shape == postfx::FogVolumeShape::Box;
        sphereVolume = sphereVolume || v.shape == postfx::FogVolumeShape::Sphere;
    }
    EXPECT_TRUE(boxVolume && sphereVolume);
    // Shadows: the spot over the sphere and the blue point light among the pillars.
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_TRUE(s.lights[1].shadows);
    EXPECT_TRUE(s.lights[3].shadows);
    // lights.json with the froxel fog and the shadows added: the same camera, sun, objects and lights.
    Scene withoutFog = s;
    withoutFog.froxelFog = postfx::FroxelFogSettings{};
    withoutFog.froxelVolumes.clear();
    for (demo::Light& l : withoutFog.lights) {
        l.shadows = false;
        l.shadowResolution = demo::Light{}.shadowResolution;
    }
    EXPECT_EQ(demo::sceneToJson(withoutFog), demo::sceneToJson(load("lights")));
}

// A lamp with shadows behind a row of columns in froxel fog: between the columns its light reaches the
// camera, the columns' shadows fan out toward it.
TEST(DemoSceneFroxelFiles, FroxelColonnade) {
    const Scene s = load("froxel_colonnade");
    EXPECT_TRUE(s.froxelFog.enabled);
    EXPECT_FALSE(s.fog.enabled);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(demo::froxelFogSettings(s)).ok());
    ASSERT_EQ(s.lights.size(), 1u);
    const demo::Light& lamp = s.lights[0];
    EXPECT_EQ(lamp.kind, demo::LightKind::Point);
    EXPECT_TRUE(lamp.shadows);
    int columns = 0;
    for (const demo::Object& o : s.objects) {
        // A column: a tall box between the camera and the lamp.
        if (o.type == demo::ObjectType::Box && o.halfSize.y > 2.0f * o.halfSize.x &&
            o.position.z > lamp.position.z && o.position.z < s.camera.position.z)
            ++columns;
    }
    EXPECT_GE(columns, 5);
}

// fog_default.json's fog as a froxel fog: the same scene and medium (sun, shadows, noise), no local lights.
TEST(DemoSceneFroxelFiles, FroxelDefaultMirrorsFogDefault) {
    const Scene s = load("froxel_default");
    const Scene fog = load("fog_default");
    EXPECT_TRUE(s.froxelFog.enabled);
    EXPECT_FALSE(s.fog.enabled);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(demo::froxelFogSettings(s)).ok());
    EXPECT_TRUE(s.sun.shadows);
    EXPECT_TRUE(s.froxelFog.noise.enabled);
    EXPECT_TRUE(s.lights.empty());
    EXPECT_TRUE(s.froxelVolumes.empty());
    expectSameMedium(s.froxelFog, fog.fog);
    Scene a = s, b = fog;
    a.froxelFog = postfx::FroxelFogSettings{};
    b.fog = postfx::FogSettings{};
    EXPECT_EQ(demo::sceneToJson(a), demo::sceneToJson(b));
}

}  // namespace
