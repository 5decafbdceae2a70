// postfx-bench --froxel's pure logic (bench/froxel_scenes.h, bench/froxel_report.h) on the committed
// scenes and on made-up rows: the froxel version of a fog scene, the sweep, the generated lights, the
// apply pass's floor, the light-list rule, the equal-error comparison, the targets and the report.
#include "froxel_report.h"
#include "froxel_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using bench::Method;
using bench::Result;
using bench::Setting;

demo::Scene load(const std::string& name) {
    demo::Scene scene;
    std::string error;
    EXPECT_TRUE(demo::loadSceneFile(std::string(POSTFX_DEMO_SCENES_DIR) + "/" + name + ".json", scene, error))
        << error;
    return scene;
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

// fog_default.json's froxel version is froxel_default.json (its medium as a froxel fog, postfx's grid).
TEST(BenchFroxelScenes, FogSceneBecomesTheFroxelFogWithTheSameMedium) {
    const demo::Scene fog = load("fog_default");
    demo::Scene froxel;
    std::string error;
    ASSERT_TRUE(bench::froxelScene(fog, froxel, error)) << error;
    EXPECT_FALSE(froxel.fog.enabled);
    EXPECT_TRUE(froxel.froxelFog.enabled);
    expectSameMedium(froxel.froxelFog, fog.fog);
    EXPECT_EQ(froxel.froxelFog.grid, postfx::FroxelFogSettings{}.grid);
    EXPECT_TRUE(froxel.froxelVolumes.empty());
    EXPECT_EQ(froxel.objects.size(), fog.objects.size());

    const demo::Scene file = load("froxel_default");
    expectSameMedium(froxel.froxelFog, file.froxelFog);
    EXPECT_EQ(froxel.froxelFog.grid, file.froxelFog.grid);
    EXPECT_EQ(froxel.froxelFog.depthDistribution, file.froxelFog.depthDistribution);
    EXPECT_EQ(froxel.froxelFog.jitter, file.froxelFog.jitter);
    EXPECT_TRUE(postfx::validateFroxelFogSettings(demo::froxelFogSettings(froxel)).ok());
}

TEST(BenchFroxelScenes, FroxelSceneStaysAndASceneWithoutFogIsAnError) {
    const demo::Scene lights = load("froxel_lights");
    demo::Scene out;
    std::string error;
    ASSERT_TRUE(bench::froxelScene(lights, out, error)) << error;
    EXPECT_EQ(out.froxelVolumes.size(), lights.froxelVolumes.size());
    EXPECT_EQ(out.lights.size(), lights.lights.size());
    expectSameMedium(out.froxelFog, lights.froxelFog);
    EXPECT_EQ(bench::froxelLightCount(out), 4u);

    EXPECT_FALSE(bench::froxelScene(load("plain"), out, error));
    EXPECT_NE(error.find("neither effects.fog nor effects.froxel_fog"), std::string::npos) << error;
}

TEST(BenchFroxelScenes, SweepIsTheCrossProductGridOutermost) {
    Setting base;
    base.scene = "fog_default";
    base.noiseSize = 128;
    const bench::FroxelSweepOptions options;
    const std::vector<Setting> sweep = bench::froxelSweep(base, options);
    ASSERT_EQ(sweep.size(), 3u * 3u * 2u * 2u);
    std::set<std::string> labels;
    for (const Setting& s : sweep) {
        EXPECT_EQ(s.method, Method::Froxel);
        EXPECT_EQ(s.scene, "fog_default");
        labels.insert(s.label());
    }
    EXPECT_EQ(labels.size(), sweep.size());
    EXPECT_EQ(sweep.front().label(), "grid=80x45x64 dist=power tricubic=off noise=128");
    EXPECT_EQ(sweep[1].label(), "grid=80x45x64 dist=power tricubic=on noise=128");
    EXPECT_EQ(sweep[2].label(), "grid=80x45x64 dist=log tricubic=off noise=128");
    EXPECT_EQ(sweep.back().label(), "grid=240x135x256 dist=log tricubic=on noise=128");

    bench::FroxelSweepOptions one;
    one.grids = {{16, 9}};
    one.slices = {32};
    one.logSlices = {true};
    one.tricubic = {false};
    base.lights = 64;
    base.lightLists = true;
    const std::vector<Setting> single = bench::froxelSweep(base, one);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_EQ(single[0].label(), "grid=16x9x32 dist=log tricubic=off noise=128 lights=64 lists=on");
}

TEST(BenchFroxelScenes, KnobsGoIntoTheScene) {
    demo::Scene froxel;
    std::string error;
    ASSERT_TRUE(bench::froxelScene(load("fog_default"), froxel, error));
    froxel.froxelFog.tileSizePx = 16;
    Setting s;
    s.method = Method::Froxel;
    s.gridX = 80, s.gridY = 45, s.gridZ = 256;
    s.logSlices = true;
    s.tricubic = true;
    demo::Scene out = bench::withFroxelKnobs(froxel, s);
    EXPECT_EQ(out.froxelFog.grid, postfx::UVec3(80, 45, 256));
    EXPECT_EQ(out.froxelFog.tileSizePx, 0u);
    EXPECT_EQ(out.froxelFog.depthDistribution, postfx::FroxelDepthDistribution::Log);
    EXPECT_TRUE(out.froxelFog.tricubic);
    EXPECT_EQ(out.froxelFog.lightListMinLights, froxel.froxelFog.lightListMinLights) << "not a light row";

    s.lightSweep = true;
    s.lightLists = true;
    EXPECT_EQ(bench::withFroxelKnobs(froxel, s).froxelFog.lightListMinLights, 1u);
    s.lightLists = false;
    EXPECT_EQ(bench::withFroxelKnobs(froxel, s).froxelFog.lightListMinLights, postfx::kMaxLocalLights + 1);
    EXPECT_TRUE(
        postfx::validateFroxelFogSettings(demo::froxelFogSettings(bench::withFroxelKnobs(froxel, s))).ok());
}

TEST(BenchFroxelScenes, SweepLightsSpreadOverTheDiscDeterministically) {
    const demo::Camera camera = load("fog_default").camera;
    for (uint32_t count : {0u, 1u, 4u, 64u, 256u}) {
        const std::vector<demo::Light> lights = bench::sweepLights(camera, count);
        ASSERT_EQ(lights.size(), count);
        for (const demo::Light& l : lights) {
            EXPECT_EQ(l.kind, demo::LightKind::Point);
            const glm::vec2 offset(l.position.x - camera.lookAt.x, l.position.z - camera.lookAt.z);
            EXPECT_LE(glm::length(offset), bench::kSweepLightDisc * 1.0001f);
            EXPECT_GE(l.position.y - camera.lookAt.y, 0.5f - 1e-4f);
            EXPECT_LE(l.position.y - camera.lookAt.y, 4.0f + 1e-4f);
            EXPECT_GT(std::max(l.intensity.r, std::max(l.intensity.g, l.intensity.b)), 0.0f);
            EXPECT_EQ(l.range, bench::kSweepLightRange);
            EXPECT_GT(l.radius, 0.0f);
            EXPECT_LE(l.radius, l.range);
        }
        demo::Scene scene;
        scene.lights = lights;
        EXPECT_EQ(bench::froxelLightCount(scene), count);
    }
    EXPECT_EQ(bench::sweepLights(camera, 300).size(), postfx::kMaxLocalLights);
    const auto a = bench::sweepLights(camera, 64), b = bench::sweepLights(camera, 64);
    for (size_t i = 0; i < a.size(); ++i)
        EXPECT_EQ(a[i].position, b[i].position);
    // The Vogel spiral fills the disc: some light in each quarter of it, and in its outer half.
    int quarters[4] = {0, 0, 0, 0}, outer = 0;
    for (const demo::Light& l : a) {
        const float dx = l.position.x - camera.lookAt.x, dz = l.position.z - camera.lookAt.z;
        ++quarters[(dx >= 0 ? 1 : 0) + (dz >= 0 ? 2 : 0)];
        outer += std::hypot(dx, dz) > bench::kSweepLightDisc * 0.7071f;
    }
    for (int q : quarters)
        EXPECT_GE(q, 10);
    EXPECT_GE(outer, 24);
    demo::Scene dark;
    dark.lights = a;
    dark.lights[3].intensity = glm::vec3(0.0f);
    EXPECT_EQ(bench::froxelLightCount(dark), 63u);
}

TEST(BenchFroxelReport, ApplyFloorCountsColourInOutAndDepth) {
    EXPECT_EQ(bench::applyFloorBytes(1920, 1080), uint64_t(1920) * 1080 * 20);
    EXPECT_NEAR(bench::applyFloorMs(1920, 1080, 3000.0), 1920.0 * 1080 * 20 / 3e12 * 1e3, 1e-12);
    EXPECT_TRUE(std::isnan(bench::applyFloorMs(1920, 1080, NAN)));
    EXPECT_TRUE(std::isnan(bench::applyFloorMs(1920, 1080, 0.0)));
}

Result froxelRow(const std::string& scene, uint32_t x, uint32_t y, uint32_t z, bool log, bool tricubic,
                 std::vector<std::pair<std::string, double>> passes, double error1, double error16) {
    Result r;
    r.setting.scene = scene;
    r.setting.method = Method::Froxel;
    r.setting.gridX = x, r.setting.gridY = y, r.setting.gridZ = z;
    r.setting.logSlices = log;
    r.setting.tricubic = tricubic;
    r.setting.jitter = true;
    double total = 0;
    for (const auto& p : passes)
        total += p.second;
    r.timing.median = r.timing.p10 = r.timing.p90 = total;
    r.timing.passMedians = std::move(passes);
    r.error[0].relativeRmse = error1;
    r.error[1].relativeRmse = (error1 + error16) / 2;
    r.error[2].relativeRmse = error16;
    for (bench::ErrorStats& e : r.error)
        e.maxAbsError = 1.0, e.fractionOff = 0.1, e.nonFinite = 0;
    return r;
}

Result lightRow(uint32_t lights, bool lists, double listMs, double scatterMs) {
    std::vector<std::pair<std::string, double>> passes;
    if (lists) passes.emplace_back("froxel_fog.light_lists", listMs);
    passes.emplace_back("froxel_fog.scatter", scatterMs);
    passes.emplace_back("froxel_fog.integrate", 0.01);
    passes.emplace_back("froxel_fog.apply", 0.02);
    Result r = froxelRow("fog_default", 160, 90, 128, false, false, passes, NAN, NAN);
    r.setting.lights = lights;
    r.setting.lightLists = lists;
    r.setting.lightSweep = true;
    for (bench::ErrorStats& e : r.error)
        e = bench::ErrorStats{};
    return r;
}

Result fogRow(const std::string& scene, uint32_t steps, float scale, double ms, double error1,
              double error16) {
    Result r;
    r.setting.scene = scene;
    r.setting.method = Method::Ours;
    r.setting.steps = steps;
    r.setting.jitter = true;
    r.setting.resolutionScale = scale;
    r.timing.median = ms;
    r.timing.passMedians = {{"fog.raymarch", ms}};
    r.error[0].relativeRmse = error1;
    r.error[1].relativeRmse = error1;
    r.error[2].relativeRmse = error16;
    return r;
}

TEST(BenchFroxelReport, LightListRuleIsTheSmallestCountFromWhichListsNeverLose) {
    using P = bench::LightListPoint;
    auto point = [](uint32_t n, double loop, double lists) {
        P p;
        p.lights = n;
        p.loopMs = loop;
        p.listsMs = lists;
        return p;
    };
    EXPECT_EQ(bench::recommendedLightListMin({}), 0u);
    // Lose at 1 and 4, win from 8.
    EXPECT_EQ(
        bench::recommendedLightListMin({point(1, 0.05, 0.06), point(4, 0.06, 0.065), point(8, 0.08, 0.07),
                                        point(64, 0.3, 0.1), point(256, 1.0, 0.3)}),
        8u);
    // A win at 8 that 16 takes back: from 64.
    EXPECT_EQ(bench::recommendedLightListMin(
                  {point(4, 0.06, 0.07), point(8, 0.08, 0.07), point(16, 0.1, 0.11), point(64, 0.3, 0.1)}),
              64u);
    // Win everywhere (ties count as not slower): 1.
    EXPECT_EQ(bench::recommendedLightListMin({point(1, 0.05, 0.05), point(4, 0.06, 0.05)}), 1u);
    // Lose at the largest: never.
    EXPECT_EQ(bench::recommendedLightListMin({point(1, 0.05, 0.04), point(256, 1.0, 1.1)}),
              postfx::kMaxLocalLights + 1);

    // From rows: the light-list pass counts with the lists; a count without both rows is left out.
    const std::vector<Result> rows = {lightRow(0, false, 0, 0.04),    lightRow(8, false, 0, 0.08),
                                      lightRow(8, true, 0.004, 0.07), lightRow(4, true, 0.004, 0.06),
                                      lightRow(4, false, 0, 0.05),    lightRow(16, false, 0, 0.1)};
    const std::vector<P> points = bench::lightListPoints(rows);
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0].lights, 4u);
    EXPECT_NEAR(points[0].listsMs, 0.064, 1e-12);
    EXPECT_NEAR(points[0].loopMs, 0.05, 1e-12);
    EXPECT_EQ(points[1].lights, 8u);
    EXPECT_EQ(points[1].lists, &rows[2]);
    EXPECT_EQ(points[1].loop, &rows[1]);
    EXPECT_EQ(bench::recommendedLightListMin(points), 8u);
}

