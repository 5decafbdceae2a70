#include "window/window_app.h"

#include "host/gpu_resources.h"
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/motion.h"
#include "window/atmosphere_controls.h"
#include "window/budget_controls.h"
#include "window/camera_controls.h"
#include "window/clouds_controls.h"
#include "window/fly_camera.h"
#include "window/fog_controls.h"
#include "window/froxel_fog_controls.h"
#include "window/light_controls.h"
#include "window/swapchain.h"
#include "window/tonemap_pass.h"
#include "window/transparency_controls.h"
#include "window/ui_overlay.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace demo::window {
namespace {

constexpr uint32_t kFramesInFlight = Renderer::kFramesInFlight;
// Every 4th frame is metered (RenderOptions::meterInterval): reading back and measuring an image costs a
// few ms of CPU, which a quarter of the frames carry; the exposure settles within a few metered frames.
constexpr uint32_t kMeterInterval = 4;

int fail(const std::string& message) {
    std::fprintf(stderr, "postfx-demo: %s\n", message.c_str());
    return 1;
}

bool sameExtent(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

class App {
public:
    explicit App(const AppOptions& options, const Scene& scene)
        : options_(options),
          scene_(scene),
          fileCamera_(scene.camera),
          fogControls_(scene),
          atmosphereControls_(scene),
          cloudsControls_(scene) {}
    ~App() { destroy(); }

    bool init(std::string& error);
    bool run(std::string& error);
    // Destroys everything but the Vulkan host (whose validation messages are counted afterwards).
    void destroy();
    const VulkanHost* host() const { return host_.get(); }

private:
    enum class Frame { Presented, Skipped };
    bool recreateSwapchain(std::string& error);
    bool recreateRenderer(std::string& error);
    bool drawFrame(Frame& outcome, std::string& error);
    void recordCommands(VkCommandBuffer cmd, uint32_t imageIndex);
    void readTimings();
    // The scene frame frameIndex_ shows: scene_ with its lights moved as the scene file says (velocity,
    // intensity change: sceneAtFrame); the camera is the fly camera's (the file's camera motion is not
    // applied in the window). scene_ itself when nothing moves.
    const Scene& frameScene();
    // R: the view back to the scene file's camera, told to postfx as a camera cut.
    void resetView();
    std::string fogQualityText() const;     // OverlayStats::quality's fog line
    std::string cloudsQualityText() const;  // its clouds line
    // OverlayStats::plan: postfx's plan for the frame about to be recorded (docs/frame-plan.md).
    std::vector<std::string> planLines();
    void hold();

    static void onFramebufferSize(GLFWwindow* window, int, int) {
        static_cast<App*>(glfwGetWindowUserPointer(window))->swapchainDirty_ = true;
    }

    AppOptions options_;
    Scene scene_;
    Camera fileCamera_;  // the scene file's camera (R resets the view to it)
    Scene movedScene_;   // frameScene()'s copy when the scene has motion
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<VulkanHost> host_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    Swapchain swapchain_;
    std::unique_ptr<Renderer> renderer_;
    VkExtent2D renderExtent_{0, 0};
    TonemapPass tonemap_;
    std::unique_ptr<UiOverlay> ui_;
    FogControls fogControls_;                    // edits scene_.fog and scene_.sun from the overlay's panel
    FroxelFogControls froxelFogControls_;        // edits scene_.froxelFog and scene_.froxelVolumes
    LightControls lightControls_;                // edits scene_.lights
    TransparencyControls transparencyControls_;  // edits objects' opacity and scene_.particles
    AtmosphereControls atmosphereControls_;  // edits scene_.atmosphere, scene_.sun.direction, the camera's y
    CloudsControls cloudsControls_;          // edits scene_.clouds
    CameraControls cameraControls_;          // edits scene_.camera.ev100 (exposure and pre-exposure)
    BudgetControls budgetControls_;          // edits scene_.budgetMs and the effects' quality
    std::array<VkCommandBuffer, kFramesInFlight> commandBuffers_{};
    std::array<VkFence, kFramesInFlight> fences_{};              // signalled when the slot's frame completed
    std::array<VkSemaphore, kFramesInFlight> imageAvailable_{};  // acquire -> the slot's submission
    bool swapchainDirty_ = false;
    bool minimised_ = false;
    bool resetKeyDown_ = false;  // R was down at the last poll (a reset per press)

    FlyCamera camera_;
    glm::vec3 meshCentre_{0.0f};  // camera position at the last setScene (plane quads are centred there)
    uint64_t frameIndex_ = 0;     // frames submitted so far
    uint64_t rendererFirstFrame_ = 0;
    OverlayStats stats_;
};

bool App::init(std::string& error) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(int(options_.width), int(options_.height), "postfx demo", nullptr, nullptr);
    if (!window_) {
        const char* what = nullptr;
        glfwGetError(&what);
        error = std::string("glfwCreateWindow failed") + (what ? std::string(": ") + what : "");
        return false;
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetFramebufferSizeCallback(window_, onFramebufferSize);

    HostOptions ho;
    ho.validation = options_.validation;
    uint32_t count = 0;
    const char** exts = glfwGetRequiredInstanceExtensions(&count);
    if (!exts) {
        error = "GLFW found no Vulkan surface support (glfwGetRequiredInstanceExtensions)";
        return false;
    }
    ho.instanceExtensions.assign(exts, exts + count);
    ho.swapchain = true;
    ho.presentSupport = [](VkInstance instance, VkPhysicalDevice pd, uint32_t family) {
        return glfwGetPhysicalDevicePresentationSupport(instance, pd, family) == GLFW_TRUE;
    };
    host_ = VulkanHost::create(ho, error);
    if (!host_) {
        error = "Vulkan: " + error;
        return false;
    }
    if (VkResult r = glfwCreateWindowSurface(host_->instance, window_, nullptr, &surface_); r != VK_SUCCESS) {
        error = std::string("glfwCreateWindowSurface failed: ") + vkResultName(r);
        return false;
    }
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(host_->physicalDevice, host_->queueFamily, surface_, &supported);
    if (!supported) {
        error = "the Vulkan queue family cannot present to the window's surface";
        return false;
    }

    const VkDevice device = host_->device;
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = host_->commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = kFramesInFlight;
    if (!vkCheck(vkAllocateCommandBuffers(device, &ai, commandBuffers_.data()), "vkAllocateCommandBuffers",
                 error))
        return false;
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fci.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (uint32_t i = 0; i < kFramesInFlight; ++i) {
        if (!vkCheck(vkCreateFence(device, &fci, nullptr, &fences_[i]), "vkCreateFence", error) ||
            !vkCheck(vkCreateSemaphore(device, &sci, nullptr, &imageAvailable_[i]), "vkCreateSemaphore",
                     error))
            return false;
    }

    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (!swapchain_.create(*host_, surface_, {uint32_t(w), uint32_t(h)}, error) || !recreateRenderer(error))
        return false;
    if (options_.ui) {
        ui_ = std::make_unique<UiOverlay>();
        if (!ui_->create(*host_, window_, swapchain_, kFramesInFlight, error)) return false;
    }
    camera_.reset(scene_.camera);
    stats_.device = host_->deviceDescription();
    return true;
}

// (Re)creates the renderer and the tonemap pass at the swapchain's extent.
bool App::recreateRenderer(std::string& error) {
    vkDeviceWaitIdle(host_->device);
    tonemap_.destroy();
    renderer_.reset();
    RenderOptions ro;
    ro.width = swapchain_.extent.width;
    ro.height = swapchain_.extent.height;
    ro.meterInterval = kMeterInterval;  // auto-exposure: the pre-exposure follows what the camera sees
    renderer_ = Renderer::create(*host_, ro, error);
    if (!renderer_ || !renderer_->setScene(scene_, error) ||
        !tonemap_.create(*host_, renderer_->hdrImage(), error))
        return false;
    renderExtent_ = swapchain_.extent;
    meshCentre_ = scene_.camera.position;
    rendererFirstFrame_ = frameIndex_;
    stats_.timingsValid = false;
    stats_.passTimings.clear();
    return true;
}

bool App::recreateSwapchain(std::string& error) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    minimised_ = w == 0 || h == 0;
    if (minimised_) return true;  // keep the old swapchain until the window is restored
    if (!vkCheck(vkDeviceWaitIdle(host_->device), "vkDeviceWaitIdle", error)) return false;
    if (!swapchain_.create(*host_, surface_, {uint32_t(w), uint32_t(h)}, error)) return false;
    if (!sameExtent(swapchain_.extent, renderExtent_) && !recreateRenderer(error)) return false;
    if (ui_ && !ui_->onSwapchainRecreated(swapchain_, error)) return false;
    swapchainDirty_ = false;
    return true;
}

// Pass timings of the frame that last used this slot (complete: its fence was waited for).
void App::readTimings() {
    if (frameIndex_ < rendererFirstFrame_ + kFramesInFlight) return;
    const uint64_t done = frameIndex_ - kFramesInFlight;
    std::vector<postfx::PassTiming> timings;
    if (renderer_->postfxContext().readPassTimings(done, timings).ok()) {
        stats_.passTimings = std::move(timings);
        stats_.timingsFrame = done;
        stats_.timingsValid = true;
    }
}

const Scene& App::frameScene() {
    if (!hasMotion(scene_)) return scene_;
    movedScene_ = scene_;  // this frame's edits of the panel included
    moveToFrame(scene_, frameIndex_, movedScene_);
    movedScene_.camera = scene_.camera;
    return movedScene_;
}

void App::resetView() {
    scene_.camera = fileCamera_;
    camera_.reset(scene_.camera);
    // The view jumps: postfx must not blend the old view's history into it (FrameInfo::cameraCut).
    renderer_->requestCameraCut();
}

std::string App::fogQualityText() const {
    if (!scene_.fog.enabled) return "";
    const std::string name = fogQualityName(scene_.fog.quality);
    if (scene_.fog.quality != postfx::FogQuality::Auto) return name;
    postfx::FogQuality chosen = postfx::FogQuality::Custom;
    if (!postfx::fogAutoQuality(renderer_->postfxContext(), chosen).ok())
        return name + ": measuring the presets";
    return name + ": " + fogQualityName(chosen);
}

std::string App::cloudsQualityText() const {
    if (!scene_.clouds.enabled) return "";
    constexpr const char* kNames[] = {"custom", "low", "medium", "high", "ultra", "auto"};
    const uint32_t q = std::min<uint32_t>(uint32_t(scene_.clouds.quality), 5u);
    const std::string name = kNames[q];
    if (scene_.clouds.quality != postfx::CloudQuality::Auto) return name;
    uint32_t chosen = 0;
    if (!renderer_->postfxContext().autoQuality("clouds", chosen).ok())
        return name + ": measuring the presets";
    return name + ": " + kNames[std::min(chosen + 1u, 4u)];
}

std::vector<std::string> App::planLines() {
    postfx::FramePlan plan;
    std::string error;
    if (!renderer_->plan(frameScene(), frameIndex_, plan, error)) return {"plan: " + error};
    char line[160];
    std::snprintf(line, sizeof line, "plan: %zu passes, %zu resources held, %.1f MiB", plan.passes.size(),
                  plan.resources.size(), double(plan.totalBytes()) / (1024.0 * 1024.0));
    std::vector<std::string> lines{line};
    // Held from earlier frames and not written by this one: LUTs and noise whose inputs did not change.
    std::string cached, history;
    for (const postfx::PlannedResource& r : plan.resources) {
        if (r.history)
            history += (history.empty() ? "" : ", ") + r.name;
        else if (r.cached)
            cached += (cached.empty() ? "" : ", ") + r.name;
    }
    lines.push_back("  cached: " + (cached.empty() ? std::string("none") : cached));
    if (!history.empty()) lines.push_back("  history: " + history);
    for (const std::string& adjusted : plan.adjusted)
        lines.push_back("  adjusted: " + adjusted);
    return lines;
}

void App::recordCommands(VkCommandBuffer cmd, uint32_t imageIndex) {
    // Renderer::recordFrame has already been recorded: HDR radiance after postfx, GENERAL.
    tonemap_.record(cmd, scene_.camera.ev100, renderer_->preExposure(), swapchain_.srgb && swapchain_.bgr);

    const VkImage target = swapchain_.images[imageIndex];
    const GpuImage& src = tonemap_.output();
    // The acquire semaphore is waited for at TRANSFER: the transition's source stage chains with it.
    imageBarrier(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    if (!swapchain_.srgb) {
        // UNORM swapchain: the blit converts RGBA8 to the swapchain's channel order (and would scale,
        // though the renderer always matches the swapchain's extent).
        VkImageBlit region{};
        region.srcSubresource = layers;
        region.srcOffsets[1] = {int32_t(src.extent.width), int32_t(src.extent.height), 1};
        region.dstSubresource = layers;
        region.dstOffsets[1] = {int32_t(swapchain_.extent.width), int32_t(swapchain_.extent.height), 1};
        vkCmdBlitImage(cmd, src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    } else {
        // sRGB swapchain: bytes copied unchanged (already sRGB-encoded, channel order set by the tonemap).
        VkImageCopy region{};
        region.srcSubresource = layers;
        region.dstSubresource = layers;
        region.extent = {std::min(src.extent.width, swapchain_.extent.width),
                         std::min(src.extent.height, swapchain_.extent.height), 1};
        vkCmdCopyImage(cmd, src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
    if (ui_) {
        ui_->record(cmd, imageIndex, swapchain_.extent);  // TRANSFER_DST -> ... -> PRESENT_SRC
    } else {
        imageBarrier(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    }
}

bool App::drawFrame(Frame& outcome, std::string& error) {
    outcome = Frame::Skipped;
    const VkDevice device = host_->device;
    const uint32_t slot = uint32_t(frameIndex_ % kFramesInFlight);
    // Frame (frameIndex - kFramesInFlight) is done: its command buffer, semaphore, the renderer's and
    // postfx's per-frame resources and ImGui's buffers of this slot are free.
    if (!vkCheck(vkWaitForFences(device, 1, &fences_[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences", error))
        return false;
    readTimings();

    uint32_t imageIndex = 0;
    VkResult r = vkAcquireNextImageKHR(device, swapchain_.handle, UINT64_MAX, imageAvailable_[slot],
                                       VK_NULL_HANDLE, &imageIndex);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        swapchainDirty_ = true;  // nothing was signalled: recreate and try again
        return true;
    }
    if (r == VK_SUBOPTIMAL_KHR)
        swapchainDirty_ = true;  // the semaphore is signalled: present this one, then recreate
    else if (!vkCheck(r, "vkAcquireNextImageKHR", error))
        return false;

    if (ui_) {
        stats_.cameraPosition = scene_.camera.position;
        stats_.yawDeg = camera_.yawDeg();
        stats_.pitchDeg = camera_.pitchDeg();
        stats_.renderExtent = renderExtent_;
        stats_.quality.clear();
        if (const std::string fog = fogQualityText(); !fog.empty())
            stats_.quality.push_back("fog quality: " + fog);
        if (const std::string clouds = cloudsQualityText(); !clouds.empty())
            stats_.quality.push_back("clouds quality: " + clouds);
        for (const std::string& line : budgetChoiceLines(scene_, renderer_->postfxContext()))
            stats_.quality.push_back(line);
        stats_.plan = planLines();
        // The controls edit scene_ before this frame records it (Renderer::recordFrame takes both fogs, the
        // fog volumes, the atmosphere, the clouds, lights, sun and camera from scene_ every frame); their
        // values are always valid for postfx, and at most one of the two fogs is on.
        ui_->build(stats_, [this] {
            // In the effects' composite order: the atmosphere (the farthest) first.
            cameraControls_.build(scene_, renderer_->preExposure());
            budgetControls_.build(scene_, renderer_->postfxContext());
            atmosphereControls_.build(scene_);
            cloudsControls_.build(scene_);
            fogControls_.build(scene_);
            froxelFogControls_.build(scene_);
            lightControls_.build(scene_);
            transparencyControls_.build(scene_);
        });
    }

    VkCommandBuffer cmd = commandBuffers_[slot];
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &bi);
    const bool recorded = renderer_->recordFrame(cmd, frameScene(), frameIndex_, error);
    if (recorded) recordCommands(cmd, imageIndex);
    if (!vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) || !recorded) return false;

    vkResetFences(device, 1, &fences_[slot]);
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.waitSemaphoreCount = 1;
    si.pWaitSemaphores = &imageAvailable_[slot];
    si.pWaitDstStageMask = &waitStage;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    si.signalSemaphoreCount = 1;
    si.pSignalSemaphores = &swapchain_.renderFinished[imageIndex];
    if (!vkCheck(vkQueueSubmit(host_->queue, 1, &si, fences_[slot]), "vkQueueSubmit", error)) return false;
    ++frameIndex_;

    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &swapchain_.renderFinished[imageIndex];
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_.handle;
    pi.pImageIndices = &imageIndex;
    r = vkQueuePresentKHR(host_->queue, &pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
        swapchainDirty_ = true;  // the present's semaphore wait still happens
    else if (!vkCheck(r, "vkQueuePresentKHR", error))
        return false;
    outcome = r == VK_ERROR_OUT_OF_DATE_KHR ? Frame::Skipped : Frame::Presented;
    return true;
}

bool App::run(std::string& error) {
    const float replanDistance = 0.25f * std::min(scene_.camera.farPlane, 1e4f);
    uint32_t presented = 0;
    double last = glfwGetTime();
    double smoothedMs = 0.0;
    while (!glfwWindowShouldClose(window_)) {
        glfwPollEvents();
        // Esc quits, except while an ImGui widget has the keyboard (Esc cancels a typed value there).
        if (glfwGetKey(window_, GLFW_KEY_ESCAPE) == GLFW_PRESS && !(ui_ && ui_->wantsKeyboard())) break;
        if (glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) {  // nothing to show (X11 keeps the size)
            glfwWaitEventsTimeout(0.1);
            last = glfwGetTime();
            continue;
        }
        if (swapchainDirty_ || minimised_) {
            if (!recreateSwapchain(error)) return false;
            if (minimised_) {
                glfwWaitEventsTimeout(0.1);
                last = glfwGetTime();
                continue;
            }
        }

        const double now = glfwGetTime();
        const double frameSeconds = now - last;
        last = now;
        // Displayed frame time: exponential average over about half a second (slow frames show as they are).
        const double alpha = smoothedMs == 0.0 ? 1.0 : 1.0 - std::exp(-frameSeconds / 0.5);
        smoothedMs += alpha * (frameSeconds * 1000.0 - smoothedMs);
        stats_.frameMs = smoothedMs;
        const bool uiMouse = ui_ && ui_->wantsMouse();
        const bool uiKeyboard = ui_ && ui_->wantsKeyboard();
        const auto moveSeconds = float(std::min(frameSeconds, 0.25));  // no big jump after a stall
        bool moved = camera_.update(window_, moveSeconds, uiMouse, uiKeyboard, scene_.camera);
        const bool resetKey = glfwGetKey(window_, GLFW_KEY_R) == GLFW_PRESS;
        if (resetKey && !resetKeyDown_ && !uiKeyboard) {
            resetView();
            moved = true;
        }
        resetKeyDown_ = resetKey;
        if (moved && glm::length(scene_.camera.position - meshCentre_) > replanDistance) {
            // Plane quads are centred under the camera at setScene (which waits for the device).
            if (!renderer_->setScene(scene_, error)) return false;
            meshCentre_ = scene_.camera.position;
        }

        Frame outcome = Frame::Skipped;
        if (!drawFrame(outcome, error)) return false;
        if (outcome == Frame::Presented && options_.frames > 0 && ++presented >= options_.frames) {
            if (options_.hold) hold();
            break;
        }
    }
    return vkCheck(vkDeviceWaitIdle(host_->device), "vkDeviceWaitIdle", error);
}

// Keeps the window (and its last frame) on screen until stdin reaches its end, the window is closed or
// Esc is pressed: lets a test take a screenshot of the X server's framebuffer at a known frame.
void App::hold() {
    vkDeviceWaitIdle(host_->device);
    std::printf("postfx-demo: presented %u frames; holding the window until stdin is closed\n",
                options_.frames);
    std::fflush(stdout);
    pollfd in{STDIN_FILENO, POLLIN, 0};
    char buffer[256];
    while (!glfwWindowShouldClose(window_) && glfwGetKey(window_, GLFW_KEY_ESCAPE) != GLFW_PRESS) {
        glfwPollEvents();
        const int n = poll(&in, 1, 50);
        if (n < 0) break;
        if (n > 0) {
            if (read(STDIN_FILENO, buffer, sizeof(buffer)) <= 0) break;  // end of input (or an error)
        }
    }
}

void App::destroy() {
    if (host_ && host_->device) {  // not after the host's own destroy() below
        vkDeviceWaitIdle(host_->device);
        ui_.reset();
        tonemap_.destroy();
        renderer_.reset();
        for (uint32_t i = 0; i < kFramesInFlight; ++i) {
            if (fences_[i]) vkDestroyFence(host_->device, fences_[i], nullptr);
            if (imageAvailable_[i]) vkDestroySemaphore(host_->device, imageAvailable_[i], nullptr);
            if (commandBuffers_[i])
                vkFreeCommandBuffers(host_->device, host_->commandPool, 1, &commandBuffers_[i]);
            fences_[i] = VK_NULL_HANDLE;
            imageAvailable_[i] = VK_NULL_HANDLE;
            commandBuffers_[i] = VK_NULL_HANDLE;
        }
        swapchain_.destroy();
        if (surface_) vkDestroySurfaceKHR(host_->instance, surface_, nullptr);
        surface_ = VK_NULL_HANDLE;
        host_->destroy();  // so that runWindow counts the messages at destruction (objects left alive)
    }
    if (window_) glfwDestroyWindow(window_);
    window_ = nullptr;
}

}  // namespace

int runWindow(const AppOptions& options, const Scene& scene) {
    App app(options, scene);
    std::string error;
    const bool ok = app.init(error) && app.run(error);
    app.destroy();
    if (!ok) return fail(error);
    if (const VulkanHost* host = app.host(); host && host->validationEnabled) {
        const std::vector<std::string> messages = host->validationMessages();
        if (!messages.empty()) {
            std::string first = messages.front();
            if (first.size() > 160) first = first.substr(0, 160) + "...";
            return fail(std::to_string(messages.size()) +
                        " Vulkan validation message(s), printed above; first: " + first);
        }
    }
    return 0;
}

}  // namespace demo::window
