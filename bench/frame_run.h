// postfx-bench --frame: the whole frame. The showcase scene (demo/scenes/showcase.json: the
// atmosphere, the clouds, froxel fog with the sun's shadows and four lights) and the same scene with the
// ray-marched fog in place of the froxel fog, per quality preset (the clouds' and the ray-marched fog's;
// the atmosphere and the froxel fog have none), at each frame size: every postfx pass's GPU time (median
// over the timed frames), each effect's share, and the error against the demo's combined CPU reference of
// every effect (Renderer::renderReference) at every stride-th pixel; writes results.csv and results.md.
#pragma once

#include "runner.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bench {

struct FrameRunArgs {
    RunnerOptions runner;  // width and height are replaced by each of `sizes`
    std::vector<std::pair<uint32_t, uint32_t>> sizes{{1920, 1080}, {3840, 2160}};
    std::vector<std::string> presets{"low", "medium", "high", "ultra"};
    // Also a row per fog with the clouds and the ray-marched fog on quality Auto under one frame budget of
    // this many ms (FrameInfo::budgetMs); 0: none.
    float budgetMs = 1.0f;
    std::string sceneDir;  // where showcase.json is
    uint32_t referenceSteps = 512;
    // The error's pixel stride at 1920 wide; scaled with the width (so every size has about as many error
    // pixels).
    uint32_t errorStride = 8;
    uint32_t shadowMapSize = 0;  // the clouds' shadow_map.size; 0: the scene's (--quick: 64)
    // --quick (lavapipe): the atmosphere's small orders table (test::smallScatteringOrders), a 32×18×32
    // froxel grid and 128² local light shadows; the GPU's work at the default sizes takes seconds a frame
    // there.
    bool quickScene = false;
    std::string out;
};

// The scene variants the mode measures: "froxel" (the showcase as committed) and "raymarched" (its froxel
// fog's medium as the ray-marched fog, marched to the same distance).
demo::Scene frameVariant(const demo::Scene& showcase, const std::string& fog);
// `scene` with the clouds' and the ray-marched fog's quality set to `preset` ("low" .. "ultra"; "budget":
// both on Auto under scene.budgetMs, which the caller sets).
demo::Scene withPreset(const demo::Scene& scene, const std::string& preset);
// `scene` with every box and sphere drawn in the demo's forward pass at opacity 0.5 and a smoke emitter: the
// volumetrics lookup (default size; at most a column per pixel below 1280 wide) and the forward pass, timed
// as "host.forward".
void withTransparentSurfaces(demo::Scene& scene, uint32_t width, uint32_t height);
// The effect a pass belongs to: its name up to the first '.' ("clouds.march" -> "clouds").
std::string passEffect(const std::string& pass);

int runFrame(const FrameRunArgs& args, const std::string& commandLine, const std::string& date);

}  // namespace bench
