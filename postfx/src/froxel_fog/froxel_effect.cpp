#include "froxel_fog/froxel_effect.h"

#include "common/cloud_shadow.h"
#include "common/medium.h"
#include "common/medium_noise.h"
#include "common/shared_resources.h"
#include "core/lookup_volume.h"
#include "core/settings_check.h"
#include "froxel_fog/froxel_settings.h"
#include "froxel_fog/froxel_uniforms.h"
#include "postfx_objects_spirv.h"

#include <algorithm>
#include <memory>

namespace postfx::froxel_fog {
namespace {

using core::HostImage;
using core::SamplerKind;
using core::Use;

constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorageBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

// Each kernel's descriptor layout: exactly the bindings it reads or writes (froxel_shared.h).
constexpr core::Binding kColorIn{gpu::kFroxelBindingColorIn, kStorage};
constexpr core::Binding kColorOut{gpu::kFroxelBindingColorOut, kStorage};
constexpr core::Binding kDepth{gpu::kFroxelBindingDepth, kSampled};
constexpr core::Binding kShadowMap{gpu::kFroxelBindingShadowMap, kSampled};
constexpr core::Binding kNoiseTexture{gpu::kFroxelBindingNoise, kSampled};
constexpr core::Binding kUniformBuffer{gpu::kFroxelBindingUniforms, kUniform};
constexpr core::Binding kLightBuffer{gpu::kFroxelBindingLights, kUniform};
constexpr core::Binding kLightListImage{gpu::kFroxelBindingLightLists, kStorage};
constexpr core::Binding kScatterImage{gpu::kFroxelBindingScatter, kStorage};
constexpr core::Binding kIntegratedImage{gpu::kFroxelBindingIntegrated, kStorage};
constexpr core::Binding kIntegratedSampled{gpu::kFroxelBindingIntegrated, kSampled};

constexpr core::Binding kAtmosphere{gpu::kFroxelBindingAtmosphere, kSampled};
constexpr core::Binding kCloudShadow{gpu::kFroxelBindingCloudShadow, kSampled};

constexpr core::Binding kLightListBindings[] = {kUniformBuffer, kLightBuffer, kLightListImage};
constexpr core::Binding kScatterBindings[] = {kShadowMap,    kNoiseTexture, kUniformBuffer,
                                              kScatterImage, kAtmosphere,   kCloudShadow};
constexpr core::Binding kScatterLightBindings[] = {kShadowMap,    kNoiseTexture, kUniformBuffer, kLightBuffer,
                                                   kScatterImage, kAtmosphere,   kCloudShadow};
constexpr core::Binding kScatterListBindings[] = {kShadowMap,   kNoiseTexture,   kUniformBuffer,
                                                  kLightBuffer, kLightListImage, kScatterImage,
                                                  kAtmosphere,  kCloudShadow};
// With temporal accumulation: the history volume and the temporal uniforms too.
constexpr core::Binding kHistorySampled{gpu::kFroxelBindingHistory, kSampled};
constexpr core::Binding kTemporalBuffer{gpu::kFroxelBindingTemporal, kUniform};
constexpr core::Binding kScatterTemporalBindings[] = {kShadowMap,    kNoiseTexture,   kUniformBuffer,
                                                      kScatterImage, kHistorySampled, kTemporalBuffer,
                                                      kAtmosphere,   kCloudShadow};
constexpr core::Binding kScatterLightTemporalBindings[] = {kShadowMap,      kNoiseTexture, kUniformBuffer,
                                                           kLightBuffer,    kScatterImage, kHistorySampled,
                                                           kTemporalBuffer, kAtmosphere,   kCloudShadow};
constexpr core::Binding kScatterListTemporalBindings[] = {
    kShadowMap,    kNoiseTexture,   kUniformBuffer,  kLightBuffer, kLightListImage,
    kScatterImage, kHistorySampled, kTemporalBuffer, kAtmosphere,  kCloudShadow};
// With local lights' shadows: the atlas and the faces; temporal: the shadowed light's two volumes.
constexpr core::Binding kShadowAtlas{gpu::kFroxelBindingShadowAtlas, kSampled};
constexpr core::Binding kShadowFaceBuffer{gpu::kFroxelBindingShadowFaces, kStorageBuffer};
constexpr core::Binding kShadowedImage{gpu::kFroxelBindingShadowedLight, kStorage};
constexpr core::Binding kShadowedSampled{gpu::kFroxelBindingShadowedHistory, kSampled};
constexpr core::Binding kShadowChangeImage{gpu::kFroxelBindingShadowChange, kStorage};
constexpr core::Binding kShadowChangeSampled{gpu::kFroxelBindingShadowChange, kSampled};
constexpr core::Binding kScatterLightShadowBindings[] = {kShadowMap,   kNoiseTexture, kUniformBuffer,
                                                         kLightBuffer, kScatterImage, kAtmosphere,
                                                         kCloudShadow, kShadowAtlas,  kShadowFaceBuffer};
constexpr core::Binding kScatterListShadowBindings[] = {
    kShadowMap,    kNoiseTexture, kUniformBuffer, kLightBuffer, kLightListImage,
    kScatterImage, kAtmosphere,   kCloudShadow,   kShadowAtlas, kShadowFaceBuffer};
constexpr core::Binding kScatterLightShadowTemporalBindings[] = {
    kShadowMap,      kNoiseTexture, kUniformBuffer, kLightBuffer,      kScatterImage,        kHistorySampled,
    kTemporalBuffer, kAtmosphere,   kCloudShadow,   kShadowFaceBuffer, kShadowChangeSampled, kShadowAtlas};
constexpr core::Binding kScatterListShadowTemporalBindings[] = {
    kShadowMap,    kNoiseTexture,     kUniformBuffer,      kLightBuffer, kLightListImage,
    kScatterImage, kHistorySampled,   kTemporalBuffer,     kAtmosphere,  kCloudShadow,
    kShadowAtlas,  kShadowFaceBuffer, kShadowChangeSampled};
// The shadow-change pass (looping over every light, with light lists).
constexpr core::Binding kShadowChangeLightBindings[] = {kUniformBuffer,   kLightBuffer,      kTemporalBuffer,
                                                        kShadowAtlas,     kShadowFaceBuffer, kShadowedImage,
                                                        kShadowedSampled, kShadowChangeImage};
constexpr core::Binding kShadowChangeListBindings[] = {kUniformBuffer,  kLightBuffer,     kLightListImage,
                                                       kTemporalBuffer, kShadowAtlas,     kShadowFaceBuffer,
                                                       kShadowedImage,  kShadowedSampled, kShadowChangeImage};
constexpr core::Binding kIntegrateBindings[] = {kUniformBuffer, kScatterImage, kIntegratedImage};
constexpr core::Binding kApplyBindings[] = {kColorIn,       kColorOut,          kDepth,
                                            kUniformBuffer, kIntegratedSampled, kAtmosphere};
constexpr core::Binding kLookupBindings[] = {kUniformBuffer,
                                             kIntegratedSampled,
                                             kAtmosphere,
                                             core::kLookupUniformsBinding,
                                             core::kLookupScatteringBinding,
                                             core::kLookupTransmittanceBinding};
constexpr core::Binding kNoiseBindings[] = {{gpu::kNoiseBindingTexture, kStorage}};

const core::ComputePipelineDesc kLightListPass{"froxel_fog.light_lists", spirv::froxel_fog_light_lists_comp,
                                               kLightListBindings};
// Scatter without local lights, looping over every light, and with light lists.
const core::ComputePipelineDesc kScatterPass[3] = {
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp, kScatterBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LOCAL_LIGHTS, kScatterLightBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LIGHT_LISTS, kScatterListBindings}};
// The same, accumulating temporally.
const core::ComputePipelineDesc kScatterTemporalPass[3] = {
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_TEMPORAL, kScatterTemporalBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LOCAL_LIGHTS_TEMPORAL,
     kScatterLightTemporalBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LIGHT_LISTS_TEMPORAL,
     kScatterListTemporalBindings}};
