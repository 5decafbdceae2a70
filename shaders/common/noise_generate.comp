#version 450
// Generates a tileable 3D noise texture (formula in common/noise.glsl) into an R8_UNORM storage image of
// size³ texels: the Perlin–Worley fBm (the fogs' noise, the clouds' base shape) or its inverted Worley fBm
// alone (the clouds' detail). Dispatched once per (size, seed) change (fog/medium_noise.h,
// declareGeneratedNoise).
#extension GL_GOOGLE_include_directive : require

#include "common/noise.glsl"
#include "common/shared.h"

layout(local_size_x = kNoiseGroupSize, local_size_y = kNoiseGroupSize, local_size_z = kNoiseGroupSize) in;

layout(push_constant) uniform Push {
    NoisePush push;
};

layout(r8, binding = kNoiseBindingTexture) uniform writeonly image3D noiseTexture;

void main() {
    uint size = push.params.x;
    uvec3 texel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(texel, uvec3(size)))) return;
    float n = push.params.z == kNoisePerlinWorley ? perlinWorleyNoise(texel, size, push.params.y)
                                                  : worleyFbm(texel, size, push.params.y);
    imageStore(noiseTexture, ivec3(texel), vec4(n, 0.0, 0.0, 0.0));
}
