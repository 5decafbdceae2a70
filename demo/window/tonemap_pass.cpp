#include "window/tonemap_pass.h"

#include "demo_shared.h"
#include "host/gpu_resources.h"
#include "postfx-demo_spirv.h"

#include <array>
#include <cmath>

namespace demo::window {
namespace {

constexpr VkFormat kOutputFormat = VK_FORMAT_R8G8B8A8_UNORM;

}  // namespace

bool TonemapPass::create(const VulkanHost& host, const ImageInfo& hdr, std::string& error) {
    destroy();
    device_ = host.device;
    hdr_ = hdr;
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(host.physicalDevice, kOutputFormat, &props);
    const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT |
                                      VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT;
    if ((props.optimalTilingFeatures & need) != need) {
        error = "the device lacks RGBA8_UNORM storage image / blit source support";
        return false;
    }
    if (!createImage(host, kOutputFormat, hdr.extent,
                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, output_, error))
        return false;

    const std::array<VkDescriptorSetLayoutBinding, 2> bindings{{
        {shared::kTonemapBindingHdr, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
        {shared::kTonemapBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT,
         nullptr},
    }};
    if (!createDescriptorSet(device_, bindings, setLayout_, pool_, set_, error)) return false;
    const std::array<VkDescriptorImageInfo, 2> images{{
        {VK_NULL_HANDLE, hdr.view, VK_IMAGE_LAYOUT_GENERAL},
        {VK_NULL_HANDLE, output_.view, VK_IMAGE_LAYOUT_GENERAL},
    }};
    std::array<VkWriteDescriptorSet, 2> writes{};
    for (size_t i = 0; i < writes.size(); ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = bindings[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        writes[i].pImageInfo = &images[i];
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);

    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(shared::TonemapPush)};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout_;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &range;
    if (!vkCheck(vkCreatePipelineLayout(device_, &plci, nullptr, &layout_), "vkCreatePipelineLayout", error))
        return false;
    return createComputePipeline(device_, spirv::tonemap_comp, layout_, "vkCreateComputePipelines (tonemap)",
                                 pipeline_, error);
}

void TonemapPass::destroy() {
    if (!device_) return;
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
    destroyImage(device_, output_);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    pool_ = VK_NULL_HANDLE;
    set_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
    device_ = VK_NULL_HANDLE;
}

void TonemapPass::record(VkCommandBuffer cmd, float ev100, float preExposure, bool swapRedBlue) const {
    const VkPipelineStageFlags compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    const VkPipelineStageFlags transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
    // The previous frame's blit/copy read the output; its content is overwritten entirely.
    imageBarrier(cmd, output_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_GENERAL, transfer, 0, compute, VK_ACCESS_SHADER_WRITE_BIT);
    // Renderer::recordFrame leaves the HDR image in GENERAL with compute writes to make visible.
    imageBarrier(cmd, hdr_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                 compute, VK_ACCESS_SHADER_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);

    shared::TonemapPush push{};
    // The image holds radiance × preExposure: the exposure applied on top is exposure / preExposure.
    push.params = glm::vec4(
        float(1.0 / (double(shared::kExposureSaturation) * std::exp2(double(ev100)) * double(preExposure))),
        swapRedBlue ? 1.0f : 0.0f, 0.0f, 0.0f);
    push.extent = glm::uvec4(output_.extent.width, output_.extent.height, 0, 0);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    const uint32_t g = shared::kTonemapGroupSize;
    vkCmdDispatch(cmd, (output_.extent.width + g - 1) / g, (output_.extent.height + g - 1) / g, 1);

    imageBarrier(cmd, output_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, compute, VK_ACCESS_SHADER_WRITE_BIT, transfer,
                 VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace demo::window
