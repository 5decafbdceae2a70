// Builds the fog pass's uniforms from a frame's inputs. Everything that depends on the camera's world
// position is done here in double precision, so the shader works in camera-relative single precision.
#pragma once

#include <postfx/context.h>

#include "fog/fog_shared.h"

namespace postfx::fog {

// The ray-marched fog's: the medium's plus its march (frame.fog).
gpu::FogUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth, bool noiseEnabled,
                               bool shadowMapEnabled);

}  // namespace postfx::fog
