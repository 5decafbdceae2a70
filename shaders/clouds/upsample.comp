#version 450
// Composites the clouds' march (reduced resolution), or its temporal accumulation, over the host's color
// at full resolution: out = color·T + L, with (L, T) upsampled depth-aware (docs/effects/clouds.md,
// "Resolution and temporal"). Of the 2×2 march texels around the pixel, those whose ray ends within
// kCloudUpsampleDistanceTolerance of the pixel's own surface (the sky matches only the sky) are blended
// with bilinear weights; when none does (an edge thinner than a texel), the texel nearest in distance is
// taken. At resolution scale 1 each pixel reads its own texel.
// With temporal accumulation the history's alpha is the optical depth τ: T = e^{-τ} per texel, then blended.
// Variants: COLOR_RGBA32F (the color format); SCATTER_RGBA32F: the march's image is RGBA32F (the
// temporal history) with RGBA16F color.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"

layout(local_size_x = kCloudGroupSize, local_size_y = kCloudGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
layout(binding = kCloudBindingDepth) uniform sampler2D depthTexture;
#include "clouds/images.glsl"
#include "clouds/ray.glsl"
#include "common/composite.glsl"

// |a - b| relative to b, 0 when both are infinite (sky matches sky), ∞ when only one is or either is NaN.
float relativeDifference(float a, float b) {
    if (isinf(a) && isinf(b)) return 0.0;
    float r = abs(a - b) / b;
    return isnan(r) ? kInfinity : r;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, cl.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    float surface = cloudRay(pixel).surface;

    uvec2 texels[4];
    float bilinear[4];
    reducedFootprint(pixel, cl.extent.xy, cl.marchExtent.xy, texels, bilinear);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    vec4 nearest = vec4(0.0);
    float nearestDifference = kInfinity;
    for (int k = 0; k < 4; ++k) {
        vec4 s = imageLoad(scatterImage, ivec2(texels[k]));
        if ((cl.flags.x & kCloudFlagOpticalDepthHistory) != 0u) s.a = exp(-s.a);
        float difference = relativeDifference(cloudRay(cloudSourcePixel(texels[k])).surface, surface);
        if (difference <= kCloudUpsampleDistanceTolerance) {
            sum += bilinear[k] * s;
            weight += bilinear[k];
        }
        if (k == 0 || difference < nearestDifference) {
            nearest = s;
            nearestDifference = difference;
        }
    }
    vec4 clouds = weight > 0.0 ? sum / weight : nearest;
    bool covered = clouds.a < 1.0 || clouds.r > 0.0 || clouds.g > 0.0 || clouds.b > 0.0;
    vec3 result = covered ? compositeOver(color.rgb, clouds.a, clouds.rgb) : color.rgb;
    imageStore(colorOut, ivec2(pixel), vec4(result, color.a));
}
