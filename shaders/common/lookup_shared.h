// The volumetrics lookup's C++/GLSL constants (postfx/volumetrics_lookup.h): the bindings every effect's
// lookup pass declares its part of the volume at, and the C++ mirror of the public uniforms.
#ifndef POSTFX_LOOKUP_SHARED_H
#define POSTFX_LOOKUP_SHARED_H

#include "common/shared.h"

#ifdef __cplusplus
namespace postfx::gpu {
#endif

// Above every effect's own bindings, so that an effect's lookup pass keeps its own numbering.
PFX_CONST(uint, kLookupBindingUniforms, 24);       // uniform buffer: PostfxLookupUniforms
PFX_CONST(uint, kLookupBindingScattering, 25);     // storage image rgba16f 3D: L (rgb)
PFX_CONST(uint, kLookupBindingTransmittance, 26);  // storage image rgba16f 3D: T (rgb)
// Passes over every froxel: kLookupGroupSize³ invocations; over every column (x, y): kLookupGroupSize².
PFX_CONST(uint, kLookupGroupSize, 4);
PFX_CONST(uint, kLookupColumnGroupSize, 8);

#ifdef __cplusplus
// postfx/volumetrics.glsl's PostfxLookupUniforms (std140: vec4 and mat4 members only).
struct LookupUniforms {
    mat4 relativeToClip;
    mat4 clipToRelative;
    vec4 camera;
    vec4 slices;
    vec4 world;
};
static_assert(sizeof(LookupUniforms) == 176);
// A lookup pass's push constants: x = 1 for the first writer of the frame (nothing to composite over).
struct LookupPush {
    uvec4 flags;
};
}  // namespace postfx::gpu
#endif

#endif
