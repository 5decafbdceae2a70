// A host's forward pass reading postfx's volumetrics lookup, for the frame tests: the probe shader
// (shaders/lookup_probe.comp, <postfx/volumetrics.glsl> at binding numbers of its own) evaluates
// postfxVolumetrics at world positions right after record().
#pragma once

#include "fog_harness.h"

#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include <vector>

namespace test {

// The lookup's (L, T) at each probed point.
struct LookupProbe {
    std::vector<glm::vec3> L, T;
};

// Records `frame` (with the lookup on, as a camera cut) over `images` in `context`, then the probe at
// `points` (xyz: world positions in the context's world frame): postfx's output in `color`, the lookup's
// (L, T) at each point in `probe`.
postfx::Status runLookupProbe(demo::VulkanHost& host, const postfx::core::Gpu& gpu, postfx::Context& context,
                              postfx::FrameInfo frame, const FogHarnessImages& images,
                              const std::vector<glm::vec4>& points, std::vector<float>& color,
                              LookupProbe& probe);

}  // namespace test
