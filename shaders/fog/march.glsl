// The fog's march along one view ray (docs/effects/fog.md, "March"): a fixed number of steps from the
// camera to the surface (or max distance), each step integrated in closed form, then the analytic
// height-fog tail. Expects the fog's bindings and medium.glsl, ray.glsl, ign.glsl, integrate.glsl and
// phase.glsl included.
#ifndef POSTFX_FOG_MARCH_GLSL
#define POSTFX_FOG_MARCH_GLSL

#include "common/medium/atmosphere_light.glsl"

struct FogScatter {
    vec3 inScattered;     // L: radiance scattered toward the camera along the ray
    float transmittance;  // T: from the camera to the surface (or through the whole medium)
};

// Empty-space skipping (fog.md, "Empty space"): the part [tEnter, tExit] of [0, marchDistance] where the
// ray is below the medium's top (fog.heights.y, above base); above it the extinction is negligible. The
// ray's height above base is heights.x + dirY·t, so it crosses the top at t = (top - heights.x) / dirY.
// An empty interval (tExit <= tEnter) means the ray crosses no medium and takes no step.
vec2 mediumInterval(float dirY, float marchDistance) {
    if (!fogFlag(kFogFlagSkipEmptySpace)) return vec2(0.0, marchDistance);
    float below = fog.heights.y - fog.heights.x;  // how far the top is above the camera (< 0: camera above)
    if (dirY == 0.0) return vec2(0.0, below > 0.0 ? marchDistance : 0.0);
    float tCross = below / dirY;
    return dirY > 0.0 ? vec2(0.0, clamp(tCross, 0.0, marchDistance))
                      : vec2(clamp(tCross, 0.0, marchDistance), marchDistance);
}

// The medium's inputs along one ray x = dir·t as affine functions of t, set up once per ray: each step
// evaluates each with one FMA per component instead of from x (the height's exponent, the noise
// coordinate, the shadow map's clip coordinates: 16 FMAs of a matrix product become 4).
struct FogRayTerms {
    float heightOrigin, heightStep;  // -height_falloff · (y(t) - base height) = origin + t · step
    vec3 noiseOrigin, noiseStep;     // noise coordinate
    vec4 shadowOrigin, shadowStep;   // shadow map clip coordinates: viewToShadow · (dir·t, 1)
};

FogRayTerms fogRayTerms(vec3 dir) {
    FogRayTerms r;
    r.heightOrigin = -fog.medium.y * fog.heights.x;
    r.heightStep = -fog.medium.y * dir.y;
    r.noiseOrigin = fog.noise.xyz;
    r.noiseStep = dir * fog.noise.w;
    r.shadowOrigin = fog.viewToShadow[3];
    r.shadowStep = fog.viewToShadow * vec4(dir, 0.0);
    return r;
}

// `jitterPixel` seeds the interleaved-gradient-noise start offset: the pixel of the image the march
// writes, so that neighbours get decorrelated offsets at any resolution.
FogScatter marchFog(FogRay ray, uvec2 jitterPixel) {
    vec3 dir = ray.dir;
    float surfaceDistance = ray.surfaceDistance;

    float maxDistance = fog.medium.w;
    float marchDistance = min(surfaceDistance, maxDistance);
    uint steps = fog.extent.z;
    vec2 interval = mediumInterval(dir.y, marchDistance);
    float dt = max(interval.y - interval.x, 0.0) / float(steps);
    if (dt <= 0.0) steps = 0u;  // no medium along the ray (or a zero-length march)
    float offset = fogFlag(kFogFlagJitter) ? interleavedGradientNoise(jitterPixel, fog.extent.w) : 0.5;

    vec3 albedo = fog.albedo.rgb;
    vec3 sunPhase = fog.sunIlluminance.rgb * henyeyGreensteinDirections(dir, fog.toSun.xyz, fog.medium.z);
    vec3 ambient = fog.ambient.rgb;

    FogRayTerms terms = fogRayTerms(dir);
    float tFirst = interval.x + offset * dt;
    float transmittance = 1.0;
    vec3 inScattered = vec3(0.0);
    bool cutOff = false;
    for (uint k = 0u; k < steps; ++k) {
        float t = tFirst + float(k) * dt;
        float height = heightTermOfExponent(terms.heightOrigin + t * terms.heightStep);
        float sigmaT = extinctionOf(noiseTermAt(terms.noiseOrigin + t * terms.noiseStep), height);
        if (sigmaT <= 0.0) continue;
        vec3 x = dir * t;  // for the atmosphere's and the clouds' light only
        vec3 sunLight = sunPhase *
                        (shadowVisibilityOfClip(terms.shadowOrigin + t * terms.shadowStep) *
                         sunTransmittanceOfHeightTerm(height)) *
                        atmosphereSunTransmittance(x) * cloudShadowVisibility(x);
        float opticalDepth = sigmaT * dt;
        inScattered += integrateStep(transmittance, albedo * (sunLight + ambient), opticalDepth);
        transmittance *= exp(-opticalDepth);
        if (transmittance < fog.march.x) {
            cutOff = true;
            break;
        }
    }

    // Analytic tail: height fog from max distance to the surface (or infinity), no noise, no shadow map.
    if (!cutOff)
        addAnalyticTail(dir, surfaceDistance, sunPhase * atmosphereSunTransmittance(dir * maxDistance),
                        inScattered, transmittance);
    return FogScatter(inScattered, transmittance);
}

#endif
