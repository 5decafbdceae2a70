// The demo renderer: resource setup, scene upload, the render() loop and the readback.
#include "host/renderer.h"

#include "demo_host_spirv.h"
#include "demo_shared.h"
#include "host/metering.h"
#include "host/renderer_impl.h"
#include "scene/scene.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace demo {
namespace {

constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

bool formatSupports(const VulkanHost& host, VkFormat format, VkFormatFeatureFlags need) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(host.physicalDevice, format, &props);
    return (props.optimalTilingFeatures & need) == need;
}

void printPostfxMessage(postfx::MessageSeverity severity, const char* message, void* /*user*/) {
    const char* level = severity == postfx::MessageSeverity::Error     ? "error"
                        : severity == postfx::MessageSeverity::Warning ? "warning"
                                                                       : "info";
    std::fprintf(stderr, "[postfx %s] %s\n", level, message);
}

}  // namespace

Renderer::Impl::~Impl() {
    const VkDevice device = host.device;
    vkDeviceWaitIdle(device);
    postfx.reset();
    for (VkFence f : fences)
        if (f) vkDestroyFence(device, f, nullptr);
    for (VkCommandBuffer c : commandBuffers)
        if (c) vkFreeCommandBuffers(device, host.commandPool, 1, &c);
    lighting.destroy(device);
    forward.destroy(device);
    localShadows.destroy(device);
    gbuffer.destroy(device);
    shadow.destroy(device);
    destroyImage(device, hdr);
    destroyImage(device, fogScratch);
    if (framePool) vkDestroyDescriptorPool(device, framePool, nullptr);
    if (frameSetLayout) vkDestroyDescriptorSetLayout(device, frameSetLayout, nullptr);
    for (GpuBuffer* b : {&frameUniforms, &lightsUniforms, &shadowFaces, &vertices, &indices, &readback})
        destroyBuffer(device, *b);
    for (GpuBuffer& b : meterCopies)
        destroyBuffer(device, b);
}

