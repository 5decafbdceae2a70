// The clouds' shadow map as the fogs read it (docs/effects/clouds.md, "Shadows"; the GLSL side is
// shaders/common/cloud_shadow.glsl): whether a frame has one, and its uv rows for camera-relative
// positions. The map's geometry is the public cloudShadowTransform (postfx/clouds.h).
#pragma once

#include <postfx/context.h>

#include <glm/glm.hpp>

namespace postfx::common {

// Whether `frame`'s clouds run and cast shadows (the map is made and read).
bool castsCloudShadows(const FrameInfo& frame);

// cloudShadowTransform's rows for camera-relative positions (the fogs' uniforms), in float.
struct CloudShadowRows {
    glm::vec4 u{0.0f, 0.0f, 0.0f, -1.0f};
    glm::vec4 v{0.0f, 0.0f, 0.0f, -1.0f};
};
CloudShadowRows cameraRelativeCloudShadowRows(const FrameInfo& frame);

}  // namespace postfx::common