// With local lights' shadows (looping over every light, with light lists), and accumulating temporally.
const core::ComputePipelineDesc kScatterShadowPass[2] = {
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LOCAL_LIGHTS_LOCAL_SHADOWS,
     kScatterLightShadowBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LIGHT_LISTS_LOCAL_SHADOWS,
     kScatterListShadowBindings}};
const core::ComputePipelineDesc kScatterShadowTemporalPass[2] = {
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LOCAL_LIGHTS_LOCAL_SHADOWS_TEMPORAL,
     kScatterLightShadowTemporalBindings},
    {"froxel_fog.scatter", spirv::froxel_fog_scatter_comp_LIGHT_LISTS_LOCAL_SHADOWS_TEMPORAL,
     kScatterListShadowTemporalBindings}};
const core::ComputePipelineDesc kShadowChangePass[2] = {
    {"froxel_fog.shadow_change", spirv::froxel_fog_shadow_change_comp_LOCAL_LIGHTS,
     kShadowChangeLightBindings},
    {"froxel_fog.shadow_change", spirv::froxel_fog_shadow_change_comp_LIGHT_LISTS,
     kShadowChangeListBindings}};
// [1]: integrating the RGBA32F temporal history.
const core::ComputePipelineDesc kIntegratePass[2] = {
    {"froxel_fog.integrate", spirv::froxel_fog_integrate_comp, kIntegrateBindings},
    {"froxel_fog.integrate", spirv::froxel_fog_integrate_comp_SCATTER_RGBA32F, kIntegrateBindings}};
