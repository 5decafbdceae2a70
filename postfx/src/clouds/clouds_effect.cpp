#include "clouds/clouds_effect.h"

#include "atmosphere/atmosphere_effect.h"
#include "atmosphere/atmosphere_shared.h"
#include "clouds/clouds_model.h"
#include "clouds/clouds_settings.h"
#include "core/camera_math.h"
#include "fog/medium_noise.h"
#include "postfx_objects_spirv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace postfx::clouds {
namespace {

using core::SamplerKind;
using core::Use;

constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;

constexpr core::Binding kMarchBindings[] = {
    {gpu::kCloudBindingUniforms, kUniform},  {gpu::kCloudBindingColorIn, kStorage},
    {gpu::kCloudBindingColorOut, kStorage},  {gpu::kCloudBindingDepth, kSampled},
    {gpu::kCloudBindingBaseNoise, kSampled}, {gpu::kCloudBindingDetailNoise, kSampled}};
constexpr core::Binding kMarchAtmosphereBindings[] = {
    {gpu::kCloudBindingUniforms, kUniform},     {gpu::kCloudBindingColorIn, kStorage},
    {gpu::kCloudBindingColorOut, kStorage},     {gpu::kCloudBindingDepth, kSampled},
    {gpu::kCloudBindingBaseNoise, kSampled},    {gpu::kCloudBindingDetailNoise, kSampled},
    {gpu::kCloudBindingAtmosphere, kUniform},   {gpu::kCloudBindingTransmittanceLut, kSampled},
    {gpu::kCloudBindingApScattering, kSampled}, {gpu::kCloudBindingApTransmittance, kSampled}};
constexpr core::Binding kNoiseBindings[] = {{gpu::kNoiseBindingTexture, kStorage}};

// [atmosphere][rgba32]
const core::ComputePipelineDesc kMarch[2][2] = {
    {{"clouds.march", spirv::clouds_march_comp, kMarchBindings},
     {"clouds.march", spirv::clouds_march_comp_COLOR_RGBA32F, kMarchBindings}},
    {{"clouds.march", spirv::clouds_march_comp_ATMOSPHERE, kMarchAtmosphereBindings},
     {"clouds.march", spirv::clouds_march_comp_COLOR_RGBA32F_ATMOSPHERE, kMarchAtmosphereBindings}}};
const core::ComputePipelineDesc kBaseNoisePass{"clouds.base_noise", spirv::common_noise_generate_comp,
                                               kNoiseBindings, sizeof(gpu::NoisePush)};
const core::ComputePipelineDesc kDetailNoisePass{"clouds.detail_noise", spirv::common_noise_generate_comp,
                                                 kNoiseBindings, sizeof(gpu::NoisePush)};

uint32_t groupsFor(uint32_t size) {
    return (size + gpu::kCloudGroupSize - 1) / gpu::kCloudGroupSize;
}

// `value` modulo `period`, in [0, period).
double wrap(double value, double period) {
    const double r = std::fmod(value, period);
    return r < 0.0 ? r + period : r;
}

}  // namespace

gpu::CloudUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth) {
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
    u.shape = glm::vec4(s.coverage, float(1.0 / topFalloff(s.cloudType)), s.noise.detailStrength, s.density);
    u.phase = glm::vec4(s.anisotropyForward, s.anisotropyBack, s.lobeMix, s.albedo);
    const CloudMultipleScattering& ms = s.multipleScattering;
    u.multiScatter = glm::vec4(ms.attenuation, ms.contribution, ms.eccentricity, float(ms.octaves));
    u.sun = glm::vec4(frame.sun.illuminance, s.lightDistance);
    u.toSun = glm::vec4(glm::vec3(glm::normalize(glm::dvec3(frame.sun.toSun))), 0.0f);
    u.ambient = glm::vec4(frame.ambient, 0.0f);
    u.march = glm::vec4(s.maxDistance, depth.reversedZ ? 0.0f : 1.0f, 0.0f, 0.0f);
    u.counts = glm::uvec4(s.steps, s.lightSteps, ms.octaves, 0u);
    u.extent =
        glm::uvec4(frame.color.extent.width, frame.color.extent.height, uint32_t(frame.frameIndex), 0u);
    u.flags.x = (s.noise.enabled ? gpu::kCloudFlagNoise : 0u) | (curved ? gpu::kCloudFlagCurved : 0u) |
                (s.shape == CloudShape::Box ? gpu::kCloudFlagBox : 0u) |
                (depth.reversedZ ? gpu::kCloudFlagDepthReversedZ : 0u) |
                (s.jitter ? gpu::kCloudFlagJitter : 0u);
    return u;
}

