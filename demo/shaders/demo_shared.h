// Shared between the demo host renderer (C++) and its shaders (GLSL): uniform and push-constant structs,
// descriptor binding numbers and workgroup sizes. Written once; C++ sees glm types in demo::shared.
// Only vec4/mat4/uvec4 members, so the C++ layout equals std140 (sizes asserted at the bottom).
#ifndef DEMO_SHADERS_DEMO_SHARED_H
#define DEMO_SHADERS_DEMO_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <cstdint>
namespace demo::shared {
using uint = uint32_t;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
#define DEMO_CONST(type, name, value) inline constexpr type name = value
#else
#define DEMO_CONST(type, name, value) const type name = value
#endif

// Descriptor set 0 of the raster passes (G-buffer, shadow map): the frame uniforms only.
// Descriptor set 0 of the lighting pass: all of these.
DEMO_CONST(uint, kBindingFrame, 0u);      // uniform FrameUniforms
DEMO_CONST(uint, kBindingAlbedo, 1u);     // sampler2D, G-buffer albedo (rgb)
DEMO_CONST(uint, kBindingNormal, 2u);     // sampler2D, G-buffer world normal (xyz)
DEMO_CONST(uint, kBindingDepth, 3u);      // sampler2D, G-buffer depth (D32)
DEMO_CONST(uint, kBindingShadowMap, 4u);  // sampler2DShadow, sun shadow map (standard Z)
DEMO_CONST(uint, kBindingHdr, 5u);        // image2D rgba16f, output radiance

DEMO_CONST(uint, kLightingGroupSize, 8u);  // lighting workgroup is kLightingGroupSize² threads

// Vertex attributes (one interleaved buffer: position, normal; both vec3 floats).
DEMO_CONST(uint, kAttribPosition, 0u);
DEMO_CONST(uint, kAttribNormal, 1u);

// Largest finite half float; radiance is clamped to it when written.
DEMO_CONST(float, kHalfMax, 65504.0f);

struct FrameUniforms {
    mat4 viewProj;        // camera-relative world (world - cameraPosition) -> clip
    mat4 invViewProj;     // inverse of viewProj: clip -> camera-relative world
    mat4 shadowViewProj;  // world -> shadow clip: xy in [-1, 1], z in [0, 1] (0 nearest the sun)
    vec4 cameraPosition;  // xyz [m]
    vec4 toSun;           // xyz: unit direction toward the sun; w: 1 when the shadow map is used
    vec4 sunIlluminance;  // rgb [lux]
    vec4 ambient;         // rgb [cd/m²]
    vec4 sky;             // rgb [cd/m²]
    // x: G-buffer depth clear value (0 reversed Z, 1 standard); y: shadow map texel size in uv;
    // z: shadow normal offset [m] (world size of one shadow texel); w: unused
    vec4 depthParams;
    uvec4 extent;  // xy: HDR image size [pixels]
};

// Push constants of the G-buffer fragment shader, per draw.
struct DrawPush {
    vec4 albedo;  // rgb diffuse reflectance
};

// Tonemap of the windowed demo (demo/shaders/tonemap.comp), the same curve as the CPU tonemap of .png
// files (demo/host/image_io.cpp): exposure 1 / (kExposureSaturation · 2^ev100), ACES fitted
// (Narkowicz 2015): x (A x + B) / (x (C x + D) + E), then the sRGB OETF.
DEMO_CONST(float, kExposureSaturation, 1.2f);  // saturation-based exposure: max luminance 1.2·2^EV100
DEMO_CONST(float, kAcesA, 2.51f);
DEMO_CONST(float, kAcesB, 0.03f);
DEMO_CONST(float, kAcesC, 2.43f);
DEMO_CONST(float, kAcesD, 0.59f);
DEMO_CONST(float, kAcesE, 0.14f);
DEMO_CONST(float, kSrgbLinearLimit, 0.0031308f);  // below: 12.92 x; above: 1.055 x^(1/2.4) - 0.055
DEMO_CONST(uint, kTonemapGroupSize, 8u);          // tonemap workgroup is kTonemapGroupSize² threads
DEMO_CONST(uint, kTonemapBindingHdr, 0u);         // image2D rgba16f, radiance (GENERAL), read
DEMO_CONST(uint, kTonemapBindingOut, 1u);         // image2D rgba8, sRGB-encoded display values, written

// Push constants of the tonemap pass.
struct TonemapPush {
    vec4 params;   // x: exposure (1 / (kExposureSaturation · 2^ev100)); y: 1 = store blue, green, red
                   // (the output is copied bit for bit into a BGRA swapchain image); zw: unused
    uvec4 extent;  // xy: image size [pixels]
};

#ifdef __cplusplus
static_assert(sizeof(FrameUniforms) == 3 * 64 + 7 * 16, "FrameUniforms must match std140");
static_assert(sizeof(DrawPush) == 16, "DrawPush must match std430 push constants");
static_assert(sizeof(TonemapPush) == 32, "TonemapPush must match std430 push constants");
}  // namespace demo::shared
#endif

#undef DEMO_CONST
#endif  // DEMO_SHADERS_DEMO_SHARED_H