// The apply pass in the color format: RGBA16F and RGBA32F.
const core::ComputePipelineDesc kApplyPass[2] = {
    {"froxel_fog.apply", spirv::froxel_fog_apply_comp, kApplyBindings},
    {"froxel_fog.apply", spirv::froxel_fog_apply_comp_COLOR_RGBA32F, kApplyBindings}};
// The volumetrics lookup's part (core/lookup_volume.h).
const core::ComputePipelineDesc kLookupPass{"froxel_fog.lookup", spirv::froxel_fog_lookup_comp,
                                            kLookupBindings, core::kLookupPushBytes};
const core::ComputePipelineDesc kNoiseGenerate{"froxel_fog.noise", spirv::common_noise_generate_comp,
                                               kNoiseBindings, sizeof(gpu::NoisePush)};

uint32_t groupsFor(uint32_t size, uint32_t groupSize = gpu::kFroxelGroupSize) {
    return (size + groupSize - 1) / groupSize;
}

// Whether a lit local light has a shadow in a given atlas (the scatter pass then reads it).
bool readsLocalShadows(const FrameInfo& frame) {
    if (!frame.localShadows.image.present()) return false;
    for (uint32_t i = 0; i < frame.lightCount; ++i) {
        const LocalLight& l = frame.lights[i];
        if (l.shadow != kNoLocalShadow && l.intensity != Vec3(0.0f)) return true;
    }
    return false;
}

bool volumesHoldDensity(const FroxelFogSettings& s) {
    for (uint32_t i = 0; i < s.volumeCount; ++i) {
        const FogVolume& v = s.volumes[i];
        const bool sized = v.shape == FogVolumeShape::Sphere
                               ? v.radius > 0.0f
                               : v.halfSize.x > 0.0f && v.halfSize.y > 0.0f && v.halfSize.z > 0.0f;
        if (v.density > 0.0f && sized) return true;
    }
    return false;
}

// Everything the accumulated volume depends on besides the camera and the lights (core/temporal.h): the
// medium, the grid, the fog volumes.
uint64_t temporalKey(const FrameInfo& frame) {
    using core::hashValue;
    const FroxelFogSettings& s = frame.froxelFog;
    uint64_t h =
        core::hashSettings(core::kHashSeed, froxelFogSettingsTable(), &s);  // the table's history fields
    const UVec3 grid = froxelGridSize(s, frame.color.extent.width, frame.color.extent.height);
    for (int a = 0; a < 3; ++a)
        h = hashValue(h, grid[a]);
    h = hashValue(h, common::castsCloudShadows(frame));  // the sun's light under the clouds
    h = hashValue(h, s.volumeCount);
    for (uint32_t i = 0; i < s.volumeCount; ++i)
        h = core::hashSettings(h, fogVolumeSettingsTable(), &s.volumes[i]);
    return h;
}

}  // namespace

FroxelFogEffect::FroxelFogEffect(const core::Gpu& gpu)
    : noiseFormatSupported_(common::noiseFormatSupported(gpu)) {}

Status FroxelFogEffect::validate(const FrameInfo& frame) const {
    const FroxelFogSettings& s = frame.froxelFog;
    if (!s.enabled) return Status::success();
    if (frame.fog.enabled)
        return {Result::InvalidArgument,
                "FrameInfo.fog.enabled and FrameInfo.froxelFog.enabled: both fogs are on in one frame; they "
                "model the same "
                "medium, so enable one of them (docs/effects/froxel-fog.md)"};
    if (Status r = validateFroxelFogSettings(s); !r) return r;
    if (Status r = checkFroxelTiles(s, frame.color.extent.width, frame.color.extent.height); !r) return r;
    return common::checkNoiseSupported(s.noise, noiseFormatSupported_, "FrameInfo.froxelFog");
}

