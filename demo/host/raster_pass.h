// A raster pass of the demo host renderer over the scene mesh: the G-buffer pass (albedo, normal,
// depth) and the sun's shadow map pass (depth only) are both instances of it.
//
// Owns its attachments. Between frames they rest in the layouts the compute passes sample them in:
// color SHADER_READ_ONLY_OPTIMAL, depth DEPTH_STENCIL_READ_ONLY_OPTIMAL, readable by COMPUTE_SHADER.
#pragma once

#include "host/gpu_resources.h"
#include "host/scene_mesh.h"

#include <span>
#include <vector>

namespace demo {

struct RasterPassDesc {
    const char* name = "";               // for error messages
    std::vector<VkFormat> colorFormats;  // cleared to 0
    VkExtent2D extent{0, 0};
    std::span<const uint32_t> vertexShader;
    std::span<const uint32_t> fragmentShader;  // empty: depth only (position attribute only)
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
    float depthClear = 1.0f;
    bool depthBias = false;  // slope-scaled depth bias (shadow maps)
};

class RasterPass {
public:
    // frameSetLayout: descriptor set 0 of the pipeline (the frame uniforms).
    bool create(const VulkanHost& host, const RasterPassDesc& desc, VkDescriptorSetLayout frameSetLayout,
                std::string& error);
    void destroy(VkDevice device);

    // Transitions the attachments (discarding their content), clears, draws `draws` and transitions them
    // back to their sampled layouts, visible to COMPUTE_SHADER reads.
    void record(VkCommandBuffer cmd, VkDescriptorSet frameSet, const GpuBuffer& vertices,
                const GpuBuffer& indices, std::span<const MeshDraw> draws) const;

    std::vector<GpuImage> color;
    GpuImage depth;  // D32_SFLOAT

private:
    bool createPipeline(VkDevice device, const RasterPassDesc& desc, std::string& error);
    void transition(VkCommandBuffer cmd, bool toAttachment) const;

    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkExtent2D extent_{0, 0};
    float depthClear_ = 1.0f;
    bool hasFragment_ = false;
};

}  // namespace demo
