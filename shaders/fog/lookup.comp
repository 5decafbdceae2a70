#version 450
// fog.lookup (docs/integration.md, "Transparent surfaces"): the ray-marched fog's medium integrated along
// each column of the volumetrics lookup, at its slices, with the march's medium, noise, shadows and light
// (march.glsl's step, kFogLookupStepsPerSlice steps per slice), and the analytic tail beyond max distance;
// (L, T) at every slice's end composited over the lookup (common/lookup.glsl).
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"
#include "common/lookup_shared.h"

layout(local_size_x = kLookupColumnGroupSize, local_size_y = kLookupColumnGroupSize) in;

#include "fog/bindings.glsl"

#include "common/ign.glsl"
#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/ray.glsl"
#include "fog/march.glsl"
#include "common/lookup.glsl"

void main() {
    uvec2 column = gl_GlobalInvocationID.xy;
    uvec3 extent = lookupExtent();
    if (any(greaterThanEqual(column, extent.xy))) return;
    vec3 dir = lookupRayDirection(lookupUv(column));
    float maxDistance = fog.medium.w;
    vec2 interval = mediumInterval(dir.y, maxDistance);
    vec3 albedo = fog.albedo.rgb;
    vec3 sunPhase = fog.sunIlluminance.rgb * henyeyGreensteinDirections(dir, fog.toSun.xyz, fog.medium.z);
    vec3 tailSun = sunPhase * atmosphereSunTransmittance(dir * maxDistance);
    FogRayTerms terms = fogRayTerms(dir);

    float transmittance = 1.0;
    vec3 inScattered = vec3(0.0);
    bool cutOff = false;
    float start = 0.0;
    for (uint k = 0u; k < extent.z; ++k) {
        float end = lookupSliceEnd(k);
        // The slice's part inside the medium's interval, in equal steps at their midpoints.
        float a = max(start, interval.x), b = min(end, interval.y);
        float dt = (b - a) / float(kFogLookupStepsPerSlice);
        for (uint s = 0u; !cutOff && dt > 0.0 && s < kFogLookupStepsPerSlice; ++s) {
            float t = a + (float(s) + 0.5) * dt;
            float height = heightTermOfExponent(terms.heightOrigin + t * terms.heightStep);
            float sigmaT = extinctionOf(noiseTermAt(terms.noiseOrigin + t * terms.noiseStep), height);
            if (sigmaT <= 0.0) continue;
            vec3 x = dir * t;
            vec3 sunLight = sunPhase *
                            (shadowVisibilityOfClip(terms.shadowOrigin + t * terms.shadowStep) *
                             sunTransmittanceOfHeightTerm(height)) *
                            atmosphereSunTransmittance(x) * cloudShadowVisibility(x);
            float opticalDepth = sigmaT * dt;
            inScattered += integrateStep(transmittance, albedo * (sunLight + fog.ambient.rgb), opticalDepth);
            transmittance *= exp(-opticalDepth);
            cutOff = transmittance < fog.march.x;
        }
        vec3 L = inScattered;
        float T = transmittance;
        if (!cutOff) addAnalyticTail(dir, end, tailSun, L, T);  // beyond max distance
        lookupComposite(ivec3(column, k), L, vec3(T));
        start = end;
    }
}
