// The local lights' shadow atlas and the raster pass that draws it (host/local_shadows.h: the layout):
// one D32_SFLOAT image, cleared to 1 (standard Z), each face drawn into its region (viewport and scissor)
// with the scene's depth through local_shadow.vert (the face's world -> clip matrix as a push constant).
//
// Between frames the atlas rests in DEPTH_STENCIL_READ_ONLY_OPTIMAL, readable by COMPUTE_SHADER (the
// lighting pass and postfx), as the sun's shadow map does (raster_pass.h).
#pragma once

#include "host/gpu_resources.h"
#include "host/scene_mesh.h"

#include <glm/glm.hpp>

#include <span>

namespace demo {

// One face to draw: its region of the atlas and its world -> clip matrix (float, for the vertex shader).
struct ShadowFaceDraw {
    VkRect2D region{};
    glm::mat4 worldToClip{1.0f};
};

class LocalShadowPass {
public:
    // A 16x16 atlas to start with (grown by reserve), the render pass and the pipeline.
    bool create(const VulkanHost& host, std::string& error);
    void destroy(VkDevice device);

    // Makes the atlas at least `extent` (each side at most the device's limit): when it is smaller, waits
    // for the device to be idle and replaces it with one of the larger of the two sizes per side (its
    // content undefined until the next record). `replaced` tells whether it did.
    bool reserve(const VulkanHost& host, VkExtent2D extent, bool& replaced, std::string& error);

    // Discards the atlas (after the previous frame's COMPUTE_SHADER reads), clears it to 1, draws every
    // face's `draws`, and leaves it in DEPTH_STENCIL_READ_ONLY_OPTIMAL, visible to COMPUTE_SHADER reads.
    void record(VkCommandBuffer cmd, const GpuBuffer& vertices, const GpuBuffer& indices,
                std::span<const MeshDraw> draws, std::span<const ShadowFaceDraw> faces);

    // D32_SFLOAT; usage DEPTH_STENCIL_ATTACHMENT | SAMPLED | TRANSFER_SRC (the reference reads it back).
    const GpuImage& atlas() const { return atlas_; }
    // Whether the atlas holds a recorded clear (record was called since it was made): until then the
    // lighting must not read it, and a frame without shadowed lights records an empty pass to clear it.
    bool cleared() const { return cleared_; }

private:
    bool createAtlas(const VulkanHost& host, VkExtent2D extent, std::string& error);
    void destroyAtlas(VkDevice device);

    GpuImage atlas_;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    bool cleared_ = false;
};

}  // namespace demo
