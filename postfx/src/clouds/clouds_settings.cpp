#include "clouds/clouds_settings.h"

#include "core/checks.h"

#include <cmath>
#include <string>

namespace postfx::clouds {
namespace {

using core::numberText;

std::string key(const std::string& name) {
    return "clouds." + name;
}

Status bad(const std::string& name, const std::string& why) {
    return core::invalid(key(name) + ": " + why);
}

// v in [lo, hi], finite.
Status range(const std::string& name, double v, double lo, double hi) {
    return core::checkRange(key(name).c_str(), v, lo, hi);
}

// v in (0, hi], finite.
Status positive(const std::string& name, double v, double hi) {
    if (Status r = range(name, v, 0.0, hi); !r) return r;
    if (v <= 0.0) return bad(name, "must be > 0");
    return Status::success();
}

Status count(const std::string& name, uint32_t v, uint32_t lo, uint32_t hi) {
    if (v < lo || v > hi)
        return bad(
            name, std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return Status::success();
}

Status powerOfTwo(const std::string& name, uint32_t v, uint32_t lo, uint32_t hi) {
    if (Status r = count(name, v, lo, hi); !r) return r;
    if ((v & (v - 1)) != 0) return bad(name, std::to_string(v) + " is not a power of two");
    return Status::success();
}

Status vec3(const std::string& name, const Vec3& v, double lo, double hi) {
    for (int c = 0; c < 3; ++c)
        if (Status r = range(name + "[" + std::to_string(c) + "]", v[c], lo, hi); !r) return r;
    return Status::success();
}

Status validateBox(const CloudBox& b) {
    for (int c = 0; c < 3; ++c)
        if (Status r = range("box.center[" + std::to_string(c) + "]", b.center[c], -core::kMaxWorldCoordinate,
                             core::kMaxWorldCoordinate);
            !r)
            return r;
    for (int c = 0; c < 3; ++c)
        if (Status r = positive("box.half_size[" + std::to_string(c) + "]", b.halfSize[c], kMaxBoxHalfSize);
            !r)
            return r;
    if (Status r = range("box.yaw_deg", b.yawDeg, -360.0, 360.0); !r) return r;
    return range("box.pitch_deg", b.pitchDeg, -360.0, 360.0);
}

// A layout a host texture can be sampled in.
Status sampledLayout(const std::string& name, VkImageLayout layout) {
    if (layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL || layout == VK_IMAGE_LAYOUT_GENERAL ||
        layout == VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL)
        return Status::success();
    return bad(name, std::to_string(int64_t(layout)) +
                         " is not SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL (a layout it can be "
                         "sampled in)");
}

Status validateCoverageMap(const CloudCoverageMap& m) {
    if (Status r = range("coverage_map.size", m.size, 1.0, kMaxTiling); !r) return r;
    if (Status r =
            range("coverage_map.origin_x", m.originX, -core::kMaxWorldCoordinate, core::kMaxWorldCoordinate);
        !r)
        return r;
    if (Status r =
            range("coverage_map.origin_z", m.originZ, -core::kMaxWorldCoordinate, core::kMaxWorldCoordinate);
        !r)
        return r;
    return m.texture ? sampledLayout("coverage_map.layout", m.layout) : Status::success();
}

Status validateNoise(const CloudNoiseSettings& n) {
    if ((n.hostBaseTexture || n.hostDetailTexture) && n.enabled)
        if (Status r = sampledLayout("noise.host_texture_layout", n.hostTextureLayout); !r) return r;
    if (Status r = powerOfTwo("noise.base_size", n.baseSize, kMinBaseSize, kMaxBaseSize); !r) return r;
    if (Status r = powerOfTwo("noise.detail_size", n.detailSize, kMinDetailSize, kMaxDetailSize); !r)
        return r;
    if (Status r = range("noise.tiling", n.tiling, kMinTiling, kMaxTiling); !r) return r;
    return range("noise.detail_strength", n.detailStrength, 0.0, 1.0);
}

Status validateMultipleScattering(const CloudMultipleScattering& m) {
    if (uint32_t(m.model) > uint32_t(CloudScatteringModel::Octaves))
        return bad("multiple_scattering.model",
                   std::to_string(uint32_t(m.model)) + " is not a CloudScatteringModel");
    if (Status r = count("multiple_scattering.octaves", m.octaves, 1, kMaxOctaves); !r) return r;
    if (Status r = positive("multiple_scattering.attenuation", m.attenuation, 1.0); !r) return r;
    if (Status r = range("multiple_scattering.contribution", m.contribution, 0.0, 1.0); !r) return r;
    if (m.contribution > m.attenuation)
        return bad("multiple_scattering.contribution",
                   numberText(m.contribution) + " must be at most attenuation (" + numberText(m.attenuation) +
                       ") to conserve energy (Wrenninge 2015)");
    return range("multiple_scattering.eccentricity", m.eccentricity, 0.0, 1.0);
}

}  // namespace

Status validateSettings(const CloudSettings& s) {
    if (!std::isfinite(s.autoBudgetMs)) return bad("auto_budget_ms", "is not finite");
    if (s.autoBudgetMs <= 0.0f)
        return bad("auto_budget_ms", core::numberText(s.autoBudgetMs) + " must be > 0");
    if (uint32_t(s.quality) > uint32_t(CloudQuality::Auto))
        return bad("quality", std::to_string(uint32_t(s.quality)) + " is not a CloudQuality");
    if (uint32_t(s.shape) > uint32_t(CloudShape::Box))
        return bad("shape", std::to_string(uint32_t(s.shape)) + " is not a CloudShape");
    if (Status r = range("bottom_height", s.bottomHeight, 0.0, kMaxHeight); !r) return r;
    if (Status r = range("top_height", s.topHeight, 0.0, kMaxHeight); !r) return r;
    if (!(s.topHeight > s.bottomHeight))
        return bad("top_height", numberText(s.topHeight) + " must be greater than bottom_height (" +
                                     numberText(s.bottomHeight) + ")");
    if (Status r = validateBox(s.box); !r) return r;
    if (Status r = range("coverage", s.coverage, 0.0, 1.0); !r) return r;
    if (Status r = validateCoverageMap(s.coverageMap); !r) return r;
    if (Status r = range("cloud_type", s.cloudType, 0.0, 1.0); !r) return r;
    if (Status r = range("density", s.density, 0.0, kMaxDensity); !r) return r;
    if (Status r = range("albedo", s.albedo, 0.0, 1.0); !r) return r;
    if (Status r = range("anisotropy_forward", s.anisotropyForward, 0.0, kMaxAnisotropy); !r) return r;
    if (Status r = range("anisotropy_back", s.anisotropyBack, -kMaxAnisotropy, 0.0); !r) return r;
    if (Status r = range("lobe_mix", s.lobeMix, 0.0, 1.0); !r) return r;
    if (Status r = validateMultipleScattering(s.multipleScattering); !r) return r;
    if (Status r = count("steps", s.steps, 1, kMaxSteps); !r) return r;
    if (Status r = count("light_steps", s.lightSteps, 1, kMaxLightSteps); !r) return r;
    if (Status r = positive("light_distance", s.lightDistance, kMaxLightDistance); !r) return r;
    if (Status r = positive("max_distance", s.maxDistance, kMaxDistance); !r) return r;
    if (Status r = vec3("wind", s.wind, -kMaxWind, kMaxWind); !r) return r;
    if (Status r = range("resolution_scale", s.resolutionScale, kMinResolutionScale, 1.0); !r) return r;
    if (Status r = positive("temporal.blend_weight", s.temporal.blendWeight, 1.0); !r) return r;
    if (Status r = count("shadow_map.size", s.shadowMap.size, kMinShadowSize, kMaxShadowSize); !r) return r;
    if (Status r = range("shadow_map.extent", s.shadowMap.extent, kMinShadowExtent, kMaxShadowExtent); !r)
        return r;
    return validateNoise(s.noise);
}

}  // namespace postfx::clouds

namespace postfx {
CloudSettings applyCloudQuality(const CloudSettings& settings, CloudQuality quality) {
    CloudSettings s = settings;
    for (const clouds::QualityPreset& p : clouds::kQualityPresets)
        if (p.quality == quality) {
            s.steps = p.steps;
            s.lightSteps = p.lightSteps;
            s.resolutionScale = p.resolutionScale;
            s.temporal.enabled = p.temporal;
        }
    return s;
}

Status validateCloudSettings(const CloudSettings& settings) {
    return clouds::validateSettings(settings);
}
}  // namespace postfx