void FroxelFogEffect::toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                                    core::WorldScratch& scratch) const {
    static constexpr char kVolumesSlot = 'v';
    FroxelFogSettings& s = frame.froxelFog;
    common::mediumToPostfx(world, s);
    if (s.volumeCount == 0) return;
    FogVolume* volumes = scratch.copy(&kVolumesSlot, s.volumes, s.volumeCount);
    for (uint32_t i = 0; i < s.volumeCount; ++i) {
        FogVolume& v = volumes[i];
        v.center = world.position(v.center);
        v.halfSize = world.extent(glm::vec3(v.halfSize));  // an axis-aligned box stays one
        v.radius = float(world.length(v.radius));
        v.edgeFalloff = float(world.length(v.edgeFalloff));
    }
    s.volumes = volumes;
}

bool FroxelFogEffect::active(const FrameInfo& frame) const {
    const FroxelFogSettings& s = frame.froxelFog;
    return s.enabled && (!common::fogMediumEmpty(s, s.noise.enabled) || volumesHoldDensity(s));
}

Status FroxelFogEffect::declare(core::FrameBuilder& b) const {
    const FrameInfo& frame = b.frame();
    const FroxelFogSettings& s = frame.froxelFog;
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;
    const Vec3 e = frame.sun.illuminance;
    const bool shadowRead = frame.shadowMap.image.present() && (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f);
    const UVec3 grid = froxelGridSize(s, frame.color.extent.width, frame.color.extent.height);

    const core::DepthInput depthInput = b.depthInput();
    const core::ImageRef noise =
        common::declareNoise(b, s.noise, {kNoise, kNoNoise, kNoiseGenerate, "froxel_fog.noise.texture_size"});

    // Local lights: their buffer, and the light lists when there are many.
    gpu::FroxelLights lights;
    const uint32_t lightCount = packLights(frame, lights, faces_);
    const bool localShadows = !faces_.empty();
    const bool lists = lightCount > 0 && lightCount >= s.lightListMinLights;
    const uint32_t words = lists ? (lightCount + 31) / 32 : 0;
    PassUniforms u =
        buildPassUniforms(frame, b.depthConvention(), grid, lightCount, words, s.noise.enabled, shadowRead);
    if (depthInput.distance) u.fog.flags.x |= gpu::kFogFlagViewDistance;
    for (uint32_t i = 0; i < lightCount; ++i)
        if (lights.lights[i].shadow.x != gpu::kFroxelNoShadow)
            u.froxel.shadowed[i / 128][i / 32 % 4] |= 1u << (i % 32);

    core::ImageDesc volume;
    volume.type = VK_IMAGE_TYPE_3D;
    volume.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    volume.extent = {grid.x, grid.y, grid.z};
    volume.sizedBy = s.tileSizePx > 0 ? "froxel_fog.tile_size_px" : "froxel_fog.grid";
    volume.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    // The scatter volume: this frame's alone, or (temporal) the accumulated one of two histories.
    const bool temporal = s.temporal.enabled;
    core::ImageRef scatter, history, shadowedOut, shadowedIn, shadowChange;
    core::BufferRef temporalUniforms;
    if (temporal) {
        const core::TemporalFrame t = history_.decide(frame, s.temporal, temporalKey(frame), true);
        gpu::TemporalUniforms tu = core::temporalUniforms(t);
        FrameInfo previous = frame;
        previous.camera = t.previousCamera;
        tu.previous.x = float(gridNear(previous, b.depthConvention()));
        tu.previous.y = t.historyScale * (storageScale(frame) / previousStorageScale_);
        temporalUniforms = b.uniforms(kTemporalUniforms, &tu, sizeof tu);
        // RGBA32F: accumulated in half, updates below half an ulp would be lost.
        core::ImageDesc historyDesc = volume;
        historyDesc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        scatter = b.historyImage(kHistory[t.writeSlot], historyDesc);
        history = b.historyImage(kHistory[t.readSlot], historyDesc);
        if (localShadows) {
            // One texel per block of 2×2×2 froxels (shadow_change.comp).
            core::ImageDesc blockDesc = volume;
            blockDesc.extent = {(grid.x + 1) / 2, (grid.y + 1) / 2, (grid.z + 1) / 2};
            blockDesc.format = VK_FORMAT_R32_SFLOAT;
            shadowedOut = b.historyImage(kShadowedLight[t.writeSlot], blockDesc);
            shadowedIn = b.historyImage(kShadowedLight[t.readSlot], blockDesc);
            blockDesc.format = VK_FORMAT_R8G8B8A8_UNORM;  // a storage format every device has
            shadowChange = b.transientImage(kShadowChange, blockDesc);
            if (t.historyValid && previousShadowed_) u.froxel.counts.y |= gpu::kFroxelFlagShadowedHistory;
        }
    } else {
        core::ImageDesc storageOnly = volume;
        storageOnly.usage = VK_IMAGE_USAGE_STORAGE_BIT;
        scatter = b.transientImage(kScatter, storageOnly);
    }
    const core::ImageRef integrated = b.transientImage(kIntegrated, volume);
    const core::BufferRef uniforms = b.uniforms(kUniforms, &u, sizeof u);
    core::BufferRef lightBuffer, faceBuffer;
    if (lightCount > 0) lightBuffer = b.uniforms(kLights, &lights, sizeof lights);
    if (localShadows)
        faceBuffer =
            b.uniforms(kShadowFaces, faces_.data(), uint32_t(faces_.size() * sizeof(gpu::FroxelShadowFace)));

    const core::ImageRef depth = b.host(HostImage::Depth);
    // Without a shadow map read, the depth image stands in at its binding (never sampled: the flag is off).
    const core::ImageRef shadow = shadowRead ? b.host(HostImage::ShadowMap) : depth;
    const Use shadowUse = shadowRead ? Use::Sampled : Use::BoundOnly;
    const Use noiseUse = s.noise.enabled ? Use::Sampled : Use::BoundOnly;
    const core::OptionalSampled sunLut = common::sampledOrStandIn(b, common::kSunTransmittanceLut, depth);
    const core::OptionalSampled cloudShadow = common::sampledOrStandIn(b, common::kCloudShadowMap, depth);

    core::ImageRef lightLists;
    if (lists) {
        const glm::uvec3 clusters =
            (glm::uvec3(grid.x, grid.y, grid.z) +
             glm::uvec3(gpu::kFroxelClusterSize, gpu::kFroxelClusterSize, gpu::kFroxelClusterSlices) - 1u) /
            glm::uvec3(gpu::kFroxelClusterSize, gpu::kFroxelClusterSize, gpu::kFroxelClusterSlices);
        core::ImageDesc desc;
        desc.type = VK_IMAGE_TYPE_3D;
        desc.format = VK_FORMAT_R32_UINT;
        desc.extent = {clusters.x, clusters.y, clusters.z * words};
        desc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
        desc.sizedBy = volume.sizedBy;
        lightLists = b.transientImage(kLightLists, desc);
        b.pass(kLightListPass, clusters.x, clusters.y, clusters.z * words)  // a group per cluster word
            .bind(gpu::kFroxelBindingUniforms, uniforms)
            .bind(gpu::kFroxelBindingLights, lightBuffer)
            .bind(gpu::kFroxelBindingLightLists, lightLists, Use::StorageWrite);
    }

    if (localShadows && temporal) {
        constexpr uint32_t g = gpu::kFroxelBlockGroupSize;
        b.pass(kShadowChangePass[lists ? 1 : 0], groupsFor((grid.x + 1) / 2, g),
               groupsFor((grid.y + 1) / 2, g), groupsFor((grid.z + 1) / 2, g))
            .bind(gpu::kFroxelBindingUniforms, uniforms)
            .bind(gpu::kFroxelBindingLights, lightBuffer);
        if (lists) b.bind(gpu::kFroxelBindingLightLists, lightLists, Use::StorageRead);
        b.bind(gpu::kFroxelBindingTemporal, temporalUniforms)
            .bind(gpu::kFroxelBindingShadowAtlas, b.host(HostImage::LocalShadowAtlas), Use::Sampled)
            .bind(gpu::kFroxelBindingShadowFaces, faceBuffer)
            .bind(gpu::kFroxelBindingShadowedHistory, shadowedIn, Use::Sampled, SamplerKind::NearestClamp)
            .bind(gpu::kFroxelBindingShadowedLight, shadowedOut, Use::StorageWrite)
            .bind(gpu::kFroxelBindingShadowChange, shadowChange, Use::StorageWrite);
    }

    const uint32_t variant = lists ? 2 : lightCount > 0 ? 1 : 0;
    const core::ComputePipelineDesc& scatterPass =
        localShadows ? (temporal ? kScatterShadowTemporalPass[variant - 1] : kScatterShadowPass[variant - 1])
                     : (temporal ? kScatterTemporalPass[variant] : kScatterPass[variant]);
    b.pass(scatterPass, groupsFor(grid.x), groupsFor(grid.y), grid.z)
        .bind(gpu::kFroxelBindingShadowMap, shadow, shadowUse)
        .bind(gpu::kFroxelBindingNoise, noise, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kFroxelBindingUniforms, uniforms);
    if (lightCount > 0) b.bind(gpu::kFroxelBindingLights, lightBuffer);
    if (lists) b.bind(gpu::kFroxelBindingLightLists, lightLists, Use::StorageRead);
    if (temporal)
        b.bind(gpu::kFroxelBindingHistory, history, Use::Sampled, SamplerKind::NearestClamp)
            .bind(gpu::kFroxelBindingTemporal, temporalUniforms);
    if (localShadows) {
        b.bind(gpu::kFroxelBindingShadowAtlas, b.host(HostImage::LocalShadowAtlas), Use::Sampled)
            .bind(gpu::kFroxelBindingShadowFaces, faceBuffer);
        if (temporal)
            b.bind(gpu::kFroxelBindingShadowChange, shadowChange, Use::Sampled, SamplerKind::LinearClamp);
    }
    b.bind(gpu::kFroxelBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler)
        .bind(gpu::kFroxelBindingCloudShadow, cloudShadow.image, cloudShadow.use, cloudShadow.sampler)
        .bind(gpu::kFroxelBindingScatter, scatter, Use::StorageWrite);

    b.pass(kIntegratePass[temporal ? 1 : 0], groupsFor(grid.x), groupsFor(grid.y), 1)
        .bind(gpu::kFroxelBindingUniforms, uniforms)
        .bind(gpu::kFroxelBindingScatter, scatter, Use::StorageRead)
        .bind(gpu::kFroxelBindingIntegrated, integrated, Use::StorageWrite);

    const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
    b.pass(kApplyPass[rgba32], groupsFor(frame.color.extent.width), groupsFor(frame.color.extent.height), 1)
        .bind(gpu::kFroxelBindingColorIn, source, Use::StorageRead)
        .bind(gpu::kFroxelBindingDepth, depthInput.image, Use::Sampled)
        .bind(gpu::kFroxelBindingUniforms, uniforms)
        .bind(gpu::kFroxelBindingIntegrated, integrated, Use::Sampled, SamplerKind::LinearClamp)
        .bind(gpu::kFroxelBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler)
        .bind(gpu::kFroxelBindingColorOut, target, Use::StorageWrite);

    if (const core::LookupTarget lookup = b.lookupTarget(); lookup.valid()) {
        uint32_t g[3];
        core::lookupGroups(lookup, false, g);
        b.pass(kLookupPass, g[0], g[1], g[2])
            .bind(gpu::kFroxelBindingUniforms, uniforms)
            .bind(gpu::kFroxelBindingIntegrated, integrated, Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kFroxelBindingAtmosphere, sunLut.image, sunLut.use, sunLut.sampler);
        core::bindLookup(b, lookup);
    }
    return Status::success();
}

