#include "window/ui_overlay.h"

#include "host/gpu_resources.h"
#include "window/swapchain.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

namespace demo::window {
namespace {

// ImGui's Vulkan backend reports failures through a plain function pointer: remember the first one.
VkResult gFirstImguiError = VK_SUCCESS;
void checkImguiResult(VkResult r) {
    if (r != VK_SUCCESS && gFirstImguiError == VK_SUCCESS) gFirstImguiError = r;
}

float srgbToLinear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

bool UiOverlay::create(VulkanHost& host, GLFWwindow* window, const Swapchain& swapchain,
                       uint32_t framesInFlight, std::string& error) {
    host_ = &host;
    framesInFlight_ = std::max(framesInFlight, 2u);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    context_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    if (swapchain.srgb) {
        // sRGB swapchain: the attachment encodes what ImGui writes, so give it linear colors.
        for (ImVec4& c : ImGui::GetStyle().Colors) {
            c.x = srgbToLinear(c.x);
            c.y = srgbToLinear(c.y);
            c.z = srgbToLinear(c.z);
        }
    }
    if (!ImGui_ImplGlfw_InitForVulkan(window, true)) {
        error = "ImGui GLFW backend initialisation failed";
        return false;
    }
    glfwBackend_ = true;

    // One combined image sampler: the font atlas.
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pci.maxSets = 1;
    pci.poolSizeCount = 1;
    pci.pPoolSizes = &size;
    if (!vkCheck(vkCreateDescriptorPool(host.device, &pci, nullptr, &pool_), "vkCreateDescriptorPool (ImGui)",
                 error))
        return false;
    return createRenderPass(swapchain.format, error) && initVulkanBackend(error) &&
           createFramebuffers(swapchain, error);
}

bool UiOverlay::createRenderPass(VkFormat format, std::string& error) {
    format_ = format;
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the tonemapped frame blitted in before
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    const VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // In: the blit/copy's writes, before the layout transition and the attachment load.
    // Out: presentation needs no access mask (the semaphore signal makes the writes available).
    const std::array<VkSubpassDependency, 2> deps{{
        {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
         VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0},
        {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0, 0},
    }};
    VkRenderPassCreateInfo rci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rci.attachmentCount = 1;
    rci.pAttachments = &color;
    rci.subpassCount = 1;
    rci.pSubpasses = &subpass;
    rci.dependencyCount = uint32_t(deps.size());
    rci.pDependencies = deps.data();
    return vkCheck(vkCreateRenderPass(host_->device, &rci, nullptr, &renderPass_),
                   "vkCreateRenderPass (ImGui)", error);
}

bool UiOverlay::initVulkanBackend(std::string& error) {
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = host_->instance;
    info.PhysicalDevice = host_->physicalDevice;
    info.Device = host_->device;
    info.QueueFamily = host_->queueFamily;
    info.Queue = host_->queue;
    info.DescriptorPool = pool_;
    info.Subpass = 0;
    // ImageCount is the number of vertex/index buffer sets ImGui rotates through: one per frame in flight
    // is enough, as the frame loop waits for frame k - framesInFlight before recording frame k.
    info.MinImageCount = framesInFlight_;
    info.ImageCount = framesInFlight_;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImguiResult;
    gFirstImguiError = VK_SUCCESS;
    if (!ImGui_ImplVulkan_Init(&info, renderPass_)) {
        error = "ImGui Vulkan backend initialisation failed";
        return false;
    }
    vulkanBackend_ = true;
    if (!host_->submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); }, error)) {
        error = "ImGui font upload: " + error;
        return false;
    }
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    if (gFirstImguiError != VK_SUCCESS) {
        error = std::string("ImGui Vulkan backend: ") + vkResultName(gFirstImguiError);
        return false;
    }
    return true;
}

bool UiOverlay::createFramebuffers(const Swapchain& swapchain, std::string& error) {
    for (VkImageView view : swapchain.views) {
        VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fci.renderPass = renderPass_;
        fci.attachmentCount = 1;
        fci.pAttachments = &view;
        fci.width = swapchain.extent.width;
        fci.height = swapchain.extent.height;
        fci.layers = 1;
        VkFramebuffer fb = VK_NULL_HANDLE;
        if (!vkCheck(vkCreateFramebuffer(host_->device, &fci, nullptr, &fb), "vkCreateFramebuffer (ImGui)",
                     error))
            return false;
        framebuffers_.push_back(fb);
    }
    return true;
}

