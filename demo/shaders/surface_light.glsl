// The light on a surface point, shared by the deferred lighting (lighting.comp) and the forward pass
// (forward.frag), so that a surface is lit alike in both: the sun through the atmosphere (T_atm), its
// shadow map and the clouds' shadow map, and the local lights with their shadows (lighting.comp states
// the formula). Expects `frame`, `shadowMap`, `cloudShadowMap`, `lightList`, `localShadowAtlas` and
// `shadowFaces` declared, and shadow.glsl and local_shadow.glsl included.
#ifndef DEMO_SURFACE_LIGHT_GLSL
#define DEMO_SURFACE_LIGHT_GLSL

// The clouds' transmittance toward the sun at world position p through the map at rows (u, v): 1 outside.
float cloudShadowAt(vec3 p, vec4 u, vec4 v) {
    vec2 uv = vec2(dot(u.xyz, p) + u.w, dot(v.xyz, p) + v.w);
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return 1.0;
    return textureLod(cloudShadowMap, uv, 0.0).r;
}

// The irradiance [pre-exposed lux] on a surface at camera-relative position `relative` (world position
// `world`) with unit normal n, the clouds' shadow read at rows (cloudU, cloudV). `facing`: a particle,
// lit as if it faced every light at half its cosine-weighted light (a diffuse puff rather than a
// flat card); its shadow lookups are offset toward each light.
vec3 surfaceIrradiance(vec3 relative, vec3 world, vec3 n, bool facing, vec4 cloudU, vec4 cloudV) {
    vec3 toSun = frame.toSun.xyz;
    float nDotL = facing ? 0.5 : max(dot(n, toSun), 0.0);
    vec3 sunNormal = facing ? toSun : n;
    float sunCos = facing ? 1.0 : nDotL;
    float visibility = 1.0;
    if (frame.toSun.w > 0.5 && nDotL > 0.0) visibility = sunVisibility(world, sunNormal, sunCos);
    if (nDotL > 0.0) visibility *= cloudShadowAt(world, cloudU, cloudV);
    float altitudeSpan = frame.sunOpticalDepthHigh.w - frame.sunOpticalDepthLow.w;
    float a = clamp((world.y - frame.sunOpticalDepthLow.w) / altitudeSpan, 0.0, 1.0);
    vec3 sunTransmittance = exp(-mix(frame.sunOpticalDepthLow.rgb, frame.sunOpticalDepthHigh.rgb, a));
    vec3 irradiance = frame.sunIlluminance.rgb * sunTransmittance * (nDotL * visibility);
    uint lightCount = uint(frame.depthParams.w);
    for (uint i = 0u; i < lightCount; ++i) {
        GpuLight light = lightList.lights[i];
        vec3 toLight = light.positionRadius.xyz - relative;
        float d = length(toLight);
        vec3 l = d > 0.0 ? toLight / d : n;
        float nDotLi = facing ? 0.5 : max(dot(n, l), 0.0);
        if (nDotLi <= 0.0) continue;
        float spot =
            spotFactor(dot(light.directionCosOuter.xyz, -l), light.directionCosOuter.w, light.cosInner.x);
        float falloff = localLightFalloff(d, light.positionRadius.w, light.intensityRange.w);
        float contribution = falloff * spot * nDotLi;
        if (light.cosInner.z > 0.5 && contribution > 0.0)
            contribution *= localShadowVisibility(light, relative, facing ? l : n, facing ? 1.0 : nDotLi, d);
        irradiance += light.intensityRange.rgb * contribution;
    }
    return min(irradiance, vec3(1e30));  // finite (I · falloff may overflow): albedo 0 gives 0
}

#endif
