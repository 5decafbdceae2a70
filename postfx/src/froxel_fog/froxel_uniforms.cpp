#include "froxel_fog/froxel_uniforms.h"

#include "common/medium.h"
#include "core/exposure.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace postfx::froxel_fog {
namespace {

// Radical inverse of `index` in `base` (Halton 1964): the sequence's index-th element in [0, 1).
float halton(uint32_t index, uint32_t base) {
    double result = 0.0, f = 1.0;
    for (uint32_t i = index; i > 0; i /= base) {
        f /= base;
        result += f * double(i % base);
    }
    return float(result);
}

constexpr uint32_t kJitterPeriod = 1024;  // frames before the Halton (2, 3, 5) samples repeat
constexpr double kStorageTarget = 4096.0;

}  // namespace

double gridNear(const FrameInfo& frame, const DepthConvention& depth) {
    const double far = frame.froxelFog.maxDistance;
    const glm::dvec4 p = glm::inverse(glm::dmat4(frame.camera.projection)) *
                         glm::dvec4(0.0, 0.0, depth.reversedZ ? 1.0 : 0.0, 1.0);
    const double near = glm::length(glm::dvec3(p) / p.w);
    if (!std::isfinite(near) || !(near > 0.0)) return far * 1e-3;
    return std::min(near, 0.5 * far);
}

float storageScale(const FrameInfo& frame) {
    const FroxelFogSettings& s = frame.froxelFog;
    // Henyey–Greenstein's largest value, at cos θ = ±1 (sign of g): (1 + |g|) / (4π (1 - |g|)²).
    const double g = std::abs(double(common::clampedAnisotropy(s.anisotropy)));
    const double peak = (1.0 + g) / (4.0 * 3.14159265358979323846 * (1.0 - g) * (1.0 - g));
    double largest = 0.0;  // of the pre-exposed radiance (core/exposure.h)
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, double(s.albedo[c]) * double(frame.preExposure) *
                                        (double(frame.sun.illuminance[c]) * peak + double(frame.ambient[c])));
    if (!(largest > kStorageTarget)) return 1.0f;
    return float(std::exp2(std::max(std::floor(std::log2(kStorageTarget / largest)), -120.0)));
}

uint32_t packLights(const FrameInfo& frame, gpu::FroxelLights& out,
                    std::vector<gpu::FroxelShadowFace>& faces) {
    const glm::dvec3 camera = frame.camera.position;
    const glm::dmat4 fromCamera = glm::translate(glm::dmat4(1.0), camera);
    const LocalShadowAtlasInput& atlas = frame.localShadows;
    const bool shadows = atlas.image.present();
    faces.clear();
    // The first face of each shadow packed so far (shared shadows are packed once).
    std::array<uint32_t, kMaxLocalLights> firstFace;
    firstFace.fill(gpu::kFroxelNoShadow);
    uint32_t count = 0;
    for (uint32_t i = 0; i < frame.lightCount; ++i) {
        const LocalLight& l = frame.lights[i];
        if (l.intensity == Vec3(0.0f)) continue;  // adds nothing (the reference drops it too)
        gpu::FroxelLight& g = out.lights[count++];
        g.positionRange = glm::vec4(glm::vec3(glm::dvec3(l.position) - camera), l.range);
        g.intensityRadius = glm::vec4(core::preExposed(l.intensity, frame.preExposure), l.sourceRadius);
        if (l.type == LightType::Spot) {
            const glm::dvec3 axis = glm::normalize(glm::dvec3(l.direction));
            g.directionCosOuter = glm::vec4(glm::vec3(axis), float(std::cos(double(l.outerConeAngle))));
            g.cosInnerBias = glm::vec4(float(std::cos(double(l.innerConeAngle))), 0.0f, 0.0f, 0.0f);
        } else {
            g.directionCosOuter = glm::vec4(0.0f, 0.0f, 0.0f, -2.0f);  // no cone
            g.cosInnerBias = glm::vec4(0.0f);
        }
        g.shadow = glm::uvec4(gpu::kFroxelNoShadow, 0u, 0u, 0u);
        if (!shadows || l.shadow == kNoLocalShadow) continue;
        const LocalShadow& shadow = atlas.shadows[l.shadow];
        if (firstFace[l.shadow] == gpu::kFroxelNoShadow) {
            firstFace[l.shadow] = uint32_t(faces.size());
            for (uint32_t f = 0; f < shadow.faceCount; ++f) {
                const LocalShadowFace& face = shadow.faces[f];
                gpu::FroxelShadowFace& gf = faces.emplace_back();
                const glm::mat4 m(glm::dmat4(face.worldToClip) * fromCamera);
                for (int r = 0; r < 4; ++r)
                    gf.clipRows[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
                gf.region = glm::vec4(float(face.offset.x), float(face.offset.y), float(face.extent.x),
                                      float(face.extent.y));
            }
        }
        g.shadow = glm::uvec4(firstFace[l.shadow], shadow.faceCount, shadow.reversedZ ? 1u : 0u, 0u);
        g.cosInnerBias.y = shadow.depthBias;
    }
    return count;
}

PassUniforms buildPassUniforms(const FrameInfo& frame, const DepthConvention& depth, const UVec3& grid,
                               uint32_t lightCount, uint32_t lightWords, bool noiseEnabled,
                               bool shadowMapEnabled) {
    const FroxelFogSettings& s = frame.froxelFog;
    PassUniforms u{};
    u.fog = common::buildMediumUniforms(s, frame, depth, noiseEnabled, shadowMapEnabled);
    gpu::FroxelUniforms& f = u.froxel;
    f.grid = glm::uvec4(grid.x, grid.y, grid.z, lightCount);
    glm::vec3 offset(0.5f);
    if (s.jitter) {
        const uint32_t index = uint32_t(frame.frameIndex % kJitterPeriod) + 1;
        offset = glm::vec3(halton(index, 2), halton(index, 3), halton(index, 5));
    }
    f.jitter = glm::vec4(offset, storageScale(frame));
    const double near = gridNear(frame, depth), far = s.maxDistance;
    f.slices = glm::vec4(float(near), float(far), s.depthExponent, float(std::log(far / near)));
    uint32_t flags = 0;
    if (s.depthDistribution == FroxelDepthDistribution::Log) flags |= gpu::kFroxelFlagLogSlices;
    if (s.tricubic) flags |= gpu::kFroxelFlagTricubic;
    if (s.localShadowFilter) flags |= gpu::kFroxelFlagShadowFilter;
    const glm::dvec3 camera = frame.camera.position;
    uint32_t volumes = 0;
    for (uint32_t i = 0; i < s.volumeCount; ++i) {
        const FogVolume& v = s.volumes[i];
        if (!(v.density > 0.0f)) continue;
        const glm::vec3 center(glm::dvec3(v.center) - camera);
        u.froxel.volumes[2 * volumes] = glm::vec4(center, v.edgeFalloff);
        u.froxel.volumes[2 * volumes + 1] = v.shape == FogVolumeShape::Sphere
                                                ? glm::vec4(v.radius, -1.0f, 0.0f, v.density)
                                                : glm::vec4(v.halfSize, v.density);
        ++volumes;
    }
    f.counts = glm::uvec4(volumes, flags, lightWords, 0u);
    return u;
}

}  // namespace postfx::froxel_fog
