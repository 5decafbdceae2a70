// An effect's lookup pass (docs/integration.md, "Transparent surfaces"): its (L, T) from the camera to
// the end of each slice of the lookup's camera-frustum volume, composited over what the effects before it
// in composite order wrote: L ← L·T_e + L_e, T ← T·T_e (the first writer stores its own).
#ifndef POSTFX_LOOKUP_GLSL
#define POSTFX_LOOKUP_GLSL

#include "common/lookup_shared.h"
#include "postfx/volumetrics.glsl"

layout(binding = kLookupBindingUniforms, std140) uniform LookupBlock {
    PostfxLookupUniforms lookup;
};
layout(binding = kLookupBindingScattering, rgba16f) uniform restrict image3D lookupScattering;
layout(binding = kLookupBindingTransmittance, rgba16f) uniform restrict image3D lookupTransmittance;
layout(push_constant) uniform LookupPushBlock {
    uvec4 lookupFlags;
};

uvec3 lookupExtent() {
    return uvec3(imageSize(lookupScattering));
}

// Where slice k ends along every ray [m]: x·(y/x)^(k / (count - 1)) (postfxLookupSliceZ's inverse).
float lookupSliceEnd(uint k) {
    return lookup.slices.x * exp(lookup.slices.z * float(k) / (lookup.slices.w - 1.0));
}

// The froxel column's uv in [0, 1]² (Vulkan NDC y down, as pixels: (column + 0.5) / extent).
vec2 lookupUv(uvec2 column) {
    return (vec2(column) + 0.5) / vec2(lookupExtent().xy);
}

// Unit camera-relative direction of the ray through uv.
vec3 lookupRayDirection(vec2 uv) {
    vec4 p = lookup.clipToRelative * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
    return normalize(p.w < 0.0 ? -p.xyz : p.xyz);
}

void lookupComposite(ivec3 froxel, vec3 L, vec3 T) {
    if (lookupFlags.x == 0u) {
        L += imageLoad(lookupScattering, froxel).rgb * T;
        T *= imageLoad(lookupTransmittance, froxel).rgb;
    }
    imageStore(lookupScattering, froxel, vec4(min(L, vec3(65504.0)), 0.0));
    imageStore(lookupTransmittance, froxel, vec4(T, 0.0));
}

#endif
