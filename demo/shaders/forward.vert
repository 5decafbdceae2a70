// Forward pass: transparent objects (world-space mesh vertices) and particles (camera-facing quads, six
// vertices each, built on the CPU), projected camera-relative as the G-buffer pass does.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(set = 0, binding = kBindingFrame, std140) uniform FrameBlock {
    FrameUniforms frame;
};
layout(push_constant) uniform PushBlock {
    ForwardPush draw;
};

layout(location = kAttribPosition) in vec3 inPosition;  // world [m]
layout(location = kAttribNormal) in vec3 inNormal;      // world, unit

layout(location = 0) out vec3 outRelative;  // camera-relative world position [m]
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outCorner;  // particles: the quad's corner in [-1, 1]²

// A particle's six vertices (two triangles), in the order the renderer writes them.
const vec2 kCorners[6] =
    vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    outRelative = inPosition - frame.cameraPosition.xyz;
    outNormal = inNormal;
    outCorner = kCorners[gl_VertexIndex % 6];
    gl_Position = frame.viewProj * vec4(outRelative, 1.0);
}