CloudsEffect::CloudsEffect(const core::Gpu& gpu) : noiseFormatSupported_(fog::noiseFormatSupported(gpu)) {}

Status CloudsEffect::validate(const FrameInfo& frame) const {
    if (!frame.clouds.enabled) return Status::success();
    if (Status s = validateSettings(frame.clouds); !s) return s;
    if (frame.clouds.noise.enabled && !noiseFormatSupported_)
        return {
            Result::Unsupported,
            "clouds.noise: the device cannot use VK_FORMAT_R8_UNORM as a storage image, linearly filtered "
            "sampled image and transfer source (turn clouds.noise off)"};
    return Status::success();
}

bool CloudsEffect::active(const FrameInfo& frame) const {
    const CloudSettings& s = frame.clouds;
    return s.enabled && s.coverage > 0.0f && s.density > 0.0f;
}

Status CloudsEffect::declare(core::FrameBuilder& b) const {
    const FrameInfo& frame = b.frame();
    const CloudSettings& s = frame.clouds;
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;

    core::ImageRef base, detail;
    if (s.noise.enabled) {
        base = fog::declareGeneratedNoise(b, kBaseNoise, kBaseNoisePass, s.noise.baseSize, s.noise.seed,
                                          gpu::kNoisePerlinWorley);
        detail = fog::declareGeneratedNoise(b, kDetailNoise, kDetailNoisePass, s.noise.detailSize,
                                            detailSeed(s.noise.seed), gpu::kNoiseWorley);
    } else {
        core::ImageDesc one;
        one.type = VK_IMAGE_TYPE_3D;
        one.format = fog::kNoiseFormat;
        one.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
        base = detail = b.transientImage(kNoNoise, one);
    }
    const Use noiseUse = s.noise.enabled ? Use::Sampled : Use::BoundOnly;
    const gpu::CloudUniforms u = buildUniforms(frame, b.depthConvention());
    const core::BufferRef uniforms = b.uniforms(kUniforms, &u, sizeof u);

    // The atmosphere's, declared earlier this frame when it runs.
    const core::BufferRef atmosphereUniforms =
        frame.atmosphere.enabled ? b.findUniforms(atmosphere::kUniforms) : core::BufferRef{};
    const bool withAtmosphere = atmosphereUniforms.valid();

    const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
    b.pass(kMarch[withAtmosphere][rgba32], groupsFor(frame.color.extent.width),
           groupsFor(frame.color.extent.height), 1)
        .bind(gpu::kCloudBindingUniforms, uniforms)
        .bind(gpu::kCloudBindingColorIn, source, Use::StorageRead)
        .bind(gpu::kCloudBindingDepth, b.host(core::HostImage::Depth), Use::Sampled)
        .bind(gpu::kCloudBindingBaseNoise, base, noiseUse, SamplerKind::LinearRepeat)
        .bind(gpu::kCloudBindingDetailNoise, detail, noiseUse, SamplerKind::LinearRepeat);
    if (withAtmosphere) {
        b.bind(gpu::kCloudBindingAtmosphere, atmosphereUniforms)
            .bind(gpu::kCloudBindingTransmittanceLut, b.find(atmosphere::kTransmittanceLut), Use::Sampled,
                  SamplerKind::LinearClamp)
            .bind(gpu::kCloudBindingApScattering, b.find(atmosphere::kApScatteringLut), Use::Sampled,
                  SamplerKind::LinearClamp)
            .bind(gpu::kCloudBindingApTransmittance, b.find(atmosphere::kApTransmittanceLut), Use::Sampled,
                  SamplerKind::LinearClamp);
    }
    b.bind(gpu::kCloudBindingColorOut, target, Use::StorageWrite);
    return Status::success();
}

}  // namespace postfx::clouds
