// The sun's light through the atmosphere for the fogs (docs/effects/atmosphere.md, "The sun for every
// effect"): with the atmosphere on, FogUniforms' sunIlluminance is the illuminance outside it, and each
// sample receives it times the transmittance LUT's T at its own position toward the sun (0 where the
// planet hides the sun). With clouds casting shadows, the clouds' shadow map dims it too
// (docs/effects/clouds.md, "Shadows"). Expects `fog` (FogUniforms).
#ifndef POSTFX_FOG_ATMOSPHERE_LIGHT_GLSL
#define POSTFX_FOG_ATMOSPHERE_LIGHT_GLSL

#include "common/medium/flags.glsl"
#include "common/air/transmittance_lut.glsl"
#include "common/cloud_shadow.glsl"

layout(binding = kMediumBindingAtmosphere) uniform sampler2D atmosphereTransmittance;
layout(binding = kMediumBindingCloudShadow) uniform sampler2D cloudShadowMap;

// T of the atmosphere from camera-relative x toward the sun; 1 with the atmosphere off.
vec3 atmosphereSunTransmittance(vec3 x) {
    if (!fogFlag(kFogFlagAtmosphere)) return vec3(1.0);
    return sunTransmittanceFromLut(atmosphereTransmittance, fog.planetCamera.xyz + x, fog.toSun.xyz,
                                   fog.planet.x, fog.planet.y, fog.planet.zw);
}

// T of the clouds from camera-relative x toward the sun; 1 without clouds casting shadows.
float cloudShadowVisibility(vec3 x) {
    if (!fogFlag(kFogFlagCloudShadow)) return 1.0;
    return cloudShadow(cloudShadowMap, fog.cloudShadowU, fog.cloudShadowV, x);
}

#endif