TEST(BenchFroxelReport, EqualErrorPairsEachFrontPointWithTheOtherFogsCheapestAtNoMoreError) {
    const auto f = [](uint32_t z, double ms, double e1, double e16) {
        return froxelRow("fog_default", 160, 90, z, false, false, {{"froxel_fog.scatter", ms}}, e1, e16);
    };
    std::vector<Result> rows = {
        f(64, 0.05, 0.030, 0.020),                           // 0: froxel front
        f(128, 0.08, 0.025, 0.012),                          // 1: froxel front
        f(256, 0.20, 0.026, 0.013),                          // 2: dominated
        fogRow("fog_default", 8, 1.0f, 0.10, 0.06, 0.015),   // 3
        fogRow("fog_default", 32, 1.0f, 0.40, 0.02, 0.004),  // 4
        fogRow("fog_default", 64, 1.0f, 0.70, 0.01, 0.002),  // 5
        fogRow("fog_height", 64, 1.0f, 0.01, 0.001, 0.001),  // another scene
    };
    Result sweepRow = lightRow(64, true, 0.01, 0.01);  // a light-count row is never on a front
    rows.push_back(sweepRow);
    const auto froxel = bench::equalErrorPoints(rows, "fog_default", Method::Froxel, Method::Ours, 0);
    ASSERT_EQ(froxel.size(), 2u);
    EXPECT_EQ(froxel[0].front, &rows[0]);
    EXPECT_EQ(froxel[0].other, &rows[4]);  // 2% <= 3%: the cheapest such
    EXPECT_EQ(froxel[1].front, &rows[1]);
    EXPECT_EQ(froxel[1].other, &rows[4]);
    const auto fog = bench::equalErrorPoints(rows, "fog_default", Method::Ours, Method::Froxel, 2);
    ASSERT_EQ(fog.size(), 3u);
    EXPECT_EQ(fog[0].front, &rows[3]);
    EXPECT_EQ(fog[0].other, &rows[1]);  // 1.2% <= 1.5%, 0.08 ms
    EXPECT_EQ(fog[1].other, nullptr);   // no froxel row gets to 0.4%
    EXPECT_EQ(fog[2].other, nullptr);
}

