#include "clouds/clouds_effect.h"

#include "clouds/clouds_model.h"
#include "clouds/clouds_settings.h"
#include "clouds/clouds_shadow.h"
#include "common/air.h"
#include "common/cloud_shadow.h"
#include "common/medium_noise.h"
#include "common/reduced_resolution.h"
#include "common/shared_resources.h"
#include "core/camera_math.h"
#include "core/exposure.h"
#include "core/lookup_volume.h"
#include "core/settings_check.h"
#include "postfx_objects_spirv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace postfx::clouds {
namespace {

using core::SamplerKind;
using core::Use;

constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;

// The march's layout has every binding whatever its specialization constants (marchConstants): those a
// frame does not use hold stand-ins, never accessed (shaders/clouds/march.comp).
constexpr core::Binding kMarchBindings[] = {
    {gpu::kCloudBindingUniforms, kUniform},         {gpu::kCloudBindingColorIn, kStorage},
    {gpu::kCloudBindingColorOut, kStorage},         {gpu::kCloudBindingDepth, kSampled},
    {gpu::kCloudBindingBaseNoise, kSampled},        {gpu::kCloudBindingDetailNoise, kSampled},
    {gpu::kCloudBindingCoverageMap, kSampled},      {gpu::kCloudBindingAtmosphere, kUniform},
    {gpu::kCloudBindingTransmittanceLut, kSampled}, {gpu::kCloudBindingApScattering, kSampled},
    {gpu::kCloudBindingApTransmittance, kSampled},  {gpu::kCloudBindingMultiScattering, kSampled},
    {gpu::kCloudBindingScatter, kStorage},          {gpu::kCloudBindingDistance, kStorage}};
constexpr core::Binding kTemporalBindings[] = {
    {gpu::kCloudBindingUniforms, kUniform},   {gpu::kCloudBindingScatter, kStorage},
    {gpu::kCloudBindingDistance, kStorage},   {gpu::kCloudBindingHistoryIn, kStorage},
    {gpu::kCloudBindingHistoryOut, kStorage}, {gpu::kCloudBindingDistanceIn, kStorage},
    {gpu::kCloudBindingTemporal, kUniform},   {gpu::kCloudBindingDepth, kSampled}};
constexpr core::Binding kUpsampleBindings[] = {{gpu::kCloudBindingUniforms, kUniform},
                                               {gpu::kCloudBindingColorIn, kStorage},
                                               {gpu::kCloudBindingColorOut, kStorage},
                                               {gpu::kCloudBindingDepth, kSampled},
                                               {gpu::kCloudBindingScatter, kStorage}};
constexpr core::Binding kShadowBindings[] = {{gpu::kCloudBindingUniforms, kUniform},
                                             {gpu::kCloudBindingBaseNoise, kSampled},
                                             {gpu::kCloudBindingDetailNoise, kSampled},
                                             {gpu::kCloudBindingCoverageMap, kSampled},
                                             {gpu::kCloudBindingShadowOut, kStorage}};
constexpr core::Binding kNoiseBindings[] = {{gpu::kNoiseBindingTexture, kStorage}};

// [rgba32]: a storage image's format is the shader's own (COLOR_RGBA32F), not a specialization constant.
const core::ComputePipelineDesc kMarch[2] = {
    {"clouds.march", spirv::clouds_march_comp, kMarchBindings},
    {"clouds.march", spirv::clouds_march_comp_COLOR_RGBA32F, kMarchBindings}};
const core::ComputePipelineDesc kTemporal[2] = {
    {"clouds.temporal", spirv::clouds_temporal_comp, kTemporalBindings},
    {"clouds.temporal", spirv::clouds_temporal_comp_COLOR_RGBA32F, kTemporalBindings}};
const core::ComputePipelineDesc kShadow{"clouds.shadow", spirv::clouds_shadow_comp, kShadowBindings};
// [0]: RGBA16F color, [1]: RGBA32F color, [2]: RGBA16F color from the RGBA32F temporal history.
const core::ComputePipelineDesc kUpsample[3] = {
    {"clouds.upsample", spirv::clouds_upsample_comp, kUpsampleBindings},
    {"clouds.upsample", spirv::clouds_upsample_comp_COLOR_RGBA32F, kUpsampleBindings},
    {"clouds.upsample", spirv::clouds_upsample_comp_SCATTER_RGBA32F, kUpsampleBindings}};
// The volumetrics lookup's part (core/lookup_volume.h), reading an RGBA16F or RGBA32F march image.
constexpr core::Binding kLookupBindings[] = {
    {gpu::kCloudBindingUniforms, kUniform}, {gpu::kCloudBindingScatter, kStorage},
    {gpu::kCloudBindingDistance, kStorage}, core::kLookupUniformsBinding,
    core::kLookupScatteringBinding,         core::kLookupTransmittanceBinding};
const core::ComputePipelineDesc kLookupPass[2] = {
    {"clouds.lookup", spirv::clouds_lookup_comp, kLookupBindings, core::kLookupPushBytes},
    {"clouds.lookup", spirv::clouds_lookup_comp_SCATTER_RGBA32F, kLookupBindings, core::kLookupPushBytes}};
const core::ComputePipelineDesc kBaseNoisePass{"clouds.base_noise", spirv::common_noise_generate_comp,
                                               kNoiseBindings, sizeof(gpu::NoisePush)};
const core::ComputePipelineDesc kDetailNoisePass{"clouds.detail_noise", spirv::common_noise_generate_comp,
                                                 kNoiseBindings, sizeof(gpu::NoisePush)};

// The texel of each block × block block the march updates in frame `frameIndex` (block 1, 2 or 4): the
// block's texels in the order of the Bayer matrix, so that consecutive frames update texels far apart.
glm::uvec2 sparseOffset(uint32_t block, uint64_t frameIndex) {
    static constexpr uint8_t kBayer2[4] = {0, 2, 3, 1};  // row-major: the frame (mod 4) of each texel
    static constexpr uint8_t kBayer4[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    const uint32_t texels = block * block, n = uint32_t(frameIndex % texels);
    for (uint32_t i = 0; i < texels && block > 1; ++i)
        if ((block == 2 ? kBayer2[i] : kBayer4[i]) == n) return {i % block, i / block};
    return {0u, 0u};
}

// Invocations per marched ray (march.comp's segments, a divisor of kCloudGroupSize): a march of few rays
// (a sparse update at a small size) is split until about kSegmentedInvocations invocations run, so that
// the GPU is not left waiting on each ray's chain of dependent fetches; a march of many rays is not (its
// segments would repeat each ray's setup and march past the cutoff for nothing). Measured on the H200
// (docs/effects/clouds.md, "Resolution and temporal"): 32 400 rays (1920×1080, k = 4) 0.252 → 0.132 ms
// in 4 segments; 129 600 rays (k = 2) no faster in 2.
uint32_t marchSegments(uint32_t rays) {
    constexpr uint32_t kSegmentedInvocations = 131072, kMaxSegments = 8;
    uint32_t segments = 1;
    while (segments < kMaxSegments && uint64_t(rays) * segments * 2 <= kSegmentedInvocations)
        segments *= 2;
    return segments;
}

uint32_t groupsFor(uint32_t size) {
    return (size + gpu::kCloudGroupSize - 1) / gpu::kCloudGroupSize;
}

// The march's specialization constants (clouds_shared.h): a pipeline per combination a frame uses, the
// graph keeping the last 4 (FrameBuilder::constants).
core::PipelineConstants marchConstants(bool atmosphere, bool scatter, bool temporal) {
    core::PipelineConstants c;
    c.values[gpu::kCloudConstantAtmosphere] = atmosphere;
    c.values[gpu::kCloudConstantScatter] = scatter;
    c.values[gpu::kCloudConstantTemporal] = temporal;
    c.count = 3;
    return c;
}

// Everything the shadow map's texels depend on: the field where it is sampled (the shape, the density's
// settings and textures, the noise's and coverage map's offsets: camera and wind·time, as the uniforms
// hold them camera-relative), the sun's direction and the map's placement. A still camera and sun without
// wind keep it: clouds.shadow does not run again (the plan lists clouds.shadow_map as cached); a moving
// camera rebuilds it every frame, as before.
uint64_t shadowBuildKey(const gpu::CloudUniforms& u, const CloudSettings& s) {
    using core::hashValue;
    uint64_t h = core::kHashSeed;
    h = hashValue(h, u.boxFromView);
    h = hashValue(h, u.origin);
    h = hashValue(h, u.layer);
    h = hashValue(h, u.boxHalf);
    h = hashValue(h, u.noiseBase);
    h = hashValue(h, u.noiseDetail);
    h = hashValue(h, u.coverageMap);
    h = hashValue(h, u.shape);
    h = hashValue(h, u.toSun);
    h = hashValue(h, u.shadow);
    h = hashValue(h, u.counts.w);
    h = hashValue(h, u.flags.x & (gpu::kCloudFlagNoise | gpu::kCloudFlagCurved | gpu::kCloudFlagBox |
                                  gpu::kCloudFlagCoverageMap));
    // The textures' contents: generated from seed and size, or the host's views.
    h = hashValue(h, s.noise.seed);
    h = hashValue(h, s.noise.baseSize);
    h = hashValue(h, s.noise.detailSize);
    h = hashValue(h, s.noise.hostBaseTexture);
    h = hashValue(h, s.noise.hostDetailTexture);
    h = hashValue(h, s.coverageMap.texture);
    return h;
}

// Everything the accumulated (L, T) depends on besides the camera, the light and the wind's motion
// (core/temporal.h): the clouds' settings, the atmosphere's when on, the extent and format.
uint64_t temporalKey(const FrameInfo& frame) {
    using core::hashValue;
    const CloudSettings& s = frame.clouds;
    uint64_t h = core::hashSettings(core::kHashSeed, cloudSettingsTable(), &s);  // the table's history fields
    h = hashValue(h, frame.color.extent.width);
    h = hashValue(h, frame.color.extent.height);
    h = hashValue(h, frame.color.format);
    h = hashValue(h, frame.atmosphere.enabled);
    if (frame.atmosphere.enabled) h = hashValue(h, common::airViewSettingsKey(frame.atmosphere));
    return h;
}

// `value` modulo `period`, in [0, period).
double wrap(double value, double period) {
    const double r = std::fmod(value, period);
    return r < 0.0 ? r + period : r;
}

}  // namespace

glm::uvec2 marchExtent(uint32_t width, uint32_t height, float resolutionScale) {
    return common::reducedExtent(width, height, resolutionScale);  // the same rounding as the fog's
}

gpu::CloudUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth,
                                 const glm::vec3& windDelta) {
    const CloudSettings& s = frame.clouds;
    const bool curved = followsPlanet(frame);
    const glm::dvec3 camera(frame.camera.position);
    gpu::CloudUniforms u{};
    const glm::dmat4 viewToClip = glm::dmat4(frame.camera.projection) * core::rotationOnly(frame.camera.view);
    u.clipToView = glm::mat4(glm::inverse(viewToClip));
    // The box's frame: rotated by yaw about y, then pitch about its x; camera-relative x -> box frame.
    u.boxFromView = glm::mat4(glm::dmat4(worldToBox(s.box)) *
                              glm::translate(glm::dmat4(1.0), camera - glm::dvec3(s.box.center)));
    const double ground = frame.atmosphere.groundRadius;
    u.origin = curved ? glm::vec4(glm::vec3(camera + glm::dvec3(0.0, ground, 0.0)), 1.0f)
                      : glm::vec4(0.0f, float(camera.y), 0.0f, 0.0f);
    const glm::dvec2 range = heightRange(s);
    u.layer = glm::vec4(glm::vec2(range), curved ? float(ground) : 0.0f, float(1.0 / (range.y - range.x)));
    u.boxHalf = glm::vec4(s.box.halfSize, 0.0f);
    // Noise coordinates: (x + offset) / period, offset = (camera - wind·t) modulo the period, in double.
    const glm::dvec3 moved = camera - glm::dvec3(s.wind) * frame.timeSeconds;
    const double basePeriod = s.noise.tiling, detailPeriod = s.noise.tiling / gpu::kCloudDetailTilingRatio;
    const auto offset = [&](double period) {
        return glm::vec3(float(wrap(moved.x, period)), float(wrap(moved.y, period)),
                         float(wrap(moved.z, period)));
    };
    u.noiseBase = glm::vec4(offset(basePeriod), float(1.0 / basePeriod));
    u.noiseDetail = glm::vec4(offset(detailPeriod), float(1.0 / detailPeriod));
    // uv = ((x - originX) / |size|, (z - originZ) / size): a negative size runs v along -z
    // (settingsToPostfx); the offsets wrapped by whole periods.
    const CloudCoverageMap& map = s.coverageMap;
    const double mapEdge = std::abs(double(map.size));
    u.coverageMap =
        glm::vec4(float(wrap(moved.x - map.originX, mapEdge)), float(wrap(moved.z - map.originZ, mapEdge)),
                  float(1.0 / mapEdge), float(1.0 / double(map.size)));
    u.shape = glm::vec4(s.coverage, float(1.0 / topFalloff(s.cloudType)), s.noise.detailStrength, s.density);
    u.phase = glm::vec4(s.anisotropyForward, s.anisotropyBack, s.lobeMix, s.albedo);
    const CloudMultipleScattering& ms = s.multipleScattering;
    u.multiScatter = glm::vec4(ms.attenuation, ms.contribution, ms.eccentricity, float(ms.octaves));
    const SlabMedium slab = slabMedium(s);
    u.slab = glm::vec4(float(slab.albedo), float(slab.asymmetry), float(slab.depthScale), float(slab.g));
    u.sun = glm::vec4(core::preExposed(frame.sun.illuminance, frame.preExposure), s.lightDistance);
    u.toSun = glm::vec4(glm::vec3(glm::normalize(glm::dvec3(frame.sun.toSun))), 0.0f);
    u.ambient = glm::vec4(core::preExposed(frame.ambient, frame.preExposure), 0.0f);
    u.march = glm::vec4(s.maxDistance, depth.reversedZ ? 0.0f : 1.0f, 0.0f, 0.0f);
    const ShadowMapGeometry shadow = shadowMapGeometry(frame);
    u.shadow = glm::vec4(glm::vec3(shadow.center - camera), float(shadow.extent));
    u.counts = glm::uvec4(s.steps, s.lightSteps, ms.octaves, shadow.size);
    u.windDelta = glm::vec4(windDelta, 0.0f);
    u.extent =
        glm::uvec4(frame.color.extent.width, frame.color.extent.height, uint32_t(frame.frameIndex), 0u);
    u.marchExtent = glm::uvec4(
        marchExtent(frame.color.extent.width, frame.color.extent.height, s.resolutionScale), 0u, 0u);
    u.sparse =
        glm::uvec4(1u, 0u, 0u, 1u);  // every texel, one invocation a ray; declare() sets a sparse update
    u.flags.x = (s.noise.enabled ? gpu::kCloudFlagNoise : 0u) | (curved ? gpu::kCloudFlagCurved : 0u) |
                (s.shape == CloudShape::Box ? gpu::kCloudFlagBox : 0u) |
                (depth.reversedZ ? gpu::kCloudFlagDepthReversedZ : 0u) |
                (s.jitter ? gpu::kCloudFlagJitter : 0u) |
                (map.texture != VK_NULL_HANDLE ? gpu::kCloudFlagCoverageMap : 0u) |
                (s.temporal.enabled ? gpu::kCloudFlagOpticalDepthHistory : 0u) |
                (ms.model == CloudScatteringModel::Slab ? gpu::kCloudFlagSlabScattering : 0u);
    return u;
}

