#version 450
// clouds.lookup (docs/integration.md, "Transparent surfaces"): at the end of every slice of the volumetrics
// lookup, the clouds in front of it: the march's (L, T) at the column's uv (bilinear over its 2×2 texels),
// each texel counted where its clouds' mean distance lies before the slice's end, composited over the
// lookup (common/lookup.glsl). The march's image is this frame's (with temporal: the accumulation, alpha
// the optical depth). Variant: SCATTER_RGBA32F, the image is RGBA32F (else RGBA16F).
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"
#include "common/lookup_shared.h"

layout(local_size_x = kLookupGroupSize, local_size_y = kLookupGroupSize, local_size_z = kLookupGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
#ifdef SCATTER_RGBA32F
layout(binding = kCloudBindingScatter, rgba32f) uniform restrict readonly image2D cloudImage;
#else
layout(binding = kCloudBindingScatter, rgba16f) uniform restrict readonly image2D cloudImage;
#endif
layout(binding = kCloudBindingDistance, r32ui) uniform restrict readonly uimage2D cloudDistances;

#include "clouds/distances.glsl"
#include "common/lookup.glsl"

void main() {
    uvec3 froxel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(froxel, lookupExtent()))) return;
    float t = lookupSliceEnd(froxel.z);
    ivec2 size = imageSize(cloudImage);
    vec2 p = lookupUv(froxel.xy) * vec2(size) - 0.5;
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    vec3 L = vec3(0.0), T = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        ivec2 offset = ivec2(k & 1, k >> 1);
        ivec2 texel = clamp(base + offset, ivec2(0), size - 1);
        float w = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        vec4 s = imageLoad(cloudImage, texel);
        if ((cl.flags.x & kCloudFlagOpticalDepthHistory) != 0u) s.a = exp(-s.a);
        float distance = unpackCloudDistances(imageLoad(cloudDistances, texel).x).x;
        bool inFront = distance >= 0.0 && distance <= t;  // negative: a NaN depth, no clouds
        L += w * (inFront ? s.rgb : vec3(0.0));
        T += w * (inFront ? s.a : 1.0);
    }
    lookupComposite(ivec3(froxel), L, T);
}
