#include "fog/fog_effect.h"

#include "common/cloud_shadow.h"
#include "common/medium.h"
#include "common/medium_noise.h"
#include "common/shared_resources.h"
#include "core/checks.h"
#include "core/lookup_volume.h"
#include "core/settings_check.h"
#include "fog/fog_settings.h"
#include "fog/fog_uniforms.h"
#include "postfx_objects_spirv.h"

namespace postfx::fog {
namespace {

using core::HostImage;
using core::SamplerKind;
using core::Use;

// Each kernel's descriptor layout: exactly the bindings it reads or writes (fog_shared.h).
constexpr core::Binding kColorIn{gpu::kFogBindingColorIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kColorOut{gpu::kFogBindingColorOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kDepth{gpu::kFogBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
constexpr core::Binding kShadowMap{gpu::kFogBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
constexpr core::Binding kNoiseTexture{gpu::kFogBindingNoise, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
constexpr core::Binding kUniformBuffer{gpu::kFogBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
constexpr core::Binding kScatterImage{gpu::kFogBindingScatter, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kAtmosphere{gpu::kMediumBindingAtmosphere, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
constexpr core::Binding kCloudShadow{gpu::kMediumBindingCloudShadow,
                                     VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
constexpr core::Binding kRaymarchBindings[] = {kColorIn,      kColorOut,      kDepth,      kShadowMap,
                                               kNoiseTexture, kUniformBuffer, kAtmosphere, kCloudShadow};
constexpr core::Binding kReducedBindings[] = {kDepth,        kShadowMap,  kNoiseTexture, kUniformBuffer,
                                              kScatterImage, kAtmosphere, kCloudShadow};
constexpr core::Binding kDistance{gpu::kFogBindingDistance, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kReducedTemporalBindings[] = {
    kDepth, kShadowMap, kNoiseTexture, kUniformBuffer, kScatterImage, kDistance, kAtmosphere, kCloudShadow};
constexpr core::Binding kUpsampleBindings[] = {kColorIn, kColorOut, kDepth, kUniformBuffer, kScatterImage};
constexpr core::Binding kHistoryIn{gpu::kFogBindingHistoryIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kHistoryOut{gpu::kFogBindingHistoryOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kDistanceIn{gpu::kFogBindingDistanceIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
constexpr core::Binding kTemporalBuffer{gpu::kFogBindingTemporal, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
constexpr core::Binding kTemporalBindings[] = {kUniformBuffer, kScatterImage, kHistoryIn,     kHistoryOut,
                                               kDistanceIn,    kDistance,     kTemporalBuffer};
// At full size the temporal pass also composites: the temporal bindings and the color images.
constexpr core::Binding kTemporalCompositeBindings[] = {kColorIn,      kColorOut,  kUniformBuffer,
                                                        kScatterImage, kHistoryIn, kHistoryOut,
                                                        kDistanceIn,   kDistance,  kTemporalBuffer};
constexpr core::Binding kLookupBindings[] = {kShadowMap,
                                             kNoiseTexture,
                                             kUniformBuffer,
                                             kAtmosphere,
                                             kCloudShadow,
                                             core::kLookupUniformsBinding,
                                             core::kLookupScatteringBinding,
                                             core::kLookupTransmittanceBinding};
constexpr core::Binding kNoiseBindings[] = {{gpu::kNoiseBindingTexture, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};

// Each color-writing kernel has an RGBA16F and an RGBA32F variant (the color format).
// The volumetrics lookup's part (core/lookup_volume.h).
const core::ComputePipelineDesc kLookupPass{"fog.lookup", spirv::fog_lookup_comp, kLookupBindings,
                                            core::kLookupPushBytes};
const core::ComputePipelineDesc kRaymarch[2] = {
    {"fog.raymarch", spirv::fog_raymarch_comp, kRaymarchBindings},
    {"fog.raymarch", spirv::fog_raymarch_comp_COLOR_RGBA32F, kRaymarchBindings}};
// [temporal][rgba32]: with temporal the march also stores each texel's ray-end distance.
const core::ComputePipelineDesc kRaymarchReduced[2][2] = {
    {{"fog.raymarch", spirv::fog_raymarch_reduced_comp, kReducedBindings},
     {"fog.raymarch", spirv::fog_raymarch_reduced_comp_COLOR_RGBA32F, kReducedBindings}},
    {{"fog.raymarch", spirv::fog_raymarch_reduced_comp_TEMPORAL, kReducedTemporalBindings},
     {"fog.raymarch", spirv::fog_raymarch_reduced_comp_COLOR_RGBA32F_TEMPORAL, kReducedTemporalBindings}}};
// [0]: RGBA16F color, [1]: RGBA32F color, [2]: RGBA16F color from an RGBA32F temporal history.
const core::ComputePipelineDesc kUpsample[3] = {
    {"fog.upsample", spirv::fog_upsample_comp, kUpsampleBindings},
    {"fog.upsample", spirv::fog_upsample_comp_COLOR_RGBA32F, kUpsampleBindings},
    {"fog.upsample", spirv::fog_upsample_comp_SCATTER_RGBA32F, kUpsampleBindings}};
// [composite][rgba32]: at full size the temporal pass composites the accumulation itself.
const core::ComputePipelineDesc kTemporal[2][2] = {
    {{"fog.temporal", spirv::fog_temporal_comp, kTemporalBindings},
     {"fog.temporal", spirv::fog_temporal_comp_COLOR_RGBA32F, kTemporalBindings}},
    {{"fog.temporal", spirv::fog_temporal_comp_COMPOSITE, kTemporalCompositeBindings},
     {"fog.temporal", spirv::fog_temporal_comp_COLOR_RGBA32F_COMPOSITE, kTemporalCompositeBindings}}};
const core::ComputePipelineDesc kNoiseGenerate{"fog.noise", spirv::common_noise_generate_comp, kNoiseBindings,
                                               sizeof(gpu::NoisePush)};

uint32_t groupsFor(uint32_t size, uint32_t groupSize = gpu::kFogGroupSize) {
    return (size + groupSize - 1) / groupSize;
}

}  // namespace

core::PipelineConstants marchConstants(const gpu::FogUniforms& u) {
    // The radius only matters with the shadow map read: one pipeline for every kernel without it.
    const bool shadowMap = (u.flags.x & gpu::kFogFlagShadowMap) != 0u;
    core::PipelineConstants c;
    c.values[gpu::kFogConstantFlags] = u.flags.x;
    c.values[gpu::kFogConstantShadowRadius] = shadowMap ? uint32_t(u.shadow.y) : 0u;
    c.count = 2;
    return c;
}

std::vector<MarchPipeline> marchPipelines() {
    return {{"full size", &kRaymarch[0]},
            {"reduced size", &kRaymarchReduced[0][0]},
            {"reduced size, temporal", &kRaymarchReduced[1][0]}};
}

namespace {

// Everything the accumulated (L, T) depends on besides the camera and the light (core/temporal.h).
uint64_t temporalKey(const FrameInfo& frame) {
    using core::hashValue;
    const FogSettings& s = frame.fog;
    uint64_t h = core::hashSettings(core::kHashSeed, fogSettingsTable(), &s);  // the table's history fields
    h = hashValue(h, frame.color.extent.width);
    h = hashValue(h, frame.color.extent.height);
    h = hashValue(h, frame.color.format);
    return hashValue(h, common::castsCloudShadows(frame));  // the sun's light under the clouds
}

}  // namespace

FogEffect::FogEffect(const core::Gpu& gpu) : noiseFormatSupported_(common::noiseFormatSupported(gpu)) {}

Status FogEffect::validate(const FrameInfo& frame) const {
    if (!frame.fog.enabled) return Status::success();
    if (Status s = validateSettings(frame.fog); !s) return s;
    if (Status s = common::checkNoiseSupported(frame.fog.noise, noiseFormatSupported_, "FrameInfo.fog"); !s)
        return s;
    return Status::success();
}

void FogEffect::toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                              core::WorldScratch&) const {
    common::mediumToPostfx(world, frame.fog);
}

bool FogEffect::active(const FrameInfo& frame) const {
    return frame.fog.enabled && !common::fogMediumEmpty(frame.fog, frame.fog.noise.enabled);
}

core::QualityRequest FogEffect::quality(const FrameInfo& frame) const {
    const FogQuality q = frame.fog.quality;
    if (q == FogQuality::Custom) return {};
    if (q == FogQuality::Auto) return {core::QualityRequest::Kind::Auto, 0, frame.fog.autoBudgetMs};
    // A value cast from another int: left as it is, for validateSettings to reject naming fog.quality.
    if (uint32_t(q) > uint32_t(FogQuality::Auto)) return {};
    return {core::QualityRequest::Kind::Preset, uint32_t(q) - uint32_t(FogQuality::Low), 0.0f};
}

void FogEffect::applyPreset(FrameInfo& frame, uint32_t preset) const {
    const FogQuality q = FogQuality(uint32_t(FogQuality::Low) + preset);
    frame.fog = applyFogQuality(frame.fog, q);
    frame.fog.quality = q;
}

std::vector<double> FogEffect::presetErrors() const {
    return qualityPresetErrors();
}

uint32_t FogEffect::autoFeatures(const FrameInfo& frame) const {
    return (frame.fog.noise.enabled ? kFogAutoFeatureNoise : 0u) |
           (frame.shadowMap.image.present() ? kFogAutoFeatureShadowMap : 0u);
}

Status FogEffect::declare(core::FrameBuilder& b) const {
    const FrameInfo& frame = b.frame();
    const FogNoiseSettings& noise = frame.fog.noise;
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;
    // The shadow map only matters to the sun's term: with no sunlight it is not read.
    const Vec3 e = frame.sun.illuminance;
    const bool shadowRead = frame.shadowMap.image.present() && (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f);
    const glm::uvec2 full{frame.color.extent.width, frame.color.extent.height};
    const glm::uvec2 march = fogMarchExtent(full.x, full.y, frame.fog.resolutionScale);
    const bool reduced = march != full;

    const bool temporal = frame.fog.temporal.enabled;

    const core::DepthInput depthInput = b.depthInput();
    const core::ImageRef noiseImage =
        common::declareNoise(b, noise, {kNoise, kNoNoise, kNoiseGenerate, "fog.noise.texture_size"});
    core::ImageDesc marchDesc;
    // The composite's format (postfx.target's when the host's color is another: core/target.h).
    marchDesc.format = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                           : VK_FORMAT_R16G16B16A16_SFLOAT;
    marchDesc.extent = {march.x, march.y, 1};
    marchDesc.sizedBy = "fog.resolution_scale";  // and the color extent
    marchDesc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    gpu::FogUniforms u = buildUniforms(frame, b.depthConvention(), noise.enabled, shadowRead);
    if (depthInput.distance) u.flags.x |= gpu::kFogFlagViewDistance;
    const core::BufferRef uniforms = b.uniforms(kUniforms, &u, sizeof u);

    const core::ImageRef depth = b.host(HostImage::Depth);
    // Without a shadow map read, the depth image stands in at its binding (never sampled: the flag is off).
    const core::ImageRef shadow = shadowRead ? b.host(HostImage::ShadowMap) : depth;
    const Use shadowUse = shadowRead ? Use::Sampled : Use::BoundOnly;
    const Use noiseUse = noise.enabled ? Use::Sampled : Use::BoundOnly;
    const core::OptionalSampled sunLut = common::sampledOrStandIn(b, common::kSunTransmittanceLut, depth);
    const core::OptionalSampled cloudShadow = common::sampledOrStandIn(b, common::kCloudShadowMap, depth);
    if (const core::LookupTarget lookup = b.lookupTarget(); lookup.valid()) {
        uint32_t g[3];
        core::lookupGroups(lookup, true, g);
        b.pass(kLookupPass, g[0], g[1], 1)
            .constants(marchConstants(u))
            .bind(gpu::kFogBindingShadowMap, shadow, shadowUse)
            .bind(gpu::kFogBindingNoise, noiseImage, noiseUse, SamplerKind::LinearRepeat)
            .bind(gpu::kFogBindingUniforms, uniforms)
            .bind(gpu::kMediumBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler)
            .bind(gpu::kMediumBindingCloudShadow, cloudShadow.image, cloudShadow.use, cloudShadow.sampler);
        core::bindLookup(b, lookup);
    }
    // Full size without temporal: one pass marches and composites.
    if (!reduced && !temporal) {
        const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
        b.pass(kRaymarch[rgba32], groupsFor(full.x, gpu::kFogMarchGroupX),
               groupsFor(full.y, gpu::kFogMarchGroupY), 1)
            .constants(marchConstants(u))
            .bind(gpu::kFogBindingColorIn, source, Use::StorageRead)
            .bind(gpu::kFogBindingDepth, depthInput.image, Use::Sampled)
            .bind(gpu::kFogBindingShadowMap, shadow, shadowUse)
            .bind(gpu::kFogBindingNoise, noiseImage, noiseUse, SamplerKind::LinearRepeat)
            .bind(gpu::kFogBindingUniforms, uniforms)
            .bind(gpu::kMediumBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler)
            .bind(gpu::kMediumBindingCloudShadow, cloudShadow.image, cloudShadow.use, cloudShadow.sampler)
            .bind(gpu::kFogBindingColorOut, target, Use::StorageWrite);
        return Status::success();
    }
    // Otherwise: march into the scatter image at the march's size, accumulate it (temporal; at full size
    // that pass composites too), then upsample into color.
    const core::ImageRef scatter = b.transientImage(kScatter, marchDesc);
    core::TemporalFrame t;
    core::ImageRef history[2], distance[2];
    if (temporal) {
        t = history_.decide(frame, frame.fog.temporal, temporalKey(frame), false);
        core::ImageDesc historyDesc = marchDesc;  // RGBA32F: accumulated in half, small updates would be lost
        historyDesc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        core::ImageDesc distanceDesc = marchDesc;
        distanceDesc.format = VK_FORMAT_R32_SFLOAT;
        for (int i = 0; i < 2; ++i) {
            history[i] = b.historyImage(kHistory[i], historyDesc);
            distance[i] = b.historyImage(kHistoryDistance[i], distanceDesc);
        }
    }
    b.pass(kRaymarchReduced[temporal][rgba32], groupsFor(march.x, gpu::kFogMarchGroupX),
           groupsFor(march.y, gpu::kFogMarchGroupY), 1)
        .constants(marchConstants(u))
        .bind(gpu::kFogBindingDepth, depthInput.image, Use::Sampled)
        .bind(gpu::kFogBindingShadowMap, shadow, shadowUse)
        .bind(gpu::kFogBindingNoise, noiseImage, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kFogBindingUniforms, uniforms)
        .bind(gpu::kMediumBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler)
        .bind(gpu::kMediumBindingCloudShadow, cloudShadow.image, cloudShadow.use, cloudShadow.sampler)
        .bind(gpu::kFogBindingScatter, scatter, Use::StorageWrite);
    core::ImageRef result = scatter;
    if (temporal) {
        // The march stores this frame's distances in the slot written this frame (the next one's "in").
        b.bind(gpu::kFogBindingDistance, distance[t.writeSlot], Use::StorageWrite);
        const gpu::TemporalUniforms tu = core::temporalUniforms(t);
        const core::BufferRef temporalUniforms = b.uniforms(kTemporalUniforms, &tu, sizeof tu);
        b.pass(kTemporal[!reduced][rgba32], groupsFor(march.x), groupsFor(march.y), 1)
            .bind(gpu::kFogBindingUniforms, uniforms)
            .bind(gpu::kFogBindingScatter, scatter, Use::StorageRead)
            .bind(gpu::kFogBindingDistance, distance[t.writeSlot], Use::StorageRead)
            .bind(gpu::kFogBindingHistoryIn, history[t.readSlot], Use::StorageRead)
            .bind(gpu::kFogBindingDistanceIn, distance[t.readSlot], Use::StorageRead)
            .bind(gpu::kFogBindingTemporal, temporalUniforms)
            .bind(gpu::kFogBindingHistoryOut, history[t.writeSlot], Use::StorageWrite);
        result = history[t.writeSlot];
        if (!reduced) {  // composited in the same pass
            b.bind(gpu::kFogBindingColorIn, b.compositeSource(), Use::StorageRead)
                .bind(gpu::kFogBindingColorOut, b.compositeTarget(), Use::StorageWrite);
            return Status::success();
        }
    }
    const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
    b.pass(kUpsample[temporal && !rgba32 ? 2 : rgba32], groupsFor(full.x), groupsFor(full.y), 1)
        .bind(gpu::kFogBindingColorIn, source, Use::StorageRead)
        .bind(gpu::kFogBindingDepth, depthInput.image, Use::Sampled)
        .bind(gpu::kFogBindingScatter, result, Use::StorageRead)
        .bind(gpu::kFogBindingUniforms, uniforms)
        .bind(gpu::kFogBindingColorOut, target, Use::StorageWrite);
    return Status::success();
}

void FogEffect::recorded(const FrameInfo& frame, bool active) {
    if (active && frame.fog.temporal.enabled)
        history_.recorded(frame, frame.fog.temporal, temporalKey(frame), false);
    else
        history_.dropped();
}

}  // namespace postfx::fog
