#version 450
// postfx.lookup_clear: the volumetrics lookup of a frame none of whose effects composites into it (all off
// or empty): (L, T) = (0, 1) everywhere.
#extension GL_GOOGLE_include_directive : require

#include "common/lookup_shared.h"

layout(local_size_x = kLookupGroupSize, local_size_y = kLookupGroupSize, local_size_z = kLookupGroupSize) in;

#include "common/lookup.glsl"

void main() {
    ivec3 froxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(uvec3(froxel), lookupExtent()))) return;
    imageStore(lookupScattering, froxel, vec4(0.0));
    imageStore(lookupTransmittance, froxel, vec4(1.0, 1.0, 1.0, 0.0));
}
