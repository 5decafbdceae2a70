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

core::HostImageUse useHostImage(const ImageInput& image, bool storage, VkAccessFlags access) {
    return core::useHostImage(image.image, image.format, image.layout, storage, access);
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

Status FogPass::pipeline(Kernel kernel, VkFormat colorFormat, core::ComputePipeline*& out) {
    const bool rgba32 = colorFormat == VK_FORMAT_R32G32B32A32_SFLOAT;
    core::ComputePipeline& p = pipelines_[int(kernel)][rgba32 ? 1 : 0];
    out = &p;
    if (p.valid()) return Status::success();
    // One layout for all three kernels; each reads the bindings it needs.
    static constexpr core::Binding kBindings[] = {
        {gpu::kFogBindingColorIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {gpu::kFogBindingColorOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {gpu::kFogBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingNoise, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {gpu::kFogBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {gpu::kFogBindingScatter, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
    };
    core::ComputePipelineDesc desc;
    desc.bindings = kBindings;
    switch (kernel) {
        case Kernel::Raymarch:
            desc.name = "fog.raymarch";
            desc.spirv = rgba32 ? spirv::fog_raymarch_comp_COLOR_RGBA32F : spirv::fog_raymarch_comp;
            break;
        case Kernel::RaymarchReduced:
            desc.name = "fog.raymarch";
            desc.spirv =
                rgba32 ? spirv::fog_raymarch_reduced_comp_COLOR_RGBA32F : spirv::fog_raymarch_reduced_comp;
            break;
        case Kernel::Upsample:
            desc.name = "fog.upsample";
            desc.spirv = rgba32 ? spirv::fog_upsample_comp_COLOR_RGBA32F : spirv::fog_upsample_comp;
            break;
    }
    return p.create(*gpu_, desc);
}

Status FogPass::prepareScatter(core::Retirement& retirement, uint64_t frameIndex, VkFormat format,
                               VkExtent3D extent) {
    if (scatter_) {
        const core::ImageDesc& d = scatter_->desc();
        if (d.format == format && d.extent.width == extent.width && d.extent.height == extent.height)
            return Status::success();
        retirement.retire(frameIndex, std::move(scatter_));  // frames in flight may still read it
    }
    core::ImageDesc desc;
    desc.format = format;
    desc.extent = extent;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    auto image = std::make_unique<core::GpuImage>();
    if (Status s = image->create(*gpu_, desc, "fog.scatter"); !s) return s;
    scatter_ = std::move(image);
    return Status::success();
}

namespace {

// Every uniform slot is 512 bytes: sizeof(FogUniforms) rounded up to 256, the largest
// minUniformBufferOffsetAlignment Vulkan allows, so the fog's memory is the same on every device.
constexpr VkDeviceSize kUniformSlotBytes = (sizeof(gpu::FogUniforms) + 255) / 256 * 256;

uint32_t groupsFor(uint32_t size) {
    return (size + gpu::kFogGroupSize - 1) / gpu::kFogGroupSize;
}

// The fog's decisions for a frame, shared by plan() and record().
struct FogFrame {
    bool noiseOn, generatedNoise, shadowRead, inPlace, reduced;
    glm::uvec2 full, march;
};

FogFrame decide(const FrameInfo& frame) {
    FogFrame f;
    const FogNoiseSettings& noise = frame.fog.noise;
    f.noiseOn = noise.enabled;
    f.generatedNoise = noise.enabled && !noise.hostTexture;
    // The shadow map only matters to the sun's term: with no sunlight it is not read.
    const glm::vec3 e = frame.sun.illuminance;
    f.shadowRead = frame.shadowMap.image.present() && (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f);
    f.inPlace = !frame.output.present();
    f.full = {frame.color.extent.width, frame.color.extent.height};
    f.march = fogMarchExtent(f.full.x, f.full.y, frame.fog.resolutionScale);
    f.reduced = f.march != f.full;
    return f;
}

uint64_t texelBytes(VkFormat colorFormat) {
    return colorFormat == VK_FORMAT_R32G32B32A32_SFLOAT ? 16 : 8;
}

}  // namespace

bool FogPass::runs(const FrameInfo& frame) {
    return frame.fog.enabled && !fogMediumEmpty(frame.fog, frame.fog.noise.enabled);
}

void FogPass::plan(const FrameInfo& frame, const FogPass* existing, uint32_t framesInFlight,
                   FramePlan& plan) {
    const FogFrame f = decide(frame);
    const FogNoiseSettings& noise = frame.fog.noise;
    const std::string target = f.inPlace ? "host.color" : "host.output";
    if (f.generatedNoise) {
        const bool generate =
            !existing || !existing->noise_ || existing->noise_->wouldGenerate(noise.textureSize, noise.seed);
        if (generate) {
            const uint32_t groups = noise.textureSize / gpu::kNoiseGroupSize;
            plan.passes.push_back({"fog.noise", "fog", {}, {"fog.noise"}, {groups, groups, groups}});
        }
        const uint64_t edge = noise.textureSize;
        plan.resources.push_back({"fog.noise", "fog", edge * edge * edge});
    } else if (!f.noiseOn) {
        plan.resources.push_back({"fog.no_noise", "fog", 1});
    }
    PlannedPass march{"fog.raymarch",
                      "fog",
                      {"host.color", "host.depth"},
                      {},
                      {groupsFor(f.march.x), groupsFor(f.march.y), 1}};
    if (f.reduced) march.reads = {"host.depth"};  // the color is read by the upsample
    if (f.shadowRead) march.reads.push_back("host.shadow_map");
    if (f.noiseOn) march.reads.push_back(f.generatedNoise ? "fog.noise" : "host.noise");
    march.reads.push_back("fog.uniforms");
    march.writes = {f.reduced ? "fog.scatter" : target};
    plan.passes.push_back(march);
    if (f.reduced) {
        plan.passes.push_back({"fog.upsample",
                               "fog",
                               {"host.color", "host.depth", "fog.scatter", "fog.uniforms"},
                               {target},
                               {groupsFor(f.full.x), groupsFor(f.full.y), 1}});
        plan.resources.push_back(
            {"fog.scatter", "fog", uint64_t(f.march.x) * f.march.y * texelBytes(frame.color.format)});
    }
    plan.resources.push_back({"fog.uniforms", "fog", kUniformSlotBytes * framesInFlight});
}

Status FogPass::createResources(const core::Gpu& gpu, const ContextCreateInfo& info) {
    gpu_ = &gpu;
    slots_ = info.framesInFlight;
    if (Status s = uniforms_.create(gpu, kUniformSlotBytes * slots_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true,
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
    return Status::success();
}

Status FogPass::record(const core::Gpu& gpu, const ContextCreateInfo& info, core::DescriptorArena& arena,
                       core::PassTimer& timer, core::Retirement& retirement, const FrameInfo& frame) {
    if (!uniforms_.handle()) {
        if (Status s = createResources(gpu, info); !s) {
            release();
            return s;
        }
    }
    VkCommandBuffer cmd = frame.commandBuffer;
    const FogFrame f = decide(frame);
    const FogNoiseSettings& noise = frame.fog.noise;
    // A texture of another size, or one nothing reads any more, may still be sampled by frames in flight.
    if (noise_ && (!f.generatedNoise || noise_->size() != noise.textureSize))
        retirement.retire(frame.frameIndex, std::move(noise_));
    if (f.generatedNoise) {
        if (!noise_) noise_ = std::make_unique<FogNoise>();
        if (Status s = noise_->prepare(gpu, noise.textureSize, noise.seed); !s) return s;
    }
    // The noise stand-in exists only while noise is off.
    if (f.noiseOn && noNoise_) {
        retirement.retire(frame.frameIndex, std::move(noNoise_));
        noNoiseReady_ = false;
    }
    if (!f.noiseOn && !noNoise_) {
        core::ImageDesc one;
        one.type = VK_IMAGE_TYPE_3D;
        one.format = VK_FORMAT_R8_UNORM;
        one.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
        auto image = std::make_unique<core::GpuImage>();
        if (Status s = image->create(gpu, one, "fog.no_noise"); !s) return s;
        noNoise_ = std::move(image);
        noNoiseReady_ = false;
    }
    if (noNoise_ && !noNoiseReady_) {  // to SHADER_READ_ONLY once; its contents are never read
        core::ImageTransition t;
        t.image = noNoise_->handle();
        t.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
        core::transition(gpu, cmd, t);
        noNoiseReady_ = true;
    }
    if (f.generatedNoise && noise_->needsGeneration()) {
        timer.beginPass(cmd, "fog.noise");
        Status s;
        noise_->recordGenerate(cmd, arena, s);
        timer.endPass(cmd);
        if (!s) return s;
    }

    // Uniforms for this frame's slot (the host guarantees the frame that used it last has completed).
    const gpu::FogUniforms u = buildUniforms(frame, info.depth, f.noiseOn, f.shadowRead);
    const VkDeviceSize offset = kUniformSlotBytes * (frame.frameIndex % slots_);
    std::memcpy(static_cast<char*>(uniforms_.mapped()) + offset, &u, sizeof u);

    // Resolution scale: march into scatter_ at the reduced size, then upsample; at full size, one pass.
    core::ComputePipeline* march = nullptr;
    core::ComputePipeline* upsample = nullptr;
    if (Status s =
            pipeline(f.reduced ? Kernel::RaymarchReduced : Kernel::Raymarch, frame.color.format, march);
        !s)
        return s;
    if (f.reduced) {
        if (Status s = pipeline(Kernel::Upsample, frame.color.format, upsample); !s) return s;
        if (Status s =
                prepareScatter(retirement, frame.frameIndex, frame.color.format, {f.march.x, f.march.y, 1});
            !s)
            return s;
    } else if (scatter_) {
        retirement.retire(frame.frameIndex, std::move(scatter_));
    }
    VkDescriptorSet marchSet = VK_NULL_HANDLE, upsampleSet = VK_NULL_HANDLE;
    if (Status s = arena.allocate(march->setLayout(), marchSet); !s) return s;
    if (f.reduced) {
        if (Status s = arena.allocate(upsample->setLayout(), upsampleSet); !s) return s;
    }

    constexpr VkAccessFlags kRead = VK_ACCESS_SHADER_READ_BIT, kWrite = VK_ACCESS_SHADER_WRITE_BIT;
    const core::HostImageUse depth = useHostImage(frame.depth, false, kRead);
    // At most color, depth, output and shadow map: a fixed array, no allocation per frame.
    std::array<core::HostImageUse, 4> useStorage{};
    size_t useCount = 0;
    useStorage[useCount++] = useHostImage(frame.color, true, f.inPlace ? kRead | kWrite : kRead);
    useStorage[useCount++] = depth;
    if (!f.inPlace) useStorage[useCount++] = useHostImage(frame.output, true, kWrite);
    if (f.shadowRead) useStorage[useCount++] = useHostImage(frame.shadowMap.image, false, kRead);
    const std::span<const core::HostImageUse> uses(useStorage.data(), useCount);

    // Without a shadow map the depth image stands in at its binding (never sampled: the flag is off).
    const VkImageView shadowView = f.shadowRead ? frame.shadowMap.image.view : frame.depth.view;
    const VkImageLayout shadowLayout = f.shadowRead ? uses.back().layout : depth.layout;
    const VkImageView noiseView =
        !f.noiseOn ? noNoise_->view() : (f.generatedNoise ? noise_->view() : noise.hostTexture);
    const VkImageLayout noiseLayout =
        f.noiseOn && !f.generatedNoise ? noise.hostTextureLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    for (VkDescriptorSet set : {marchSet, upsampleSet}) {
        if (!set) continue;
        core::DescriptorWrites writes(set);
        writes.storageImage(gpu::kFogBindingColorIn, frame.color.view)
            .storageImage(gpu::kFogBindingColorOut, f.inPlace ? frame.color.view : frame.output.view)
            .sampledImage(gpu::kFogBindingDepth, frame.depth.view, depth.layout, nearestClamp_)
            .sampledImage(gpu::kFogBindingShadowMap, shadowView, shadowLayout, nearestClamp_)
            .sampledImage(gpu::kFogBindingNoise, noiseView, noiseLayout, linearRepeat_)
            .uniformBuffer(gpu::kFogBindingUniforms, uniforms_.handle(), offset, sizeof(gpu::FogUniforms));
        if (f.reduced) writes.storageImage(gpu::kFogBindingScatter, scatter_->view());
        writes.apply(gpu);
    }

    for (const core::HostImageUse& use : uses)
        core::transition(gpu, cmd, use.acquire);
    auto dispatch = [&](const core::ComputePipeline& p, VkDescriptorSet set, glm::uvec2 size) {
        timer.beginPass(cmd, p.name());
        p.bind(cmd, set, nullptr);
        gpu.fn.vkCmdDispatch(cmd, groupsFor(size.x), groupsFor(size.y), 1);
        timer.endPass(cmd);
    };
    if (!f.reduced) {
        dispatch(*march, marchSet, f.full);
    } else {
        // The scatter image's old contents are discarded; its last reads (the previous frame's upsample)
        // finish before the march writes it.
        core::ImageTransition discard;
        discard.image = scatter_->handle();
        discard.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        discard.dstAccess = kWrite;
        core::transition(gpu, cmd, discard);
        dispatch(*march, marchSet, f.march);
        core::ImageTransition written;
        written.image = scatter_->handle();
        written.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
        written.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        written.srcAccess = kWrite;
        written.dstAccess = kRead;
        core::transition(gpu, cmd, written);
        dispatch(*upsample, upsampleSet, f.full);
    }
    for (const core::HostImageUse& use : uses)
        core::transition(gpu, cmd, use.release);
    return Status::success();
}

void FogPass::release() {
    noise_.reset();
    scatter_.reset();
    for (auto& kernel : pipelines_)
        for (core::ComputePipeline& p : kernel)
            p.reset();
    uniforms_.reset();
    noNoise_.reset();
    if (gpu_) {
        if (nearestClamp_) gpu_->fn.vkDestroySampler(gpu_->device, nearestClamp_, gpu_->allocator);
        if (linearRepeat_) gpu_->fn.vkDestroySampler(gpu_->device, linearRepeat_, gpu_->allocator);
    }
    nearestClamp_ = linearRepeat_ = VK_NULL_HANDLE;
    noNoiseReady_ = false;
    gpu_ = nullptr;
}

}  // namespace postfx::fog
