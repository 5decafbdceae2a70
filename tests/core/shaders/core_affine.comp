#version 450
// Test shader for postfx's core helpers: out = in * scale + offset into a storage buffer and a 2D image.
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const float kScale = 1.0;
// clang-format off
layout(push_constant) uniform Push {
    float offset;
    uint width;
    uint height;
} pc;
layout(std430, binding = 0) readonly buffer Input { float values[]; } inputs;
layout(std430, binding = 1) writeonly buffer Output { float values[]; } outputs;
// clang-format on
layout(rgba16f, binding = 2) uniform writeonly image2D image;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint i = p.y * pc.width + p.x;
    float v = inputs.values[i] * kScale + pc.offset;
    outputs.values[i] = v;
    imageStore(image, ivec2(p), vec4(v, float(p.x), float(p.y), 1.0));
}
