// Descriptor bindings of the fog's march (postfx's raymarch and the benchmark's baselines share them).
// COLOR_RGBA32F selects the storage format of the color images (common/color_format.glsl).
#ifndef POSTFX_FOG_BINDINGS_GLSL
#define POSTFX_FOG_BINDINGS_GLSL

#include "common/color_format.glsl"
layout(binding = kFogBindingColorIn, COLOR_FORMAT) uniform readonly image2D colorIn;
layout(binding = kFogBindingColorOut, COLOR_FORMAT) uniform writeonly image2D colorOut;
layout(binding = kFogBindingDepth) uniform sampler2D depthTexture;
layout(binding = kFogBindingShadowMap) uniform sampler2D shadowMap;
layout(binding = kFogBindingNoise) uniform sampler3D noiseTexture;
layout(binding = kFogBindingUniforms, std140) uniform Uniforms {
    FogUniforms fog;
};

#endif
