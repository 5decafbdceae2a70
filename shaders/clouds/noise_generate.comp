#version 450
// Generates one of the clouds' tileable 3D noise textures (docs/effects/clouds.md, "Density") into an
// R8_UNORM storage image of size³ texels: the base shape (Perlin–Worley, the formula of
// common/noise.glsl, as the fogs' noise) or the detail (its inverted Worley fBm alone, under another seed).
// Dispatched once per (size, seed) change.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"
#include "common/noise.glsl"

layout(local_size_x = kCloudNoiseGroupSize, local_size_y = kCloudNoiseGroupSize,
       local_size_z = kCloudNoiseGroupSize) in;

layout(push_constant) uniform Push {
    CloudNoisePush push;
};

layout(r8, binding = kCloudNoiseBindingTexture) uniform writeonly image3D noiseTexture;

void main() {
    uint size = push.params.x;
    uvec3 texel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(texel, uvec3(size)))) return;
    float n = push.params.z == 0u ? perlinWorleyNoise(texel, size, push.params.y)
                                  : worleyFbm(texel, size, push.params.y);
    imageStore(noiseTexture, ivec3(texel), vec4(n, 0.0, 0.0, 0.0));
}
