#version 450
// The tutorial host's vertex shader: world position [cm] to clip space; normal and albedo passed on.

// clang-format off
layout(push_constant) uniform PushConstants {
    mat4 viewProjection;  // world [cm] -> Vulkan clip space, standard Z
    vec4 toSun;           // xyz: unit direction toward the sun (world axes, z up)
    vec4 sunRadiance;     // rgb: a white Lambertian surface facing the sun [cd/m²] × pre-exposure
    vec4 ambient;         // rgb: the sky's radiance [cd/m²] × pre-exposure
} pc;
// clang-format on

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inAlbedo;

layout(location = 0) out vec3 normal;
layout(location = 1) out vec3 albedo;

void main() {
    gl_Position = pc.viewProjection * vec4(inPosition, 1.0);
    normal = inNormal;
    albedo = inAlbedo;
}
