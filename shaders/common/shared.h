// The header shared by postfx's C++ and GLSL for the context's own passes, and the machinery every
// effect's shared header (shaders/<effect>/<effect>_shared.h) uses: PFX_CONST, the GLSL names of the
// C++ types. Structs have only vec4/uvec4/mat4 members, so std140 and the C++ layout agree; their sizes
// are static_asserted.
#ifndef POSTFX_SHARED_H
#define POSTFX_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <cstdint>
namespace postfx::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#define PFX_CONST(type, name, value) inline constexpr type name = value
#else
#define PFX_CONST(type, name, value) const type name = value
const float kInfinity = 1.0 / 0.0;
#endif

// ---- the context's own passes (shaders/core/) ----
PFX_CONST(uint, kCopyGroupSize, 8);   // postfx.copy workgroup: kCopyGroupSize² pixels
PFX_CONST(uint, kCopyBindingIn, 0);   // storage image: host color (read)
PFX_CONST(uint, kCopyBindingOut, 1);  // storage image: host output (written)
// postfx.view_distance (core/view_distance.comp): the host's depth unprojected once per frame for every
// effect that reads it, when two or more do (docs/architecture.md, "Shared inputs").
PFX_CONST(uint, kViewDistanceGroupSize, 8);     // workgroup: kViewDistanceGroupSize² invocations
PFX_CONST(uint, kViewDistanceRows, 4);          // pixels per invocation, kViewDistanceGroupSize rows apart
PFX_CONST(uint, kViewDistanceBindingDepth, 0);  // sampler2D: host depth
PFX_CONST(uint, kViewDistanceBindingOut, 1);    // storage image r32f: the surface distance [m]

// ---- the tileable Perlin–Worley noise formula (shaders/common/noise.glsl; the fog generates its texture)
// ---- Octave o of each fBm has a lattice of min(base << o, size) cells per tile: a power of two that divides
// the (power-of-two) texture size, so the texture tiles.
PFX_CONST(uint, kNoisePerlinOctaves, 4u);
PFX_CONST(uint, kNoisePerlinBasePeriod, 4u);  // cells per tile of the first Perlin octave
PFX_CONST(uint, kNoiseWorleyOctaves, 3u);
PFX_CONST(uint, kNoiseWorleyBasePeriod, 4u);  // cells per tile of the first Worley octave
// Perlin–Worley values below this map to 0 (stretches the used range to mean ~0.5; noise.glsl).
PFX_CONST(float, kNoiseRangeLow, 0.3f);

// ---- the noise generation pass (shaders/common/noise_generate.comp): the fogs' and the clouds' textures
// ----
PFX_CONST(uint, kNoiseGroupSize, 4);       // workgroup: kNoiseGroupSize³ texels
PFX_CONST(uint, kNoiseBindingTexture, 0);  // storage image: the r8 noise texture being generated
PFX_CONST(uint, kNoisePerlinWorley, 0u);   // NoisePush.params.z: the Perlin–Worley fBm
PFX_CONST(uint, kNoiseWorley, 1u);         // NoisePush.params.z: the inverted Worley fBm alone
struct NoisePush {                         // push constants of noise_generate.comp
    uvec4 params;  // x: texture size [texels], y: seed, z: kNoisePerlinWorley or kNoiseWorley
};
struct ViewDistancePush {  // push constants of core/view_distance.comp
    mat4 clipToView;       // camera-relative: inverse(projection · rotation of view)
    vec4 params;           // x: no-geometry depth (0 reversed Z, 1 standard), y, z: extent [px]
};

// ---- temporal accumulation: the fogs, the clouds (docs/temporal.md; postfx/src/core/temporal.h) ----
PFX_CONST(uint, kTemporalMaxSpheres, 64u);  // postfx::kTemporalMaxRejectedSpheres
// A history texel at or above this fraction of its format's largest value clipped: it is not rescaled
// after a pre-exposure drop (common/history_rescale.glsl).
PFX_CONST(float, kTemporalClipFraction, 0.5f);

struct TemporalUniforms {
    mat4 previousClip;  // current camera-relative position -> the previous frame's clip space
    vec4 cameraDelta;   // xyz: current camera position - previous [m]; w: the current frame's weight [1]
    vec4 previous;      // x: the previous grid's near [m] (froxel fog); y: the history's radiance factor:
                        // this frame's pre-exposure / the previous frame's (froxel fog: times its
                        // storage scale / the previous)
    uvec4 state;        // x: 1 when the history is valid, y: rejected spheres
    vec4 spheres[64];   // rejected spheres: xyz: camera-relative centre [m], w: radius [m]
};

#ifdef __cplusplus
static_assert(sizeof(TemporalUniforms) == 64 + 3 * 16 + 64 * 16, "TemporalUniforms must match std140");
static_assert(sizeof(NoisePush) == 16, "NoisePush must match the shader's push constants");
static_assert(sizeof(ViewDistancePush) == 80, "ViewDistancePush must match the shader's push constants");
}  // namespace postfx::gpu
#endif

#endif  // POSTFX_SHARED_H
