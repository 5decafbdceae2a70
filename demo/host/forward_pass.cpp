#include "host/forward_pass.h"

#include "demo_host_spirv.h"
#include "demo_shared.h"

#include <postfx/volumetrics_lookup.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace demo {
namespace {

constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL;

postfx::VolumetricsLookupBindings lookupBindings() {
    postfx::VolumetricsLookupBindings b;
    b.uniforms = shared::kForwardBindingLookupUniforms;
    b.scattering = shared::kForwardBindingLookupScattering;
    b.transmittance = shared::kForwardBindingLookupTransmittance;
    return b;
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace

bool ForwardPass::create(const VulkanHost& host, const GpuImage& hdr, VkDescriptorSetLayout lightingSetLayout,
                         uint32_t framesInFlight, std::string& error) {
    const VkDevice device = host.device;
    extent_ = hdr.extent;

    // One colour attachment, loaded and stored in GENERAL (the layout the HDR image rests in), so the pass
    // has no layout transition; record() orders it with explicit barriers.
    const VkAttachmentDescription color{0,
                                        hdr.format,
                                        VK_SAMPLE_COUNT_1_BIT,
                                        VK_ATTACHMENT_LOAD_OP_LOAD,
                                        VK_ATTACHMENT_STORE_OP_STORE,
                                        VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                        VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                        kGeneral,
                                        kGeneral};
    const VkAttachmentReference ref{0, kGeneral};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rpci.attachmentCount = 1;
    rpci.pAttachments = &color;
    rpci.subpassCount = 1;
    rpci.pSubpasses = &subpass;
    if (!vkCheck(vkCreateRenderPass(device, &rpci, nullptr, &renderPass_), "vkCreateRenderPass (forward)",
                 error))
        return false;
    VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = renderPass_;
    fci.attachmentCount = 1;
    fci.pAttachments = &hdr.view;
    fci.width = extent_.width;
    fci.height = extent_.height;
    fci.layers = 1;
    if (!vkCheck(vkCreateFramebuffer(device, &fci, nullptr, &framebuffer_), "vkCreateFramebuffer (forward)",
                 error))
        return false;

    // Set 1: postfx's lookup, one set per frame in flight.
    VkDescriptorSetLayoutBinding bindings[postfx::kVolumetricsLookupBindingCount];
    postfx::volumetricsLookupLayout(lookupBindings(), VK_SHADER_STAGE_FRAGMENT_BIT, bindings);
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = postfx::kVolumetricsLookupBindingCount;
    lci.pBindings = bindings;
    if (!vkCheck(vkCreateDescriptorSetLayout(device, &lci, nullptr, &lookupLayout_),
                 "vkCreateDescriptorSetLayout (forward)", error))
        return false;
    const std::array<VkDescriptorPoolSize, 2> sizes{{
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * framesInFlight},
    }};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = framesInFlight;
    pci.poolSizeCount = uint32_t(sizes.size());
    pci.pPoolSizes = sizes.data();
    if (!vkCheck(vkCreateDescriptorPool(device, &pci, nullptr, &lookupPool_),
                 "vkCreateDescriptorPool (forward)", error))
        return false;
    lookupSets_.resize(framesInFlight);
    const std::vector<VkDescriptorSetLayout> layouts(framesInFlight, lookupLayout_);
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = lookupPool_;
    ai.descriptorSetCount = framesInFlight;
    ai.pSetLayouts = layouts.data();
    if (!vkCheck(vkAllocateDescriptorSets(device, &ai, lookupSets_.data()),
                 "vkAllocateDescriptorSets (forward)", error))
        return false;

    const VkDescriptorSetLayout setLayouts[2] = {lightingSetLayout, lookupLayout_};
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof(shared::ForwardPush)};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 2;
    plci.pSetLayouts = setLayouts;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &push;
    if (!vkCheck(vkCreatePipelineLayout(device, &plci, nullptr, &layout_), "vkCreatePipelineLayout (forward)",
                 error))
        return false;
    particleBuffers_.resize(framesInFlight);
    return createPipeline(device, spirv::forward_frag, pipeline_, error);
}

