// Renderer internals shared by renderer.cpp (setup, render loop, readback) and renderer_frame.cpp
// (one frame's commands).
#pragma once

#include "host/gpu_resources.h"
#include "host/lighting_pass.h"
#include "host/raster_pass.h"
#include "host/renderer.h"

#include <postfx/context.h>

#include <array>

namespace demo {

struct Renderer::Impl {
    explicit Impl(VulkanHost& h) : host(h) {}
    ~Impl();

    VulkanHost& host;
    RenderOptions options;
    VkExtent2D extent{0, 0};

    GpuBuffer frameUniforms;  // shared::FrameUniforms, written with vkCmdUpdateBuffer each frame
    VkDescriptorSetLayout frameSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool framePool = VK_NULL_HANDLE;
    VkDescriptorSet frameSet = VK_NULL_HANDLE;  // set 0 of the raster passes

    RasterPass gbuffer;  // color[0] albedo, color[1] normal (RGBA16F), depth D32
    RasterPass shadow;   // depth only, shadowMapSize²
    GpuImage hdr;        // RGBA16F radiance
    LightingPass lighting;

    GpuBuffer vertices, indices;  // host-visible scene mesh
    std::vector<MeshDraw> draws;

    std::unique_ptr<postfx::Context> postfx;
    ImageInfo hdrInfo, depthInfo;
    ShadowMapInfo shadowInfo;

    // render(): one command buffer and fence per frame in flight, and the readback buffer.
    std::array<VkCommandBuffer, kFramesInFlight> commandBuffers{};
    std::array<VkFence, kFramesInFlight> fences{};
    GpuBuffer readback;
    uint64_t nextFrameIndex = 0;
    bool broken = false;  // a submission failed: the fences can no longer be trusted

    bool createResources(std::string& error);
    bool createFrameSet(std::string& error);
    bool createPostfx(std::string& error);
    void recordReadback(VkCommandBuffer cmd) const;
};

}  // namespace demo
