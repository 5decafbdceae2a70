#include "clouds/clouds_settings.h"

#include "core/checks.h"
#include "core/settings_check.h"

#include <postfx/settings_table.h>

#include <cmath>
#include <string>

namespace postfx::clouds {
namespace {

using core::numberText;

constexpr const char* kPrefix = "FrameInfo.clouds";

Status bad(const std::string& member, const std::string& why) {
    return core::invalid(std::string(kPrefix) + "." + member + ": " + why);
}

bool powerOfTwo(uint32_t v) {
    return v && (v & (v - 1)) == 0;
}

// A layout a host texture can be sampled in.
Status sampledLayout(const std::string& member, VkImageLayout layout) {
    if (layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL || layout == VK_IMAGE_LAYOUT_GENERAL ||
        layout == VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL)
        return Status::success();
    return bad(member,
               std::to_string(int64_t(layout)) +
                   " is not SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL (a layout it can be "
                   "sampled in)");
}

}  // namespace

Status validateSettings(const CloudSettings& s) {
    if (Status r = core::checkSettings(cloudSettingsTable(), &s, kPrefix); !r) return r;
    // The rules beside the table's ranges.
    if (!(s.topHeight > s.bottomHeight))
        return bad("topHeight", numberText(s.topHeight) + " must be greater than bottomHeight (" +
                                    numberText(s.bottomHeight) + ")");
    const CloudMultipleScattering& m = s.multipleScattering;
    if (m.contribution > m.attenuation)
        return bad("multipleScattering.contribution",
                   numberText(m.contribution) + " must be at most attenuation (" + numberText(m.attenuation) +
                       ") to conserve energy (Wrenninge 2015)");
    if (s.coverageMap.texture)
        if (Status r = sampledLayout("coverageMap.layout", s.coverageMap.layout); !r) return r;
    if (s.temporal.enabled && s.updateBlock != 1 && s.updateBlock != 2 && s.updateBlock != kMaxUpdateBlock)
        return bad("updateBlock", std::to_string(s.updateBlock) + " is not 1, 2 or 4");
    const CloudNoiseSettings& n = s.noise;
    if ((n.hostBaseTexture || n.hostDetailTexture) && n.enabled)
        if (Status r = sampledLayout("noise.hostTextureLayout", n.hostTextureLayout); !r) return r;
    if (!powerOfTwo(n.baseSize))
        return bad("noise.baseSize", std::to_string(n.baseSize) + " is not a power of two");
    if (!powerOfTwo(n.detailSize))
        return bad("noise.detailSize", std::to_string(n.detailSize) + " is not a power of two");
    return Status::success();
}

void settingsToPostfx(const core::WorldTransform& world, CloudSettings& s) {
    s.wind = world.direction(glm::vec3(s.wind));
    // boxToWorld = R_up(yaw)·R_x(pitch) on the host's axes; R·R_a(θ)·R⁻¹ = R_{R·a}(det R · θ) for the
    // signed permutation R, which takes the host's up to +y and its x to +x.
    s.box.center = world.position(s.box.center);
    s.box.halfSize = world.extent(glm::vec3(s.box.halfSize));
    s.box.yawDeg = float(world.determinant()) * s.box.yawDeg;
    s.box.pitchDeg = float(world.determinant()) * s.box.pitchDeg;
    // v = (h - originZ)/size along the host's axis h = sign·z·u: v = (z - sign·originZ/u) / (sign·size/u).
    CloudCoverageMap& map = s.coverageMap;
    const double vSign = world.sign(2);
    map.originX = world.length(map.originX);
    map.originZ = vSign * world.length(map.originZ);
    map.size = float(vSign * world.length(map.size));
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
            s.updateBlock = p.updateBlock;
        }
    return s;
}

Status validateCloudSettings(const CloudSettings& settings) {
    return clouds::validateSettings(settings);
}
}  // namespace postfx
