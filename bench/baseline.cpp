// The benchmark's two baselines (bench/baseline.h): compute pipelines over postfx's fog bindings and
// FogUniforms (built by postfx::fog::buildUniforms), plus a push constant with the step length. The bench
// is a host: it calls the Vulkan loader directly (vk*), with the demo host's device.
#include "baseline.h"

#include "bench_baseline_spirv.h"
#include "core/checks.h"
#include "fog/fog_settings.h"
#include "fog/fog_shared.h"
#include "fog/fog_uniforms.h"
#include "host/gpu_resources.h"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

namespace bench {
namespace {

namespace gpu = postfx::gpu;

// record() calls one frame slot can hold: each gets its own uniform block and descriptor set, so a
// frame may record several baselines (both kinds, several step lengths) into its command buffers.
constexpr uint32_t kMaxRecordsPerFrame = 16;

struct PushConstants {
    float stepLength;  // [m]
};

constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

uint32_t findMemoryType(const demo::VulkanHost& host, uint32_t typeBits, VkMemoryPropertyFlags need) {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(host.physicalDevice, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & need) == need) return i;
    return UINT32_MAX;
}

// A 1×1×1 R8_UNORM 3D image and view (demo::createImage makes 2D images only).
bool createStandIn3D(const demo::VulkanHost& host, demo::GpuImage& out, std::string& error) {
    out.format = VK_FORMAT_R8_UNORM;
    out.extent = {1, 1};
    out.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_3D;
    ici.format = out.format;
    ici.extent = {1, 1, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (!demo::vkCheck(vkCreateImage(host.device, &ici, nullptr, &out.image),
                       "vkCreateImage (baseline stand-in)", error))
        return false;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(host.device, out.image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = findMemoryType(host, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (ai.memoryTypeIndex == UINT32_MAX) ai.memoryTypeIndex = findMemoryType(host, req.memoryTypeBits, 0);
    if (ai.memoryTypeIndex == UINT32_MAX) {
        error = "no Vulkan memory type for the baseline's stand-in noise image";
        return false;
    }
    if (!demo::vkCheck(vkAllocateMemory(host.device, &ai, nullptr, &out.memory), "vkAllocateMemory", error))
        return false;
    if (!demo::vkCheck(vkBindImageMemory(host.device, out.image, out.memory, 0), "vkBindImageMemory", error))
        return false;
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = out.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_3D;
    vci.format = out.format;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    return demo::vkCheck(vkCreateImageView(host.device, &vci, nullptr, &out.view), "vkCreateImageView",
                         error);
}

}  // namespace

const char* baselineName(Baseline b) {
    switch (b) {
        case Baseline::SeedAsWritten:
            return "seed-as-written";
        case Baseline::SeedFixedRiemann:
            return "seed-fixed-riemann";
    }
    return "unknown";
}

struct BaselinePass::Impl {
    explicit Impl(demo::VulkanHost& h) : host(h) {}
    ~Impl();

    demo::VulkanHost& host;
    uint32_t slots = 0;  // frames in flight

    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    std::array<VkPipeline, 2> pipelines{};  // indexed by Baseline
    VkSampler nearestClamp = VK_NULL_HANDLE;
    VkSampler linearRepeat = VK_NULL_HANDLE;

    // Uniform ring: slots × kMaxRecordsPerFrame aligned FogUniforms blocks, host-visible and coherent.
    demo::GpuBuffer uniforms;
    VkDeviceSize uniformStride = 0;

    // One descriptor pool per frame slot, reset when a frame records its first baseline. A frame's
    // records are the consecutive record() calls with the same frameIndex: a call whose frameIndex
    // differs from the previous call's starts a new frame (so frame indices may restart, e.g. per
    // benchmark configuration, as long as the host waits as FrameInfo requires).
    struct Slot {
        VkDescriptorPool pool = VK_NULL_HANDLE;
        uint32_t records = 0;  // record() calls of the frame now using the slot
    };
    std::vector<Slot> frameSlots;
    bool recorded = false;        // record() has been called (lastFrameIndex is valid)
    uint64_t lastFrameIndex = 0;  // frameIndex of the previous record() call

    demo::GpuImage noShadowMap;  // 1×1 R32_SFLOAT stand-in when the frame has no shadow map
    demo::GpuImage noNoise;      // 1×1×1 R8_UNORM stand-in when noiseView is null
    bool standInsReady = false;  // both transitioned to SHADER_READ_ONLY_OPTIMAL (recorded once)

    bool create(uint32_t framesInFlight, std::string& error);
};

BaselinePass::Impl::~Impl() {
    const VkDevice device = host.device;
    for (VkPipeline p : pipelines)
        if (p) vkDestroyPipeline(device, p, nullptr);
    if (pipelineLayout) vkDestroyPipelineLayout(device, pipelineLayout, nullptr);
    if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    for (Slot& s : frameSlots)
        if (s.pool) vkDestroyDescriptorPool(device, s.pool, nullptr);
    if (nearestClamp) vkDestroySampler(device, nearestClamp, nullptr);
    if (linearRepeat) vkDestroySampler(device, linearRepeat, nullptr);
    demo::destroyBuffer(device, uniforms);
    demo::destroyImage(device, noShadowMap);
    demo::destroyImage(device, noNoise);
}

bool BaselinePass::Impl::create(uint32_t framesInFlight, std::string& error) {
    const VkDevice device = host.device;
    if (framesInFlight == 0) {
        error = "BaselinePass: framesInFlight must be at least 1";
        return false;
    }
    slots = framesInFlight;

    // The bindings of shaders/fog/raymarch.comp (common/shared.h).
    const std::array<VkDescriptorSetLayoutBinding, 6> bindings = {{
        {gpu::kFogBindingColorIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {gpu::kFogBindingColorOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {gpu::kFogBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
        {gpu::kFogBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
        {gpu::kFogBindingNoise, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
        {gpu::kFogBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
    }};
    VkDescriptorSetLayoutCreateInfo dslci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dslci.bindingCount = uint32_t(bindings.size());
    dslci.pBindings = bindings.data();
    if (!demo::vkCheck(vkCreateDescriptorSetLayout(device, &dslci, nullptr, &setLayout),
                       "vkCreateDescriptorSetLayout (baseline)", error))
        return false;

    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &push;
    if (!demo::vkCheck(vkCreatePipelineLayout(device, &plci, nullptr, &pipelineLayout),
                       "vkCreatePipelineLayout (baseline)", error))
        return false;

    const std::array<std::span<const uint32_t>, 2> spirv = {spirv::bench_shaders_seed_as_written_comp,
                                                            spirv::bench_shaders_seed_fixed_riemann_comp};
    for (size_t i = 0; i < spirv.size(); ++i)
        if (!demo::createComputePipeline(device, spirv[i], pipelineLayout,
                                         "vkCreateComputePipelines (baseline)", pipelines[i], error))
            return false;

    // The samplers of postfx's fog pass: nearest/clamp for texelFetch of depth and shadow map,
    // linear/repeat for the noise.
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    if (!demo::vkCheck(vkCreateSampler(device, &sci, nullptr, &nearestClamp), "vkCreateSampler (baseline)",
                       error))
        return false;
    sci.magFilter = sci.minFilter = VK_FILTER_LINEAR;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    if (!demo::vkCheck(vkCreateSampler(device, &sci, nullptr, &linearRepeat), "vkCreateSampler (baseline)",
                       error))
        return false;

    const VkDeviceSize align =
        std::max<VkDeviceSize>(host.properties.limits.minUniformBufferOffsetAlignment, 16);
    uniformStride = (sizeof(gpu::FogUniforms) + align - 1) / align * align;
    if (!demo::createBuffer(host, uniformStride * slots * kMaxRecordsPerFrame,
                            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true, uniforms, error))
        return false;

    const std::array<VkDescriptorPoolSize, 3> sizes = {{
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 2 * kMaxRecordsPerFrame},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * kMaxRecordsPerFrame},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kMaxRecordsPerFrame},
    }};
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = kMaxRecordsPerFrame;
    dpci.poolSizeCount = uint32_t(sizes.size());
    dpci.pPoolSizes = sizes.data();
    frameSlots.resize(slots);
    for (Slot& s : frameSlots)
        if (!demo::vkCheck(vkCreateDescriptorPool(device, &dpci, nullptr, &s.pool),
                           "vkCreateDescriptorPool (baseline)", error))
            return false;

    if (!demo::createImage(host, VK_FORMAT_R32_SFLOAT, {1, 1}, VK_IMAGE_USAGE_SAMPLED_BIT, noShadowMap,
                           error))
        return false;
    return createStandIn3D(host, noNoise, error);
}

std::unique_ptr<BaselinePass> BaselinePass::create(demo::VulkanHost& host, uint32_t framesInFlight,
                                                   std::string& error) {
    auto impl = std::make_unique<Impl>(host);
    if (!impl->create(framesInFlight, error)) return nullptr;
    return std::unique_ptr<BaselinePass>(new BaselinePass(std::move(impl)));
}

BaselinePass::BaselinePass(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BaselinePass::~BaselinePass() = default;

bool BaselinePass::record(VkCommandBuffer cmd, const postfx::FrameInfo& frame,
                          const postfx::DepthConvention& depth, Baseline which, float stepLength,
                          VkImageView noiseView, VkQueryPool queryPool, uint32_t query, std::string& error) {
    Impl& m = *impl_;
    const VkDevice device = m.host.device;

    // Inputs: the same checks as postfx's fog, plus what the baseline itself needs.
    if (!(stepLength > 0.0f) || !std::isfinite(stepLength)) {
        error = std::string(baselineName(which)) + ": step length must be finite and > 0";
        return false;
    }
    postfx::ContextCreateInfo limits;
    limits.maxExtent = {16384, 16384};
    postfx::Status s = postfx::core::checkSharedInputs(frame, limits);
    if (s) s = postfx::fog::validateSettings(frame.fog);
    if (!s) {
        error = std::string(baselineName(which)) + ": " + s.message;
        return false;
    }
    if (frame.color.format != VK_FORMAT_R16G16B16A16_SFLOAT ||
        frame.color.layout != VK_IMAGE_LAYOUT_GENERAL || !frame.color.view) {
        error = std::string(baselineName(which)) + ": FrameInfo.color must be an RGBA16F view in GENERAL";
        return false;
    }
    if (!frame.depth.view) {
        error = std::string(baselineName(which)) + ": FrameInfo.depth.view is VK_NULL_HANDLE";
        return false;
    }
    if (frame.output.present()) {
        error = std::string(baselineName(which)) + ": FrameInfo.output is not supported (in place only)";
        return false;
    }
    const size_t pipelineIndex = which == Baseline::SeedAsWritten ? 0 : 1;

    // This frame's slot: a new frame resets its descriptor pool (the host has waited for the frame that
    // used the slot last, framesInFlight frames ago).
    Impl::Slot& slot = m.frameSlots[frame.frameIndex % m.slots];
    if (!m.recorded || m.lastFrameIndex != frame.frameIndex) {
        if (!demo::vkCheck(vkResetDescriptorPool(device, slot.pool, 0), "vkResetDescriptorPool (baseline)",
                           error))
            return false;
        slot.records = 0;
        m.recorded = true;
        m.lastFrameIndex = frame.frameIndex;
    }
    if (slot.records >= kMaxRecordsPerFrame) {
        error = std::string(baselineName(which)) + ": more than " + std::to_string(kMaxRecordsPerFrame) +
                " baseline records in one frame";
        return false;
    }
    const uint32_t block = uint32_t(frame.frameIndex % m.slots) * kMaxRecordsPerFrame + slot.records;
    ++slot.records;

    const bool noiseOn = noiseView != VK_NULL_HANDLE;
    const bool shadowOn = frame.shadowMap.image.present();
    const gpu::FogUniforms u = postfx::fog::buildUniforms(frame, depth, noiseOn, shadowOn);
    const VkDeviceSize offset = m.uniformStride * block;
    std::memcpy(static_cast<char*>(m.uniforms.mapped) + offset, &u, sizeof u);

    VkDescriptorSet set = VK_NULL_HANDLE;
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = slot.pool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &m.setLayout;
    if (!demo::vkCheck(vkAllocateDescriptorSets(device, &dsai, &set), "vkAllocateDescriptorSets (baseline)",
                       error))
        return false;

    const VkDescriptorImageInfo colorInfo{VK_NULL_HANDLE, frame.color.view, VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorImageInfo depthInfo{m.nearestClamp, frame.depth.view, frame.depth.layout};
    const VkDescriptorImageInfo shadowInfo =
        shadowOn
            ? VkDescriptorImageInfo{m.nearestClamp, frame.shadowMap.image.view, frame.shadowMap.image.layout}
            : VkDescriptorImageInfo{m.nearestClamp, m.noShadowMap.view,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo noiseInfo{m.linearRepeat, noiseOn ? noiseView : m.noNoise.view,
                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorBufferInfo uniformInfo{m.uniforms.buffer, offset, sizeof(gpu::FogUniforms)};
    auto write = [&](uint32_t binding, VkDescriptorType type) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        return w;
    };
    std::array<VkWriteDescriptorSet, 6> writes = {
        write(gpu::kFogBindingColorIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
        write(gpu::kFogBindingColorOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
        write(gpu::kFogBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER),
        write(gpu::kFogBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER),
        write(gpu::kFogBindingNoise, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER),
        write(gpu::kFogBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    };
    writes[0].pImageInfo = &colorInfo;  // in place: read and written through the same view
    writes[1].pImageInfo = &colorInfo;
    writes[2].pImageInfo = &depthInfo;
    writes[3].pImageInfo = &shadowInfo;
    writes[4].pImageInfo = &noiseInfo;
    writes[5].pBufferInfo = &uniformInfo;
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);

    // One-time: the stand-ins go to SHADER_READ_ONLY (never sampled: the flags skip them).
    if (!m.standInsReady) {
        for (demo::GpuImage* image : {&m.noShadowMap, &m.noNoise})
            demo::imageBarrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                               kCompute, VK_ACCESS_SHADER_READ_BIT);
        m.standInsReady = true;
    }

    // The caller guarantees: color in GENERAL with prior writes visible to compute; depth and shadow map
    // readable by compute shaders in their given layouts. No barrier is needed before the dispatch.
    const PushConstants push{stepLength};
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queryPool, query);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipelines[pipelineIndex]);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipelineLayout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, m.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    const uint32_t group = gpu::kFogGroupSize;
    vkCmdDispatch(cmd, (frame.color.extent.width + group - 1) / group,
                  (frame.color.extent.height + group - 1) / group, 1);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queryPool, query + 1);

    // The color writes, visible to later compute shaders and transfers (read or write); still GENERAL.
    VkImageMemoryBarrier after{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                          VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    after.oldLayout = after.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    after.srcQueueFamilyIndex = after.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    after.image = frame.color.image;
    after.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, kCompute, kCompute | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &after);
    return true;
}

}  // namespace bench
