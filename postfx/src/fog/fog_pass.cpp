#include "fog/fog_pass.h"

#include "core/barriers.h"
#include "fog/fog_settings.h"
#include "fog/fog_uniforms.h"
#include "postfx_spirv.h"

#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <string>

namespace postfx::fog {
namespace {

Status invalid(std::string message) {
    return {Result::InvalidArgument, std::move(message)};
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool isShadowFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_R32_SFLOAT ||
           f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D24_UNORM_S8_UINT;
}

// Layouts a compute shader can sample a (depth) image in without a transition.
bool sampleableLayout(VkImageLayout l) {
    return l == VK_IMAGE_LAYOUT_GENERAL || l == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL;
}

// The layout a host image is used in by the fog, and the barriers taking it there and back.
struct HostImageUse {
    VkImageLayout layout;
    core::ImageTransition acquire, release;
};

// Storage images (color, output) are used in GENERAL; sampled ones (depth, shadow map) in their own
// layout when a shader may sample it there, else in SHADER_READ_ONLY_OPTIMAL.
HostImageUse useHostImage(const ImageInput& image, bool storage, VkAccessFlags access) {
    const VkImageLayout layout =
        storage ? VK_IMAGE_LAYOUT_GENERAL
                : (sampleableLayout(image.layout) ? image.layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    // Layout transitions of depth/stencil images cover both aspects; the host's view selects depth.
    const VkImageAspectFlags aspect = core::aspectOfFormat(image.format);
    return {layout, core::acquireHostImage(image.image, aspect, image.layout, layout, access),
            core::releaseHostImage(image.image, aspect, layout, image.layout, access)};
}

}  // namespace

Status FogPass::validate(const FrameInfo& frame) {
    const FogSettings& fog = frame.fog;
    if (Status s = validateSettings(fog); !s) return s;
    if (Status s = validateLighting(frame.sun, frame.ambient); !s) return s;
    const glm::dvec3 p = frame.camera.position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return invalid("FrameInfo.camera.position is not finite");
    if (!finite(frame.camera.view)) return invalid("FrameInfo.camera.view is not finite");
    if (!finite(frame.camera.projection)) return invalid("FrameInfo.camera.projection is not finite");
    if (std::abs(glm::determinant(glm::dmat4(frame.camera.projection))) < 1e-30)
        return invalid("FrameInfo.camera.projection is singular");
    if (!std::isfinite(frame.timeSeconds)) return invalid("FrameInfo.timeSeconds is not finite");
    const ShadowMapInput& shadow = frame.shadowMap;
    if (shadow.image.present()) {
        if (!shadow.image.view) return invalid("FrameInfo.shadowMap.image.view is VK_NULL_HANDLE");
        if (!isShadowFormat(shadow.image.format))
            return invalid("FrameInfo.shadowMap.image.format " + std::to_string(shadow.image.format) +
                           " is not supported (expected D32_SFLOAT, D16_UNORM, X8_D24, D24S8 or R32_SFLOAT)");
        if (shadow.image.extent.width == 0 || shadow.image.extent.height == 0)
            return invalid("FrameInfo.shadowMap.image.extent is empty");
        if (shadow.image.layout == VK_IMAGE_LAYOUT_UNDEFINED)
            return invalid("FrameInfo.shadowMap.image.layout is UNDEFINED");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(shadow.worldToClip[c][r]))
                    return invalid("FrameInfo.shadowMap.worldToClip is not finite");
        if (!(shadow.depthBias >= 0.0f) || !std::isfinite(shadow.depthBias))
            return invalid("FrameInfo.shadowMap.depthBias must be finite and >= 0");
    }
    if (frame.output.present()) {
        if (frame.output.format != frame.color.format)
            return invalid("FrameInfo.output.format differs from FrameInfo.color.format");
        if (frame.output.extent.width != frame.color.extent.width ||
            frame.output.extent.height != frame.color.extent.height)
            return invalid("FrameInfo.output.extent differs from FrameInfo.color.extent");
        if (!frame.output.view) return invalid("FrameInfo.output.view is VK_NULL_HANDLE");
        if (frame.output.layout == VK_IMAGE_LAYOUT_UNDEFINED)
            return invalid("FrameInfo.output.layout is UNDEFINED: postfx returns images in their layout");
        if (frame.output.image == frame.color.image)
            return invalid("FrameInfo.output is FrameInfo.color: leave output empty to composite in place");
    }
    return Status::success();
}

core::ComputePipeline& FogPass::pipelineFor(VkFormat colorFormat) {
    return colorFormat == VK_FORMAT_R32G32B32A32_SFLOAT ? raymarch32_ : raymarch16_;
}

Status FogPass::createResources(const core::Gpu& gpu, const ContextCreateInfo& info) {
    gpu_ = &gpu;
    const core::Binding bindings[] = {
        {gpu::kFogBindingColorIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {gpu::kFogBindingColorOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {gpu::kFogBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingNoise, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
    };
    core::ComputePipelineDesc desc;
    desc.name = "fog.raymarch";
    desc.bindings = bindings;
    desc.spirv = spirv::fog_raymarch_comp;
    if (Status s = raymarch16_.create(gpu, desc); !s) return s;
    desc.spirv = spirv::fog_raymarch_comp_COLOR_RGBA32F;
    if (Status s = raymarch32_.create(gpu, desc); !s) return s;

    const VkDeviceSize align =
        std::max<VkDeviceSize>(gpu.properties.limits.minUniformBufferOffsetAlignment, 16);
    uniformStride_ = (sizeof(gpu::FogUniforms) + align - 1) / align * align;
    slots_ = info.framesInFlight;
    if (Status s = uniforms_.create(gpu, uniformStride_ * slots_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true,
                                    "fog.uniforms");
        !s)
        return s;

    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    if (Status s =
            core::vulkanStatus(gpu.fn.vkCreateSampler(gpu.device, &sampler, gpu.allocator, &nearestClamp_),
                               "vkCreateSampler for fog");
        !s)
        return s;
    sampler.magFilter = sampler.minFilter = VK_FILTER_LINEAR;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    if (Status s =
            core::vulkanStatus(gpu.fn.vkCreateSampler(gpu.device, &sampler, gpu.allocator, &linearRepeat_),
                               "vkCreateSampler for fog noise");
        !s)
        return s;

    core::ImageDesc one;
    one.format = VK_FORMAT_R32_SFLOAT;
    one.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    if (Status s = noShadowMap_.create(gpu, one, "fog.no_shadow_map"); !s) return s;
    one.type = VK_IMAGE_TYPE_3D;
    one.format = VK_FORMAT_R8_UNORM;
    if (Status s = noNoise_.create(gpu, one, "fog.no_noise"); !s) return s;
    standInsReady_ = false;
    return Status::success();
}

Status FogPass::record(const core::Gpu& gpu, const ContextCreateInfo& info, core::DescriptorArena& arena,
                       core::PassTimer& timer, core::Retirement& retirement, const FrameInfo& frame) {
    if (!raymarch16_.valid()) {
        if (Status s = createResources(gpu, info); !s) {
            release();
            return s;
        }
    }
    VkCommandBuffer cmd = frame.commandBuffer;
    const FogNoiseSettings& noise = frame.fog.noise;
    const bool noiseOn = noise.enabled;
    const bool generatedNoise = noiseOn && !noise.hostTexture;
    // A texture of another size, or one nothing reads any more, may still be sampled by frames in flight.
    if (noise_ && (!generatedNoise || noise_->size() != noise.textureSize))
        retirement.retire(frame.frameIndex, std::move(noise_));
    if (generatedNoise) {
        if (!noise_) noise_ = std::make_unique<FogNoise>();
        if (Status s = noise_->prepare(gpu, noise.textureSize, noise.seed); !s) return s;
    }

    // One-time: the stand-ins go to SHADER_READ_ONLY (never sampled: the flags skip them).
    if (!standInsReady_) {
        for (core::GpuImage* image : {&noShadowMap_, &noNoise_}) {
            core::ImageTransition t;
            t.image = image->handle();
            t.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
            core::transition(gpu, cmd, t);
        }
        standInsReady_ = true;
    }
    if (generatedNoise && noise_->needsGeneration()) {
        timer.beginPass(cmd, "fog.noise");
        Status s;
        noise_->recordGenerate(cmd, arena, s);
        timer.endPass(cmd);
        if (!s) return s;
    }

    // Uniforms for this frame's slot (the host guarantees the frame that used it last has completed).
    const bool shadowOn = frame.shadowMap.image.present();
    const gpu::FogUniforms u = buildUniforms(frame, info.depth, noiseOn, shadowOn);
    const VkDeviceSize offset = uniformStride_ * (frame.frameIndex % slots_);
    std::memcpy(static_cast<char*>(uniforms_.mapped()) + offset, &u, sizeof u);

    core::ComputePipeline& pipeline = pipelineFor(frame.color.format);
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (Status s = arena.allocate(pipeline.setLayout(), set); !s) return s;
    const bool inPlace = !frame.output.present();
    constexpr VkAccessFlags kRead = VK_ACCESS_SHADER_READ_BIT, kWrite = VK_ACCESS_SHADER_WRITE_BIT;
    const HostImageUse depth = useHostImage(frame.depth, false, kRead);
    // At most color, depth, output and shadow map: a fixed array, no allocation per frame.
    std::array<HostImageUse, 4> useStorage{};
    size_t useCount = 0;
    useStorage[useCount++] = useHostImage(frame.color, true, inPlace ? kRead | kWrite : kRead);
    useStorage[useCount++] = depth;
    if (!inPlace) useStorage[useCount++] = useHostImage(frame.output, true, kWrite);
    if (shadowOn) useStorage[useCount++] = useHostImage(frame.shadowMap.image, false, kRead);
    const std::span<const HostImageUse> uses(useStorage.data(), useCount);
    const VkImageLayout shadowLayout =
        shadowOn ? uses.back().layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

    const VkImageView noiseView =
        !noiseOn ? noNoise_.view() : (generatedNoise ? noise_->view() : noise.hostTexture);
    const VkImageLayout noiseLayout =
        noiseOn && !generatedNoise ? noise.hostTextureLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    core::DescriptorWrites(set)
        .storageImage(gpu::kFogBindingColorIn, frame.color.view)
        .storageImage(gpu::kFogBindingColorOut, inPlace ? frame.color.view : frame.output.view)
        .sampledImage(gpu::kFogBindingDepth, frame.depth.view, depth.layout, nearestClamp_)
        .sampledImage(gpu::kFogBindingShadowMap, shadowOn ? frame.shadowMap.image.view : noShadowMap_.view(),
                      shadowLayout, nearestClamp_)
        .sampledImage(gpu::kFogBindingNoise, noiseView, noiseLayout, linearRepeat_)
        .uniformBuffer(gpu::kFogBindingUniforms, uniforms_.handle(), offset, sizeof(gpu::FogUniforms))
        .apply(gpu);

    for (const HostImageUse& use : uses)
        core::transition(gpu, cmd, use.acquire);
    timer.beginPass(cmd, "fog.raymarch");
    pipeline.bind(cmd, set, nullptr);
    const uint32_t groups = gpu::kFogGroupSize;
    gpu.fn.vkCmdDispatch(cmd, (frame.color.extent.width + groups - 1) / groups,
                         (frame.color.extent.height + groups - 1) / groups, 1);
    timer.endPass(cmd);
    for (const HostImageUse& use : uses)
        core::transition(gpu, cmd, use.release);
    return Status::success();
}

void FogPass::release() {
    noise_.reset();
    raymarch16_.reset();
    raymarch32_.reset();
    uniforms_.reset();
    noShadowMap_.reset();
    noNoise_.reset();
    if (gpu_) {
        if (nearestClamp_) gpu_->fn.vkDestroySampler(gpu_->device, nearestClamp_, gpu_->allocator);
        if (linearRepeat_) gpu_->fn.vkDestroySampler(gpu_->device, linearRepeat_, gpu_->allocator);
    }
    nearestClamp_ = linearRepeat_ = VK_NULL_HANDLE;
    standInsReady_ = false;
    gpu_ = nullptr;
}

}  // namespace postfx::fog
