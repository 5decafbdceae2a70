#include "fog/fog_uniforms.h"

#include "common/medium.h"
#include "common/reduced_resolution.h"
#include "fog/fog_settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace postfx::fog {

gpu::FogUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth, bool noiseEnabled,
                               bool shadowMapEnabled) {
    const FogSettings& s = frame.fog;
    gpu::FogUniforms u = common::buildMediumUniforms(s, frame, depth, noiseEnabled, shadowMapEnabled);
    u.shadow.y = float((s.shadowKernel - 1) / 2);
    u.march.x = s.transmittanceCutoff;
    u.extent.z = s.steps;
    u.scatterExtent = glm::uvec4(
        fogMarchExtent(frame.color.extent.width, frame.color.extent.height, s.resolutionScale), 0u, 0u);
    if (s.jitter) u.flags.x |= gpu::kFogFlagJitter;
    if (s.skipEmptySpace) u.flags.x |= gpu::kFogFlagSkipEmptySpace;
    return u;
}

}  // namespace postfx::fog
