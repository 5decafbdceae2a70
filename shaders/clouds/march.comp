#version 450
// The clouds' march (docs/effects/clouds.md, "March" and "Composite"): one ray per pixel of the march
// (the color's at resolution scale 1), or with a sparse update (cl.sparse.x = k > 1) per k×k block,
// marching the block's texel cl.sparse.yz. cl.sparse.w consecutive invocations share a ray, each marching
// one segment of its steps from T = 1; the first composes the segments front to back (L = Σ T_before·L_j,
// τ = Σ τ_j): a sparse update's few rays would otherwise leave the GPU waiting on each ray's chain of
// dependent fetches.
// The view ray's part inside the shape and before the geometry (and max distance) is split into `steps`
// equal steps whatever its length; each sample's extinction σt comes from the density field, its light
// from lighting.glsl, and each step is integrated in closed form (T·S·(1 - e^{-σt·Δ})/σt, in which the
// density appears once). The march stops once T < kCloudTransmittanceCutoff.
// out = color·T + L. With the atmosphere (kCloudAtmosphere) the clouds are seen through the air in front
// of them: the aerial perspective (L_ap, T_ap) at the clouds' extinction-weighted mean distance gives
// L' = T_ap·L + (1 - T)·L_ap·E (the air in front of the clouds, which the sky behind them already held,
// is no longer attenuated by them).
// Variant COLOR_RGBA32F: the color format. The rest are specialization constants (clouds_shared.h), so
// that one shader serves every frame and the compiler drops what a frame does not take: kCloudAtmosphere;
// kCloudScatter writes (L', T) into the march's own image at its extent (reduced resolution or temporal:
// upsample.comp composites it), kCloudTemporal also the texel's distances (clouds/distances.glsl): the
// reprojection distance (the clouds' mean distance, or where the ray ends when it meets none; -1 for a
// NaN depth: no history) and the surface's. Every binding is in the layout whatever the constants; those
// a frame does not use hold stand-ins, never accessed.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"
#include "common/air_shared.h"

layout(constant_id = kCloudConstantAtmosphere) const bool kCloudAtmosphere = false;
layout(constant_id = kCloudConstantScatter) const bool kCloudScatter = false;
layout(constant_id = kCloudConstantTemporal) const bool kCloudTemporal = false;

