// The ray-marched fog behind the effect boundary (docs/effects/fog.md): its settings' checks, its
// quality presets, and its declaration of a frame: the noise texture (generated, the host's, or a
// stand-in), the scatter image of a reduced-resolution march, the uniforms, and the passes
// fog.noise, fog.raymarch, fog.temporal and fog.upsample (at full size with temporal, fog.temporal
// composites).
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"
#include "core/temporal.h"
#include "fog/fog_shared.h"

namespace postfx::fog {

// The fog's resources, as the frame plan names them.
inline constexpr core::ResourceId kNoise{"fog.noise"};        // generated noise texture (persistent)
inline constexpr core::ResourceId kNoNoise{"fog.no_noise"};   // 1-texel stand-in when noise is off
inline constexpr core::ResourceId kScatter{"fog.scatter"};    // reduced-resolution march (L, T)
inline constexpr core::ResourceId kUniforms{"fog.uniforms"};  // FogUniforms
// Temporal accumulation (fog.md#temporal): two (L, T) histories and two ray-end distance images at the
// march's size, read and written in turn, and the TemporalUniforms.
inline constexpr core::ResourceId kHistory[2] = {{"fog.history_a"}, {"fog.history_b"}};
inline constexpr core::ResourceId kHistoryDistance[2] = {{"fog.history_distance_a"},
                                                         {"fog.history_distance_b"}};
inline constexpr core::ResourceId kTemporalUniforms{"fog.temporal_uniforms"};

// The fog's march pipelines for RGBA16F color, each with what it is for (for tools that inspect the compiled
// pipelines: postfx-bench --pipeline-stats): fog.raymarch at full size, reduced, reduced with temporal.
struct MarchPipeline {
    const char* variant;  // "full size", ...
    const core::ComputePipelineDesc* desc;
};
std::vector<MarchPipeline> marchPipelines();
// The march's specialization constants for a frame's uniforms (fog_shared.h, kFogConstant*).
core::PipelineConstants marchConstants(const gpu::FogUniforms& uniforms);

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
    std::vector<double> presetErrors() const override;
    uint32_t autoFeatures(const FrameInfo& frame) const override;

    // The noise's wind along postfx's axes.
    void toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                       core::WorldScratch& scratch) const override;
    Status declare(core::FrameBuilder& builder) const override;
    void recorded(const FrameInfo& frame, bool active) override;

private:
    bool noiseFormatSupported_ = false;
    core::TemporalHistory history_;
};

}  // namespace postfx::fog
