#version 450
// Composites a reduced-resolution march (raymarch_reduced.comp), or the temporal accumulation of one
// (temporal.comp), over the host's color at full resolution: out = color · T + L, with (L, T)
// upsampled depth-aware (docs/effects/fog.md, "Resolution scale"). Of the 2×2 scatter texels around the
// pixel, those whose ray ends within kFogUpsampleDistanceTolerance of the pixel's own surface distance are
// blended with bilinear weights; when none does (an edge thinner than a texel), the texel of nearest distance
// is taken (nearest-depth upsampling). The CPU reference does the same (fog_reference.cpp).
//
// Variants: COLOR_RGBA32F selects the storage format of the images (default rgba16f); SCATTER_RGBA32F
// an RGBA32F scatter image (the temporal history) with RGBA16F color.
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = kFogGroupSize, local_size_y = kFogGroupSize) in;

#include "fog/bindings.glsl"
#include "fog/scatter_image.glsl"

#include "common/medium/ray.glsl"
#include "common/composite.glsl"

// |a - b|, 0 when both are infinite (pixels with no geometry match each other), ∞ when one is.
float distanceDifference(float a, float b) {
    return isinf(a) && isinf(b) ? 0.0 : abs(a - b);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, fog.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    float distance = fogRay(pixel).surfaceDistance;

    uvec2 texels[4];
    float bilinear[4];
    reducedFootprint(pixel, fog.extent.xy, fog.scatterExtent.xy, texels, bilinear);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    vec4 nearest = vec4(0.0);
    float nearestDifference = kInfinity;
    for (int k = 0; k < 4; ++k) {
        vec4 s = imageLoad(scatterImage, ivec2(texels[k]));
        float difference = distanceDifference(fogRay(fogSourcePixel(texels[k])).surfaceDistance, distance);
        if (!isinf(difference) && difference <= kFogUpsampleDistanceTolerance * distance) {
            sum += bilinear[k] * s;
            weight += bilinear[k];
        }
        if (k == 0 || difference < nearestDifference) {
            nearest = s;
            nearestDifference = difference;
        }
    }
    vec4 scatter = weight > 0.0 ? sum / weight : nearest;
    imageStore(colorOut, ivec2(pixel), vec4(compositeOver(color.rgb, scatter.a, scatter.rgb), color.a));
}
