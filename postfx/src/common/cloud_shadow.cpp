#include "common/cloud_shadow.h"

#include <postfx/clouds.h>

namespace postfx::common {

bool castsCloudShadows(const FrameInfo& frame) {
    const CloudSettings& s = frame.clouds;
    return s.enabled && s.castShadows && s.coverage > 0.0f && s.density > 0.0f;
}

CloudShadowRows cameraRelativeCloudShadowRows(const FrameInfo& frame) {
    const CloudShadowTransform t = cloudShadowTransform(frame);
    const glm::dvec3 camera(frame.camera.position);
    // P = x + camera: the constant term takes the camera's part, in double.
    auto row = [&](const DVec4& r) {
        const glm::dvec3 a(r.x, r.y, r.z);
        return glm::vec4(glm::vec3(a), float(r.w + glm::dot(a, camera)));
    };
    return {row(t.u), row(t.v)};
}

}  // namespace postfx::common
