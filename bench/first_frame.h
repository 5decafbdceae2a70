// postfx-bench --first-frame: the CPU time of record() in the first frames of a new context, where it
// compiles its pipelines (docs/integration.md, "Pipelines"). A showcase-like frame (demo/scenes/
// showcase.json: the atmosphere, the clouds and the froxel fog with the sun's shadows and lights), the same
// with the ray-marched fog, and that one with the clouds and the fog on quality Auto (whose preset turns
// compile in later frames), each in a new context per setup: none; Context::prewarm first; a
// VkPipelineCache saved by an earlier context (as a host loading it from disk); both; none again (what the
// driver keeps by itself within the process). Per row: prewarm's time, the first record()'s, the first
// frame's submission until the queue is idle (its GPU work, and what a driver compiles only when a pipeline
// first runs), the worst and median record() of the frames after it (a camera cut among them), and the
// pipelines compiled in each (counted at vkCreateComputePipelines). Prints a table; writes no file. Needs
// only libvulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct FirstFrameArgs {
    uint32_t width = 1920, height = 1080;
    uint32_t frames = 12;  // frames recorded after the first, per row
    std::string sceneDir;  // where showcase.json is
    // Of "froxel" (the showcase), "raymarched" (with the ray-marched fog), "auto" (that one with the clouds
    // and the fog on quality Auto).
    std::vector<std::string> scenes{"froxel", "raymarched", "auto"};
    bool validation = false;
    bool driverCache = false;  // leave the drivers' own shader disk caches on
    // Small images, LUTs, volumes and shadow maps (--quick, for lavapipe): the same pipelines, little GPU
    // work.
    bool small = false;
};

int runFirstFrame(const FirstFrameArgs& args, const std::string& commandLine);

}  // namespace bench