CloudsEffect::CloudsEffect(const core::Gpu& gpu) : noiseFormatSupported_(common::noiseFormatSupported(gpu)) {}

Status CloudsEffect::validate(const FrameInfo& frame) const {
    if (!frame.clouds.enabled) return Status::success();
    if (Status s = validateSettings(frame.clouds); !s) return s;
    const CloudNoiseSettings& n = frame.clouds.noise;
    if (n.enabled && (!n.hostBaseTexture || !n.hostDetailTexture) && !noiseFormatSupported_)
        return {
            Result::Unsupported,
            "clouds.noise: the device cannot use VK_FORMAT_R8_UNORM as a storage image, linearly filtered "
            "sampled image and transfer source (give clouds.noise.hostBaseTexture and hostDetailTexture, or "
            "turn "
            "clouds.noise off)"};
    return Status::success();
}

void CloudsEffect::toPostfxFrame(const core::WorldTransform& world, FrameInfo& frame,
                                 core::WorldScratch&) const {
    settingsToPostfx(world, frame.clouds);
}

bool CloudsEffect::active(const FrameInfo& frame) const {
    const CloudSettings& s = frame.clouds;
    return s.enabled && s.coverage > 0.0f && s.density > 0.0f;
}

std::vector<double> CloudsEffect::presetErrors() const {
    std::vector<double> out;
    for (const QualityPreset& p : kQualityPresets)
        out.push_back(p.error);
    return out;
}

