#version 450
// The tutorial host's fragment shader: Lambert's sun term plus the sky's ambient, pre-exposed. The
// attachment is sRGB: the hardware encodes the linear value written here.

// clang-format off
layout(push_constant) uniform PushConstants {
    mat4 viewProjection;
    vec4 toSun;
    vec4 sunRadiance;
    vec4 ambient;
} pc;
// clang-format on

layout(location = 0) in vec3 normal;
layout(location = 1) in vec3 albedo;

layout(location = 0) out vec4 outColor;

void main() {
    float cosine = max(dot(normalize(normal), pc.toSun.xyz), 0.0);
    outColor = vec4(albedo * (pc.sunRadiance.rgb * cosine + pc.ambient.rgb), 1.0);
}
