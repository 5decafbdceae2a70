// The demo's deferred host renderer: G-buffer (albedo, normal, D32 depth), a directional sun with a
// shadow map, local lights with shadow maps in one atlas (host/local_shadows.h), Lambert lighting into an
// RGBA16F HDR target, then postfx records its passes into the same command buffer through its public API,
// then (for display/PNG only) tonemapping.
//
// Shading convention (tests rely on it), per RGB channel:
//   L = albedo/π · E · max(0, n·l) · visibility + albedo · ambient
// with E the sun illuminance, l the direction toward the sun, visibility from the shadow map
// (1 when sun.shadows is false); pixels with no geometry get scene.sky.
#pragma once

#include "host/image_io.h"
#include "host/vulkan_host.h"
#include "scene/motion.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <postfx/context.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace demo {

struct RenderOptions {
    uint32_t width = 1280;
    uint32_t height = 720;
    // Frames rendered by render(), indices 0..frames-1; the last one is returned (temporal accumulation
    // builds up over them). Frame k shows the scene's state at frame k (sceneAtFrame: its camera and lights
    // moved, scene/motion.h); the index also sets postfx's time (k · scene.frameTime, 1/60 s by default)
    // and the fog's jitter pattern, so render() and renderReference() show the same frame (index
    // frames - 1).
    uint32_t frames = 1;
    // When set, every frame is at this time [s] for postfx (the noise's wind offset), so that frames
    // differ only in their index (the fog's jitter pattern, and the scene's motion if it has any);
    // otherwise frame k is at k · scene.frameTime (frameTimeSeconds).
    std::optional<double> fixedTimeSeconds;
    bool reversedZ = true;     // depth convention of the G-buffer (and of the postfx context)
    bool infiniteFar = false;  // projection without a far plane
    uint32_t shadowMapSize = 2048;
    // Store the HDR image pre-exposed (scenePreExposure; postfx::FrameInfo::preExposure), as a host
    // lighting in physical units into RGBA16F should; false: physical units (pre-exposure 1), where a
    // 100,000 lux sun's in-scattering clips at RGBA16F's 65,504.
    bool preExpose = true;
    // A window's auto-exposure (with preExpose): every meterInterval-th frame recordFrame records copies its
    // HDR image to a host buffer of its frame slot, and the next recordFrame of that slot (its frame done)
    // measures it and sets the pre-exposure of the frames after (host/metering.h), so the pre-exposure
    // follows what the camera sees. 0: off (render() meters its frame 0 itself).
    uint32_t meterInterval = 0;
};

// Linear RGBA32F pixels, row-major, top row first.

// One of the renderer's images, as handed to postfx or to a window's blit/tonemap.
struct ImageInfo {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D, mip 0, layer 0 (depth aspect for depth images)
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // layout once a recorded frame has executed
    VkImageUsageFlags usage = 0;                       // as created
};

// The sun's shadow map (postfx's fog reads it too).
struct ShadowMapInfo {
    ImageInfo image;  // D32_SFLOAT, DEPTH_STENCIL_READ_ONLY_OPTIMAL; standard Z: 0 nearest the sun, cleared 1
    VkSampler compareSampler = VK_NULL_HANDLE;  // nearest, compare LESS_OR_EQUAL (1 = lit), border depth 1
    glm::mat4 viewProj{1.0f};  // world -> shadow clip: xy in [-1, 1] (uv = xy / 2 + 1/2), depth in [0, 1]
    float texelWorldSize = 0;  // [m] edge of one texel
    // The last recorded frame drew it: sun.shadows, a box or sphere to cast, and something reads it (the
    // lighting when the sun gives light, or postfx's frame plan).
    bool enabled = false;
};

// renderReference's clouds path-traced: the paths and, back, the Monte Carlo standard error of the clouds.
struct CloudsPathTracing {
    uint32_t samples = 64;  // paths per pixel, >= 2
    uint64_t seed = 1;
    // Out: the standard error of each pixel's clouds radiance [cd/m²] (RGBA, out's layout, alpha 0), as the
    // clouds left the pixel (before the fog in front, if any); empty when the scene has no clouds.
    std::vector<float> standardError;
};

class Renderer {
public:
    static constexpr uint32_t kFramesInFlight = 2;  // render()'s command buffers; postfx is created with it

    static std::unique_ptr<Renderer> create(VulkanHost& host, const RenderOptions& options,
                                            std::string& error);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders frames 0..options.frames-1 of `scene` (every call), frame k showing sceneAtFrame(scene, k),
    // and reads back the last frame's HDR radiance (after postfx). Frame 0 is a camera cut
    // (FrameInfo::cameraCut: no temporal history of an earlier call is kept), and so is the frame
    // scene.cameraCutFrame names. Calls setScene first, and again (waiting for the device) when the camera
    // has moved a quarter of its far distance (at most 2.5 km) from where the planes were centred, and for
    // the last frame when it moved at all, so that its planes are those renderReference() draws.
    bool render(const Scene& scene, ImageF& out, std::string& error);

