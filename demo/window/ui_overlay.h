// The windowed demo's Dear ImGui overlay (ImGui 1.86, GLFW + Vulkan backends): a small panel with the
// device, frame time, camera and postfx pass timings, and the caller's sections (the fog controls),
// drawn over the swapchain image in a render pass that loads the blitted frame (loadOp LOAD) and leaves
// the image ready to present.
#pragma once

#include "host/vulkan_host.h"

#include <postfx/context.h>

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace demo::window {

class Swapchain;

struct OverlayStats {
    std::string device;
    double frameMs = 0.0;  // smoothed CPU time between frames
    glm::vec3 cameraPosition{0.0f};
    float yawDeg = 0.0f, pitchDeg = 0.0f;
    VkExtent2D renderExtent{0, 0};
    uint64_t timingsFrame = 0;  // the frame `passTimings` belongs to
    bool timingsValid = false;  // false until a frame's timings were read
    std::vector<postfx::PassTiming> passTimings;
    // The effects' quality as recorded, a line each ("fog quality: auto: high", "clouds quality: medium"),
    // then the frame budget's choice (budgetChoiceLines); empty when no effect with presets is on.
    std::vector<std::string> quality;
    // postfx's frame plan for the frame being recorded: passes, resources, which are cached (held and not
    // rebuilt) and which are temporal histories.
    std::vector<std::string> plan;
};

class UiOverlay {
public:
    UiOverlay() = default;
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;
    ~UiOverlay() { destroy(); }

    // ImGui context + GLFW backend (installs its callbacks, chaining any installed before) + Vulkan backend.
    // `framesInFlight` >= 2: ImGui rotates that many vertex/index buffers.
    bool create(VulkanHost& host, GLFWwindow* window, const Swapchain& swapchain, uint32_t framesInFlight,
                std::string& error);
    // After the swapchain was recreated: new framebuffers (and render pass / pipeline if the format changed).
    bool onSwapchainRecreated(const Swapchain& swapchain, std::string& error);
    void destroy();

    // True while ImGui wants the mouse / keyboard (the pointer is over the panel, a widget is active).
    bool wantsMouse() const;
    bool wantsKeyboard() const;

    // Builds this frame's UI (call once per frame before record). `sections`, when given, adds more
    // widgets to the panel below the statistics (e.g. FogControls::build). The panel is at most as tall
    // as the window and scrolls when its content is taller.
    void build(const OverlayStats& stats, const std::function<void()>& sections = {});
    // Records the render pass over swapchain image `imageIndex`, which must be in TRANSFER_DST_OPTIMAL
    // after TRANSFER writes; leaves it in PRESENT_SRC_KHR.
    void record(VkCommandBuffer cmd, uint32_t imageIndex, VkExtent2D extent);

private:
    bool createRenderPass(VkFormat format, std::string& error);
    bool createFramebuffers(const Swapchain& swapchain, std::string& error);
    bool initVulkanBackend(std::string& error);
    void destroyFramebuffers();
    void shutdownVulkanBackend();

    VulkanHost* host_ = nullptr;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    uint32_t framesInFlight_ = 2;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    bool context_ = false, glfwBackend_ = false, vulkanBackend_ = false;
    size_t timingLines_ = 0;  // the most lines the pass timings have taken (the block never shrinks)
};

}  // namespace demo::window
