// G-buffer pass: world-space mesh vertices, projected camera-relative (keeps precision far from origin).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(set = 0, binding = kBindingFrame, std140) uniform FrameBlock {
    FrameUniforms frame;
};

layout(location = kAttribPosition) in vec3 inPosition;  // world [m]
layout(location = kAttribNormal) in vec3 inNormal;      // world, unit

layout(location = 0) out vec3 outNormal;

void main() {
    outNormal = inNormal;
    gl_Position = frame.viewProj * vec4(inPosition - frame.cameraPosition.xyz, 1.0);
}
