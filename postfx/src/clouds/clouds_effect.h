// The clouds behind the effect boundary (docs/effects/clouds.md): their settings' checks and their
// declaration of a frame: the noise textures (persistent: generated once per size and seed), the uniforms
// and the march that composites the clouds over the host's color. With the atmosphere on they read its
// uniforms and LUTs (declared earlier in the frame: the sun's transmittance, the aerial perspective).
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"
#include "core/temporal.h"

#include "clouds/clouds_shared.h"

namespace postfx::clouds {

inline constexpr core::ResourceId kBaseNoise{"clouds.base_noise"};      // r8 3D, Perlin–Worley (persistent)
inline constexpr core::ResourceId kDetailNoise{"clouds.detail_noise"};  // r8 3D, Worley fBm (persistent)
inline constexpr core::ResourceId kNoNoise{"clouds.no_noise"};          // 1-texel stand-in, noise off
inline constexpr core::ResourceId kNoCoverageMap{"clouds.no_coverage_map"};  // 1-texel stand-in, no map
// Stand-ins at the march's bindings a frame does not use: without the atmosphere the aerial perspective's
// transmittance (a 2D array of two 1-texel layers), without temporal the distance image (1 r32ui texel).
inline constexpr core::ResourceId kNoAtmosphere{"clouds.no_atmosphere"};
inline constexpr core::ResourceId kNoDistance{"clouds.no_distance"};
// Without temporal, with the volumetrics lookup: the march's distances for clouds.lookup.
inline constexpr core::ResourceId kLookupDistance{"clouds.lookup_distance"};
inline constexpr core::ResourceId kUniforms{"clouds.uniforms"};  // CloudUniforms
// Reduced resolution or temporal (docs/effects/clouds.md, "Resolution and temporal"): the march's (L, T)
// and reprojection distance at its extent, two accumulated (L, T) and two distance images read and
// written in turn, and the TemporalUniforms.
inline constexpr core::ResourceId kScatter{"clouds.scatter"};
inline constexpr core::ResourceId kHistory[2] = {{"clouds.history_a"}, {"clouds.history_b"}};
inline constexpr core::ResourceId kHistoryDistance[2] = {{"clouds.history_distance_a"},
                                                         {"clouds.history_distance_b"}};
inline constexpr core::ResourceId kTemporalUniforms{"clouds.temporal_uniforms"};

// The detail texture's seed: the base's, decorrelated (its Worley layers would otherwise repeat the
// base's own Worley octaves at 1/8 of their size).
inline uint32_t detailSeed(uint32_t seed) {
    return seed ^ 0x5bd1e995u;
}

// The march's extent for a color image of `width`×`height` at `resolutionScale` [px].
glm::uvec2 marchExtent(uint32_t width, uint32_t height, float resolutionScale);

// The uniforms of `frame` (validated): exposed for the tests. `windDelta`: how far the wind moved the
// clouds since the previous recorded frame [m].
gpu::CloudUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth,
                                 const glm::vec3& windDelta = glm::vec3(0.0f));

class CloudsEffect final : public core::Effect {
public:
    explicit CloudsEffect(const core::Gpu& gpu);

    const char* name() const override { return "clouds"; }
    Status validate(const FrameInfo& frame) const override;
    // Enabled with some coverage and density.
    bool active(const FrameInfo& frame) const override;

    uint32_t presetCount() const override { return 4; }  // Low, Medium, High, Ultra
    core::QualityRequest quality(const FrameInfo& frame) const override;
    void applyPreset(FrameInfo& frame, uint32_t preset) const override;
    uint32_t fallbackPreset() const override { return 1; }  // Medium
    std::vector<double> presetErrors() const override;
    uint32_t autoFeatures(const FrameInfo& frame) const override;

    // The wind, the box and the coverage map in postfx's frame (settingsToPostfx).
    void toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                       core::WorldScratch& scratch) const override;
    Status declare(core::FrameBuilder& builder) const override;
    void recorded(const FrameInfo& frame, bool active) override;

private:
    bool noiseFormatSupported_ = false;
    core::TemporalHistory history_;
    double historyTime_ = 0.0;  // FrameInfo::timeSeconds of the last frame recorded with history
};

}  // namespace postfx::clouds
