// Descriptor bindings of the froxel fog's kernels (each pipeline's layout holds the ones it uses).
// COLOR_RGBA32F selects the storage format of the color images (common/color_format.glsl).
#ifndef POSTFX_FROXEL_BINDINGS_GLSL
#define POSTFX_FROXEL_BINDINGS_GLSL

#include "common/color_format.glsl"
layout(binding = kFroxelBindingColorIn, COLOR_FORMAT) uniform readonly image2D colorIn;
layout(binding = kFroxelBindingColorOut, COLOR_FORMAT) uniform writeonly image2D colorOut;
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