void UiOverlay::destroyFramebuffers() {
    for (VkFramebuffer fb : framebuffers_)
        vkDestroyFramebuffer(host_->device, fb, nullptr);
    framebuffers_.clear();
}

void UiOverlay::shutdownVulkanBackend() {
    if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
    vulkanBackend_ = false;
    if (renderPass_) vkDestroyRenderPass(host_->device, renderPass_, nullptr);
    renderPass_ = VK_NULL_HANDLE;
}

bool UiOverlay::onSwapchainRecreated(const Swapchain& swapchain, std::string& error) {
    destroyFramebuffers();
    if (swapchain.format != format_) {  // the pipeline was built for the old render pass
        shutdownVulkanBackend();
        if (!createRenderPass(swapchain.format, error) || !initVulkanBackend(error)) return false;
    }
    return createFramebuffers(swapchain, error);
}

void UiOverlay::destroy() {
    if (!host_) return;
    vkDeviceWaitIdle(host_->device);
    destroyFramebuffers();
    shutdownVulkanBackend();
    if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
    glfwBackend_ = false;
    if (context_) ImGui::DestroyContext();
    context_ = false;
    if (pool_) vkDestroyDescriptorPool(host_->device, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
    host_ = nullptr;
}

bool UiOverlay::wantsMouse() const {
    return context_ && ImGui::GetIO().WantCaptureMouse;
}
bool UiOverlay::wantsKeyboard() const {
    return context_ && ImGui::GetIO().WantCaptureKeyboard;
}

void UiOverlay::build(const OverlayStats& s, const std::function<void()>& sections) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    // Never taller than the window (10 px margins): the panel scrolls instead (mouse wheel over it).
    const float maxHeight = std::max(ImGui::GetIO().DisplaySize.y - 20.0f, 100.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(FLT_MAX, maxHeight));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("postfx demo", nullptr, flags)) {
        ImGui::TextUnformatted(s.device.c_str());
        ImGui::Text("%ux%u   %.1f ms (%.1f fps)", s.renderExtent.width, s.renderExtent.height, s.frameMs,
                    s.frameMs > 0.0 ? 1000.0 / s.frameMs : 0.0);
        ImGui::Text("camera  %.2f, %.2f, %.2f m", s.cameraPosition.x, s.cameraPosition.y, s.cameraPosition.z);
        ImGui::Text("        yaw %.1f, pitch %.1f deg", s.yawDeg, s.pitchDeg);
        ImGui::Separator();
        size_t lines = 1;
        if (!s.timingsValid) {
            ImGui::TextDisabled("postfx passes: (waiting for a frame)");
        } else if (s.passTimings.empty()) {
            ImGui::Text("postfx passes (frame %llu): none", static_cast<unsigned long long>(s.timingsFrame));
        } else {
            ImGui::Text("postfx passes (frame %llu):", static_cast<unsigned long long>(s.timingsFrame));
            double total = 0.0;
            for (const postfx::PassTiming& t : s.passTimings) {
                ImGui::Text("  %-24s %7.3f ms", t.name.c_str(), t.milliseconds);
                total += t.milliseconds;
            }
            ImGui::Text("  %-24s %7.3f ms", "total", total);
            lines += s.passTimings.size() + 1;
        }
        for (const std::string& line : s.quality) {
            ImGui::TextUnformatted(line.c_str());
            ++lines;
        }
        for (const std::string& line : s.plan) {
            ImGui::TextWrapped("%s", line.c_str());
            ++lines;
        }
        // Keep the block as tall as it has been, so that the widgets below do not move under the mouse
        // when passes come and go (e.g. the fog switched off from the panel).
        timingLines_ = std::max(timingLines_, lines);
        if (lines < timingLines_)
            ImGui::Dummy(ImVec2(0.0f, float(timingLines_ - lines) * ImGui::GetTextLineHeightWithSpacing()));
        ImGui::Separator();
        ImGui::TextDisabled("WASD, Q/E: move (Shift: fast)  right drag: look  R: reset view  Esc: quit");
        if (sections) {
            ImGui::Separator();
            sections();
        }
    }
    ImGui::End();
    ImGui::Render();
}

void UiOverlay::record(VkCommandBuffer cmd, uint32_t imageIndex, VkExtent2D extent) {
    VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    bi.renderPass = renderPass_;
    bi.framebuffer = framebuffers_[imageIndex];
    bi.renderArea = {{0, 0}, extent};
    vkCmdBeginRenderPass(cmd, &bi, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
}

}  // namespace demo::window
