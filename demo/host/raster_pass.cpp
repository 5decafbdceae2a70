#include "host/raster_pass.h"

#include "demo_shared.h"

namespace demo {
namespace {

// Shadow map bias: depth slope-scaled (in the rasterizer) on top of the lighting's normal offset.
constexpr float kDepthBiasConstant = 2.0f;
constexpr float kDepthBiasSlope = 1.5f;

constexpr VkImageLayout kColorRest = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
constexpr VkImageLayout kDepthRest = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
constexpr VkImageLayout kColorAttachment = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
constexpr VkImageLayout kDepthAttachment = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

VkImageMemoryBarrier barrier(const GpuImage& image, VkImageLayout from, VkImageLayout to,
                             VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image.image;
    b.subresourceRange = {image.aspect, 0, 1, 0, 1};
    return b;
}

}  // namespace

bool RasterPass::create(const VulkanHost& host, const RasterPassDesc& desc,
                        VkDescriptorSetLayout frameSetLayout, std::string& error) {
    const VkDevice device = host.device;
    extent_ = desc.extent;
    depthClear_ = desc.depthClear;
    hasFragment_ = !desc.fragmentShader.empty();
    color.resize(desc.colorFormats.size());
    const std::string prefix = std::string(desc.name) + ": ";
    for (size_t i = 0; i < color.size(); ++i) {
        if (!createImage(host, desc.colorFormats[i], extent_,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, color[i], error)) {
            error = prefix + error;
            return false;
        }
    }
    // TRANSFER_SRC: Renderer::renderReference reads depth and shadow map back for the CPU reference.
    if (!createImage(host, VK_FORMAT_D32_SFLOAT, extent_,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                     depth, error)) {
        error = prefix + error;
        return false;
    }

    // Render pass: attachments stay in their attachment layouts; record() transitions them around it
    // with explicit barriers, so there are no implicit layout transitions to reason about.
    std::vector<VkAttachmentDescription> attachments;
    std::vector<VkAttachmentReference> colorRefs;
    std::vector<VkImageView> views;
    for (const GpuImage& c : color) {
        colorRefs.push_back({uint32_t(attachments.size()), kColorAttachment});
        attachments.push_back({0, c.format, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR,
                               VK_ATTACHMENT_STORE_OP_STORE, VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                               VK_ATTACHMENT_STORE_OP_DONT_CARE, kColorAttachment, kColorAttachment});
        views.push_back(c.view);
    }
    const VkAttachmentReference depthRef{uint32_t(attachments.size()), kDepthAttachment};
    attachments.push_back({0, depth.format, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR,
                           VK_ATTACHMENT_STORE_OP_STORE, VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                           VK_ATTACHMENT_STORE_OP_DONT_CARE, kDepthAttachment, kDepthAttachment});
    views.push_back(depth.view);
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = uint32_t(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pDepthStencilAttachment = &depthRef;
    VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rpci.attachmentCount = uint32_t(attachments.size());
    rpci.pAttachments = attachments.data();
    rpci.subpassCount = 1;
    rpci.pSubpasses = &subpass;
    if (!vkCheck(vkCreateRenderPass(device, &rpci, nullptr, &renderPass_), "vkCreateRenderPass", error))
        return false;
    VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = renderPass_;
    fci.attachmentCount = uint32_t(views.size());
    fci.pAttachments = views.data();
    fci.width = extent_.width;
    fci.height = extent_.height;
    fci.layers = 1;
    if (!vkCheck(vkCreateFramebuffer(device, &fci, nullptr, &framebuffer_), "vkCreateFramebuffer", error))
        return false;

    VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(shared::DrawPush)};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = 1;
    lci.pSetLayouts = &frameSetLayout;
    lci.pushConstantRangeCount = hasFragment_ ? 1 : 0;
    lci.pPushConstantRanges = &push;
    if (!vkCheck(vkCreatePipelineLayout(device, &lci, nullptr, &layout_), "vkCreatePipelineLayout", error))
        return false;
    return createPipeline(device, desc, error);
}

bool RasterPass::createPipeline(VkDevice device, const RasterPassDesc& desc, std::string& error) {
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkPipelineShaderStageCreateInfo stages[2]{};
    bool ok = createShaderModule(device, desc.vertexShader, modules[0], error) &&
              (!hasFragment_ || createShaderModule(device, desc.fragmentShader, modules[1], error));
    for (int i = 0; i < 2; ++i) {
        stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        stages[i].module = modules[i];
        stages[i].pName = "main";
    }
    // Interleaved MeshVertex: position, then normal (the depth-only pass reads positions only).
    const VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[2] = {
        {shared::kAttribPosition, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {shared::kAttribNormal, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, normal))}};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = hasFragment_ ? 2 : 1;
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
    raster.cullMode = VK_CULL_MODE_NONE;  // planes are two-sided; boxes and spheres are closed
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.depthBiasEnable = desc.depthBias;
    raster.depthBiasConstantFactor = desc.depthBias ? kDepthBiasConstant : 0.0f;
    raster.depthBiasSlopeFactor = desc.depthBias ? kDepthBiasSlope : 0.0f;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depthState{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depthState.depthTestEnable = VK_TRUE;
    depthState.depthWriteEnable = VK_TRUE;
    depthState.depthCompareOp = desc.depthCompare;
    std::vector<VkPipelineColorBlendAttachmentState> blends(color.size());
    for (auto& b : blends)
        b.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();

    VkGraphicsPipelineCreateInfo pci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pci.stageCount = hasFragment_ ? 2 : 1;
    pci.pStages = stages;
    pci.pVertexInputState = &vertexInput;
    pci.pInputAssemblyState = &assembly;
    pci.pViewportState = &viewportState;
    pci.pRasterizationState = &raster;
    pci.pMultisampleState = &multisample;
    pci.pDepthStencilState = &depthState;
    pci.pColorBlendState = &blend;
    pci.layout = layout_;
    pci.renderPass = renderPass_;
    if (ok) {
        ok = vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pci, nullptr, &pipeline_),
                     "vkCreateGraphicsPipelines", error);
    }
    for (VkShaderModule m : modules)
        if (m) vkDestroyShaderModule(device, m, nullptr);
    return ok;
}

