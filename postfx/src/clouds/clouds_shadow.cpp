#include "clouds/clouds_shadow.h"

#include "clouds/clouds_model.h"
#include "clouds/clouds_settings.h"
#include "common/cloud_shadow.h"

#include <cmath>

namespace postfx::clouds {
namespace {

// The sun's direction, normalised; its y at most this: no shadow map (every point maps outside).
constexpr double kMinSunY = 1e-6;

glm::dvec3 toSun(const FrameInfo& frame) {
    return glm::normalize(glm::dvec3(frame.sun.toSun));
}

// The world height of the shape's bottom plane: the layer's bottom, or the box's lowest corner.
double bottomPlane(const CloudSettings& s) {
    if (s.shape != CloudShape::Box) return s.bottomHeight;
    const glm::dmat3 boxToWorld = glm::transpose(worldToBox(s.box));
    double below = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        below += std::abs(boxToWorld[axis].y) * double(s.box.halfSize[axis]);
    return s.box.center.y - below;
}

}  // namespace

ShadowMapGeometry shadowMapGeometry(const FrameInfo& frame) {
    const CloudSettings& s = frame.clouds;
    ShadowMapGeometry g;
    g.extent = s.shadowMap.extent;
    g.size = s.shadowMap.size;
    const double texel = g.extent / g.size;
    const glm::dvec3 camera(frame.camera.position);
    g.center = {std::round(camera.x / texel) * texel, bottomPlane(s), std::round(camera.z / texel) * texel};
    return g;
}

}  // namespace postfx::clouds

namespace postfx {

namespace {

// In postfx's frame: uv.x = (P.x + (y_b - P.y)·s_x - c_x) / E + 1/2 with s = toSun.xz / toSun.y (P moved
// along the sun's direction onto the plane y = y_b), the same for uv.y with z.
CloudShadowTransform postfxTransform(const FrameInfo& frame) {
    CloudShadowTransform t;
    if (!common::castsCloudShadows(frame)) return t;
    const glm::dvec3 sun = clouds::toSun(frame);
    if (!(sun.y > clouds::kMinSunY)) return t;
    const clouds::ShadowMapGeometry g = clouds::shadowMapGeometry(frame);
    const double sx = sun.x / sun.y, sz = sun.z / sun.y, e = g.extent;
    t.u = {1.0 / e, -sx / e, 0.0, (sx * g.center.y - g.center.x) / e + 0.5};
    t.v = {0.0, -sz / e, 1.0 / e, (sz * g.center.y - g.center.z) / e + 0.5};
    return t;
}

}  // namespace

CloudShadowTransform cloudShadowTransform(const FrameInfo& frame, const WorldFrame& world) {
    const core::WorldTransform transform(world);
    if (transform.identity()) return postfxTransform(frame);
    // The frame's inputs the map depends on in postfx's frame; the rows then read the host's positions.
    FrameInfo f = frame;
    f.camera = transform.camera(frame.camera);
    f.sun.toSun = transform.direction(glm::vec3(frame.sun.toSun));
    clouds::settingsToPostfx(transform, f.clouds);
    CloudShadowTransform t = postfxTransform(f);
    for (DVec4* row : {&t.u, &t.v})
        *row = DVec4(transform.hostRow(glm::dvec3(*row)), row->w);
    return t;
}

}  // namespace postfx
