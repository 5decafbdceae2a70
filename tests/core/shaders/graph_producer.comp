#version 450
// Test-only effect "producer" (tests/core/test_frame_graph.cpp): fills a 4×4 image with a constant.
layout(local_size_x = 4, local_size_y = 4) in;
layout(push_constant) uniform Push {
    vec4 value;
}
pc;
layout(rgba16f, binding = 0) uniform writeonly image2D lut;

void main() {
    imageStore(lut, ivec2(gl_GlobalInvocationID.xy), pc.value);
}
