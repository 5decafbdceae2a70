#include "host/lighting_pass.h"

#include "demo_host_spirv.h"
#include "demo_shared.h"

#include <array>

namespace demo {
namespace {

bool createSampler(VkDevice device, bool shadowCompare, VkSampler& out, std::string& error,
                   VkFilter filter = VK_FILTER_NEAREST) {
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = filter;  // the shadow map is gathered (D32 linear filtering is optional)
    sci.minFilter = filter;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    const VkSamplerAddressMode mode =
        shadowCompare ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = mode;
    sci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;  // depth 1 beyond the map: never occluded
    sci.compareEnable = shadowCompare;
    sci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // lit when receiver depth <= stored occluder depth
    sci.maxLod = 0.0f;
    return vkCheck(vkCreateSampler(device, &sci, nullptr, &out), "vkCreateSampler", error);
}

}  // namespace

bool LightingPass::create(const VulkanHost& host, const LightingInputs& in, std::string& error) {
    const VkDevice device = host.device;
    if (!createSampler(device, false, pointSampler_, error) ||
        !createSampler(device, true, shadowSampler, error) ||
        !createSampler(device, false, linearSampler_, error, VK_FILTER_LINEAR))
        return false;
    albedoView_ = in.albedo->view;

    using namespace shared;
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    // The forward pass binds this set too (forward.vert, forward.frag).
    const VkShaderStageFlags fs = cs | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkShaderStageFlags vfs = fs | VK_SHADER_STAGE_VERTEX_BIT;
    const std::array<VkDescriptorSetLayoutBinding, 10> bindings{{
        {kBindingFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, vfs, nullptr},
        {kBindingAlbedo, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingNormal, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingHdr, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, cs, nullptr},
        {kBindingLights, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, fs, nullptr},
        {kBindingCloudShadow, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingLocalShadowAtlas, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fs, nullptr},
        {kBindingLocalShadowFaces, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, fs, nullptr},
    }};
    if (!createDescriptorSet(device, bindings, setLayout_, pool_, set_, error)) return false;

    const VkDescriptorBufferInfo ubo{in.frameUniforms->buffer, 0, sizeof(FrameUniforms)};
    const VkDescriptorBufferInfo lightsUbo{in.lights->buffer, 0, sizeof(LightsUniforms)};
    const VkImageLayout readOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkImageLayout depthReadOnly = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    const std::array<VkDescriptorImageInfo, 5> images{{
        {pointSampler_, in.albedo->view, readOnly},
        {pointSampler_, in.normal->view, readOnly},
        {pointSampler_, in.depth->view, depthReadOnly},
        {shadowSampler, in.shadowMap->view, depthReadOnly},
        {VK_NULL_HANDLE, in.hdr->view, VK_IMAGE_LAYOUT_GENERAL},
    }};
    std::array<VkWriteDescriptorSet, 7> writes{};  // the cloud shadow's: setCloudShadow below
    for (size_t i = 0; i < writes.size(); ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = bindings[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = bindings[i].descriptorType;
        if (i == 0)
            writes[i].pBufferInfo = &ubo;
        else if (i == 6)
            writes[i].pBufferInfo = &lightsUbo;
        else
            writes[i].pImageInfo = &images[i - 1];
    }
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    setCloudShadow(device, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED);
    setLocalShadowAtlas(device, in.localShadowAtlas->view);
    const VkDescriptorBufferInfo faces{in.shadowFaces->buffer, 0, sizeof(LocalShadowFaces)};
    VkWriteDescriptorSet facesWrite{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    facesWrite.dstSet = set_;
    facesWrite.dstBinding = kBindingLocalShadowFaces;
    facesWrite.descriptorCount = 1;
    facesWrite.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    facesWrite.pBufferInfo = &faces;
    vkUpdateDescriptorSets(device, 1, &facesWrite, 0, nullptr);

    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout_;
    if (!vkCheck(vkCreatePipelineLayout(device, &plci, nullptr, &layout_), "vkCreatePipelineLayout", error))
        return false;
    return createComputePipeline(device, spirv::lighting_comp, layout_, "vkCreateComputePipelines (lighting)",
                                 pipeline_, error);
}

void LightingPass::setCloudShadow(VkDevice device, VkImageView view, VkImageLayout layout) {
    if (!view) layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // the albedo's
    const bool first = cloudShadowLayout_ == VK_IMAGE_LAYOUT_UNDEFINED;
    if (!first && view == cloudShadowView_ && layout == cloudShadowLayout_) return;
    if (!first) vkDeviceWaitIdle(device);
    cloudShadowView_ = view;
    cloudShadowLayout_ = layout;
    const VkDescriptorImageInfo image{linearSampler_, view ? view : albedoView_, layout};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = shared::kBindingCloudShadow;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void LightingPass::setLocalShadowAtlas(VkDevice device, VkImageView view) {
    // Nearest and no comparison: local_shadow.glsl fetches texels and compares them itself (postfx's rule).
    const VkDescriptorImageInfo image{pointSampler_, view, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = shared::kBindingLocalShadowAtlas;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void LightingPass::destroy(VkDevice device) {
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    if (pointSampler_) vkDestroySampler(device, pointSampler_, nullptr);
    if (linearSampler_) vkDestroySampler(device, linearSampler_, nullptr);
    if (shadowSampler) vkDestroySampler(device, shadowSampler, nullptr);
    *this = LightingPass{};
}

void LightingPass::record(VkCommandBuffer cmd, VkExtent2D extent) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
    const uint32_t g = shared::kLightingGroupSize;
    vkCmdDispatch(cmd, (extent.width + g - 1) / g, (extent.height + g - 1) / g, 1);
}

}  // namespace demo
