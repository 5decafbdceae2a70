// The shared medium (FogMedium: both fogs; docs/effects/fog.md, "Model"): the checks its settings table
// (common/medium_table.h) cannot state and its bounds (its part of the uniforms: medium_uniforms.cpp).
#include "common/medium.h"

#include "core/checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace postfx::common {
namespace {

Status bad(const std::string& field, const std::string& why) {
    return core::invalid(field + ": " + why);
}

bool isPowerOfTwo(uint32_t v) {
    return v && !(v & (v - 1));
}

}  // namespace

float clampedAnisotropy(float g) {
    return std::clamp(g, -kMaxAnisotropy, kMaxAnisotropy);
}

Status checkMediumRules(const FogMedium& m, const std::string& p) {
    const FogNoiseSettings& n = m.noise;
    if (!n.enabled) return Status::success();
    if (!n.hostTexture && (n.textureSize < 16 || n.textureSize > 256 || !isPowerOfTwo(n.textureSize)))
        return bad(p + ".noise.textureSize",
                   std::to_string(n.textureSize) + " must be a power of two in [16, 256]");
    if (n.hostTexture && n.hostTextureLayout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL &&
        n.hostTextureLayout != VK_IMAGE_LAYOUT_GENERAL &&
        n.hostTextureLayout != VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL)
        return bad(p + ".noise.hostTextureLayout",
                   std::to_string(int64_t(n.hostTextureLayout)) +
                       " is not SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL (a layout it can be "
                       "sampled in)");
    return Status::success();
}

double fogMediumTop(const FogMedium& s, bool noiseEnabled) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (fogMediumEmpty(s, noiseEnabled)) return -kInf;
    if (s.heightFalloff <= 0.0f) return kInf;
    const double noiseMax =
        noiseEnabled ? std::clamp(1.0 - double(s.noise.threshold), 0.0, 1.0) * double(s.noise.multiplier)
                     : 1.0;
    // density · noise_max · e^{-k·y} = ε / max_distance  <=>  y = ln(density · noise_max · max_distance / ε)
    // / k
    const double bound = double(s.density) * noiseMax * double(s.maxDistance) / kNegligibleOpticalDepth;
    return std::log(bound) / double(s.heightFalloff);
}

}  // namespace postfx::common
