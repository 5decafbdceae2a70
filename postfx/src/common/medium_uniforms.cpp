// The shared medium's part of the fogs' uniforms (common/medium.h): camera-relative, built in double.
#include "common/cloud_shadow.h"
#include "common/medium.h"
#include "core/camera_math.h"
#include "core/exposure.h"

#include <glm/gtc/matrix_transform.hpp>

namespace postfx::common {

gpu::FogUniforms buildMediumUniforms(const FogMedium& s, const FrameInfo& frame, const DepthConvention& depth,
                                     bool noiseEnabled, bool shadowMapEnabled) {
    const glm::dvec3 camera = frame.camera.position;
    gpu::FogUniforms u{};
    u.clipToView =
        glm::mat4(glm::inverse(glm::dmat4(frame.camera.projection) * core::rotationOnly(frame.camera.view)));
    // camera-relative x -> world (x + camera) -> shadow clip
    u.viewToShadow = glm::mat4(frame.shadowMap.worldToClip * glm::translate(glm::dmat4(1.0), camera));
    // In double: a long float vector's dot product would overflow (toSun = (1e30, 0, 0) gives 0 in float).
    u.toSun = glm::vec4(glm::vec3(glm::normalize(glm::dvec3(frame.sun.toSun))), 0.0f);
    u.sunIlluminance = glm::vec4(core::preExposed(frame.sun.illuminance, frame.preExposure), 0.0f);
    u.ambient = glm::vec4(core::preExposed(frame.ambient, frame.preExposure), 0.0f);
    u.albedo = glm::vec4(s.albedo, 0.0f);
    // An empty medium (fogMediumEmpty) has no extinction anywhere, the analytic tail's included.
    const float density = fogMediumEmpty(s, noiseEnabled) ? 0.0f : s.density;
    u.medium = glm::vec4(density, s.heightFalloff, clampedAnisotropy(s.anisotropy), s.maxDistance);
    u.heights =
        glm::vec4(float(camera.y - double(s.baseHeight)), float(fogMediumTop(s, noiseEnabled)), 0.0f, 0.0f);

    const double scale = 0.01 * double(s.noise.tiling);
    const glm::dvec3 noiseAtCamera = (camera - glm::dvec3(s.noise.wind) * frame.timeSeconds) * scale;
    const glm::dvec3 wrapped = noiseAtCamera - glm::floor(noiseAtCamera);
    u.noise = glm::vec4(glm::vec3(wrapped), float(scale));
    u.noiseRemap = glm::vec4(s.noise.threshold, s.noise.multiplier, 0.0f, 0.0f);

    u.shadow = glm::vec4(frame.shadowMap.depthBias, 0.0f, 0.0f, 0.0f);  // a 1×1 kernel
    const float noGeometryDepth = depth.reversedZ ? 0.0f : 1.0f;
    u.march = glm::vec4(0.0f, noGeometryDepth, 0.0f, 0.0f);
    u.extent = glm::uvec4(frame.color.extent.width, frame.color.extent.height, 0u,
                          uint32_t(frame.frameIndex & 0xffffffffu));
    u.scatterExtent = glm::uvec4(frame.color.extent.width, frame.color.extent.height, 0u, 0u);
    uint32_t flags = 0;
    if (noiseEnabled) flags |= gpu::kFogFlagNoise;
    if (shadowMapEnabled) flags |= gpu::kFogFlagShadowMap;
    if (shadowMapEnabled && frame.shadowMap.reversedZ) flags |= gpu::kFogFlagShadowReversedZ;
    const glm::mat4& m = u.viewToShadow;  // m[column][row]
    if (shadowMapEnabled && m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f)
        flags |= gpu::kFogFlagShadowOrthographic;
    if (s.selfShadow) flags |= gpu::kFogFlagSelfShadow;
    if (s.analyticTail) flags |= gpu::kFogFlagAnalyticTail;
    if (depth.reversedZ) flags |= gpu::kFogFlagDepthReversedZ;
    // The sun through the atmosphere (common/medium/atmosphere_light.glsl): its transmittance LUT at each
    // sample.
    const AtmosphereSettings& a = frame.atmosphere;
    if (a.enabled) {
        flags |= gpu::kFogFlagAtmosphere;
        u.planet = glm::vec4(a.groundRadius, a.topRadius, float(a.transmittanceLutSize.x),
                             float(a.transmittanceLutSize.y));
        u.planetCamera = glm::vec4(glm::vec3(camera + glm::dvec3(0.0, a.groundRadius, 0.0)), 0.0f);
    }
    // The sun through the clouds (common/medium/atmosphere_light.glsl): their shadow map, which the clouds
    // declare earlier in the frame whenever they cast shadows.
    if (common::castsCloudShadows(frame)) {
        flags |= gpu::kFogFlagCloudShadow;
        const common::CloudShadowRows rows = common::cameraRelativeCloudShadowRows(frame);
        u.cloudShadowU = rows.u;
        u.cloudShadowV = rows.v;
    }
    u.flags = glm::uvec4(flags, 0u, 0u, 0u);
    return u;
}

}  // namespace postfx::common
