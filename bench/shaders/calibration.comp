#version 450
// postfx-bench's calibration dispatch (bench/calibration.h): the same fixed ALU work every time, a loop of
// `iterations` steps of four independent multiply-adds per invocation on a small grid, no memory traffic.
// Its time follows the GPU's shader clock (and any other work sharing the GPU), not the bench's settings.
layout(local_size_x = 64) in;

// Written only when the loop ends on a value it never reaches, so that the loop is not optimised away.
layout(std430, binding = 0) writeonly buffer Sink {
    float sink[];
};
layout(push_constant) uniform Push {
    uint iterations;
};

void main() {
    const float seed = float(gl_GlobalInvocationID.x & 1023u) * 1e-6;
    vec4 x = vec4(seed, seed + 0.25, seed + 0.5, seed + 0.75);
    // x -> x · a + b with |a| < 1 stays bounded: no denormals, no infinities, whatever the iterations.
    const vec4 a = vec4(0.9995, 0.9993, 0.9991, 0.9989);
    const vec4 b = vec4(1e-4, 2e-4, 3e-4, 4e-4);
    // In blocks of 256 steps: llvmpipe ends any one loop after 65535 iterations.
    for (uint block = 0u; block < iterations / 256u; ++block)
        for (uint i = 0u; i < 256u; ++i)
            x = fma(x, a, b);
    for (uint i = 0u; i < iterations % 256u; ++i)
        x = fma(x, a, b);
    if (x.x + x.y + x.z + x.w < -1.0) sink[gl_GlobalInvocationID.x & 63u] = x.x;
}