layout(local_size_x = kCloudGroupSize, local_size_y = kCloudGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
layout(binding = kCloudBindingDepth) uniform sampler2D depthTexture;
layout(binding = kCloudBindingBaseNoise) uniform sampler3D baseNoise;
layout(binding = kCloudBindingDetailNoise) uniform sampler3D detailNoise;
layout(binding = kCloudBindingCoverageMap) uniform sampler2D coverageMap;
#include "clouds/images.glsl"
layout(binding = kCloudBindingDistance, r32ui) uniform restrict writeonly uimage2D distanceOut;
#include "clouds/distances.glsl"

layout(binding = kCloudBindingAtmosphere, std140) uniform Atmosphere {
    AtmosphereUniforms atmo;
};
layout(binding = kCloudBindingTransmittanceLut) uniform sampler2D transmittanceLut;
layout(binding = kCloudBindingApScattering) uniform sampler3D apScattering;
layout(binding = kCloudBindingApTransmittance) uniform sampler2DArray apTransmittance;
layout(binding = kCloudBindingMultiScattering) uniform sampler3D multiScatteringLut;
#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "common/air/model.glsl"
#include "common/air/aerial_perspective_lookup.glsl"
#include "common/air/march.glsl"
#include "common/air/aerial_perspective_far.glsl"

#include "clouds/ray.glsl"
#include "clouds/density.glsl"
#include "clouds/lighting.glsl"
#include "common/ign.glsl"
#include "common/composite.glsl"
#include "common/integrate.glsl"

// The segments' (L, τ) and (weighted distance, weight sum), composed by the ray's first invocation.
shared vec4 segmentLight[kCloudGroupSize * kCloudGroupSize];
shared vec2 segmentDistance[kCloudGroupSize * kCloudGroupSize];

void main() {
    uint segments = cl.sparse.w, segment = gl_GlobalInvocationID.x % segments;
    uvec2 texel =
        uvec2(gl_GlobalInvocationID.x / segments, gl_GlobalInvocationID.y) * cl.sparse.x + cl.sparse.yz;
    bool inside = all(lessThan(texel, cl.marchExtent.xy));  // no return before the barrier below
    CloudRay ray;
    vec3 d = vec3(0.0);
    // T = e^{-τ} from the summed optical depth τ (a product of per-step exponentials drifts, and 1 - T
    // cancels for thin clouds: oneMinusExp(τ) keeps it). The mean distance weights each step by the
    // share of the light it removes, T·(1 - e^{-σΔ}), normalised by their sum (no division by 1 - T).
    float tau = 0.0;
    vec3 L = vec3(0.0);
    float weightedDistance = 0.0;
    float weightSum = 0.0;
    vec2 seg = vec2(0.0);
    if (inside) {
        ray = cloudTexelRay(texel);
        d = ray.dir;
        seg = cloudSegment(vec3(0.0), d, ray.far);
    }
    if (seg.y > seg.x) {
        float T = 1.0;
        float dt = (seg.y - seg.x) / float(cl.counts.x);
        // A sparse update marches a texel every k² frames: its own consecutive jitters, not every k²-th
        // (IGN's shift repeats over 64 frames: with k = 4 a texel would see 4 of them).
        uint jitterFrame = cl.extent.z / (cl.sparse.x * cl.sparse.x);
        float offset =
            (cl.flags.x & kCloudFlagJitter) != 0u ? interleavedGradientNoise(texel, jitterFrame) : 0.5;
        float albedo = cl.phase.w;
        uint first = segment * cl.counts.x / segments, end = (segment + 1u) * cl.counts.x / segments;
        for (uint i = first; i < end; ++i) {
            float t = seg.x + (float(i) + offset) * dt;
            vec3 x = d * t;
            float h = cloudHeightFraction(x);
            float sigma = cl.shape.w * cloudField(x, h);
            if (sigma <= 0.0) continue;
            float opticalDepth = sigma * dt;
            vec3 light = cloudInScattered(x, d, sigma, h);
            L += integrateStep(T, vec3(albedo) * light, opticalDepth);
            float removed = T * oneMinusExp(opticalDepth);
            weightedDistance += t * removed;
            weightSum += removed;
            tau += opticalDepth;
            T = exp(-tau);
            if (T < kCloudTransmittanceCutoff) break;
        }
    }
    if (segments > 1u) {
        segmentLight[gl_LocalInvocationIndex] = vec4(L, tau);
        segmentDistance[gl_LocalInvocationIndex] = vec2(weightedDistance, weightSum);
        barrier();
        if (segment != 0u) return;
        L = vec3(0.0);
        tau = weightedDistance = weightSum = 0.0;
        for (uint j = 0u; j < segments; ++j) {
            float before = exp(-tau);
            vec4 light = segmentLight[gl_LocalInvocationIndex + j];
            vec2 distances = segmentDistance[gl_LocalInvocationIndex + j];
            L += before * light.rgb;
            weightedDistance += before * distances.x;
            weightSum += before * distances.y;
            tau += light.a;
        }
    }
    if (!inside) return;
    float T = exp(-tau);
    bool met = tau > 0.0;  // any extinction on the ray
    float meanDistance = weightSum > 0.0 ? weightedDistance / weightSum : ray.far;
    if (kCloudAtmosphere && met) {
        vec3 apL, apT;
        aerialPerspectiveAnyDistance(d * meanDistance, kCloudFarAerialPerspectiveSteps, apL, apT);
        L = apT * L + oneMinusExp(tau) * apL * atmo.sun.rgb;
    }
    if (kCloudScatter) {
        imageStore(scatterImage, ivec2(texel), vec4(min(L, vec3(kColorMax)), T));
        if (kCloudTemporal)
            imageStore(distanceOut, ivec2(texel),
                       uvec4(packCloudDistances(isnan(ray.surface) ? -1.0 : meanDistance, ray.surface)));
    } else {
        vec4 color = imageLoad(colorIn, ivec2(texel));
        vec3 result = met ? compositeOver(color.rgb, T, L) : color.rgb;
        imageStore(colorOut, ivec2(texel), vec4(result, color.a));
    }
}
