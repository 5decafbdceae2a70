// The windowed demo's GPU tonemap: the renderer's HDR radiance (RGBA16F) -> an RGBA8_UNORM image of
// sRGB-encoded display values (demo/shaders/tonemap.comp, the same curve as the .png files), which the
// frame then blits or copies into the swapchain image.
#pragma once

#include "host/gpu_resources.h"
#include "host/renderer.h"

namespace demo::window {

class TonemapPass {
public:
    TonemapPass() = default;
    TonemapPass(const TonemapPass&) = delete;
    TonemapPass& operator=(const TonemapPass&) = delete;
    ~TonemapPass() { destroy(); }

    // `hdr`: the renderer's HDR image (storage usage, GENERAL when read); the output has its extent.
    bool create(const VulkanHost& host, const ImageInfo& hdr, std::string& error);
    void destroy();

    // Records: output -> GENERAL (after the previous frame's transfer read), HDR compute writes ->
    // this read, the dispatch, then output -> TRANSFER_SRC_OPTIMAL readable by TRANSFER.
    // swapRedBlue: store (b, g, r) for a bit-exact copy into a BGRA image.
    // `preExposure`: the factor the HDR image holds radiance with (Renderer::preExposure).
    void record(VkCommandBuffer cmd, float ev100, float preExposure, bool swapRedBlue) const;

    const GpuImage& output() const { return output_; }  // RGBA8_UNORM, TRANSFER_SRC_OPTIMAL after record

private:
    VkDevice device_ = VK_NULL_HANDLE;
    ImageInfo hdr_;
    GpuImage output_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace demo::window
