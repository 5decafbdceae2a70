#include "host/camera_math.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace demo {

glm::mat4 perspectiveProjection(float fovY, float aspect, float nearPlane, float farPlane, bool reversedZ,
                                bool infiniteFar) {
    // With d = -z_view the distance along the view axis, depth = (m22·z + m32) / d.
    const float f = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = -f;     // Vulkan clip y points down
    m[2][3] = -1.0f;  // w = d
    if (reversedZ) {
        if (infiniteFar) {  // depth = near / d
            m[2][2] = 0.0f;
            m[3][2] = nearPlane;
        } else {  // depth = near·(far - d) / (d·(far - near))
            m[2][2] = nearPlane / (farPlane - nearPlane);
            m[3][2] = farPlane * nearPlane / (farPlane - nearPlane);
        }
    } else {
        if (infiniteFar) {  // depth = 1 - near / d
            m[2][2] = -1.0f;
            m[3][2] = -nearPlane;
        } else {  // depth = far·(d - near) / (d·(far - near))
            m[2][2] = farPlane / (nearPlane - farPlane);
            m[3][2] = -farPlane * nearPlane / (farPlane - nearPlane);
        }
    }
    return m;
}

glm::mat4 cameraView(const Camera& camera) {
    return glm::lookAtRH(camera.position, camera.lookAt, camera.up);
}

ShadowFit fitShadowMap(const Scene& scene, uint32_t mapSize) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    glm::vec3 lo(kInf), hi(-kInf);
    for (const Object& o : scene.objects) {
        if (o.type == ObjectType::Box) {
            lo = glm::min(lo, o.position - o.halfSize);
            hi = glm::max(hi, o.position + o.halfSize);
        } else if (o.type == ObjectType::Sphere) {
            lo = glm::min(lo, o.position - glm::vec3(o.radius));
            hi = glm::max(hi, o.position + glm::vec3(o.radius));
        }
    }
    ShadowFit fit;
    if (!(lo.x <= hi.x) || mapSize == 0) return fit;  // no finite object: nothing is fitted
    const float margin = 0.05f * glm::length(hi - lo) + 0.25f;
    lo -= glm::vec3(margin);
    hi += glm::vec3(margin);

    // Light view: eye on the sun side of the box centre, looking along -toSun (toward the scene).
    const glm::vec3 toSun = glm::normalize(scene.sun.direction);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const glm::vec3 up = std::abs(toSun.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAtRH(centre + toSun, centre, up);

    glm::vec3 lsLo(kInf), lsHi(-kInf);  // light-space bounds; z grows toward the sun
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        glm::vec3 p = glm::vec3(view * glm::vec4(corner, 1.0f));
        lsLo = glm::min(lsLo, p);
        lsHi = glm::max(lsHi, p);
    }
    // Planes crossing the footprint (an infinite prism along the sun direction) are receivers of
    // long shadows (or occluders): extend the depth range to where the prism's edges meet them.
    const float zCasterLo = lsLo.z, zCasterHi = lsHi.z;
    for (const Object& o : scene.objects) {
        if (o.type != ObjectType::Plane) continue;
        glm::vec3 n = glm::mat3(view) * o.normal;
        glm::vec3 p = glm::vec3(view * glm::vec4(o.position, 1.0f));
        if (std::abs(n.z) < 1e-4f) continue;  // plane parallel to the sun direction
        for (int i = 0; i < 4; ++i) {
            float x = (i & 1) ? lsHi.x : lsLo.x, y = (i & 2) ? lsHi.y : lsLo.y;
            float z = (glm::dot(n, p) - n.x * x - n.y * y) / n.z;
            z = std::clamp(z, zCasterLo - 1e4f, zCasterHi + 1e4f);
            lsLo.z = std::min(lsLo.z, z - margin);
            lsHi.z = std::max(lsHi.z, z + margin);
        }
    }
    // The fog's reach: postfx marches each ray at most max_distance from the camera (the analytic tail
    // beyond reads no shadow map), so its samples inside the footprint lie in a ball around the camera,
    // clipped to the camera's side of each plane (nothing behind one is seen). Extend the far side of the
    // depth range to the farthest such point, so that the fog under a caster with no receiver below it is
    // compared inside the map. (postfx shadows a sample beyond the far plane under a caster anyway; this
    // keeps the map the description of all the fog sees.) The near side stays at the casters: nothing
    // nearer the sun shadows, and postfx lights the fog before the near plane.
    // Either fog (the froxel fog's grid also ends at its max_distance, and its tail reads no shadow map).
    float reach = 0.0f;
    if (scene.fog.enabled) reach = std::max(reach, scene.fog.maxDistance);
    if (scene.froxelFog.enabled) reach = std::max(reach, scene.froxelFog.maxDistance);
    if (reach > 0.0f) {
        const glm::vec3 camera = glm::vec3(view * glm::vec4(scene.camera.position, 1.0f));
        // Distance in the light's xy from the camera to the footprint rectangle: the ball's chord
        // along the sun inside the footprint reaches down to camera.z - sqrt(reach² - d²).
        const glm::vec2 nearest = glm::clamp(glm::vec2(camera), glm::vec2(lsLo), glm::vec2(lsHi));
        const float d = glm::length(glm::vec2(camera) - nearest);
        if (d < reach) {
            float fogFar = camera.z - std::sqrt(reach * reach - d * d);
            for (const Object& o : scene.objects) {
                if (o.type != ObjectType::Plane) continue;
                const glm::vec3 n = glm::mat3(view) * o.normal;
                const glm::vec3 p = glm::vec3(view * glm::vec4(o.position, 1.0f));
                // The camera's side of the plane is bounded away from the sun (z decreasing) when it is
                // the side toward the sun: then nothing visible inside the footprint lies farther than
                // the plane's lowest z over the footprint's corners.
                const float side = glm::dot(n, camera - p);
                if (std::abs(n.z) < 1e-4f || side * n.z <= 0.0f) continue;
                float lowest = kInf;
                for (int i = 0; i < 4; ++i) {
                    const float x = (i & 1) ? lsHi.x : lsLo.x, y = (i & 2) ? lsHi.y : lsLo.y;
                    lowest = std::min(lowest, (glm::dot(n, p) - n.x * x - n.y * y) / n.z);
                }
                fogFar = std::max(fogFar, lowest);
            }
            lsLo.z = std::min(lsLo.z, std::max(fogFar, zCasterLo - 1e4f) - margin);
        }
    }
    // orthoRH_ZO maps view z = -near to depth 0 and z = -far to depth 1.
    const glm::mat4 proj = glm::orthoRH_ZO(lsLo.x, lsHi.x, lsLo.y, lsHi.y, -lsHi.z, -lsLo.z);
    fit.viewProj = proj * view;
    // A fit float cannot hold (a grazing sun over a scene 1e7 m deep, found by the scene fuzzer) is not
    // valid: the scene then renders without a shadow map, as with shadows off.
    fit.valid = true;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            fit.valid = fit.valid && std::isfinite(fit.viewProj[c][r]);
    fit.texelWorldSize = std::max(lsHi.x - lsLo.x, lsHi.y - lsLo.y) / float(mapSize);
    return fit;
}

float shadowDepthBias(const ShadowFit& fit) {
    // The shadow projection is orthographic, so depth per metre along the sun is |row 2 of viewProj|.
    const glm::mat4& m = fit.viewProj;
    const float depthPerMetre = glm::length(glm::vec3(m[0][2], m[1][2], m[2][2]));
    return fit.texelWorldSize * depthPerMetre;
}

}  // namespace demo
