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
using glm::clamp;
using glm::max;
using glm::smoothstep;
#define DEMO_CONST(type, name, value) inline constexpr type name = value
#define DEMO_INLINE inline
#else
#define DEMO_CONST(type, name, value) const type name = value
#define DEMO_INLINE
#endif

// Descriptor set 0 of the raster passes (G-buffer, shadow map): the frame uniforms only.
// Descriptor set 0 of the lighting pass: all of these.
DEMO_CONST(uint, kBindingFrame, 0u);      // uniform FrameUniforms
DEMO_CONST(uint, kBindingAlbedo, 1u);     // sampler2D, G-buffer albedo (rgb)
DEMO_CONST(uint, kBindingNormal, 2u);     // sampler2D, G-buffer world normal (xyz)
DEMO_CONST(uint, kBindingDepth, 3u);      // sampler2D, G-buffer depth (D32)
DEMO_CONST(uint, kBindingShadowMap, 4u);  // sampler2DShadow, sun shadow map (standard Z)
DEMO_CONST(uint, kBindingHdr, 5u);        // image2D rgba16f, output radiance
DEMO_CONST(uint, kBindingLights, 6u);     // uniform LightsUniforms, the scene's local lights
// sampler2D r32f, postfx's cloud shadow map of the previous frame (postfx::kCloudsShadowMap); the albedo
// stands in while postfx holds none (then the rows below put every point outside it: never sampled)
DEMO_CONST(uint, kBindingCloudShadow, 7u);
// sampler2D (nearest, no compare), the local lights' shadow atlas (D32, standard Z; host/local_shadows.h)
DEMO_CONST(uint, kBindingLocalShadowAtlas, 8u);
DEMO_CONST(uint, kBindingLocalShadowFaces, 9u);  // readonly buffer LocalShadowFaces, the atlas's faces

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
    // z: shadow normal offset [m] (world size of one shadow texel); w: number of local lights
    vec4 depthParams;
    uvec4 extent;  // xy: HDR image size [pixels]
    // The sun's optical depth through postfx's atmosphere (host/atmosphere_lighting.h): rgb at altitude w
    // [m] of sunOpticalDepthLow and of sunOpticalDepthHigh; lighting.comp interpolates it linearly in the
    // lit point's altitude (world y, clamped to [low.w, high.w]) and multiplies sunIlluminance by
    // exp(-depth). All 0 without the atmosphere.
    vec4 sunOpticalDepthLow;
    vec4 sunOpticalDepthHigh;
    // postfx::cloudShadowTransform of the frame that made the cloud shadow map (the previous one), rows for
    // world positions: uv = (dot(u.xyz, world) + u.w, dot(v.xyz, world) + v.w); outside [0, 1]²: no shadow.
    vec4 cloudShadowU;
    vec4 cloudShadowV;
};

// Local lights (scene `lights`, postfx::LocalLight), at most kMaxDemoLights (= postfx::kMaxLocalLights;
// checked in renderer_frame.cpp). 256 · 64 bytes = 16 KiB, the smallest maxUniformBufferRange Vulkan allows.
DEMO_CONST(uint, kMaxDemoLights, 256u);
struct GpuLight {
    vec4 positionRadius;     // xyz: camera-relative position [m]; w: source radius [m]
    vec4 intensityRange;     // rgb: luminous intensity [cd]; w: range [m]
    vec4 directionCosOuter;  // xyz: unit cone axis; w: cos(outer half angle) (point light: -2)
    // x: cos(inner half angle) (point light: -1); y: its first face in LocalShadowFaces; z: its number of
    // faces (0: no shadow); w: the depth bias of its faces (postfx::LocalShadow::depthBias)
    vec4 cosInner;
};
struct LightsUniforms {
    GpuLight lights[kMaxDemoLights];  // the first FrameUniforms::depthParams.w are used
};