uint32_t CloudsEffect::autoFeatures(const FrameInfo& frame) const {
    return (frame.atmosphere.enabled ? kCloudAutoFeatureAtmosphere : 0u) |
           (frame.clouds.castShadows ? kCloudAutoFeatureShadows : 0u) |
           (frame.clouds.noise.enabled ? kCloudAutoFeatureNoise : 0u);
}

core::QualityRequest CloudsEffect::quality(const FrameInfo& frame) const {
    const CloudQuality q = frame.clouds.quality;
    // Custom, or a value cast from another int (left for validateSettings to reject naming clouds.quality).
    if (q == CloudQuality::Custom || uint32_t(q) > uint32_t(CloudQuality::Auto)) return {};
    if (q == CloudQuality::Auto) return {core::QualityRequest::Kind::Auto, 0, frame.clouds.autoBudgetMs};
    return {core::QualityRequest::Kind::Preset, uint32_t(q) - uint32_t(CloudQuality::Low), 0.0f};
}

void CloudsEffect::applyPreset(FrameInfo& frame, uint32_t preset) const {
    const CloudQuality q = CloudQuality(uint32_t(CloudQuality::Low) + preset);
    frame.clouds = applyCloudQuality(frame.clouds, q);
    frame.clouds.quality = q;
}

