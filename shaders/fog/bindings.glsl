// Descriptor bindings of the fog's march (postfx's raymarch and the benchmark's baselines share them).
// COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#ifndef POSTFX_FOG_BINDINGS_GLSL
#define POSTFX_FOG_BINDINGS_GLSL

#ifdef COLOR_RGBA32F
layout(binding = kFogBindingColorIn, rgba32f) uniform readonly image2D colorIn;
layout(binding = kFogBindingColorOut, rgba32f) uniform writeonly image2D colorOut;
const float kColorMax = 3.402823466e38;
#else
layout(binding = kFogBindingColorIn, rgba16f) uniform readonly image2D colorIn;
layout(binding = kFogBindingColorOut, rgba16f) uniform writeonly image2D colorOut;
const float kColorMax = 65504.0;  // largest finite half: never write Inf
#endif
layout(binding = kFogBindingDepth) uniform sampler2D depthTexture;
layout(binding = kFogBindingShadowMap) uniform sampler2D shadowMap;
layout(binding = kFogBindingNoise) uniform sampler3D noiseTexture;
layout(binding = kFogBindingUniforms, std140) uniform Uniforms {
    FogUniforms fog;
};

#endif
