// Renderer internals shared by renderer.cpp (setup, render loop, readback) and renderer_frame.cpp
// (one frame's commands).
#pragma once

#include "host/atmosphere_lighting.h"
#include "host/camera_math.h"
#include "host/forward_pass.h"
#include "host/gpu_resources.h"
#include "host/lighting_pass.h"
#include "host/local_shadow_pass.h"
#include "host/local_shadows.h"
#include "host/raster_pass.h"
#include "host/renderer.h"

#include <postfx/context.h>

#include <array>
#include <vector>

namespace demo {

// What postfx is told about one frame: its FrameInfo without the command buffer and the images (color,
// depth, output), built by ONE function (Renderer::Impl::postfxInputs) for both the GPU frame and the CPU
// references (postfx::reference::FogInputs, FroxelFogInputs), so that the two cannot diverge.
using PostfxInputs = postfx::FrameInfo;

// The light of one frame, computed once per frame (Renderer::Impl::frameLight) and read by both the
// surfaces' uniforms and postfx's inputs.
struct FrameLight {
    AtmosphereLighting surfaces;  // the sun's transmittance, the ambient and the sky (atmosphereLighting)
    // The factor the HDR image is stored with (postfx::FrameInfo::preExposure; scenePreExposure with
    // surfaces.ambient).
    float preExposure = 1.0f;
};

// The pre-exposure the demo stores its HDR image with: the camera's exposure 1 / (1.2 · 2^ev100) rounded
// down to a power of two (multiplying by it and dividing it out are exact in float and half: pre-exposing
// moves values in range, it rounds nothing), so that what shows near white on screen is near 1 in the
// RGBA16F image and a 100,000 lux sun's in-scattering fits it; limited to what postfx accepts
// (FrameInfo::preExposure: its range, the pre-exposed sun and ambient ≤ 1e7, each light's intensity
// ≤ 1e9). 1 when options.preExpose is off. `ambient`: the surfaces' (and postfx's) ambient.
float scenePreExposure(const Scene& scene, const glm::vec3& ambient, const RenderOptions& options);

// The pre-exposures postfx accepts for the scene (FrameInfo::preExposure's range and the light limits
// above), powers of two.
struct PreExposureRange {
    double lowest = 1.0, highest = 1.0;
};
PreExposureRange preExposureRange(const Scene& scene, const glm::vec3& ambient);

struct Renderer::Impl {
    explicit Impl(VulkanHost& h) : host(h) {}
    ~Impl();

    VulkanHost& host;
    RenderOptions options;
    VkExtent2D extent{0, 0};

    GpuBuffer frameUniforms;   // shared::FrameUniforms, written with vkCmdUpdateBuffer each frame
    GpuBuffer lightsUniforms;  // shared::LightsUniforms, written with vkCmdUpdateBuffer each frame
    // The scene's lights as postfx reads them (FrameInfo::lights points here; rebuilt by postfxInputs).
    mutable std::vector<postfx::LocalLight> localLights;
    VkDescriptorSetLayout frameSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool framePool = VK_NULL_HANDLE;
    VkDescriptorSet frameSet = VK_NULL_HANDLE;  // set 0 of the raster passes

    RasterPass gbuffer;  // color[0] albedo, color[1] normal (RGBA16F), depth D32
    RasterPass shadow;   // depth only, shadowMapSize²
    GpuImage hdr;        // RGBA16F radiance
    LightingPass lighting;
    // The local lights' shadow atlas and its pass (scene lights[i].shadows), and the faces the lighting
    // reads (shared::LocalShadowFaces, written with vkCmdUpdateBuffer each frame with shadowed lights).
    LocalShadowPass localShadows;
    GpuBuffer shadowFaces;
    // The layout postfx was last told (FrameInfo::localShadows.shadows points here; rebuilt by
    // postfxInputs).
    mutable LocalShadowLayout localShadowLayout;

    GpuBuffer vertices, indices;  // host-visible scene mesh
    std::vector<MeshDraw> draws;  // one per scene object (setScene)
    // The transparent objects and particles, after postfx (host/forward_pass.h).
    ForwardPass forward;
    // Set once postfx refused to write its volumetrics lookup: the forward pass draws without it (a
    // warning is printed once).

    std::unique_ptr<postfx::Context> postfx;
    ImageInfo hdrInfo, depthInfo;
    ShadowMapInfo shadowInfo;

    // render(): one command buffer and fence per frame in flight, and the readback buffer.
    std::array<VkCommandBuffer, kFramesInFlight> commandBuffers{};
    std::array<VkFence, kFramesInFlight> fences{};
    GpuBuffer readback;
    bool broken = false;  // a submission failed: the fences can no longer be trusted
    // The surfaces' sun transmittance, ambient and sky through the scene's atmosphere, recomputed only when
    // the sun or the atmosphere change.
    mutable AtmosphereLightingCache atmosphereLighting;
    // postfx's cloud shadow transform of the last recorded frame, whose shadow map the next frame's
    // lighting reads (docs/effects/clouds.md, "Shadows").
    postfx::CloudShadowTransform cloudShadow;
    // requestCameraCut(): the next recorded frame is a camera cut (FrameInfo::cameraCut).
    bool cameraCutRequested = false;
    // The pre-exposure of the last recorded frame (its HDR image holds radiance × this).
    float preExposure = 1.0f;
    // The pre-exposure metered from what the camera sees (render()'s frame 0, or a window's frames with
    // options.meterInterval; 0: none, frameLight takes scenePreExposure's).
    double meteredExposure = 0.0;
    // options.meterInterval: per frame slot, the copy of a frame's HDR image (host-visible, created on
    // first use), the pre-exposure it was stored with, and whether it waits to be measured.
    std::array<GpuBuffer, kFramesInFlight> meterCopies;
    std::array<float, kFramesInFlight> meterCopyExposure{};
    std::array<bool, kFramesInFlight> meterCopyPending{};

