#include "fog/fog_effect.h"

#include "core/checks.h"
#include "fog/fog_settings.h"
#include "fog/fog_uniforms.h"
#include "fog/medium_noise.h"
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
constexpr core::Binding kRaymarchBindings[] = {kColorIn,   kColorOut,     kDepth,
                                               kShadowMap, kNoiseTexture, kUniformBuffer};
constexpr core::Binding kReducedBindings[] = {kDepth, kShadowMap, kNoiseTexture, kUniformBuffer,
                                              kScatterImage};
constexpr core::Binding kUpsampleBindings[] = {kColorIn, kColorOut, kDepth, kUniformBuffer, kScatterImage};
constexpr core::Binding kNoiseBindings[] = {{gpu::kNoiseBindingTexture, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};

// Each color-writing kernel has an RGBA16F and an RGBA32F variant (the color format).
const core::ComputePipelineDesc kRaymarch[2] = {
    {"fog.raymarch", spirv::fog_raymarch_comp, kRaymarchBindings},
    {"fog.raymarch", spirv::fog_raymarch_comp_COLOR_RGBA32F, kRaymarchBindings}};
const core::ComputePipelineDesc kRaymarchReduced[2] = {
    {"fog.raymarch", spirv::fog_raymarch_reduced_comp, kReducedBindings},
    {"fog.raymarch", spirv::fog_raymarch_reduced_comp_COLOR_RGBA32F, kReducedBindings}};
const core::ComputePipelineDesc kUpsample[2] = {
    {"fog.upsample", spirv::fog_upsample_comp, kUpsampleBindings},
    {"fog.upsample", spirv::fog_upsample_comp_COLOR_RGBA32F, kUpsampleBindings}};
const core::ComputePipelineDesc kNoiseGenerate{"fog.noise", spirv::fog_noise_generate_comp, kNoiseBindings,
                                               sizeof(gpu::NoisePush)};

uint32_t groupsFor(uint32_t size) {
    return (size + gpu::kFogGroupSize - 1) / gpu::kFogGroupSize;
}

}  // namespace

FogEffect::FogEffect(const core::Gpu& gpu) : noiseFormatSupported_(noiseFormatSupported(gpu)) {}

Status FogEffect::validate(const FrameInfo& frame) const {
    if (!frame.fog.enabled) return Status::success();
    if (Status s = validateSettings(frame.fog); !s) return s;
    if (Status s = checkNoiseSupported(frame.fog.noise, noiseFormatSupported_, "fog"); !s) return s;
    return Status::success();
}

bool FogEffect::active(const FrameInfo& frame) const {
    return frame.fog.enabled && !fogMediumEmpty(frame.fog, frame.fog.noise.enabled);
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

    const core::ImageRef noiseImage = declareNoise(b, noise, {kNoise, kNoNoise, kNoiseGenerate});
    core::ImageRef scatter;
    if (reduced) {
        core::ImageDesc desc;
        desc.format = frame.color.format;
        desc.extent = {march.x, march.y, 1};
        desc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
        scatter = b.transientImage(kScatter, desc);
    }
    const gpu::FogUniforms u = buildUniforms(frame, b.depthConvention(), noise.enabled, shadowRead);
    const core::BufferRef uniforms = b.uniforms(kUniforms, &u, sizeof u);

    const core::ImageRef depth = b.host(HostImage::Depth);
    // Without a shadow map read, the depth image stands in at its binding (never sampled: the flag is off).
    const core::ImageRef shadow = shadowRead ? b.host(HostImage::ShadowMap) : depth;
    const Use shadowUse = shadowRead ? Use::Sampled : Use::BoundOnly;
    const Use noiseUse = noise.enabled ? Use::Sampled : Use::BoundOnly;
    // Resolution scale: march into the scatter image at the reduced size, then upsample into color; at
    // full size one pass marches and composites.
    if (!reduced) {
        const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
        b.pass(kRaymarch[rgba32], groupsFor(full.x), groupsFor(full.y), 1)
            .bind(gpu::kFogBindingColorIn, source, Use::StorageRead)
            .bind(gpu::kFogBindingDepth, depth, Use::Sampled)
            .bind(gpu::kFogBindingShadowMap, shadow, shadowUse)
            .bind(gpu::kFogBindingNoise, noiseImage, noiseUse, SamplerKind::LinearRepeat)
            .bind(gpu::kFogBindingUniforms, uniforms)
            .bind(gpu::kFogBindingColorOut, target, Use::StorageWrite);
        return Status::success();
    }
    b.pass(kRaymarchReduced[rgba32], groupsFor(march.x), groupsFor(march.y), 1)
        .bind(gpu::kFogBindingDepth, depth, Use::Sampled)
        .bind(gpu::kFogBindingShadowMap, shadow, shadowUse)
        .bind(gpu::kFogBindingNoise, noiseImage, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kFogBindingUniforms, uniforms)
        .bind(gpu::kFogBindingScatter, scatter, Use::StorageWrite);
    const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
    b.pass(kUpsample[rgba32], groupsFor(full.x), groupsFor(full.y), 1)
        .bind(gpu::kFogBindingColorIn, source, Use::StorageRead)
        .bind(gpu::kFogBindingDepth, depth, Use::Sampled)
        .bind(gpu::kFogBindingScatter, scatter, Use::StorageRead)
        .bind(gpu::kFogBindingUniforms, uniforms)
        .bind(gpu::kFogBindingColorOut, target, Use::StorageWrite);
    return Status::success();
}

}  // namespace postfx::fog
