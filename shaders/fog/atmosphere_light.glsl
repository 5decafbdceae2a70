// The sun's light through the atmosphere for the fogs (docs/effects/atmosphere.md, "The sun for every
// effect"): with the atmosphere on, FogUniforms' sunIlluminance is the illuminance outside it, and each
// sample receives it times the transmittance LUT's T at its own position toward the sun (0 where the
// planet hides the sun). Expects `fog` (FogUniforms).
#ifndef POSTFX_FOG_ATMOSPHERE_LIGHT_GLSL
#define POSTFX_FOG_ATMOSPHERE_LIGHT_GLSL

#include "atmosphere/transmittance_lut.glsl"

layout(binding = kFogBindingAtmosphere) uniform sampler2D atmosphereTransmittance;

// T of the atmosphere from camera-relative x toward the sun; 1 with the atmosphere off.
vec3 atmosphereSunTransmittance(vec3 x) {
    if ((fog.flags.x & kFogFlagAtmosphere) == 0u) return vec3(1.0);
    return sunTransmittanceFromLut(atmosphereTransmittance, fog.planetCamera.xyz + x, fog.toSun.xyz,
                                   fog.planet.x, fog.planet.y, fog.planet.zw);
}

#endif