struct Report {
    bench::RunInfo info;
    std::vector<Result> rows;
};

Report madeUpRun(double scatterMs) {
    Report r;
    r.info.device = "Test GPU, 1.0";
    r.info.vulkanApi = "1.3.0";
    r.info.date = "2026-01-01T00:00:00Z";
    r.info.commandLine = "postfx-bench --froxel";
    r.info.width = 1920, r.info.height = 1080;
    r.info.errorStride = 4;
    r.info.referenceSteps = 4096;
    r.info.frames = 30;
    r.info.copyBandwidth = 3000.0;
    r.info.bandwidth = 3000.0;
    r.info.froxelTargetScene = "fog_default";
    r.info.lightListDefault = 8;
    const std::vector<std::pair<std::string, double>> passes = {
        {"froxel_fog.scatter", scatterMs}, {"froxel_fog.integrate", 0.01}, {"froxel_fog.apply", 0.02}};
    r.rows.push_back(froxelRow("fog_default", 80, 45, 64, false, false, passes, 0.05, 0.03));
    r.rows.push_back(froxelRow("fog_default", 160, 90, 128, false, true, passes, 0.04, 0.02));   // tricubic
    r.rows.push_back(froxelRow("fog_default", 160, 90, 128, true, false, passes, 0.04, 0.02));   // log
    r.rows.push_back(froxelRow("fog_default", 160, 90, 128, false, false, passes, 0.03, 0.01));  // the target
    r.rows.push_back(froxelRow("froxel_lights", 160, 90, 128, false, false, passes, 0.03, 0.01));
    r.rows.push_back(fogRow("fog_default", 32, 1.0f, 0.4, 0.02, 0.004));
    r.rows.push_back(lightRow(0, false, 0, 0.04));
    r.rows.push_back(lightRow(64, false, 0, 0.3));
    r.rows.push_back(lightRow(64, true, 0.005, 0.1));
    bench::markFroxelFronts(r.rows);
    return r;
}

