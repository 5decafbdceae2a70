// Descriptor bindings of the froxel fog's kernels (each pipeline's layout holds the ones it uses).
// COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#ifndef POSTFX_FROXEL_BINDINGS_GLSL
#define POSTFX_FROXEL_BINDINGS_GLSL

#ifdef COLOR_RGBA32F
layout(binding = kFroxelBindingColorIn, rgba32f) uniform readonly image2D colorIn;
layout(binding = kFroxelBindingColorOut, rgba32f) uniform writeonly image2D colorOut;
const float kColorMax = 3.402823466e38;
#else
layout(binding = kFroxelBindingColorIn, rgba16f) uniform readonly image2D colorIn;
layout(binding = kFroxelBindingColorOut, rgba16f) uniform writeonly image2D colorOut;
const float kColorMax = 65504.0;  // largest finite half: never write Inf
#endif
layout(binding = kFroxelBindingDepth) uniform sampler2D depthTexture;
layout(binding = kFroxelBindingShadowMap) uniform sampler2D shadowMap;
layout(binding = kFroxelBindingNoise) uniform sampler3D noiseTexture;
layout(binding = kFroxelBindingUniforms, std140) uniform Uniforms {
    FogUniforms fog;  // the shared medium (common/medium/medium.glsl reads it)
    FroxelUniforms froxel;
};
layout(binding = kFroxelBindingLights, std140) uniform Lights {
    FroxelLights local;
};
layout(binding = kFroxelBindingLightLists, r32ui) uniform uimage3D lightLists;

#endif
