// The forward pass: transparent objects and particles (host/forward_draws.h), drawn after postfx into the
// HDR image postfx composited, lit as the deferred lighting lights the G-buffer and seen through postfx's
// volumetrics lookup (docs/integration.md, "Transparent surfaces"); see demo/shaders/forward.frag.
//
// Descriptor set 0 is the lighting pass's (LightingPass::set: frame uniforms, lights, shadow maps, the
// G-buffer depth for the depth test); set 1 postfx's lookup, one set per frame in flight, written with
// Context::writeVolumetricsLookup after each record().
#pragma once

#include "host/forward_draws.h"
#include "host/gpu_resources.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace demo {

class ForwardPass {
public:
    // hdr: the colour attachment (RGBA16F, usage COLOR_ATTACHMENT, GENERAL between passes);
    // lightingSetLayout: set 0; framesInFlight: lookup sets and particle buffers.
    bool create(const VulkanHost& host, const GpuImage& hdr, VkDescriptorSetLayout lightingSetLayout,
                uint32_t framesInFlight, std::string& error);
    void destroy(VkDevice device);

    // Copies `frame`'s particle vertices into the buffer of `slot` (grown as needed; the caller has waited
    // for the frame that last used the slot).
    bool upload(const VulkanHost& host, size_t slot, const ForwardFrame& frame, std::string& error);
    // The lookup's descriptor set of `slot` (set 1), for Context::writeVolumetricsLookup.
    VkDescriptorSet lookupSet(size_t slot) const { return lookupSets_[slot]; }

    struct Inputs {
        VkDescriptorSet lightingSet = VK_NULL_HANDLE;
        const GpuBuffer* vertices = nullptr;  // the scene mesh
        const GpuBuffer* indices = nullptr;
        glm::vec4 cloudShadowU{0.0f, 0.0f, 0.0f, -1.0f};  // shared::ForwardPush's rows
        glm::vec4 cloudShadowV{0.0f, 0.0f, 0.0f, -1.0f};
        bool lookup = true;  // false: the surfaces without postfx's lookup (the benchmark's lookup share)
    };
    // Records `frame`'s draws (upload()ed into `slot`), after postfx: waits for compute writes (postfx's
    // composite, the lookup, the clouds' shadow map), blends into the HDR image and leaves it in GENERAL
    // with its writes visible to COMPUTE_SHADER (as recordFrame promises without this pass), every read of
    // this pass done before later compute work.
    void record(VkCommandBuffer cmd, size_t slot, const ForwardFrame& frame, const Inputs& in) const;

private:
    bool createPipeline(VkDevice device, std::span<const uint32_t> fragment, VkPipeline& out,
                        std::string& error);

    VkExtent2D extent_{0, 0};
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout lookupLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool lookupPool_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> lookupSets_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::vector<GpuBuffer> particleBuffers_;  // host-visible, one per frame in flight
};

}  // namespace demo
