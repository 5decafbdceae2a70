// Scene files: effects.fog (demo/scene/fog_json.cpp) -- defaults, every key, round trips, errors
// naming their key path, and the committed fog scenes.
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
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

Parsed parse(const std::string& text) {
    Parsed p;
    p.ok = demo::parseScene(text, p.scene, p.error);
    return p;
}
Parsed parse(const json& j) {
    return parse(j.dump());
}

json base() {
    return json::parse(R"({
      "camera": {"position": [0, 2, 10], "look_at": [0, 1, 0], "fov_y_deg": 60, "near": 0.1, "far": 1000},
      "sun": {"direction": [0, 1, 0], "illuminance": [1000, 1000, 1000], "shadows": true},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "albedo": [0.5, 0.5, 0.5]}]
    })");
}

// base() with effects.fog = `fog`.
json withFog(const json& fog) {
    json j = base();
    j["effects"] = {{"fog", fog}};
    return j;
}

// Every key with a value different from its default.
json everyKey() {
    return json::parse(R"({
      "enabled": false,
      "density": 0.125,
      "albedo": [0.25, 0.5, 0.75],
      "anisotropy": -0.3,
      "height_falloff": 0.05,
      "base_height": -12.5,
      "max_distance": 321,
      "steps": 77,
      "jitter": false,
      "resolution_scale": 0.5,
      "transmittance_cutoff": 0.01,
      "self_shadow": true,
      "analytic_tail": false,
      "skip_empty_space": false,
      "shadow_kernel": 5,
      "quality": "custom",
      "temporal": {"enabled": true, "blend_weight": 0.25},
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

void expectSameFog(const postfx::FogSettings& a, const postfx::FogSettings& b) {
    EXPECT_EQ(a.enabled, b.enabled);
    EXPECT_EQ(a.density, b.density);
    EXPECT_EQ(a.albedo, b.albedo);
    EXPECT_EQ(a.anisotropy, b.anisotropy);
    EXPECT_EQ(a.heightFalloff, b.heightFalloff);
    EXPECT_EQ(a.baseHeight, b.baseHeight);
    EXPECT_EQ(a.maxDistance, b.maxDistance);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.jitter, b.jitter);
    EXPECT_EQ(a.transmittanceCutoff, b.transmittanceCutoff);
    EXPECT_EQ(a.selfShadow, b.selfShadow);
    EXPECT_EQ(a.analyticTail, b.analyticTail);
    EXPECT_EQ(a.shadowKernel, b.shadowKernel);
    EXPECT_EQ(a.quality, b.quality);
    EXPECT_EQ(a.autoBudgetMs, b.autoBudgetMs);
    EXPECT_EQ(a.noise.enabled, b.noise.enabled);
    EXPECT_EQ(a.noise.textureSize, b.noise.textureSize);
    EXPECT_EQ(a.noise.seed, b.noise.seed);
    EXPECT_EQ(a.noise.tiling, b.noise.tiling);
    EXPECT_EQ(a.noise.threshold, b.noise.threshold);
    EXPECT_EQ(a.noise.multiplier, b.noise.multiplier);
    EXPECT_EQ(a.noise.wind, b.noise.wind);
    EXPECT_EQ(a.temporal.enabled, b.temporal.enabled);
    EXPECT_EQ(a.temporal.blendWeight, b.temporal.blendWeight);
}

// ---- defaults ------------------------------------------------------------------------------------

TEST(FogScene, AbsentMeansDisabledDefaults) {
    for (const json& j : {base(), [] {
                              json e = base();
                              e["effects"] = json::object();
                              return e;
                          }()}) {
        const Parsed p = parse(j);
        ASSERT_TRUE(p.ok) << p.error;
        expectSameFog(p.scene.fog, postfx::FogSettings{});
        EXPECT_FALSE(p.scene.fog.enabled);
    }
}

TEST(FogScene, EmptyObjectEnablesFogWithDefaults) {
    const Parsed p = parse(withFog(json::object()));
    ASSERT_TRUE(p.ok) << p.error;
    postfx::FogSettings expected;
    expected.enabled = true;
    expectSameFog(p.scene.fog, expected);
}

TEST(FogScene, EmptyNoiseObjectEnablesNoiseWithDefaults) {
    const Parsed p = parse(withFog({{"noise", json::object()}}));
    ASSERT_TRUE(p.ok) << p.error;
    postfx::FogSettings expected;
    expected.enabled = true;
    expected.noise.enabled = true;
    expectSameFog(p.scene.fog, expected);
}

TEST(FogScene, EnabledFalseIsKept) {
    const Parsed p = parse(withFog({{"enabled", false}, {"noise", {{"enabled", false}}}}));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_FALSE(p.scene.fog.enabled);
    EXPECT_FALSE(p.scene.fog.noise.enabled);
}

// ---- every key -----------------------------------------------------------------------------------

TEST(FogScene, EveryKeyIsRead) {
    const Parsed p = parse(withFog(everyKey()));
    ASSERT_TRUE(p.ok) << p.error;
    const postfx::FogSettings& f = p.scene.fog;
    EXPECT_FALSE(f.enabled);
    EXPECT_EQ(f.density, 0.125f);
    EXPECT_EQ(f.albedo, glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(f.anisotropy, -0.3f);
    EXPECT_EQ(f.heightFalloff, 0.05f);
    EXPECT_EQ(f.baseHeight, -12.5f);
    EXPECT_EQ(f.maxDistance, 321.0f);
    EXPECT_EQ(f.steps, 77u);
    EXPECT_FALSE(f.jitter);
    EXPECT_EQ(f.resolutionScale, 0.5f);
    EXPECT_EQ(f.transmittanceCutoff, 0.01f);
    EXPECT_TRUE(f.selfShadow);
    EXPECT_FALSE(f.analyticTail);
    EXPECT_FALSE(f.skipEmptySpace);
    EXPECT_EQ(f.shadowKernel, 5u);
    EXPECT_EQ(f.quality, postfx::FogQuality::Custom);  // auto_budget_ms: QualityDefaultsToCustom...
    EXPECT_TRUE(f.noise.enabled);
    EXPECT_EQ(f.noise.textureSize, 64u);
    EXPECT_EQ(f.noise.seed, 4000000000u);
    EXPECT_EQ(f.noise.tiling, 2.5f);
    EXPECT_EQ(f.noise.threshold, 0.3f);
    EXPECT_EQ(f.noise.multiplier, 4.0f);
    EXPECT_EQ(f.noise.wind, glm::vec3(1.0f, -2.0f, 0.5f));
}

TEST(FogScene, QualityDefaultsToCustomAndReadsEveryName) {
    const Parsed defaults = parse(withFog(json::object()));
    ASSERT_TRUE(defaults.ok) << defaults.error;
    EXPECT_EQ(defaults.scene.fog.quality, postfx::FogQuality::Custom);
    EXPECT_EQ(defaults.scene.fog.autoBudgetMs, 0.5f);
    const std::pair<const char*, postfx::FogQuality> names[] = {
        {"custom", postfx::FogQuality::Custom}, {"low", postfx::FogQuality::Low},
        {"medium", postfx::FogQuality::Medium}, {"high", postfx::FogQuality::High},
        {"ultra", postfx::FogQuality::Ultra},   {"auto", postfx::FogQuality::Auto},
    };
    for (const auto& [name, quality] : names) {
        const bool isAuto = quality == postfx::FogQuality::Auto;
        const Parsed p =
            parse(withFog(isAuto ? json{{"quality", name}, {"auto_budget_ms", 2}} : json{{"quality", name}}));
        ASSERT_TRUE(p.ok) << name << ": " << p.error;
        EXPECT_EQ(p.scene.fog.quality, quality) << name;
        EXPECT_EQ(p.scene.fog.autoBudgetMs, isAuto ? 2.0f : 0.5f) << name;
        EXPECT_EQ(p.scene.fog.steps, postfx::FogSettings{}.steps)
            << name << ": the preset is applied by postfx, not the loader";
        EXPECT_EQ(demo::sceneToJson(p.scene)["effects"]["fog"]["quality"], name);
    }
}

// Custom is the default quality, so a host that sets steps gets its steps; the knobs' defaults are the
// Medium preset's values, so an untouched FogSettings costs what Medium costs.
TEST(FogScene, DefaultKnobsAreTheMediumPreset) {
    const postfx::FogSettings defaults;
    const postfx::FogSettings medium = postfx::applyFogQuality(defaults, postfx::FogQuality::Medium);
    EXPECT_EQ(defaults.quality, postfx::FogQuality::Custom);
    EXPECT_EQ(defaults.steps, medium.steps);
    EXPECT_EQ(defaults.jitter, medium.jitter);
    EXPECT_EQ(defaults.shadowKernel, medium.shadowKernel);
    EXPECT_EQ(defaults.resolutionScale, medium.resolutionScale);
}

TEST(FogScene, IntegersMayBeWrittenAsWholeDecimals) {
    const Parsed p = parse(withFog({{"steps", 64.0}, {"shadow_kernel", 7.0}, {"noise", {{"seed", 3.0}}}}));
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.scene.fog.steps, 64u);
    EXPECT_EQ(p.scene.fog.shadowKernel, 7u);
    EXPECT_EQ(p.scene.fog.noise.seed, 3u);
}

TEST(FogScene, EveryKeyRoundTrips) {
    const Parsed first = parse(withFog(everyKey()));
    ASSERT_TRUE(first.ok) << first.error;
    const json out = demo::sceneToJson(first.scene);
    // Every key is written, with the value read.
    const json& fog = out["effects"]["fog"];
    const json in = everyKey();
    EXPECT_EQ(out["effects"].size(), 4u);  // fog, froxel_fog, atmosphere and clouds (off), every key written
    EXPECT_EQ(fog.size(), in.size());
    EXPECT_EQ(fog["noise"].size(), in["noise"].size());
    for (const auto& [key, value] : in.items()) {
        if (key == "noise") continue;
        EXPECT_EQ(fog[key], value) << key;
    }
    for (const auto& [key, value] : in["noise"].items())
        EXPECT_EQ(fog["noise"][key], value) << "noise." << key;

    const Parsed second = parse(out.dump(2));
    ASSERT_TRUE(second.ok) << second.error;
    expectSameFog(second.scene.fog, first.scene.fog);
    EXPECT_EQ(demo::sceneToJson(second.scene), out);
}

TEST(FogScene, DefaultsRoundTrip) {
    for (const json& fog : {json(nullptr), json::object()}) {
        const Parsed first = parse(fog.is_null() ? base() : withFog(fog));
        ASSERT_TRUE(first.ok) << first.error;
        const json out = demo::sceneToJson(first.scene);
        EXPECT_EQ(out["effects"]["fog"]["enabled"], !fog.is_null());
        EXPECT_EQ(out["effects"]["fog"]["steps"], 32);  // Medium's
        EXPECT_EQ(out["effects"]["fog"]["shadow_kernel"], 1);
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << second.error;
        expectSameFog(second.scene.fog, first.scene.fog);
    }
}

// Each key alone, at a few values including its range's ends, reads back exactly.
TEST(FogScene, EachKeyRoundTripsAtItsBounds) {
    const std::vector<std::pair<std::string, json>> cases = {
        {"/density", 0},
        {"/density", 1e6},
        {"/anisotropy", -0.999},
        {"/anisotropy", 0.999},
        {"/height_falloff", 0},
        {"/height_falloff", 10},
        {"/base_height", -3e38},
        {"/max_distance", 1e-3},
        {"/max_distance", 1e7},
        {"/steps", 1},
        {"/steps", 4096},
        {"/transmittance_cutoff", 0},
        {"/transmittance_cutoff", 0.999},
        {"/shadow_kernel", 1},
        {"/shadow_kernel", 7},
        {"/auto_budget_ms", 1e-6},
        {"/auto_budget_ms", 1e6},
        {"/albedo", {0, 1, 0.1}},
        {"/noise/texture_size", 16},
        {"/noise/texture_size", 256},
        {"/noise/seed", 0},
        {"/noise/seed", 4294967295u},
        {"/noise/tiling", 1000},
        {"/noise/tiling", 1e-6},
        {"/noise/threshold", 0},
        {"/noise/threshold", 1},
        {"/noise/multiplier", 0},
        {"/noise/multiplier", 1000},
        {"/noise/wind", {-1000, 0, 1000}},
    };
    for (const auto& [pointer, value] : cases) {
        json fog = json::object();
        fog[json::json_pointer(pointer)] = value;
        if (pointer == "/auto_budget_ms") fog["quality"] = "auto";  // Auto's own key
        const Parsed first = parse(withFog(fog));
        ASSERT_TRUE(first.ok) << pointer << " = " << value << ": " << first.error;
        const json out = demo::sceneToJson(first.scene);
        const json& written = out["effects"]["fog"][json::json_pointer(pointer)];
        if (value.is_number()) {
            EXPECT_EQ(float(written.get<double>()), float(value.get<double>()))
                << pointer << ": wrote " << written;
        }
        const Parsed second = parse(out);
        ASSERT_TRUE(second.ok) << pointer << ": " << second.error;
        expectSameFog(second.scene.fog, first.scene.fog);
    }
}

// ---- errors --------------------------------------------------------------------------------------

struct FogRejection {
    const char* name;
    json effects;
    std::string message;  // the error starts with this
};

void PrintTo(const FogRejection& r, std::ostream* os) {
    *os << r.name;
}

std::vector<FogRejection> fogRejections() {
    const auto fog = [](const char* pointer, const json& value) {
        json f = json::object();
        f[json::json_pointer(pointer)] = value;
        return json{{"fog", f}};
    };
    return {
        // unknown keys, at every level
        {"UnknownEffect",
         {{"rain", json::object()}},
         "effects.rain: unknown key (expected fog, froxel_fog, atmosphere or clouds)"},
        {"UnknownFogKey", fog("/colour", {1, 1, 1}),
         "effects.fog.colour: unknown key (expected enabled, density, albedo, anisotropy, height_falloff, "
         "base_height, max_distance, self_shadow, analytic_tail, noise, steps, jitter, resolution_scale, "
         "transmittance_cutoff, skip_empty_space, shadow_kernel, quality, auto_budget_ms or temporal)"},
        {"FroxelKeyInFog", fog("/grid", {8, 8, 8}), "effects.fog.grid: unknown key"},
        {"UnknownNoiseKey", fog("/noise/octaves", 4),
         "effects.fog.noise.octaves: unknown key (expected enabled, texture_size, seed, tiling, threshold, "
         "multiplier or wind)"},
        {"HostTextureIsNoKey", fog("/noise/host_texture", 1), "effects.fog.noise.host_texture: unknown key"},
        // types
        {"FogNotObject", {{"fog", true}}, "effects.fog: expected an object, got true"},
        {"NoiseNotObject", fog("/noise", 1), "effects.fog.noise: expected an object, got 1"},
        {"EnabledNumber", fog("/enabled", 1), "effects.fog.enabled: expected true or false, got 1"},
        {"DensityString", fog("/density", "0.1"), "effects.fog.density: expected a number, got the string"},
        {"AlbedoTwoNumbers", fog("/albedo", {1, 1}), "effects.fog.albedo: expected an array of 3 numbers"},
        {"AlbedoElement", fog("/albedo", {0.5, 0.5, 1.5}),
         "effects.fog.albedo[2]: expected a number in [0, 1], got 1.5"},
        {"StepsFraction", fog("/steps", 2.5), "effects.fog.steps: expected an integer, got 2.5"},
        {"StepsNegative", fog("/steps", -1),
         "effects.fog.steps: expected an integer in [0, 4294967295], got -1"},
        {"StepsHuge", fog("/steps", 5000000000), "effects.fog.steps: expected an integer in [0, 4294967295]"},
        {"StepsString", fog("/steps", "32"), "effects.fog.steps: expected an integer, got the string"},
        {"JitterNull", fog("/jitter", nullptr), "effects.fog.jitter: expected true or false, got null"},
        {"SeedNegative", fog("/noise/seed", -5), "effects.fog.noise.seed: expected an integer in"},
        {"WindElement", fog("/noise/wind", {0, "x", 0}), "effects.fog.noise.wind[1]: expected a number"},
        {"DensityTooLarge", fog("/density", 1e39), "effects.fog.density: expected a number of magnitude"},
        {"QualityUnknown", fog("/quality", "extreme"),
         "effects.fog.quality: expected \"custom\", \"low\", \"medium\", \"high\", \"ultra\" or \"auto\", "
         "got the string"},
        {"QualityUpperCase", fog("/quality", "Low"), "effects.fog.quality: expected \"custom\""},
        {"QualityNumber", fog("/quality", 2), "effects.fog.quality: expected \"custom\""},
        {"AutoBudgetString", fog("/auto_budget_ms", "1"), "effects.fog.auto_budget_ms: expected a number"},
        // ranges, from postfx::validateFogSettings
        {"DensityNegative", fog("/density", -1), "effects.fog.density: -1 is outside [0, 1e+06]"},
        {"AnisotropyTwo", fog("/anisotropy", 2), "effects.fog.anisotropy: 2 is outside [-0.999, 0.999]"},
        {"HeightFalloffNegative", fog("/height_falloff", -0.1), "effects.fog.height_falloff: "},
        {"MaxDistanceZero", fog("/max_distance", 0), "effects.fog.max_distance: "},
        {"AutoBudgetZero",
         {{"fog", {{"quality", "auto"}, {"auto_budget_ms", 0}}}},
         "effects.fog.auto_budget_ms: 0 must be > 0"},
        {"AutoBudgetNegative",
         {{"fog", {{"quality", "auto"}, {"auto_budget_ms", -1}}}},
         "effects.fog.auto_budget_ms: -1 must be > 0"},
        // a key that the chosen mode ignores
        {"AutoBudgetWithoutAuto", fog("/auto_budget_ms", 1),
         "effects.fog.auto_budget_ms: ignored with quality \"custom\" (used with \"auto\")"},
        {"StepsWithAPreset",
         {{"fog", {{"quality", "medium"}, {"steps", 64}}}},
         "effects.fog.steps: ignored with quality \"medium\" (used with \"custom\")"},
        {"StepsZero", fog("/steps", 0), "effects.fog.steps: 0 is outside [1, 4096]"},
        {"StepsTooMany", fog("/steps", 4097), "effects.fog.steps: 4097 is outside [1, 4096]"},
        {"ResolutionScaleTooSmall", fog("/resolution_scale", 0.2),
         "effects.fog.resolution_scale: 0.2 is outside [0.25, 1]"},
        {"ResolutionScaleAboveOne", fog("/resolution_scale", 2),
         "effects.fog.resolution_scale: 2 is outside [0.25, 1]"},
        {"CutoffOne", fog("/transmittance_cutoff", 1), "effects.fog.transmittance_cutoff: "},
        {"KernelEven", fog("/shadow_kernel", 4), "effects.fog.shadow_kernel: 4 must be odd, in [1, 7]"},
        {"KernelNine", fog("/shadow_kernel", 9), "effects.fog.shadow_kernel: "},
        {"TextureSizeNotPowerOfTwo", fog("/noise/texture_size", 100), "effects.fog.noise.texture_size: "},
        {"TextureSizeTooLarge", fog("/noise/texture_size", 512), "effects.fog.noise.texture_size: "},
        {"TilingZero", fog("/noise/tiling", 0), "effects.fog.noise.tiling: "},
        {"ThresholdTwo", fog("/noise/threshold", 2), "effects.fog.noise.threshold: "},
        {"MultiplierNegative", fog("/noise/multiplier", -1), "effects.fog.noise.multiplier: "},
        {"WindTooFast", fog("/noise/wind", {0, 2000, 0}), "effects.fog.noise.wind[1]: "},
        // noise keys are range-checked even while the noise (or the fog) is off
        {"TilingZeroNoiseOff",
         {{"fog", {{"enabled", false}, {"noise", {{"enabled", false}, {"tiling", 0}}}}}},
         "effects.fog.noise.tiling: "},
    };
}

class FogSceneRejects : public ::testing::TestWithParam<FogRejection> {};

TEST_P(FogSceneRejects, WithOneLineNamingTheKeyPath) {
    const FogRejection& r = GetParam();
    json j = base();
    j["effects"] = r.effects;
    Scene scene = demo::defaultScene();
    std::string error;
    EXPECT_FALSE(demo::parseScene(j.dump(2), scene, error));
    EXPECT_EQ(error.rfind(r.message, 0), 0u) << "error: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(demo::sceneToJson(scene), demo::sceneToJson(demo::defaultScene()));  // left unchanged
}

INSTANTIATE_TEST_SUITE_P(Cases, FogSceneRejects, ::testing::ValuesIn(fogRejections()),
                         [](const ::testing::TestParamInfo<FogRejection>& info) { return info.param.name; });

// ---- committed fog scenes ------------------------------------------------------------------------

TEST(FogSceneFiles, EachCommittedFogSceneLoadsWithFogOn) {
    for (const char* name : {"fog_default", "fog_homogeneous", "fog_height", "fog_noise", "fog_shadowed"}) {
        SCOPED_TRACE(name);
        Scene s;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/" + name + ".json", s, error)) << error;
        EXPECT_TRUE(s.fog.enabled);
        EXPECT_TRUE(postfx::validateFogSettings(s.fog).ok());
        const std::string n = name;
        if (n == "fog_homogeneous") {
            EXPECT_EQ(s.fog.heightFalloff, 0.0f);
            EXPECT_FALSE(s.fog.noise.enabled);
            EXPECT_FALSE(s.sun.shadows);
        }
        if (n == "fog_height") {
            EXPECT_GT(s.fog.heightFalloff, 0.0f);
            EXPECT_FALSE(s.fog.noise.enabled);
        }
        if (n == "fog_noise") {
            EXPECT_TRUE(s.fog.noise.enabled);
        }
        if (n == "fog_shadowed") {
            EXPECT_TRUE(s.sun.shadows);
            EXPECT_FALSE(s.fog.noise.enabled);
        }
        if (n == "fog_default") {
            EXPECT_TRUE(s.sun.shadows);
            EXPECT_TRUE(s.fog.noise.enabled);
            // The plain scene with fog added: the same camera, sun and objects.
            Scene withoutFog = s;
            withoutFog.fog = postfx::FogSettings{};
            Scene plain;
            ASSERT_TRUE(demo::loadSceneFile(kScenesDir + "/plain.json", plain, error)) << error;
            EXPECT_EQ(demo::sceneToJson(withoutFog), demo::sceneToJson(plain));
        }
    }
}

}  // namespace
