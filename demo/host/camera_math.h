// Camera and sun matrices of the demo host renderer (pure math, unit-tested).
// Conventions: world right-handed, y up; Vulkan clip space (x right, y down, depth in [0, 1]).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace demo {

// Perspective projection of a right-handed view space (camera looks down -z) to Vulkan clip space,
// y flipped so that +y view is up in the image.
//   standard Z: near -> depth 0, far -> 1;  reversed Z: near -> 1, far -> 0.
//   infiniteFar: no far plane (depth reaches 1 / 0 at infinite distance); `farPlane` is ignored.
// fovY in radians, aspect = width / height.
glm::mat4 perspectiveProjection(float fovY, float aspect, float nearPlane, float farPlane, bool reversedZ,
                                bool infiniteFar);

// World -> view (right-handed, camera at the origin looking down -z, y up).
glm::mat4 cameraView(const Camera& camera);

// The sun's orthographic shadow map projection, fitted to the scene.
struct ShadowFit {
    bool valid = false;        // false when the scene has no finite object (box, sphere) to cast
    glm::mat4 viewProj{1.0f};  // world -> clip: xy in [-1, 1], depth in [0, 1] (0 nearest the sun)
    float texelWorldSize = 0;  // [m] edge of one shadow texel (the larger of x and y)
};

// Covers the bounding box of all boxes and spheres (with a margin) as seen from the sun: no shadow
// falls outside that footprint. In depth it reaches from the casters' sun side to the farthest of the
// casters, every plane where it crosses the footprint (receivers of long shadows) and, with fog on (either
// fog), the farthest point inside the footprint that the fog reaches (max_distance around the camera, on
// the camera's side of the planes).
ShadowFit fitShadowMap(const Scene& scene, uint32_t mapSize);

// The depth bias the renderer gives postfx with the shadow map (ShadowMapInput::depthBias, shadow depth
// units): one texel's depth change on a surface at 45 degrees to the sun.
float shadowDepthBias(const ShadowFit& fit);

}  // namespace demo