std::unique_ptr<Renderer> Renderer::create(VulkanHost& host, const RenderOptions& options,
                                           std::string& error) {
    const uint32_t maxDim = host.properties.limits.maxImageDimension2D;
    if (options.width == 0 || options.height == 0 || options.width > maxDim || options.height > maxDim) {
        error = "image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                " is outside 1.." + std::to_string(maxDim) + " per side";
        return nullptr;
    }
    if (options.shadowMapSize == 0 || options.shadowMapSize > maxDim) {
        error = "shadow map size " + std::to_string(options.shadowMapSize) + " is outside 1.." +
                std::to_string(maxDim);
        return nullptr;
    }
    if (options.frames == 0) {
        error = "frames must be at least 1";
        return nullptr;
    }
    if (!formatSupports(host, kHdrFormat,
                        VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) ||
        !formatSupports(
            host, kDepthFormat,
            VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        error = "the device lacks RGBA16F storage/attachment or D32_SFLOAT depth sampling support";
        return nullptr;
    }
    auto impl = std::make_unique<Impl>(host);
    impl->options = options;
    impl->extent = {options.width, options.height};
    if (!impl->createResources(error) || !impl->createPostfx(error)) return nullptr;
    return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

bool Renderer::Impl::createFrameSet(std::string& error) {
    const VkDevice device = host.device;
    const VkDescriptorSetLayoutBinding binding{shared::kBindingFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                               VK_SHADER_STAGE_VERTEX_BIT, nullptr};
    if (!createDescriptorSet(device, {&binding, 1}, frameSetLayout, framePool, frameSet, error)) return false;
    const VkDescriptorBufferInfo info{frameUniforms.buffer, 0, sizeof(shared::FrameUniforms)};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = frameSet;
    write.dstBinding = shared::kBindingFrame;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    return true;
}

bool Renderer::Impl::createResources(std::string& error) {
    const VkDevice device = host.device;
    if (!createBuffer(host, sizeof(shared::FrameUniforms),
                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false,
                      frameUniforms, error) ||
        !createBuffer(host, sizeof(shared::LightsUniforms),
                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false,
                      lightsUniforms, error) ||
        !createBuffer(host, sizeof(shared::LocalShadowFaces),
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false,
                      shadowFaces, error) ||
        !createFrameSet(error))
        return false;

    RasterPassDesc g;
    g.name = "G-buffer";
    g.colorFormats = {kHdrFormat, kHdrFormat};  // albedo, world normal
    g.extent = extent;
    g.vertexShader = spirv::gbuffer_vert;
    g.fragmentShader = spirv::gbuffer_frag;
    g.depthCompare = options.reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
    g.depthClear = options.reversedZ ? 0.0f : 1.0f;
    RasterPassDesc s;
    s.name = "shadow map";
    s.extent = {options.shadowMapSize, options.shadowMapSize};
    s.vertexShader = spirv::shadow_vert;
    s.depthCompare = VK_COMPARE_OP_LESS;
    s.depthClear = 1.0f;
    s.depthBias = true;
    if (!gbuffer.create(host, g, frameSetLayout, error) || !shadow.create(host, s, frameSetLayout, error) ||
        !localShadows.create(host, error))
        return false;

    // COLOR_ATTACHMENT: the forward pass blends transparent surfaces into it after postfx.
    if (!createImage(host, kHdrFormat, extent,
                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                     hdr, error))
        return false;
    LightingInputs in{&frameUniforms,
                      &lightsUniforms,
                      &gbuffer.color[0],
                      &gbuffer.color[1],
                      &gbuffer.depth,
                      &shadow.depth,
                      &hdr,
                      &localShadows.atlas(),
                      &shadowFaces};
    if (!lighting.create(host, in, error) ||
        !forward.create(host, hdr, lighting.setLayout(), kFramesInFlight, error))
        return false;
    if (!createBuffer(host, VkDeviceSize(extent.width) * extent.height * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      true, readback, error))
        return false;

    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = host.commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = kFramesInFlight;
    if (!vkCheck(vkAllocateCommandBuffers(device, &ai, commandBuffers.data()), "vkAllocateCommandBuffers",
                 error))
        return false;
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fci.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    for (VkFence& f : fences)
        if (!vkCheck(vkCreateFence(device, &fci, nullptr, &f), "vkCreateFence", error)) return false;

    // The shadow maps are sampled every frame but drawn only with shadows on: start them cleared (lit).
    const std::vector<MeshDraw> none;
    if (!host.submitAndWait(
            [&](VkCommandBuffer cmd) {
                shadow.record(cmd, frameSet, vertices, indices, none);
                localShadows.record(cmd, vertices, indices, none, {});
            },
            error))
        return false;

    hdrInfo = {hdr.image, hdr.view, hdr.format, extent, VK_IMAGE_LAYOUT_GENERAL, hdr.usage};
    const GpuImage& d = gbuffer.depth;
    depthInfo = {d.image, d.view, d.format, extent, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, d.usage};
    shadowInfo.image = {shadow.depth.image,
                        shadow.depth.view,
                        shadow.depth.format,
                        shadow.depth.extent,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                        shadow.depth.usage};
    shadowInfo.compareSampler = lighting.shadowSampler;
    return true;
}

bool Renderer::Impl::createPostfx(std::string& error) {
    postfx::ContextCreateInfo ci;
    ci.instance = host.instance;
    ci.physicalDevice = host.physicalDevice;
    ci.device = host.device;
    ci.getInstanceProcAddr = vkGetInstanceProcAddr;
    ci.getDeviceProcAddr = vkGetDeviceProcAddr;
    ci.queueFamilyIndex = host.queueFamily;
    ci.maxExtent = extent;
    ci.depth.reversedZ = options.reversedZ;
    ci.depth.infiniteFar = options.infiniteFar;
    ci.framesInFlight = kFramesInFlight;
    ci.debugLabels = host.debugUtilsEnabled;  // postfx's passes named in RenderDoc / Nsight
    ci.messageCallback = printPostfxMessage;
    if (postfx::Status s = postfx::Context::create(ci, postfx); !s.ok()) {
        error = "postfx context: " + s.message;
        return false;
    }
    return true;
}

bool Renderer::setScene(const Scene& scene, std::string& error) {
    Impl& r = *impl_;
    if (!vkCheck(vkDeviceWaitIdle(r.host.device), "vkDeviceWaitIdle", error)) return false;
    const SceneMesh mesh = buildSceneMesh(scene, r.options.infiniteFar);
    const VkDeviceSize vbytes = mesh.vertices.size() * sizeof(MeshVertex);
    const VkDeviceSize ibytes = mesh.indices.size() * sizeof(uint32_t);
    // Host-visible buffers, grown as needed (never zero-sized).
    if (r.vertices.size < vbytes || !r.vertices.buffer) {
        destroyBuffer(r.host.device, r.vertices);
        if (!createBuffer(r.host, std::max<VkDeviceSize>(vbytes, 4096), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                          true, r.vertices, error))
            return false;
    }
    if (r.indices.size < ibytes || !r.indices.buffer) {
        destroyBuffer(r.host.device, r.indices);
        if (!createBuffer(r.host, std::max<VkDeviceSize>(ibytes, 4096), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                          true, r.indices, error))
            return false;
    }
    if (vbytes) std::memcpy(r.vertices.mapped, mesh.vertices.data(), vbytes);
    if (ibytes) std::memcpy(r.indices.mapped, mesh.indices.data(), ibytes);
    r.draws = mesh.draws;
    return true;
}

VkCommandBuffer Renderer::Impl::beginSlot(size_t slot, std::string& error) {
    if (!vkCheck(vkWaitForFences(host.device, 1, &fences[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences",
                 error))
        return VK_NULL_HANDLE;
    VkCommandBuffer cmd = commandBuffers[slot];
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &bi);
    return cmd;
}

bool Renderer::Impl::meterFirstFrame(const Scene& state, std::string& error) {
    meteredExposure = 0.0;  // the first pass: the camera's exposure (scenePreExposure)
    if (!options.preExpose) return true;
    const double wanted = exposureFromEv100(state.camera.ev100);
    for (uint32_t pass = 0; pass < kMeteringPasses; ++pass) {
        const size_t slot = 0;  // frame 0's
        VkCommandBuffer cmd = beginSlot(slot, error);
        if (!cmd) return false;
        const bool recorded = recordFrame(cmd, state, 0, postfx::ImageInput{}, error);
        if (recorded) recordReadback(cmd);
        if (!vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) || !recorded) return false;
        if (!submit(cmd, slot, error) ||
            !vkCheck(vkWaitForFences(host.device, 1, &fences[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences",
                     error))
            return false;
        const Metering m = meterHalfImage(static_cast<const uint16_t*>(readback.mapped),
                                          size_t(extent.width) * extent.height);
        const PreExposureRange range = preExposureRange(state, frameLight(state).surfaces.ambient);
        const double next = meteredPreExposure(m, preExposure, wanted, range.lowest, range.highest);
        if (next == double(preExposure) || pass + 1 == kMeteringPasses) break;  // frame 0 stands
        meteredExposure = next;
    }
    return true;
}

bool Renderer::render(const Scene& scene, ImageF& out, std::string& error) {
    Impl& r = *impl_;
    const VkDevice device = r.host.device;
    if (r.broken) {
        error = "the renderer is unusable after a failed submission";
        return false;
    }
    // Frame f shows `state`: the scene moved to frame f (a copy of the camera and lights only when the
    // scene has motion). Plane quads are centred under the camera at setScene (scene_mesh.h).
    const bool motion = hasMotion(scene);
    Scene moving = motion ? scene : Scene{};
    const Scene& state = motion ? moving : scene;
    if (!setScene(scene, error)) return false;
    glm::vec3 meshCentre = scene.camera.position;
    const float replanDistance = 0.25f * std::min(scene.camera.farPlane, 1e4f);
    // Frame 0, rendered until its pre-exposure fits what it shows (host/metering.h), stands as the first.
    if (motion) moveToFrame(scene, 0, moving);
    if (!r.meterFirstFrame(state, error)) return false;
    const uint32_t first = r.options.preExpose ? 1 : 0;
    for (uint32_t f = first; f < r.options.frames; ++f) {
        // Every call renders frames 0..frames-1 (renderReference() shows frame frames-1). The previous
        // call waited for all its frames, so restarting the indices reuses nothing still in flight.
        const uint64_t frameIndex = f;
        if (motion) {
            moveToFrame(scene, frameIndex, moving);
            const float moved = glm::length(moving.camera.position - meshCentre);
            const bool last = f + 1 == r.options.frames;
            if (moved > replanDistance || (last && moved > 0.0f)) {
                if (!setScene(moving, error)) return false;  // waits for the frames in flight
                meshCentre = moving.camera.position;
            }
        }
        const size_t slot = frameIndex % kFramesInFlight;
        // The command buffer and postfx's per-frame resources of frame (index - kFramesInFlight) are free.
        VkCommandBuffer cmd = r.beginSlot(slot, error);
        if (!cmd) return false;
        const bool recorded = recordFrame(cmd, state, frameIndex, error);
        if (recorded && f + 1 == r.options.frames) r.recordReadback(cmd);
        if (!vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) || !recorded) return false;
        if (!r.submit(cmd, slot, error)) return false;
    }
    if (!vkCheck(vkWaitForFences(device, kFramesInFlight, r.fences.data(), VK_TRUE, UINT64_MAX),
                 "vkWaitForFences", error))
        return false;

    // RGBA16F -> RGBA32F (the memory is coherent; the barrier made the copy visible to the host), the
    // pre-exposure divided out: radiance in physical units.
    out.width = r.extent.width;
    out.height = r.extent.height;
    out.rgba.resize(size_t(out.width) * out.height * 4);
    const auto* half = static_cast<const uint16_t*>(r.readback.mapped);
    for (size_t i = 0; i < out.rgba.size(); ++i)
        out.rgba[i] = glm::unpackHalf1x16(half[i]);
    unexpose(out.rgba, r.preExposure);
    return true;
}

const ImageInfo& Renderer::hdrImage() const {
    return impl_->hdrInfo;
}
const ImageInfo& Renderer::depthImage() const {
    return impl_->depthInfo;
}
const ShadowMapInfo& Renderer::shadowMap() const {
    return impl_->shadowInfo;
}
postfx::Context& Renderer::postfxContext() const {
    return *impl_->postfx;
}
float Renderer::preExposure() const {
    return impl_->preExposure;
}

void unexpose(std::vector<float>& rgba, float preExposure) {
    const double scale = 1.0 / double(preExposure);
    for (size_t i = 0; i < rgba.size(); ++i)
        if (i % 4 != 3) rgba[i] = float(double(rgba[i]) * scale);
}

}  // namespace demo