void FroxelFogEffect::prewarmVariants(const FrameInfo& frame, core::PrewarmVariants& out) const {
    // A lit light: the frame's first (any light counts alike here), else one at the camera.
    LocalLight light;
    light.position = frame.camera.position;
    if (frame.lightCount > 0) light = frame.lights[0];
    if (light.intensity == Vec3(0.0f))
        light.intensity = Vec3(float(std::min(1.0, 1e8 / double(frame.preExposure))));
    const bool shadows = frame.localShadows.image.present() && frame.localShadows.shadowCount > 0;
    const uint32_t listed = std::max(frame.froxelFog.lightListMinLights, 2u);
    for (const uint32_t count : {0u, 1u, listed}) {
        if (count > kMaxLocalLights) continue;
        for (const bool shadowed : {false, true}) {
            if (shadowed && (!shadows || count == 0)) continue;
            light.shadow = shadowed ? 0u : kNoLocalShadow;
            const std::vector<LocalLight>& lights = out.lights.emplace_back(count, light);
            FrameInfo& v = out.frames.emplace_back(frame);
            v.lights = lights.data();
            v.lightCount = count;
        }
    }
}

void FroxelFogEffect::recorded(const FrameInfo& frame, bool active) {
    if (active && frame.froxelFog.temporal.enabled) {
        history_.recorded(frame, frame.froxelFog.temporal, temporalKey(frame), true);
        previousStorageScale_ = storageScale(frame);
        previousShadowed_ = readsLocalShadows(frame);
    } else {
        history_.dropped();
        previousShadowed_ = false;
    }
}

}  // namespace postfx::froxel_fog