    // renderReference(): where postfx writes the fogged frame so that the HDR image keeps the
    // un-fogged scene (FrameInfo::output); created on first use.
    GpuImage fogScratch;

    // Points the lighting at postfx's cloud shadow map held from the previous frame (or at none) and
    // returns the rows its uniforms carry; orders the map's writes before the lighting's reads.
    postfx::CloudShadowTransform bindCloudShadow(VkCommandBuffer cmd);

    // The local shadow layout of `scene` (its lights with shadows) within the atlas's limit.
    LocalShadowLayout localShadowsOf(const Scene& scene) const;
    // Grows the atlas to hold the layout of `scene` (waiting for the device when it must be replaced, and
    // pointing the lighting at the new one): before anything gives postfx the frame (plan or record).
    bool reserveLocalShadows(const Scene& scene, std::string& error);

    bool createResources(std::string& error);
    bool createFrameSet(std::string& error);
    bool createPostfx(std::string& error);
    void recordHdrCopy(VkCommandBuffer cmd, const GpuBuffer& buffer) const;
    void recordReadback(VkCommandBuffer cmd) const;
    // options.meterInterval: measures `slot`'s copy when one waits (its frame done: the caller waited for
    // it) into meteredExposure; after recording frame `frameIndex`, records its copy when it is due.
    void meterCompletedFrame(const Scene& scene, size_t slot);
    bool recordMeterCopy(VkCommandBuffer cmd, uint64_t frameIndex, std::string& error);
    // Records frame 0 of `state` (a camera cut), reads it back and meters it (host/metering.h); again
    // with the metered pre-exposure (meteredExposure) while that changes, at most kMeteringPasses times.
    // The HDR image and the readback then hold frame 0 as rendered with meteredExposure (or the camera's
    // scenePreExposure when that fit). Nothing to do (meteredExposure 0) without options.preExpose.
    bool meterFirstFrame(const Scene& state, std::string& error);
    // 2^33 to 2^-33 in steps of 2^-16 and the pass that measures exactly.
    static constexpr uint32_t kMeteringPasses = 6;

    // The scene's light for a frame: the surfaces' lighting through the atmosphere and the pre-exposure.
    FrameLight frameLight(const Scene& scene) const;
    // The shadow map fit, and whether frame `frameIndex` draws it: sun.shadows, something to cast, and a
    // reader: the lighting (when the sun gives light) or postfx (when its frame plan reads host.shadow_map,
    // asked with the frame's `light`; without it, frameLight computes it).
    ShadowFit shadowFit(const Scene& scene) const;
    bool drawsShadows(const Scene& scene, const ShadowFit& fit, uint64_t frameIndex) const;
    bool drawsShadows(const Scene& scene, const ShadowFit& fit, uint64_t frameIndex,
                      const FrameLight& light) const;
    // The camera's projection, exactly as the G-buffer pass uses it.
    glm::mat4 projection(const Scene& scene) const;
    // postfx's per-frame inputs for frame `frameIndex` of `scene` with the frame's `light` (without it,
    // frameLight computes it); the shadow map's image empty when `shadows` is false.
    PostfxInputs postfxInputs(const Scene& scene, uint64_t frameIndex, const ShadowFit& fit, bool shadows,
                              const FrameLight& light) const;
    PostfxInputs postfxInputs(const Scene& scene, uint64_t frameIndex, const ShadowFit& fit,
                              bool shadows) const;
    // postfx's FrameInfo for frame `frameIndex` of `scene` (Renderer::frameInputs), recorded into `cmd`:
    // postfxInputs with the images.
    postfx::FrameInfo frameInfo(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                                const ShadowFit& fit, bool shadows, const FrameLight& light,
                                const postfx::ImageInput& fogOutput) const;
    // Renderer::recordFrame, with postfx writing to `fogOutput` (FrameInfo::output) when present.
    bool recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                     const postfx::ImageInput& fogOutput, std::string& error);
    // The forward pass of `scene` after postfx recorded `frame` (its lookup written into this slot's set).
    VkQueryPool forwardQueries = VK_NULL_HANDLE;  // timeForwardPass
    uint32_t forwardFirstQuery = 0;
    bool forwardLookup = true;
    bool recordForward(VkCommandBuffer cmd, const Scene& scene, const postfx::FrameInfo& frame,
                       std::string& error);
    // Waits for the slot's fence (its frame in flight done), then resets and begins its command buffer for
    // one submission; the command buffer, or null on a failed wait.
    VkCommandBuffer beginSlot(size_t slot, std::string& error);
    // Submits the ended `cmd` on the host's queue, signalling fences[slot] (reset first); a failed
    // submission marks the renderer broken.
    bool submit(VkCommandBuffer cmd, size_t slot, std::string& error);
};

}  // namespace demo
