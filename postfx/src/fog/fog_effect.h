// The ray-marched fog behind the effect boundary (docs/effects/fog.md): its settings' checks, its
// quality presets, and its declaration of a frame: the noise texture (generated, the host's, or a
// stand-in), the scatter image of a reduced-resolution march, the uniforms, and the passes
// fog.noise, fog.raymarch and fog.upsample.
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"

namespace postfx::fog {

// The fog's resources, as the frame plan names them.
inline constexpr core::ResourceId kNoise{"fog.noise"};        // generated noise texture (persistent)
inline constexpr core::ResourceId kNoNoise{"fog.no_noise"};   // 1-texel stand-in when noise is off
inline constexpr core::ResourceId kScatter{"fog.scatter"};    // reduced-resolution march (L, T)
inline constexpr core::ResourceId kUniforms{"fog.uniforms"};  // FogUniforms

class FogEffect final : public core::Effect {
public:
    // Queries once whether the device can generate the noise texture (R8_UNORM storage, linear filter).
    explicit FogEffect(const core::Gpu& gpu);

    const char* name() const override { return "fog"; }
    Status validate(const FrameInfo& frame) const override;
    // Enabled, and a medium that is not empty everywhere (density 0, noise multiplier 0 or threshold 1).
    bool active(const FrameInfo& frame) const override;

    uint32_t presetCount() const override { return 4; }  // Low, Medium, High, Ultra
    core::QualityRequest quality(const FrameInfo& frame) const override;
    void applyPreset(FrameInfo& frame, uint32_t preset) const override;
    uint32_t fallbackPreset() const override { return 1; }  // Medium
    uint32_t autoFeatures(const FrameInfo& frame) const override;

    Status declare(core::FrameBuilder& builder) const override;

private:
    bool noiseFormatSupported_ = false;
};

}  // namespace postfx::fog
