#version 450
// The clouds' march (docs/effects/clouds.md, "March" and "Composite"): one invocation per pixel.
// The view ray's part inside the shape and before the geometry (and max distance) is split into `steps`
// equal steps whatever its length; each sample's extinction σt comes from the density field, its light
// from lighting.glsl, and each step is integrated in closed form (T·S·(1 - e^{-σt·Δ})/σt, in which the
// density appears once). The march stops once T < kCloudTransmittanceCutoff.
// out = color·T + L. With ATMOSPHERE the clouds are seen through the air in front of them: the aerial
// perspective (L_ap, T_ap) at the clouds' extinction-weighted mean distance gives
// out = color·T + T_ap·L + (1 - T)·L_ap·E (the air in front of the clouds, which the sky behind them
// already held, is no longer attenuated by them).
// Variants: COLOR_RGBA32F (the color format), ATMOSPHERE.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"
#ifdef ATMOSPHERE
#include "atmosphere/atmosphere_shared.h"
#endif

layout(local_size_x = kCloudGroupSize, local_size_y = kCloudGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
layout(binding = kCloudBindingDepth) uniform sampler2D depthTexture;
layout(binding = kCloudBindingBaseNoise) uniform sampler3D baseNoise;
layout(binding = kCloudBindingDetailNoise) uniform sampler3D detailNoise;
#ifdef COLOR_RGBA32F
layout(binding = kCloudBindingColorIn, rgba32f) uniform restrict readonly image2D colorIn;
layout(binding = kCloudBindingColorOut, rgba32f) uniform restrict writeonly image2D colorOut;
const float kColorMax = 3.402823466e38;
#else
layout(binding = kCloudBindingColorIn, rgba16f) uniform restrict readonly image2D colorIn;
layout(binding = kCloudBindingColorOut, rgba16f) uniform restrict writeonly image2D colorOut;
const float kColorMax = 65504.0;  // largest finite half: never write Inf
#endif

#ifdef ATMOSPHERE
layout(binding = kCloudBindingAtmosphere, std140) uniform Atmosphere {
    AtmosphereUniforms atmo;
};
layout(binding = kCloudBindingTransmittanceLut) uniform sampler2D transmittanceLut;
layout(binding = kCloudBindingApScattering) uniform sampler3D apScattering;
layout(binding = kCloudBindingApTransmittance) uniform sampler2DArray apTransmittance;
#include "atmosphere/model.glsl"
#include "atmosphere/aerial_perspective_lookup.glsl"
#endif

#include "clouds/density.glsl"
#include "clouds/lighting.glsl"
#include "common/ign.glsl"
#include "common/composite.glsl"
#include "common/integrate.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, cl.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    float depth = texelFetch(depthTexture, ivec2(pixel), 0).r;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(cl.extent.xy) * 2.0 - 1.0;
    bool noGeometry = depth == cl.march.y;
    vec4 p = cl.clipToView * vec4(ndc, noGeometry ? 0.5 : depth, 1.0);
    vec3 view = p.xyz / p.w;
    vec3 d = normalize(p.w < 0.0 ? -p.xyz : p.xyz);
    float far = noGeometry ? cl.march.x : min(length(view), cl.march.x);

    vec2 seg = cloudSegment(vec3(0.0), d, far);
    float T = 1.0;
    vec3 L = vec3(0.0);
    float weightedDistance = 0.0;
    if (seg.y > seg.x) {
        float dt = (seg.y - seg.x) / float(cl.counts.x);
        float offset =
            (cl.flags.x & kCloudFlagJitter) != 0u ? interleavedGradientNoise(pixel, cl.extent.z) : 0.5;
        float albedo = cl.phase.w;
        for (uint i = 0u; i < cl.counts.x; ++i) {
            float t = seg.x + (float(i) + offset) * dt;
            vec3 x = d * t;
            float h = cloudHeightFraction(x);
            float sigma = cl.shape.w * cloudField(x, h);
            if (sigma <= 0.0) continue;
            float opticalDepth = sigma * dt;
            vec3 light = cloudInScattered(x, d, sigma, h);
            L += integrateStep(T, vec3(albedo) * light, opticalDepth);
            float next = T * exp(-opticalDepth);
            weightedDistance += t * (T - next);
            T = next;
            if (T < kCloudTransmittanceCutoff) break;
        }
    }
    vec3 result = color.rgb;
    if (T < 1.0) {
#ifdef ATMOSPHERE
        vec3 apL, apT;
        aerialPerspective(d * (weightedDistance / (1.0 - T)), apL, apT);
        L = apT * L + (1.0 - T) * apL * atmo.sun.rgb;
#endif
        result = compositeOver(color.rgb, T, L);
    }
    imageStore(colorOut, ivec2(pixel), vec4(result, color.a));
}
