// G-buffer pass: albedo (per draw) and world normal.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(push_constant) uniform PushBlock {
    DrawPush draw;
};

layout(location = 0) in vec3 inNormal;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;

void main() {
    outAlbedo = vec4(draw.albedo.rgb, 1.0);
    outNormal = vec4(normalize(inNormal), 1.0);
}
