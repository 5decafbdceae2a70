// Shadow map pass: depth only, orthographic from the sun (standard Z: 0 nearest the sun).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(set = 0, binding = kBindingFrame, std140) uniform FrameBlock {
    FrameUniforms frame;
};

layout(location = kAttribPosition) in vec3 inPosition;  // world [m]

void main() {
    gl_Position = frame.shadowViewProj * vec4(inPosition, 1.0);
}
