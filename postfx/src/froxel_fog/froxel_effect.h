// The froxel fog behind the effect boundary (docs/effects/froxel-fog.md): its settings' checks and its
// declaration of a frame: the noise texture (the shared medium's), the uniforms and local lights, and
// the passes froxel_fog.noise, froxel_fog.light_lists (with many lights), froxel_fog.shadow_change (local
// shadows with temporal accumulation), froxel_fog.scatter,
// froxel_fog.integrate and froxel_fog.apply over the grid's two volumes (the scatter volume's two
// histories with temporal accumulation).
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"
#include "core/temporal.h"
#include "froxel_fog/froxel_shared.h"

#include <vector>

namespace postfx::froxel_fog {

// The froxel fog's resources, as the frame plan names them.
inline constexpr core::ResourceId kNoise{"froxel_fog.noise"};             // generated noise (persistent)
inline constexpr core::ResourceId kNoNoise{"froxel_fog.no_noise"};        // 1-texel stand-in, noise off
inline constexpr core::ResourceId kUniforms{"froxel_fog.uniforms"};       // FogUniforms + FroxelUniforms
inline constexpr core::ResourceId kLights{"froxel_fog.lights"};           // FroxelLights
inline constexpr core::ResourceId kLightLists{"froxel_fog.light_lists"};  // r32ui cluster light bits
inline constexpr core::ResourceId kScatter{"froxel_fog.scatter"};         // rgba16f (albedo·light, σt)
inline constexpr core::ResourceId kIntegrated{"froxel_fog.integrated"};   // rgba16f (L, T) per slice end
// Temporal accumulation (froxel-fog.md#temporal): the scatter volume becomes two, read and written in
// turn (the accumulated one replaces froxel_fog.scatter), and the TemporalUniforms.
inline constexpr core::ResourceId kHistory[2] = {{"froxel_fog.history_a"}, {"froxel_fog.history_b"}};
inline constexpr core::ResourceId kTemporalUniforms{"froxel_fog.temporal_uniforms"};
// Local lights' shadows (froxel-fog.md#local-light-shadows): their faces (a storage buffer), and with
// temporal accumulation the shadowed lights' light at the centre of each block of 2×2×2 froxels, this
// frame's and the last's, and the blocks where it changed (rgba8, 1 or 0).
inline constexpr core::ResourceId kShadowFaces{"froxel_fog.shadow_faces"};
inline constexpr core::ResourceId kShadowedLight[2] = {{"froxel_fog.shadowed_light_a"},
                                                       {"froxel_fog.shadowed_light_b"}};
inline constexpr core::ResourceId kShadowChange{"froxel_fog.shadow_change"};

class FroxelFogEffect final : public core::Effect {
public:
    explicit FroxelFogEffect(const core::Gpu& gpu);

    const char* name() const override { return "froxel_fog"; }
    Status validate(const FrameInfo& frame) const override;
    // Enabled, with a shared medium that is not empty or a fog volume that holds some density.
    bool active(const FrameInfo& frame) const override;
    // The noise's wind and the fog volumes (copied) in postfx's frame.
    void toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                       core::WorldScratch& scratch) const override;
    Status declare(core::FrameBuilder& builder) const override;
    // The scatter pass's variants the lights select frame by frame: none, a loop over them, light lists,
    // each with the local lights' shadows when the frame has an atlas with shadows.
    void prewarmVariants(const FrameInfo& frame, core::PrewarmVariants& out) const override;
    void recorded(const FrameInfo& frame, bool active) override;

private:
    bool noiseFormatSupported_ = false;
    core::TemporalHistory history_;
    float previousStorageScale_ = 1.0f;  // the last recorded frame's storageScale
    bool previousShadowed_ = false;      // the last recorded frame wrote its shadowed lights' light
    // declare()'s scratch for the shadow faces (kept: no allocation once warm).
    mutable std::vector<gpu::FroxelShadowFace> faces_;
};

}  // namespace postfx::froxel_fog
