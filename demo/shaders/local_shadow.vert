// Local light shadow pass: depth only into one face's region of the atlas, perspective from the light
// (standard Z: 0 at the near plane). The face's matrix comes per face as a push constant.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(push_constant, std430) uniform FacePush {
    ShadowFacePush face;
};

layout(location = kAttribPosition) in vec3 inPosition;  // world [m]

void main() {
    gl_Position = face.worldToClip * vec4(inPosition, 1.0);
}
