#version 450
// atmosphere.lookup (docs/integration.md, "Transparent surfaces"): the aerial perspective from the camera
// to the end of every slice of the volumetrics lookup, as the apply pass reads it for a surface at that
// distance (the aerial-perspective LUTs), composited over the lookup (common/lookup.glsl).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"
#include "common/lookup_shared.h"

layout(local_size_x = kLookupGroupSize, local_size_y = kLookupGroupSize, local_size_z = kLookupGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler3D multiScatteringLut;
layout(binding = kAtmosphereBindingApScattering) uniform sampler3D apScattering;
layout(binding = kAtmosphereBindingApTransmittance) uniform sampler2DArray apTransmittance;

#include "common/air/model.glsl"
#include "common/air/aerial_perspective_lookup.glsl"
#include "common/lookup.glsl"

void main() {
    uvec3 froxel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(froxel, lookupExtent()))) return;
    vec3 x = lookupRayDirection(lookupUv(froxel.xy)) * lookupSliceEnd(froxel.z);
    vec3 L, T;
    aerialPerspective(x, L, T);
    lookupComposite(ivec3(froxel), L * atmo.sun.rgb, T);
}
