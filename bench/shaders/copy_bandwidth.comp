#version 450
// postfx-bench --froxel's memory-bandwidth probe (Runner::copyBandwidth): a compute pass copying
// `words` 16-byte words from `source` to `target`, each invocation a word at a time with a grid stride,
// as a compute pass streams memory (the froxel fog's apply pass reads and writes the colour image).
layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Source {
    uvec4 source[];
};
layout(std430, binding = 1) writeonly buffer Target {
    uvec4 target[];
};
layout(push_constant) uniform Push {
    uint words;
};

void main() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint i = gl_GlobalInvocationID.x; i < words; i += stride)
        target[i] = source[i];
}
