// The clouds behind the effect boundary (docs/effects/clouds.md): their settings' checks and their
// declaration of a frame: the noise textures (persistent: generated once per size and seed), the uniforms
// and the march that composites the clouds over the host's color. With the atmosphere on they read its
// uniforms and LUTs (declared earlier in the frame: the sun's transmittance, the aerial perspective).
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"

#include "clouds/clouds_shared.h"

namespace postfx::clouds {

inline constexpr core::ResourceId kBaseNoise{"clouds.base_noise"};      // r8 3D, Perlin–Worley (persistent)
inline constexpr core::ResourceId kDetailNoise{"clouds.detail_noise"};  // r8 3D, Worley fBm (persistent)
inline constexpr core::ResourceId kNoNoise{"clouds.no_noise"};          // 1-texel stand-in, noise off
inline constexpr core::ResourceId kUniforms{"clouds.uniforms"};         // CloudUniforms

// The detail texture's seed: the base's, decorrelated (its Worley layers would otherwise repeat the
// base's own Worley octaves at 1/8 of their size).
inline uint32_t detailSeed(uint32_t seed) {
    return seed ^ 0x5bd1e995u;
}

// The uniforms of `frame` (validated): exposed for the tests.
gpu::CloudUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth);

class CloudsEffect final : public core::Effect {
public:
    explicit CloudsEffect(const core::Gpu& gpu);

    const char* name() const override { return "clouds"; }
    Status validate(const FrameInfo& frame) const override;
    // Enabled with some coverage and density.
    bool active(const FrameInfo& frame) const override;
    Status declare(core::FrameBuilder& builder) const override;

private:
    bool noiseFormatSupported_ = false;
};

}  // namespace postfx::clouds
