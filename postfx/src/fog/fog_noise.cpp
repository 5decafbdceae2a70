#include "fog/fog_noise.h"

#include "common/shared.h"
#include "core/barriers.h"
#include "postfx_spirv.h"

#include <string>

namespace postfx::fog {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8_UNORM;
constexpr uint32_t kMinSize = 16, kMaxSize = 256;

bool isPowerOfTwo(uint32_t v) {
    return v && !(v & (v - 1));
}

// R8_UNORM must be writable as a storage image, sampled with linear filtering (the fog's trilinear
// reads) and copied from (read-back).
Status checkFormat(const core::Gpu& gpu) {
    VkFormatProperties props{};
    gpu.fn.vkGetPhysicalDeviceFormatProperties(gpu.physicalDevice, kFormat, &props);
    const VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    if ((props.optimalTilingFeatures & needed) != needed)
        return {Result::Unsupported,
                "fog.noise: the device cannot use VK_FORMAT_R8_UNORM as a storage image, "
                "linearly filtered sampled image and transfer source (format features " +
                    std::to_string(props.optimalTilingFeatures) + ")"};
    return Status::success();
}

}  // namespace

Status FogNoise::prepare(const core::Gpu& gpu, uint32_t size, uint32_t seed) {
    if (size < kMinSize || size > kMaxSize || !isPowerOfTwo(size))
        return {Result::InvalidArgument,
                "fog.noise.texture_size: " + std::to_string(size) + " must be a power of two in [16, 256]"};
    if (gpu_ && gpu_ != &gpu) release();
    gpu_ = &gpu;

    if (!pipeline_.valid()) {
        if (Status s = checkFormat(gpu); !s) return s;
        const core::Binding bindings[] = {{gpu::kNoiseBindingTexture, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
        core::ComputePipelineDesc desc;
        desc.name = "fog.noise";
        desc.spirv = spirv::fog_noise_generate_comp;
        desc.bindings = bindings;
        desc.pushConstantBytes = sizeof(gpu::NoisePush);
        if (Status s = pipeline_.create(gpu, desc); !s) return s;
    }

    if (!image_.handle() || size != size_) {
        image_.reset();
        size_ = 0;
        generated_ = false;
        core::ImageDesc desc;
        desc.type = VK_IMAGE_TYPE_3D;
        desc.format = kFormat;
        desc.extent = {size, size, size};
        desc.usage =
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        if (Status s = image_.create(gpu, desc, "fog.noise"); !s) return s;
        size_ = size;
        seed_ = seed;
        pending_ = true;
    } else if (seed != seed_) {
        seed_ = seed;
        pending_ = true;
    }
    return Status::success();
}

bool FogNoise::recordGenerate(VkCommandBuffer cmd, core::DescriptorArena& arena, Status& status) {
    status = Status::success();
    if (!pending_ || !image_.handle()) return false;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (Status s = arena.allocate(pipeline_.setLayout(), set); !s) {
        status = {s.code, "fog.noise: " + s.message};
        return false;
    }
    core::DescriptorWrites(set).storageImage(gpu::kNoiseBindingTexture, image_.view()).apply(*gpu_);

    // To GENERAL for the shader's writes, discarding the old texels. A regeneration must wait for the
    // earlier commands that read the old texture: the fog's sampling (compute shader). A read-back's
    // copy is covered too: its closing barrier ends in the compute stage, which this one chains to.
    core::ImageTransition t;
    t.image = image_.handle();
    t.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    t.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    t.srcStage = generated_ ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT : VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    t.srcAccess = 0;
    t.dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.dstAccess = VK_ACCESS_SHADER_WRITE_BIT;
    core::transition(*gpu_, cmd, t);

    const gpu::NoisePush push{glm::uvec4(size_, seed_, 0u, 0u)};
    pipeline_.bind(cmd, set, &push);
    const uint32_t groups = size_ / gpu::kNoiseGroupSize;  // size is a power of two >= 16
    gpu_->fn.vkCmdDispatch(cmd, groups, groups, groups);

    // Shader writes -> the fog's sampled reads (compute).
    t.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
    t.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.srcAccess = VK_ACCESS_SHADER_WRITE_BIT;
    t.dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
    core::transition(*gpu_, cmd, t);

    pending_ = false;
    generated_ = true;
    return true;
}

Status FogNoise::recordReadback(VkCommandBuffer cmd, VkBuffer dst, VkDeviceSize offset) const {
    if (!ready()) return {Result::InvalidArgument, "fog.noise: read-back of a texture not generated yet"};
    if (!dst) return {Result::InvalidArgument, "fog.noise: read-back into a null buffer"};

    // SHADER_READ_ONLY -> TRANSFER_SRC after the earlier compute reads (the texels' writes were made
    // available by the generation's barrier).
    core::ImageTransition t;
    t.image = image_.handle();
    t.oldLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    t.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.srcAccess = 0;
    t.dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    t.dstAccess = VK_ACCESS_TRANSFER_READ_BIT;
    core::transition(*gpu_, cmd, t);

    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.bufferRowLength = 0;  // tightly packed: x fastest, then y, then z
    region.bufferImageHeight = 0;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {size_, size_, size_};
    gpu_->fn.vkCmdCopyImageToBuffer(cmd, image_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, 1,
                                    &region);

    // Back to SHADER_READ_ONLY for the fog (the copy only read it).
    t.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    t.srcStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    t.srcAccess = 0;
    t.dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
    core::transition(*gpu_, cmd, t);

    // The copied bytes -> host reads after the submission's fence.
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = dst;
    toHost.offset = offset;
    toHost.size = texelBytes();
    gpu_->fn.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                                  nullptr, 1, &toHost, 0, nullptr);
    return Status::success();
}

void FogNoise::release() {
    image_.reset();
    pipeline_.reset();
    gpu_ = nullptr;
    size_ = 0;
    seed_ = 0;
    pending_ = false;
    generated_ = false;
}

}  // namespace postfx::fog
