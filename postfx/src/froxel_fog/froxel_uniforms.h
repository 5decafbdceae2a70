// Builds the froxel fog's uniforms and light buffer from a frame (camera-relative, in double on the host).
#pragma once

#include <postfx/context.h>

#include "froxel_fog/froxel_shared.h"

#include <vector>

namespace postfx::froxel_fog {

// What the froxel fog's kernels read from binding kFroxelBindingUniforms.
struct PassUniforms {
    gpu::FogUniforms fog;  // the shared medium (common/medium/medium.glsl)
    gpu::FroxelUniforms froxel;
};
static_assert(sizeof(PassUniforms) == sizeof(gpu::FogUniforms) + sizeof(gpu::FroxelUniforms));

// The slices' near end [m]: the radial distance of the projection's near plane on the view axis, at most
// half of max_distance (max_distance·1e-3 when the projection has no finite near plane).
double gridNear(const FrameInfo& frame, const DepthConvention& depth);

// The power of two the scatter and integrated volumes' radiance is stored times, so that the sun's and
// the ambient light's largest in-scattered radiance, albedo·(E·p_max + ambient), is at most 4096 in the
// rgba16f volumes (whose largest value is 65504); 1 when it already is.
float storageScale(const FrameInfo& frame);

// `lights` receives the frame's local lights with a non-zero intensity (camera-relative); returns how many.
// `faces` receives the faces of their shadows (each shadow once, camera-relative), each light's
// FroxelLight::shadow pointing at its shadow's first face; none without FrameInfo.localShadows' image.
uint32_t packLights(const FrameInfo& frame, gpu::FroxelLights& lights,
                    std::vector<gpu::FroxelShadowFace>& faces);

// `grid`: froxelGridSize of the frame; `lightWords`: light-list words per cluster (0 without lists).
PassUniforms buildPassUniforms(const FrameInfo& frame, const DepthConvention& depth, const UVec3& grid,
                               uint32_t lightCount, uint32_t lightWords, bool noiseEnabled,
                               bool shadowMapEnabled);

}  // namespace postfx::froxel_fog
