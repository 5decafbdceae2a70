#version 450
// Test-only effect "consumer" (tests/core/test_frame_graph.cpp): color += the producer's image at texel
// (0, 0), rgb only.
layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Push {
    uvec2 extent;
}
pc;
layout(rgba16f, binding = 0) uniform readonly image2D colorIn;
layout(rgba16f, binding = 1) uniform writeonly image2D colorOut;
layout(binding = 2) uniform sampler2D lut;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), pc.extent))) return;
    vec4 c = imageLoad(colorIn, p);
    imageStore(colorOut, p, vec4(c.rgb + texelFetch(lut, ivec2(0), 0).rgb, c.a));
}
