#version 450
// Generates the fog's tileable 3D noise texture: one Perlin–Worley fBm value per texel (formula in
// common/noise.glsl), into an R8_UNORM storage image of size³ texels. Dispatched once per
// (size, seed) change by postfx::fog::FogNoise.
#extension GL_GOOGLE_include_directive : require

#include "common/noise.glsl"
#include "fog/fog_shared.h"

layout(local_size_x = kNoiseGroupSize, local_size_y = kNoiseGroupSize, local_size_z = kNoiseGroupSize) in;

layout(push_constant) uniform Push {
    NoisePush push;  // x: size, y: seed
};

layout(r8, binding = kNoiseBindingTexture) uniform writeonly image3D noiseTexture;

void main() {
    uint size = push.params.x;
    uvec3 texel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(texel, uvec3(size)))) return;
    float n = perlinWorleyNoise(texel, size, push.params.y);
    imageStore(noiseTexture, ivec3(texel), vec4(n, 0.0, 0.0, 0.0));
}
