// postfx-bench --pipeline-stats: what the driver compiled postfx's march pipelines into (register count,
// occupancy, instruction counts, whatever statistics it reports through VK_KHR_pipeline_executable_
// properties), on a device of its own with that extension (docs/accuracy-cost/README.md, "What limits the
// ray-marched fog's march"). Prints a table; returns the process exit code (1 without the extension).
#pragma once

namespace bench {

int runPipelineStats();

}  // namespace bench