    // The same frame as render() (index options.frames - 1) with postfx's fog replaced by its CPU
    // reference (postfx::reference::renderFog for scene.fog, renderFroxelFog for scene.froxelFog with
    // the scene's lights and fog volumes; double precision, `stepsPerPixel` midpoint steps, no jitter,
    // all CPU threads). The GPU renders the frame up to lighting; postfx runs too, writing to a scratch
    // image, so that the noise texture it generates can be read back while the HDR image keeps the
    // un-fogged scene (postfx::kFogNoiseTexture or kFroxelFogNoiseTexture). Read back: HDR color, depth,
    // shadow map (when drawn), noise (when on), the clouds' shadow map (when they cast shadows: the fog's
    // reference dims its sunlight by it); the camera, sun, ambient, lights, shadow and time inputs are
    // those of the GPU frame. With clouds casting shadows a frame of the same state is recorded first, so
    // that the surfaces are lit under the map of the frame shown (render()'s lighting reads the previous
    // frame's). Without fog the result is the un-fogged scene. `out` has render()'s layout.
    // The frame shows sceneAtFrame(scene, options.frames - 1), the state of render()'s last frame (the
    // reference itself is of that one frame: it has no history); its postfx frame is a camera cut.
    // Calls setScene(that state) first. `stride` > 1 evaluates the reference only at the pixels (x, y) with x
    // and y multiples of `stride` (CPU time / stride²): `out` is then ceil(W / stride) x ceil(H / stride),
    // its pixel (i, j) being the frame's pixel (i · stride, j · stride).
    // `pathTracedClouds`, when given, has the clouds path-traced (postfx::reference::CloudInputs::pathTraced,
    // docs/effects/clouds.md, "Path-traced truth") instead of marched, and receives their standard error.
    bool renderReference(const Scene& scene, ImageF& out, std::string& error, uint32_t stepsPerPixel = 4096,
                         uint32_t stride = 1, CloudsPathTracing* pathTracedClouds = nullptr);

    // Builds and uploads the scene's meshes (planes are centred under the camera as it is now).
    // Waits for the device to be idle first, so it may be called between frames of a window loop.
    bool setScene(const Scene& scene, std::string& error);

    // Records one frame into `cmd` (recording, outside a render pass): frame uniforms, shadow map
    // (when scene.sun.shadows), G-buffer, lighting, then postfx (scene.fog, scene.froxelFog; time
    // frameTimeSeconds(scene, frameIndex); FrameInfo::cameraCut on frame 0, when scene.cameraCutFrame is
    // frameIndex, and when requestCameraCut() was called since the last recorded frame). The local shadow
    // atlas is drawn for the lights with `shadows` (grown first, waiting for the device, when they need
    // more room) and given to postfx in FrameInfo::localShadows.
    // Geometry comes from the last setScene(); camera, sun, ambient, sky, lights and fog from `scene` as
    // given: `scene` is the frame's state, its motion is not applied here (sceneAtFrame does that).
    // Frames execute in recording order on host.queue; before recording frame k the caller waits
    // for frame k - kFramesInFlight. After it, hdrImage() is in GENERAL with COMPUTE_SHADER writes
    // to make visible to its reader. A caller may read it (blit, tonemap, sample) in TRANSFER,
    // COMPUTE_SHADER or FRAGMENT_SHADER stages and leave it in any layout: the next frame waits for
    // those stages and discards it. postfx reads depthImage(), shadowMap() and the local shadow atlas in
    // COMPUTE_SHADER; the next frame's raster passes wait for COMPUTE_SHADER before overwriting them.
    bool recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex, std::string& error);
    // The same with postfx writing to `fogOutput` (postfx::FrameInfo::output: same extent, RGBA16F or
    // RGBA32F, usage STORAGE, in its `layout`) instead of compositing into hdrImage(), which then keeps
    // the un-fogged scene (only read by postfx).
    bool recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                     const postfx::ImageInput& fogOutput, std::string& error);
    // What recordFrame(cmd, scene, frameIndex) gives postfx: images (HDR color in GENERAL, depth and
    // shadow map in the layouts they rest in), time, camera, sun, ambient, shadow map, scene.fog,
    // scene.froxelFog and scene.lights (FrameInfo::lights points into the renderer: valid until its next
    // frame or frameInputs call; FrameInfo::froxelFog.volumes points into scene.froxelVolumes: valid while
    // `scene` lives and its froxelVolumes is unchanged, froxelFogSettings). For a host pass that wants
    // exactly postfx's inputs after recordFrame (the benchmark's baselines). Records nothing.
    postfx::FrameInfo frameInputs(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex) const;

    // The next recorded frame tells postfx FrameInfo::cameraCut: the view does not continue the previous
    // frame's (the window demo's view reset), so every temporal history is dropped.
    void requestCameraCut();
    // The next recordFrame writes two timestamps into `pool` at `firstQuery` and `firstQuery + 1` around its
    // forward pass (the benchmark's timing of the transparent surfaces), when it draws one; the caller
    // resets them before. A null pool: none. lookup false: that frame's forward pass leaves postfx's
    // lookup out of its surfaces (unfogged), so that the difference of two timings is the lookup's share.
    void timeForwardPass(VkQueryPool pool, uint32_t firstQuery, bool lookup = true);

    // postfx's plan (docs/frame-plan.md) for frame `frameIndex` of `scene` as recordFrame(cmd, scene,
    // frameIndex) would record it now (given what postfx already holds, e.g. a generated noise texture).
    bool plan(const Scene& scene, uint64_t frameIndex, postfx::FramePlan& out, std::string& error) const;

    const ImageInfo& hdrImage() const;    // RGBA16F radiance; usage STORAGE | SAMPLED | TRANSFER_SRC
    const ImageInfo& depthImage() const;  // D32_SFLOAT, DEPTH_STENCIL_READ_ONLY_OPTIMAL
    const ShadowMapInfo& shadowMap() const;
    postfx::Context& postfxContext() const;  // the context created from this renderer's handles
    // The pre-exposure of the last recorded frame: hdrImage() holds radiance × this (scenePreExposure:
    // the camera's exposure, within postfx's limits). render() and renderReference() divide it out.
    float preExposure() const;

    struct Impl;

private:
    explicit Renderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Divides the pre-exposure out of RGBA radiance (alpha untouched): physical units again.
void unexpose(std::vector<float>& rgba, float preExposure);

}  // namespace demo
