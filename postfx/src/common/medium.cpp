// The shared medium (FogMedium: both fogs; docs/effects/fog.md, "Model"): its checks, its bounds and its
// key (its part of the uniforms: medium_uniforms.cpp).
#include "common/medium.h"

#include "core/checks.h"
#include "core/temporal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace postfx::common {
namespace {

using core::checkRange;

Status bad(const std::string& field, const std::string& why) {
    return core::invalid(field + ": " + why);
}

bool isPowerOfTwo(uint32_t v) {
    return v && !(v & (v - 1));
}

}  // namespace

uint64_t mediumKey(const FogMedium& m) {
    using core::hashValue;
    uint64_t h = core::kHashSeed;
    h = hashValue(h, m.density);
    for (int c = 0; c < 3; ++c)
        h = hashValue(h, m.albedo[c]);
    h = hashValue(h, m.anisotropy);
    h = hashValue(h, m.heightFalloff);
    h = hashValue(h, m.baseHeight);
    h = hashValue(h, m.maxDistance);
    h = hashValue(h, m.selfShadow);
    h = hashValue(h, m.analyticTail);
    const FogNoiseSettings& n = m.noise;
    h = hashValue(h, n.enabled);
    if (!n.enabled) return h;
    h = hashValue(h, n.textureSize);
    h = hashValue(h, n.seed);
    h = hashValue(h, n.tiling);
    h = hashValue(h, n.threshold);
    h = hashValue(h, n.multiplier);
    for (int c = 0; c < 3; ++c)
        h = hashValue(h, n.wind[c]);
    h = hashValue(h, n.hostTexture);
    return hashValue(h, n.hostTextureLayout);
}

float clampedAnisotropy(float g) {
    return std::clamp(g, -kMaxAnisotropy, kMaxAnisotropy);
}

Status validateMedium(const FogMedium& m, const std::string& p) {
    if (Status r = checkRange((p + ".density").c_str(), m.density, 0.0, 1e6); !r) return r;
    for (int c = 0; c < 3; ++c)
        if (Status r = checkRange((p + ".albedo").c_str(), m.albedo[c], 0.0, 1.0); !r) return r;
    if (Status r = checkRange((p + ".anisotropy").c_str(), m.anisotropy, -1.0, 1.0); !r) return r;
    if (Status r = checkRange((p + ".height_falloff").c_str(), m.heightFalloff, 0.0, 10.0); !r) return r;
    if (!std::isfinite(m.baseHeight)) return bad(p + ".base_height", "is not finite");
    if (Status r = checkRange((p + ".max_distance").c_str(), m.maxDistance, 0.0, 1e7); !r) return r;
    if (m.maxDistance <= 0.0f) return bad(p + ".max_distance", "must be > 0");
    const FogNoiseSettings& n = m.noise;
    if (!n.enabled) return Status::success();
    if (!n.hostTexture && (n.textureSize < 16 || n.textureSize > 256 || !isPowerOfTwo(n.textureSize)))
        return bad((p + ".noise.texture_size"),
                   std::to_string(n.textureSize) + " must be a power of two in [16, 256]");
    if (n.hostTexture && n.hostTextureLayout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL &&
        n.hostTextureLayout != VK_IMAGE_LAYOUT_GENERAL &&
        n.hostTextureLayout != VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL)
        return bad((p + ".noise.host_texture_layout"),
                   std::to_string(int64_t(n.hostTextureLayout)) +
                       " is not SHADER_READ_ONLY_OPTIMAL, GENERAL or READ_ONLY_OPTIMAL (a layout it can be "
                       "sampled in)");
    if (Status r = checkRange((p + ".noise.tiling").c_str(), n.tiling, 0.0, 1000.0); !r) return r;
    if (n.tiling <= 0.0f) return bad((p + ".noise.tiling"), "must be > 0");
    if (Status r = checkRange((p + ".noise.threshold").c_str(), n.threshold, 0.0, 1.0); !r) return r;
    if (Status r = checkRange((p + ".noise.multiplier").c_str(), n.multiplier, 0.0, 1e3); !r) return r;
    for (int c = 0; c < 3; ++c)
        if (Status r = checkRange((p + ".noise.wind").c_str(), n.wind[c], -1e3, 1e3); !r) return r;
    return Status::success();
}

Status validateTemporal(const TemporalSettings& t, const std::string& p) {
    const std::string key = p + ".temporal.blend_weight";
    if (Status r = checkRange(key.c_str(), t.blendWeight, 0.0, 1.0); !r) return r;
    if (t.blendWeight <= 0.0f) return bad(key, core::numberText(t.blendWeight) + " must be > 0");
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
