#include "host/local_shadow_pass.h"

#include "demo_host_spirv.h"
#include "demo_shared.h"

#include <algorithm>

namespace demo {
namespace {

// The sun's shadow pass's rasteriser bias (raster_pass.cpp), slope-scaled, under the depth bias the
// lighting and postfx compare with (local_shadows.h).
constexpr float kDepthBiasConstant = 2.0f;
constexpr float kDepthBiasSlope = 1.5f;

constexpr VkFormat kAtlasFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkExtent2D kInitialExtent{16, 16};
constexpr VkImageLayout kRest = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
constexpr VkImageLayout kAttachment = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

bool LocalShadowPass::create(const VulkanHost& host, std::string& error) {
    const VkDevice device = host.device;
    // Depth only; the attachment stays in its attachment layout, record() transitions around the pass.
    const VkAttachmentDescription attachment{0,
                                             kAtlasFormat,
                                             VK_SAMPLE_COUNT_1_BIT,
                                             VK_ATTACHMENT_LOAD_OP_CLEAR,
                                             VK_ATTACHMENT_STORE_OP_STORE,
                                             VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                             VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                             kAttachment,
                                             kAttachment};
    const VkAttachmentReference depthRef{0, kAttachment};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.pDepthStencilAttachment = &depthRef;
    VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rpci.attachmentCount = 1;
    rpci.pAttachments = &attachment;
    rpci.subpassCount = 1;
    rpci.pSubpasses = &subpass;
    if (!vkCheck(vkCreateRenderPass(device, &rpci, nullptr, &renderPass_), "vkCreateRenderPass", error))
        return false;

    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(shared::ShadowFacePush)};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &push;
    if (!vkCheck(vkCreatePipelineLayout(device, &lci, nullptr, &layout_), "vkCreatePipelineLayout", error))
        return false;

    VkShaderModule module = VK_NULL_HANDLE;
    if (!createShaderModule(device, spirv::local_shadow_vert, module, error)) return false;
    VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
    stage.module = module;
    stage.pName = "main";
    const VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription position{shared::kAttribPosition, 0, VK_FORMAT_R32G32B32_SFLOAT,
                                                     uint32_t(offsetof(MeshVertex, position))};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 1;
    vertexInput.pVertexAttributeDescriptions = &position;
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewportState.viewportCount = 1;  // per face: dynamic
    viewportState.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;  // planes are two-sided
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.depthBiasEnable = VK_TRUE;
    raster.depthBiasConstantFactor = kDepthBiasConstant;
    raster.depthBiasSlopeFactor = kDepthBiasSlope;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depthState{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depthState.depthTestEnable = VK_TRUE;
    depthState.depthWriteEnable = VK_TRUE;
    depthState.depthCompareOp = VK_COMPARE_OP_LESS;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;

    VkGraphicsPipelineCreateInfo pci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pci.stageCount = 1;
    pci.pStages = &stage;
    pci.pVertexInputState = &vertexInput;
    pci.pInputAssemblyState = &assembly;
    pci.pViewportState = &viewportState;
    pci.pRasterizationState = &raster;
    pci.pMultisampleState = &multisample;
    pci.pDepthStencilState = &depthState;
    pci.pColorBlendState = &blend;
    pci.pDynamicState = &dynamic;
    pci.layout = layout_;
    pci.renderPass = renderPass_;
    const bool ok = vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pci, nullptr, &pipeline_),
                            "vkCreateGraphicsPipelines (local shadows)", error);
    vkDestroyShaderModule(device, module, nullptr);
    return ok && createAtlas(host, kInitialExtent, error);
}

bool LocalShadowPass::createAtlas(const VulkanHost& host, VkExtent2D extent, std::string& error) {
    const uint32_t maxDim = host.properties.limits.maxImageDimension2D;
    if (extent.width > maxDim || extent.height > maxDim) {
        error = "local shadow atlas: " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                " exceeds the device's limit of " + std::to_string(maxDim) + " per side";
        return false;
    }
    cleared_ = false;
    if (!createImage(host, kAtlasFormat, extent,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                     atlas_, error)) {
        error = "local shadow atlas: " + error;
        return false;
    }
    VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = renderPass_;
    fci.attachmentCount = 1;
    fci.pAttachments = &atlas_.view;
    fci.width = extent.width;
    fci.height = extent.height;
    fci.layers = 1;
    return vkCheck(vkCreateFramebuffer(host.device, &fci, nullptr, &framebuffer_), "vkCreateFramebuffer",
                   error);
}

void LocalShadowPass::destroyAtlas(VkDevice device) {
    if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
    destroyImage(device, atlas_);
    cleared_ = false;
}

bool LocalShadowPass::reserve(const VulkanHost& host, VkExtent2D extent, bool& replaced, std::string& error) {
    replaced = false;
    if (extent.width <= atlas_.extent.width && extent.height <= atlas_.extent.height) return true;
    // Frames in flight may still read the old atlas.
    if (!vkCheck(vkDeviceWaitIdle(host.device), "vkDeviceWaitIdle", error)) return false;
    const VkExtent2D grown{std::max(extent.width, atlas_.extent.width),
                           std::max(extent.height, atlas_.extent.height)};
    destroyAtlas(host.device);
    replaced = true;
    return createAtlas(host, grown, error);
}

void LocalShadowPass::destroy(VkDevice device) {
    destroyAtlas(device);
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    renderPass_ = VK_NULL_HANDLE;
}

void LocalShadowPass::record(VkCommandBuffer cmd, const GpuBuffer& vertices, const GpuBuffer& indices,
                             std::span<const MeshDraw> draws, std::span<const ShadowFaceDraw> faces) {
    const VkPipelineStageFlags compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    // After the previous frame's reads (lighting, postfx, a readback's copy chained to them), discarded.
    imageBarrier(cmd, atlas_, VK_IMAGE_LAYOUT_UNDEFINED, kAttachment, compute, 0, kDepthStages,
                 VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    VkClearValue clear{};
    clear.depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rbi.renderPass = renderPass_;
    rbi.framebuffer = framebuffer_;
    rbi.renderArea = {{0, 0}, atlas_.extent};
    rbi.clearValueCount = 1;
    rbi.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (!draws.empty() && !faces.empty()) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        for (const ShadowFaceDraw& face : faces) {
            const VkViewport viewport{float(face.region.offset.x),
                                      float(face.region.offset.y),
                                      float(face.region.extent.width),
                                      float(face.region.extent.height),
                                      0.0f,
                                      1.0f};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &face.region);
            const shared::ShadowFacePush push{face.worldToClip};
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), &push);
            for (const MeshDraw& d : draws)
                vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, 0, 0);
        }
    }
    vkCmdEndRenderPass(cmd);
    imageBarrier(cmd, atlas_, kAttachment, kRest, kDepthStages, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                 compute, VK_ACCESS_SHADER_READ_BIT);
    cleared_ = true;
}

}  // namespace demo
