// The local lights' shadow maps (scene `lights[i].shadows`, docs/scene-format.md#lights) as one depth atlas:
// each shadowed light's faces (one for a spot, six for a point light) and where they lie in the atlas (pure
// math, unit-tested). The same maps light the demo's surfaces (lighting.comp) and postfx's froxel fog
// (FrameInfo::localShadows), so the two agree.
//
// Depth is standard Z (0 at the near plane, 1 at the far plane, cleared to 1), perspective:
//   spot:  one face looking along the cone's axis, field of view 2 · (outer angle + kSpotMarginDeg);
//          a spot wider than kMaxSpotFaceOuterDeg gets a point light's six faces;
//   point: six 90° faces, +X, -X, +Y, -Y, +Z, -Z (a cube map's, up vectors as a cube map's);
// near plane max(kMinShadowNear, source radius), far plane the light's range (at least twice near).
#pragma once

#include "scene/light.h"

#include <postfx/inputs.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace demo {

inline constexpr float kMinShadowNear = 0.05f;        // [m]
inline constexpr float kSpotMarginDeg = 2.0f;         // beyond the outer angle, for the PCF's kernel
inline constexpr float kMaxSpotFaceOuterDeg = 58.0f;  // a single face up to a 120° field of view
// The atlas's largest edge (also limited by the device): 8192² D32 texels are 256 MiB.
inline constexpr uint32_t kMaxShadowAtlasEdge = 8192;

// The depth bias given with every face (postfx::LocalShadow::depthBias, the lighting's comparison): the
// depth change of one texel on a surface at 45° to the light, `kShadowBiasDistance` from it. z = f/(f-n) ·
// (1 - n/d) changes by n·f/(f-n) / d² per metre at distance d, and a texel spans d · texelAngle metres
// (texelAngle = 2·tan(half field of view) / resolution), so the bias is n·f/(f-n) · texelAngle / 4 m: a
// 512² 90° face with n 0.1 m gives 9.8e-5. Farther than 4 m it covers more than a texel (0.4 m at 20 m:
// only samples that close behind a caster's surface are lit, inside the caster as a rule); nearer, the
// surfaces' normal offset keeps them free of acne, and the fog's samples are never that close to them.
inline constexpr double kShadowBiasDistance = 4.0;  // [m]

struct LocalShadowLayout {
    glm::uvec2 extent{0u};  // the atlas's texels in use; 0: no light casts shadows
    // One per shadowed light, in the lights' order (postfx::LocalShadow: faces, regions, matrices, bias).
    std::vector<postfx::LocalShadow> shadows;
    // Per light of the scene: its index in `shadows`, or postfx::kNoLocalShadow.
    std::vector<uint32_t> lightShadow;
    uint32_t faceCount = 0;        // the faces of all shadows
    uint32_t resolutionShift = 0;  // every face's resolution was halved this many times to fit the atlas
};

// The faces of every light with `shadows`, packed in rows (a shelf packer, largest faces first) into an
// atlas at most `maxEdge` texels wide and high; when they do not fit at the lights' resolutions, every
// resolution is halved (not below 16) until they do.
LocalShadowLayout layoutLocalShadows(std::span<const Light> lights, uint32_t maxEdge);

// The face's world size of one texel per metre of distance from the light (2·tan(half field of view) /
// resolution), read from its matrix: a perspective projection's x scale is the length of its first row.
double shadowTexelAngle(const postfx::LocalShadowFace& face);

}  // namespace demo