void RasterPass::destroy(VkDevice device) {
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    framebuffer_ = VK_NULL_HANDLE;
    renderPass_ = VK_NULL_HANDLE;
    for (GpuImage& c : color)
        destroyImage(device, c);
    color.clear();
    destroyImage(device, depth);
}

// toAttachment: rest -> attachment (after the previous frame's compute reads; content discarded).
// Otherwise attachment -> rest (attachment writes made visible to compute shader reads).
void RasterPass::transition(VkCommandBuffer cmd, bool toAttachment) const {
    std::vector<VkImageMemoryBarrier> barriers;
    const VkAccessFlags colorWrite = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    const VkAccessFlags depthRW =
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    const VkAccessFlags read = VK_ACCESS_SHADER_READ_BIT;
    for (const GpuImage& c : color) {
        barriers.push_back(toAttachment
                               ? barrier(c, VK_IMAGE_LAYOUT_UNDEFINED, kColorAttachment, 0, colorWrite)
                               : barrier(c, kColorAttachment, kColorRest, colorWrite, read));
    }
    barriers.push_back(toAttachment ? barrier(depth, VK_IMAGE_LAYOUT_UNDEFINED, kDepthAttachment, 0, depthRW)
                                    : barrier(depth, kDepthAttachment, kDepthRest,
                                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, read));
    const VkPipelineStageFlags compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    VkPipelineStageFlags attachmentStages = kDepthStages;
    if (!color.empty()) attachmentStages |= VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    vkCmdPipelineBarrier(cmd, toAttachment ? compute : attachmentStages,
                         toAttachment ? attachmentStages : compute, 0, 0, nullptr, 0, nullptr,
                         uint32_t(barriers.size()), barriers.data());
}

void RasterPass::record(VkCommandBuffer cmd, VkDescriptorSet frameSet, const GpuBuffer& vertices,
                        const GpuBuffer& indices, std::span<const MeshDraw> draws) const {
    transition(cmd, true);
    std::vector<VkClearValue> clears(color.size() + 1);
    for (size_t i = 0; i < color.size(); ++i)
        clears[i].color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    clears.back().depthStencil = {depthClear_, 0};
    VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rbi.renderPass = renderPass_;
    rbi.framebuffer = framebuffer_;
    rbi.renderArea = {{0, 0}, extent_};
    rbi.clearValueCount = uint32_t(clears.size());
    rbi.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (!draws.empty()) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frameSet, 0, nullptr);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        for (const MeshDraw& d : draws) {
            if (hasFragment_) {
                const shared::DrawPush push{glm::vec4(d.albedo, 1.0f)};
                vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
            }
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, 0, 0);
        }
    }
    vkCmdEndRenderPass(cmd);
    transition(cmd, false);
}

}  // namespace demo
