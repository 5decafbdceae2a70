// The deferred lighting compute pass: G-buffer + depth + sun shadow map + local lights and their shadow
// atlas -> HDR radiance (RGBA16F).
// See demo/shaders/lighting.comp for the shading formula.
#pragma once

#include "host/gpu_resources.h"

namespace demo {

struct LightingInputs {
    const GpuBuffer* frameUniforms = nullptr;    // shared::FrameUniforms
    const GpuBuffer* lights = nullptr;           // shared::LightsUniforms
    const GpuImage* albedo = nullptr;            // SHADER_READ_ONLY_OPTIMAL when dispatched
    const GpuImage* normal = nullptr;            // SHADER_READ_ONLY_OPTIMAL
    const GpuImage* depth = nullptr;             // DEPTH_STENCIL_READ_ONLY_OPTIMAL
    const GpuImage* shadowMap = nullptr;         // DEPTH_STENCIL_READ_ONLY_OPTIMAL
    const GpuImage* hdr = nullptr;               // GENERAL, written
    const GpuImage* localShadowAtlas = nullptr;  // DEPTH_STENCIL_READ_ONLY_OPTIMAL (setLocalShadowAtlas)
    const GpuBuffer* shadowFaces = nullptr;      // shared::LocalShadowFaces, storage buffer
};

class LightingPass {
public:
    bool create(const VulkanHost& host, const LightingInputs& inputs, std::string& error);
    void destroy(VkDevice device);
    // Dispatch only; the caller orders it against the writers and readers of the images.
    void record(VkCommandBuffer cmd, VkExtent2D extent) const;
    // Points the cloud shadow binding at `view` in `layout` (VK_NULL_HANDLE: the albedo stand-in); when
    // that changes the binding, first waits until the device is idle (no pending frame uses the set).
    void setCloudShadow(VkDevice device, VkImageView view, VkImageLayout layout);
    // Points the local shadow atlas binding at `view` (DEPTH_STENCIL_READ_ONLY_OPTIMAL), after the atlas was
    // replaced (LocalShadowPass::reserve, which waited for the device: no pending frame uses the set).
    void setLocalShadowAtlas(VkDevice device, VkImageView view);

    // The descriptor set and its layout, for the forward pass's set 0: every binding but the HDR image is
    // visible to fragment shaders too, the frame uniforms to vertex shaders.
    VkDescriptorSetLayout setLayout() const { return setLayout_; }
    VkDescriptorSet set() const { return set_; }
    // What the cloud shadow binding holds (setCloudShadow; VK_NULL_HANDLE: the stand-in).
    VkImageView cloudShadowView() const { return cloudShadowView_; }
    VkImageLayout cloudShadowLayout() const { return cloudShadowLayout_; }

    VkSampler shadowSampler = VK_NULL_HANDLE;  // nearest, compare LESS_OR_EQUAL, border = depth 1 (lit)

private:
    VkSampler pointSampler_ = VK_NULL_HANDLE;
    VkSampler linearSampler_ = VK_NULL_HANDLE;  // the cloud shadow map: linear, clamp to edge
    VkImageView albedoView_ = VK_NULL_HANDLE;   // the cloud shadow's stand-in
    VkImageView cloudShadowView_ = VK_NULL_HANDLE;
    VkImageLayout cloudShadowLayout_ = VK_IMAGE_LAYOUT_UNDEFINED;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace demo