// The falloff of local lights, the one definition shared by the demo's surface lighting (lighting.comp)
// and its tests; postfx's froxel fog uses the same model (docs/scene-format.md#lights). Illuminance at
// distance d from a light of intensity I [cd] on a surface facing it: E = I · localLightFalloff(d, r, range)
// · spotFactor(...): inverse square guarded by the source radius r, 1 / (d² + r²), times Unreal's window
// clamp(1 - (d/range)⁴, 0, 1)², which reaches 0 at `range` smoothly.
DEMO_INLINE float localLightFalloff(float d, float radius, float range) {
    float x = d / range;  // d and range >= 0; x4 overflows to +inf far away, giving window 0
    float x2 = x * x;
    float window = clamp(1.0f - x2 * x2, 0.0f, 1.0f);
    // d² + r² underflows for radii below about 1e-19 m: 1e-30 m² keeps the result finite.
    return window * window / max(d * d + radius * radius, 1e-30f);
}
// Spot cone: smoothstep(cos outer, cos inner, cos angle), with cosAngle = dot(axis, light -> point);
// a hard edge when inner == outer. Point lights pass cosOuter = -2, cosInner = -1 (always 1).
DEMO_INLINE float spotFactor(float cosAngle, float cosOuter, float cosInner) {
    if (cosInner <= cosOuter) return cosAngle >= cosOuter ? 1.0f : 0.0f;
    return smoothstep(cosOuter, cosInner, cosAngle);
}

// One face of a local light's shadow in the atlas (postfx::LocalShadowFace), for the surfaces' lighting.
// The faces of every shadowed light, in the lights' order: at most six per light.
DEMO_CONST(uint, kMaxDemoShadowFaces, 6u * kMaxDemoLights);
struct GpuShadowFace {
    mat4 worldToClip;  // camera-relative world -> the face's clip space (worldToClip · translate(camera))
    vec4 region;       // xy: the region's first texel; zw: its size [texels]
    vec4 params;       // x: world size of one texel per metre from the light (2·tan(half fov) / size)
};
// Read as a storage buffer (std430, which lays out mat4 and vec4 members as std140 does).
struct LocalShadowFaces {
    GpuShadowFace faces[kMaxDemoShadowFaces];
};

// Push constants of the local shadow pass (local_shadow.vert), per face.
struct ShadowFacePush {
    mat4 worldToClip;  // world -> the face's clip space
};

// Push constants of the G-buffer fragment shader, per draw.
struct DrawPush {
    vec4 albedo;  // rgb diffuse reflectance
};

// The forward pass (forward.vert, forward.frag): its descriptor set 0 is the lighting pass's set (the
// bindings above; the G-buffer depth read for the depth test), set 1 postfx's volumetrics lookup at these
// bindings (postfx::VolumetricsLookupBindings).
DEMO_CONST(uint, kForwardLookupSet, 1u);
DEMO_CONST(uint, kForwardBindingLookupUniforms, 0u);
DEMO_CONST(uint, kForwardBindingLookupScattering, 1u);
DEMO_CONST(uint, kForwardBindingLookupTransmittance, 2u);
// What a forward draw is (ForwardPush::params.x).
DEMO_CONST(uint, kForwardOpenSurface, 0u);    // a plane: both sides drawn
DEMO_CONST(uint, kForwardClosedSurface, 1u);  // a box or sphere: its back faces discarded
DEMO_CONST(uint, kForwardParticle, 2u);       // a camera-facing quad, a soft disc (6 vertices each)

// Push constants of the forward pass, per draw (vertex and fragment stages).
struct ForwardPush {
    vec4 albedoOpacity;  // rgb: diffuse reflectance; a: opacity [1]
    vec4 params;         // x: kForward*; y: 1 to leave postfx's lookup out (a benchmark's timing); zw: unused
    // postfx::cloudShadowTransform of this frame (the clouds' shadow map it wrote), or rows putting every
    // point outside the map (w = -1) when the lighting's binding holds another image.
    vec4 cloudShadowU;
    vec4 cloudShadowV;
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
static_assert(sizeof(FrameUniforms) == 3 * 64 + 11 * 16, "FrameUniforms must match std140");
static_assert(sizeof(LightsUniforms) == 16384, "LightsUniforms must match std140 and fit 16 KiB");
static_assert(sizeof(DrawPush) == 16, "DrawPush must match std430 push constants");
static_assert(sizeof(ForwardPush) == 64, "ForwardPush must match std430 push constants");
static_assert(sizeof(GpuShadowFace) == 96, "GpuShadowFace must match std430");
static_assert(sizeof(ShadowFacePush) == 64, "ShadowFacePush must match std430 push constants");
static_assert(sizeof(TonemapPush) == 32, "TonemapPush must match std430 push constants");
}  // namespace demo::shared
#endif

#undef DEMO_CONST
#undef DEMO_INLINE
#endif  // DEMO_SHADERS_DEMO_SHARED_H