void CloudsEffect::recorded(const FrameInfo& frame, bool active) {
    if (active && frame.clouds.temporal.enabled) {
        history_.recorded(frame, frame.clouds.temporal, temporalKey(frame), false);
        historyTime_ = frame.timeSeconds;
    } else {
        history_.dropped();
    }
}

Status CloudsEffect::declare(core::FrameBuilder& b) const {
    const FrameInfo& frame = b.frame();
    const CloudSettings& s = frame.clouds;
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;

    // The noise textures: the host's, or generated once per size and seed; a stand-in without noise.
    core::ImageDesc one;
    one.type = VK_IMAGE_TYPE_3D;
    one.format = common::kNoiseFormat;
    one.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    core::ImageRef base, detail;
    if (!s.noise.enabled) {
        base = detail = b.transientImage(kNoNoise, one);
    } else {
        const VkImageLayout layout = s.noise.hostTextureLayout;
        base = s.noise.hostBaseTexture ? b.external("host.clouds_base_noise", s.noise.hostBaseTexture, layout)
                                       : common::declareGeneratedNoise(
                                             b, kBaseNoise, kBaseNoisePass, s.noise.baseSize, s.noise.seed,
                                             gpu::kNoisePerlinWorley, "clouds.noise.base_size");
        detail = s.noise.hostDetailTexture
                     ? b.external("host.clouds_detail_noise", s.noise.hostDetailTexture, layout)
                     : common::declareGeneratedNoise(b, kDetailNoise, kDetailNoisePass, s.noise.detailSize,
                                                     detailSeed(s.noise.seed), gpu::kNoiseWorley,
                                                     "clouds.noise.detail_size");
    }
    // The host's coverage map, or a stand-in.
    const bool withMap = s.coverageMap.texture != VK_NULL_HANDLE;
    core::ImageRef coverageMap;
    if (withMap) {
        coverageMap = b.external("host.clouds_coverage_map", s.coverageMap.texture, s.coverageMap.layout);
    } else {
        core::ImageDesc flat = one;
        flat.type = VK_IMAGE_TYPE_2D;
        coverageMap = b.transientImage(kNoCoverageMap, flat);
    }
    const Use mapUse = withMap ? Use::Sampled : Use::BoundOnly;
    const Use noiseUse = s.noise.enabled ? Use::Sampled : Use::BoundOnly;
    const uint32_t width = frame.color.extent.width, height = frame.color.extent.height;
    const glm::uvec2 march = marchExtent(width, height, s.resolutionScale);
    const bool temporal = s.temporal.enabled;
    // The volumetrics lookup reads the march's image and distances: it marches into its image.
    const bool lookup = frame.volumetricsLookup.enabled;
    const bool scatter = temporal || lookup || march != glm::uvec2(width, height);
    core::TemporalFrame t;
    glm::vec3 windDelta(0.0f);
    if (temporal) {
        t = history_.decide(frame, s.temporal, temporalKey(frame), false);
        if (t.historyValid) windDelta = glm::vec3(glm::dvec3(s.wind) * (frame.timeSeconds - historyTime_));
    }
    const core::DepthInput depthInput = b.depthInput();
    gpu::CloudUniforms u = buildUniforms(frame, b.depthConvention(), windDelta);
    // A sparse update needs history (a frame without it marches every texel) and a block inside the image.
    const uint32_t block = temporal && t.historyValid && march.x >= s.updateBlock && march.y >= s.updateBlock
                               ? s.updateBlock
                               : 1u;
    const uint32_t segments =
        marchSegments(((march.x + block - 1) / block) * ((march.y + block - 1) / block));
    u.sparse = glm::uvec4(block, sparseOffset(block, frame.frameIndex), segments);
    if (depthInput.distance) u.flags.x |= gpu::kCloudFlagViewDistance;
    const core::BufferRef uniforms = b.uniforms(kUniforms, &u, sizeof u);

    // The atmosphere's, declared earlier this frame when it runs.
    const core::BufferRef atmosphereUniforms =
        frame.atmosphere.enabled ? common::find(b, common::kAirUniforms) : core::BufferRef{};
    const bool withAtmosphere = atmosphereUniforms.valid();

    if (common::castsCloudShadows(
            frame)) {  // before the fogs, which read it; held: the host reads it next frame
        core::ImageDesc shadowDesc;
        shadowDesc.format = VK_FORMAT_R32_SFLOAT;
        shadowDesc.extent = {s.shadowMap.size, s.shadowMap.size, 1};
        shadowDesc.sizedBy = "clouds.shadow_map.size";
        shadowDesc.usage =
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        // Persistent: rebuilt only when what its texels depend on changes (shadowBuildKey).
        const core::ImageRef shadowMap =
            b.persistentImage(common::kCloudShadowMap.id, shadowDesc, shadowBuildKey(u, s));
        b.exportImage(shadowMap);
        b.pass(kShadow, groupsFor(s.shadowMap.size), groupsFor(s.shadowMap.size), 1)
            .bind(gpu::kCloudBindingUniforms, uniforms)
            .bind(gpu::kCloudBindingBaseNoise, base, noiseUse, SamplerKind::LinearRepeat)
            .bind(gpu::kCloudBindingDetailNoise, detail, noiseUse, SamplerKind::LinearRepeat)
            .bind(gpu::kCloudBindingCoverageMap, coverageMap, mapUse, SamplerKind::LinearRepeat)
            .bind(gpu::kCloudBindingShadowOut, shadowMap, Use::StorageWrite);
    }

    // Stand-ins at the march's bindings this frame does not use (never accessed): a 2D array for the
    // aerial perspective's transmittance without the atmosphere, an r32ui image for the distances
    // without temporal.
    core::ImageRef noAtmosphere, noDistance, lookupDistance;
    if (!withAtmosphere) {
        core::ImageDesc array = one;
        array.type = VK_IMAGE_TYPE_2D;
        array.layers = 2;
        noAtmosphere = b.transientImage(kNoAtmosphere, array);
    }
    if (!temporal) {
        core::ImageDesc distance;
        distance.format = VK_FORMAT_R32_UINT;
        distance.usage = VK_IMAGE_USAGE_STORAGE_BIT;
        if (lookup) {
            distance.extent = {march.x, march.y, 1};
            lookupDistance = b.transientImage(kLookupDistance, distance);
        } else {
            noDistance = b.transientImage(kNoDistance, distance);
        }
    }

    b.pass(kMarch[rgba32], groupsFor((march.x + block - 1) / block * segments),
           groupsFor((march.y + block - 1) / block), 1)
        .constants(marchConstants(withAtmosphere, scatter, temporal || lookup))
        .bind(gpu::kCloudBindingUniforms, uniforms)
        .bind(gpu::kCloudBindingDepth, depthInput.image, Use::Sampled)
        .bind(gpu::kCloudBindingBaseNoise, base, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kCloudBindingDetailNoise, detail, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kCloudBindingCoverageMap, coverageMap, mapUse, SamplerKind::LinearRepeat);
    if (withAtmosphere) {
        // The multiple-scattering LUT for the aerial perspective beyond the LUT's depth; without multiple
        // scattering the atmosphere's 3D stand-in, never read.
        const core::ImageRef transmittanceLut = common::find(b, common::kSunTransmittanceLut);
        const core::ImageRef multiScattering = common::find(b, common::kAirMultipleScatteringLut);
        const core::ImageRef msStandIn = common::find(b, common::kAirMultipleScatteringStandIn);
        b.bind(gpu::kCloudBindingAtmosphere, atmosphereUniforms)
            .bind(gpu::kCloudBindingTransmittanceLut, transmittanceLut, Use::Sampled,
                  SamplerKind::LinearClamp)
            .bind(gpu::kCloudBindingApScattering, common::find(b, common::kAerialPerspectiveLut),
                  Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kCloudBindingApTransmittance, common::find(b, common::kAerialTransmittanceLut),
                  Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kCloudBindingMultiScattering, multiScattering.valid() ? multiScattering : msStandIn,
                  multiScattering.valid() ? Use::Sampled : Use::BoundOnly, SamplerKind::LinearClamp);
    } else {  // of the bindings' kinds: the clouds' uniforms, the depth, the base noise (3D), the 2D array
        b.bind(gpu::kCloudBindingAtmosphere, uniforms)
            .bind(gpu::kCloudBindingTransmittanceLut, depthInput.image, Use::BoundOnly)
            .bind(gpu::kCloudBindingApScattering, base, Use::BoundOnly)
            .bind(gpu::kCloudBindingApTransmittance, noAtmosphere, Use::BoundOnly)
            .bind(gpu::kCloudBindingMultiScattering, base, Use::BoundOnly);
    }
    if (!temporal)
        b.bind(gpu::kCloudBindingDistance, lookup ? lookupDistance : noDistance,
               lookup ? Use::StorageWrite : Use::StorageBoundOnly);
    if (!scatter) {  // full size without temporal: the march composites (the target stands in for its image)
        const core::ImageRef target = b.compositeTarget();
        b.bind(gpu::kCloudBindingColorIn, b.compositeSource(), Use::StorageRead)
            .bind(gpu::kCloudBindingColorOut, target, Use::StorageWrite)
            .bind(gpu::kCloudBindingScatter, target, Use::StorageBoundOnly);
        return Status::success();
    }
    core::ImageDesc marchDesc;
    // The composite's format (postfx.target's when the host's color is another: core/target.h).
    marchDesc.format = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                           : VK_FORMAT_R16G16B16A16_SFLOAT;
    marchDesc.extent = {march.x, march.y, 1};
    marchDesc.sizedBy = "clouds.resolution_scale";  // and the color extent
    marchDesc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    const core::ImageRef scatterImage = b.transientImage(kScatter, marchDesc);
    // The march's image stands in for the color it does not composite.
    b.bind(gpu::kCloudBindingScatter, scatterImage, Use::StorageWrite)
        .bind(gpu::kCloudBindingColorIn, scatterImage, Use::StorageBoundOnly)
        .bind(gpu::kCloudBindingColorOut, scatterImage, Use::StorageBoundOnly);
    core::ImageRef result = scatterImage;
    core::ImageRef distance[2];  // with temporal: the distances, last frame's and this one's
    if (temporal) {
        core::ImageDesc historyDesc = marchDesc;  // RGBA32F: in half, small updates would be lost
        historyDesc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        core::ImageDesc distanceDesc = marchDesc;
        distanceDesc.format = VK_FORMAT_R32_UINT;  // two halfs (shaders/clouds/distances.glsl)
        core::ImageRef history[2];
        for (int i = 0; i < 2; ++i) {
            history[i] = b.historyImage(kHistory[i], historyDesc);
            distance[i] = b.historyImage(kHistoryDistance[i], distanceDesc);
        }
        // The march stores this frame's distances in the slot written this frame (the next one's "in").
        b.bind(gpu::kCloudBindingDistance, distance[t.writeSlot], Use::StorageWrite);
        gpu::TemporalUniforms tu = core::temporalUniforms(t);
        // An updated texel of a sparse update gets a sample every block² frames: the running mean of its
        // own samples (the full march after the reset and about n/block² since), 1/(1 + n/block²), until
        // that falls to the blend weight, per sample (1 - (1 - w)^block per sample measured no better on a
        // panning view, 7.7% against 7.9%, and noisier on a still one, 3.2% against 2.3% with block 4).
        if (block > 1)
            tu.cameraDelta.w =
                std::max(s.temporal.blendWeight,
                         float(1.0 / (1.0 + double(t.framesSinceReset) / double(block * block))));
        const core::BufferRef temporalUniforms = b.uniforms(kTemporalUniforms, &tu, sizeof tu);
        b.pass(kTemporal[rgba32], groupsFor(march.x), groupsFor(march.y), 1)
            .bind(gpu::kCloudBindingUniforms, uniforms)
            .bind(gpu::kCloudBindingScatter, scatterImage, Use::StorageRead)
            .bind(gpu::kCloudBindingDepth, depthInput.image, Use::Sampled)  // statically used by the shader
            .bind(gpu::kCloudBindingDistance, distance[t.writeSlot], Use::StorageReadWrite)  // skipped texels
            .bind(gpu::kCloudBindingHistoryIn, history[t.readSlot], Use::StorageRead)
            .bind(gpu::kCloudBindingDistanceIn, distance[t.readSlot], Use::StorageRead)
            .bind(gpu::kCloudBindingTemporal, temporalUniforms)
            .bind(gpu::kCloudBindingHistoryOut, history[t.writeSlot], Use::StorageWrite);
        result = history[t.writeSlot];
    }
    b.pass(kUpsample[temporal && !rgba32 ? 2 : rgba32], groupsFor(width), groupsFor(height), 1)
        .bind(gpu::kCloudBindingUniforms, uniforms)
        .bind(gpu::kCloudBindingColorIn, b.compositeSource(), Use::StorageRead)
        .bind(gpu::kCloudBindingDepth, depthInput.image, Use::Sampled)
        .bind(gpu::kCloudBindingScatter, result, Use::StorageRead)
        .bind(gpu::kCloudBindingColorOut, b.compositeTarget(), Use::StorageWrite);

    if (const core::LookupTarget target = b.lookupTarget(); target.valid()) {
        uint32_t g[3];
        core::lookupGroups(target, false, g);
        b.pass(kLookupPass[temporal || rgba32], g[0], g[1], g[2])
            .bind(gpu::kCloudBindingUniforms, uniforms)
            .bind(gpu::kCloudBindingScatter, result, Use::StorageRead)
            .bind(gpu::kCloudBindingDistance, temporal ? distance[t.writeSlot] : lookupDistance,
                  Use::StorageRead);
        core::bindLookup(b, target);
    }
    return Status::success();
}

}  // namespace postfx::clouds