bool ForwardPass::createPipeline(VkDevice device, std::span<const uint32_t> fragment, VkPipeline& out,
                                 std::string& error) {
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    bool ok = createShaderModule(device, spirv::forward_vert, modules[0], error) &&
              createShaderModule(device, fragment, modules[1], error);
    VkPipelineShaderStageCreateInfo stages[2]{};
    for (int i = 0; i < 2; ++i) {
        stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        stages[i].module = modules[i];
        stages[i].pName = "main";
    }
    const VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[2] = {
        {shared::kAttribPosition, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {shared::kAttribNormal, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, normal))}};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 2;
    vertexInput.pVertexAttributeDescriptions = attributes;
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    const VkViewport viewport{0, 0, float(extent_.width), float(extent_.height), 0, 1};
    const VkRect2D scissor{{0, 0}, extent_};
    VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewportState.viewportCount = 1;
    viewportState.pViewports = &viewport;
    viewportState.scissorCount = 1;
    viewportState.pScissors = &scissor;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;  // forward.frag discards closed objects' back faces
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    // out = src · α + dst · (1 − α); the frame's alpha kept.
    VkPipelineColorBlendAttachmentState blendState{};
    blendState.blendEnable = VK_TRUE;
    blendState.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blendState.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blendState.colorBlendOp = VK_BLEND_OP_ADD;
    blendState.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
    blendState.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blendState.alphaBlendOp = VK_BLEND_OP_ADD;
    blendState.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blendState;

    VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gci.stageCount = 2;
    gci.pStages = stages;
    gci.pVertexInputState = &vertexInput;
    gci.pInputAssemblyState = &assembly;
    gci.pViewportState = &viewportState;
    gci.pRasterizationState = &raster;
    gci.pMultisampleState = &multisample;
    gci.pColorBlendState = &blend;
    gci.layout = layout_;
    gci.renderPass = renderPass_;
    if (ok) {
        ok = vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &gci, nullptr, &out),
                     "vkCreateGraphicsPipelines (forward)", error);
    }
    for (VkShaderModule m : modules)
        if (m) vkDestroyShaderModule(device, m, nullptr);
    return ok;
}

void ForwardPass::destroy(VkDevice device) {
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (lookupPool_) vkDestroyDescriptorPool(device, lookupPool_, nullptr);
    if (lookupLayout_) vkDestroyDescriptorSetLayout(device, lookupLayout_, nullptr);
    if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    for (GpuBuffer& b : particleBuffers_)
        destroyBuffer(device, b);
    *this = ForwardPass{};
}

bool ForwardPass::upload(const VulkanHost& host, size_t slot, const ForwardFrame& frame, std::string& error) {
    const VkDeviceSize bytes = frame.particleVertices.size() * sizeof(MeshVertex);
    if (bytes == 0) return true;
    GpuBuffer& buffer = particleBuffers_[slot];
    if (buffer.size < bytes) {
        destroyBuffer(host.device, buffer);
        if (!createBuffer(host, std::max<VkDeviceSize>(bytes, 64 * 1024), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                          true, buffer, error))
            return false;
    }
    std::memcpy(buffer.mapped, frame.particleVertices.data(), bytes);
    return true;
}

void ForwardPass::record(VkCommandBuffer cmd, size_t slot, const ForwardFrame& frame,
                         const Inputs& in) const {
    if (frame.draws.empty()) return;
    // postfx's composite into the HDR image, its lookup and the clouds' shadow map before this pass's
    // reads and blending (its reads of the HDR image before the blend's writes).
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rbi.renderPass = renderPass_;
    rbi.framebuffer = framebuffer_;
    rbi.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &in.lightingSet, 0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, shared::kForwardLookupSet, 1,
                            &lookupSets_[slot], 0, nullptr);
    const VkDeviceSize offset = 0;
    vkCmdBindIndexBuffer(cmd, in.indices->buffer, 0, VK_INDEX_TYPE_UINT32);
    int bound = -1;  // 0: the scene mesh's vertices, 1: the particles'
    for (const ForwardDraw& d : frame.draws) {
        const int want = d.particle ? 1 : 0;
        if (want != bound) {
            const VkBuffer vb = d.particle ? particleBuffers_[slot].buffer : in.vertices->buffer;
            vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
            bound = want;
        }
        const shared::ForwardPush push{glm::vec4(d.albedo, d.opacity),
                                       glm::vec4(float(d.kind), in.lookup ? 0.0f : 1.0f, 0.0f, 0.0f),
                                       in.cloudShadowU, in.cloudShadowV};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
        if (d.particle)
            vkCmdDraw(cmd, d.count, 1, d.first, 0);
        else
            vkCmdDrawIndexed(cmd, d.count, 1, d.first, 0, 0);
    }
    vkCmdEndRenderPass(cmd);
    // The blend's writes visible to compute (the HDR image's readers chain their barriers from
    // COMPUTE_SHADER), and every read above done before later compute work overwrites what it read.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

}  // namespace demo
