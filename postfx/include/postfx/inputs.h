// The per-frame inputs every effect shares: the camera, the sun, the shadow map and local lights
// (FrameInfo). Checked once by Context::record and Context::plan, whichever effects run. Everything that
// lives in the world is in the host's world frame (ContextCreateInfo::world: its up axis, handedness and
// units, "[host units]" below; docs/integration.md, "World frame and units"), and every range of such a
// field holds for the number as the host gives it.
#pragma once

#include <postfx/types.h>

#include <cstdint>

namespace postfx {

// The camera that rendered color and depth.
struct CameraInput {
    // World position [host units] (double: postfx works camera-relative); each component in [-1e9, 1e9].
    DVec3 position{0.0};
    // World -> view, rigid in the host's units (a view space of either handedness: -z or +z forward); only
    // its rotation is used (position gives the translation); finite, rotation invertible.
    Mat4 view{1.0f};
    // View [host units] -> Vulkan clip, in the context's DepthConvention; finite, and projection · view
    // rotation invertible with an inverse finite in float (postfx reconstructs view rays through it on the
    // GPU; checked as postfx's frame has it, in metres).
    Mat4 projection{1.0f};
};

// The sun (or moon): a directional light.
struct SunInput {
    // Direction toward the sun along the host's axes, finite, length >= 1e-6 (normalised by postfx). The
    // default is up in postfx's own frame (y up).
    Vec3 toSun{0.0f, 1.0f, 0.0f};
    Vec3 illuminance{0.0f};  // [lux] on a surface facing the sun; each in [0, 1e7]
};

// The host's sun shadow map. Optional: with no image the sun is unshadowed (visibility 1).
//
// Each PCF tap tests the sample's shadow depth z = c.z/c.w (c = worldToClip · x) against one texel:
//   - inside the map's depth range (z in [0, 1]): lit when z - depthBias <= stored (reversed Z:
//     z + depthBias >= stored);
//   - beyond the far plane (z > 1; reversed Z: z < 0): in shadow where the texel holds a caster, lit
//     where it holds the cleared far value (1; reversed Z: 0), so fog under a caster with no receiver
//     below it inside the map is shadowed;
//   - before the near plane (z < 0; reversed Z: z > 1): lit.
// Outside the map's u, v in [0, 1] the sample is lit. So the map's volume must hold every caster (its
// receivers need not be inside), with texels where nothing was drawn at the cleared far value; fog before
// the near plane is lit even under a caster that depth clamping flattened onto it (docs/effects/fog.md).
struct ShadowMapInput {
    // Depth image (D32_SFLOAT, D16_UNORM, X8_D24_UNORM_PACK32, D24_UNORM_S8_UINT or R32_SFLOAT), usage
    // SAMPLED, any square or rectangular size.
    ImageInput image;
    // World [host units] -> shadow clip space: x, y in [-1, 1] map to u, v = (x, y)/2 + 1/2, z/w is the
    // stored depth. Finite, and worldToClip · translate(camera.position), the camera-relative transform
    // postfx hands the GPU (in metres: its x, y, z columns times unitsPerMetre), finite in float (each
    // element within ±3.4e38).
    DMat4 worldToClip{1.0};
    bool reversedZ = false;  // true: larger stored depth is nearer the sun
    float depthBias = 0.0f;  // added toward "lit" before comparing [shadow depth units]; finite, >= 0
    // (every field is checked only when `image` is present)
};

// A local light (point or spot) for the effects that light their medium with local lights (froxel fog,
// next). Effects that do not read lights ignore them; every light given is checked.
enum class LightType : uint32_t { Point, Spot };  // another value (cast from an int) is rejected

// LocalLight::shadow of a light that casts no shadow.
inline constexpr uint32_t kNoLocalShadow = 0xffffffffu;

struct LocalLight {
    LightType type = LightType::Point;
    DVec3 position{0.0};                // world position [host units]; each component in [-1e9, 1e9]
    Vec3 direction{0.0f, -1.0f, 0.0f};  // the cone's axis along the host's axes [1]; finite; spot: length
                                        // >= 1e-6 (normalised); the default is down in postfx's frame
    Vec3 intensity{0.0f};               // luminous intensity per RGB channel [cd]; each in [0, 1e9]
    float range = 100.0f;              // distance beyond which the light is ignored [host units]; finite, > 0
    float sourceRadius = 0.05f;        // guards the inverse square near the light [host units]; (0, range]
    float innerConeAngle = 0.0f;       // spot: full intensity inside this half angle [rad]; in [0, outer]
    float outerConeAngle = 0.785398f;  // spot: no light outside this half angle [rad]; in [0, π/2)
    // Its shadow: an index into FrameInfo.localShadows.shadows (< shadowCount), or kNoLocalShadow: the
    // light shines through everything. Several lights may share one shadow.
    uint32_t shadow = kNoLocalShadow;
};

// At most this many local lights per frame (FrameInfo::lightCount).
inline constexpr uint32_t kMaxLocalLights = 256;

// One depth map of a local light in the host's shadow atlas (LocalShadowAtlasInput): a spot light's, or
// one face of a point light's cube.
struct LocalShadowFace {
    UVec2 offset{0u};  // the region's first texel (x, y) in the atlas [texels]
    UVec2 extent{0u};  // the region's size [texels]; each >= 1, and offset + extent inside the atlas
    // World [host units] -> the face's clip space (perspective or orthographic): x, y in [-1, 1] map across
    // the region (u, v = (x, y)/2 + 1/2 of it), z/w is the depth stored there. Finite, invertible, and
    // worldToClip · translate(camera.position) finite in float (as the sun's ShadowMapInput::worldToClip).
    DMat4 worldToClip{1.0};
};

// Faces of one local light's shadow: 1 (a spot light) to 6 (a point light's cube).
inline constexpr uint32_t kMaxLocalShadowFaces = 6;

// One light's shadow: its faces in the atlas and how their depths compare. A sample uses the first face
// whose clip square holds it (w > 0, |x| <= w, |y| <= w), so the six faces of a cube meet with neither gap
// nor overlap; a sample no face holds is lit. In that face the sun's rules apply (ShadowMapInput): one tap
// (or the froxel fog's filtered mode) of z = c.z/c.w against the texel; inside [0, 1] lit when
// z - depthBias <= stored (reversed Z: z + depthBias >= stored); beyond the far plane shadowed where the
// texel holds a caster, lit where it holds the cleared far value (1; reversed Z: 0); before the near
// plane lit. Texels of the region where nothing was drawn must hold the cleared far value.
struct LocalShadow {
    uint32_t faceCount = 1;  // [1, kMaxLocalShadowFaces]
    LocalShadowFace faces[kMaxLocalShadowFaces];
    bool reversedZ = false;  // true: larger stored depth is nearer the light
    float depthBias = 0.0f;  // added toward "lit" before comparing [shadow depth units]; finite, >= 0
};

// The host's shadow maps of its local lights, packed in one depth atlas (as engines keep them): regions
// of any size, one per spot light and six per point light. Optional: with no image, no light may name a
// shadow and every light is unshadowed.
struct LocalShadowAtlasInput {
    // Depth image (D32_SFLOAT, D16_UNORM, X8_D24_UNORM_PACK32, D24_UNORM_S8_UINT or R32_SFLOAT), usage
    // SAMPLED, any size.
    ImageInput image;
    const LocalShadow* shadows = nullptr;  // shadowCount shadows (may be null when 0); read during record()
    uint32_t shadowCount = 0;              // [0, kMaxLocalLights]
    // (every field is checked when `image` is present or shadowCount > 0)
};

}  // namespace postfx