TEST(BenchFroxelReport, TargetsFromTheRows) {
    Report run = madeUpRun(0.05);
    const Result* target = bench::froxelTargetRow(run.info, run.rows);
    ASSERT_EQ(target, &run.rows[3]);
    std::vector<bench::FroxelTarget> t = bench::froxelTargets(run.info, run.rows);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].row, target);
    EXPECT_NEAR(t[0].measured, 0.08, 1e-12);
    EXPECT_TRUE(t[0].met());
    EXPECT_EQ(t[1].row, &run.rows[8]) << "64 >= the default 8: with lists";
    EXPECT_NEAR(t[1].measured, 0.135, 1e-12);
    EXPECT_TRUE(t[1].met());
    EXPECT_EQ(t[2].row, target);
    EXPECT_NEAR(t[2].measured, 0.02 / bench::applyFloorMs(1920, 1080, 3000.0), 1e-9);
    EXPECT_TRUE(t[2].met());

    run.info.lightListDefault = 65;  // 64 lights would loop
    t = bench::froxelTargets(run.info, run.rows);
    EXPECT_EQ(t[1].row, &run.rows[7]);
    EXPECT_FALSE(t[1].met());

    run.info.bandwidth = 10000.0;  // a floor of 0.0041 ms: the apply's 0.02 ms is 4.8× it
    EXPECT_FALSE(bench::froxelTargets(run.info, run.rows)[2].met());

    run.info.froxelTargetScene = "froxel_lights";
    EXPECT_EQ(bench::froxelTargetRow(run.info, run.rows), &run.rows[4]);
    EXPECT_EQ(bench::froxelTargets(run.info, run.rows)[1].row, nullptr) << "no light rows on that scene";
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(BenchFroxelReport, MarkdownAndCsvSayWhatTheRowsSay) {
    const std::string dir = (std::filesystem::temp_directory_path() / "postfx_bench_froxel_report").string();
    std::filesystem::create_directories(dir);
    Report run = madeUpRun(0.09);  // 0.12 ms: the first target missed by 20%, scatter the largest pass
    std::string error;
    ASSERT_TRUE(bench::writeFroxelMarkdown(dir + "/results.md", run.info, run.rows, error)) << error;
    ASSERT_TRUE(bench::writeFroxelCsv(dir + "/results.csv", run.info, run.rows, error)) << error;
    const std::string md = readFile(dir + "/results.md");
    EXPECT_NE(md.find("| device | Test GPU, 1.0 |"), std::string::npos);
    EXPECT_NE(md.find("`postfx-bench --froxel`"), std::string::npos);
    EXPECT_NE(md.find("**MISS** by 20% (0.12 ms > 0.1 ms)"), std::string::npos) << md;
    EXPECT_NE(md.find("scatter (0.09 ms, 75% of the passes' sum)"), std::string::npos) << md;
    EXPECT_NE(md.find("**PASS** (0.135 ms ≤ 0.2 ms)"), std::string::npos) << md;
    EXPECT_NE(md.find("## Light lists"), std::string::npos);
    EXPECT_NE(md.find("This run: **64**; this build's default: 8."), std::string::npos) << md;
    EXPECT_NE(md.find("## Froxel fog against the ray-marched fog at equal error"), std::string::npos);
    EXPECT_NE(md.find("### fog_default, one frame"), std::string::npos);
    EXPECT_EQ(md.find("### froxel_lights,"), std::string::npos) << "no ray-marched rows there";
    EXPECT_NE(md.find("## froxel_lights"), std::string::npos);
    EXPECT_NE(md.find("## fog_default: light-count sweep"), std::string::npos);
    EXPECT_EQ(md.find("Not 1920×1080"), std::string::npos);

    const std::string csv = readFile(dir + "/results.csv");
    std::istringstream lines(csv);
    std::string line, header;
    size_t rows = 0;
    bool device = false;
    while (std::getline(lines, line)) {
        if (line.rfind("#", 0) == 0) {
            device = device || line == "# device: Test GPU, 1.0";
            continue;
        }
        if (header.empty()) {
            header = line;
            continue;
        }
        ++rows;
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), std::count(header.begin(), header.end(), ','))
            << line;
    }
    EXPECT_TRUE(device);
    EXPECT_EQ(rows, run.rows.size());
    std::string expected;
    for (const std::string& c : bench::froxelCsvColumns())
        expected += (expected.empty() ? "" : ",") + c;
    EXPECT_EQ(header, expected);
    std::filesystem::remove_all(dir);
}

}  // namespace
