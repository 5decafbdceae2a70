// The demo's own Vulkan instance and device (a host renderer owns these; postfx only borrows them).
// Headless by default; with surface extensions for the windowed demo. Optionally under the Khronos
// validation layer with synchronization validation, counting every message it reports.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace demo {

struct HostOptions {
    // Enable VK_LAYER_KHRONOS_validation with synchronization validation. Also turned on by the
    // environment variable POSTFX_VALIDATION=1. Tests always turn it on.
    bool validation = false;
    std::vector<const char*> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
    // The instance's VkApplicationInfo::apiVersion; 0: 1.2 where the loader has it, else 1.1.
    uint32_t apiVersion = 0;
    // Optional: the queue family must also present, e.g. wrapping glfwGetPhysicalDevicePresentationSupport.
    // Called after the instance exists, for each candidate (device, graphics+compute family).
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t queueFamily)> presentSupport;
};

// "VK_ERROR_DEVICE_LOST" etc.; "VkResult(<n>)" for codes it does not know.
const char* vkResultName(VkResult result);

// Whether physical device `pd` offers device extension `name`.
bool hasDeviceExtension(VkPhysicalDevice pd, const char* name);

class VulkanHost {
public:
    static std::unique_ptr<VulkanHost> create(const HostOptions& options, std::string& error);
    ~VulkanHost();  // destroy()

    // Waits for the device, then destroys the command pool, the device, the messenger and the instance
    // (idempotent; the handles become VK_NULL_HANDLE and the host cannot be used for Vulkan work again).
    // The messages the validation layer reports meanwhile (objects still alive on the device when it is
    // destroyed) are counted like the others: call this, then validationMessages(), to see every message.
    void destroy();

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics + compute (+ present when a window asks for it)
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;  // of queueFamily, RESET_COMMAND_BUFFER_BIT
    VkPhysicalDeviceProperties properties{};
    uint32_t apiVersion = 0;  // the instance's VkApplicationInfo::apiVersion (HostOptions::apiVersion)
    bool validationEnabled = false;
    bool debugUtilsEnabled = false;  // VK_EXT_debug_utils is enabled on the instance (labels work)

    // Validation messages (warnings and errors) reported since creation, those of destroy() included.
    std::vector<std::string> validationMessages() const;
    size_t validationMessageCount() const;
    // Returns the messages reported so far and forgets them (tests that provoke a message on purpose).
    std::vector<std::string> takeValidationMessages();

    // "llvmpipe (LLVM 15.0.6, 256 bits), Mesa 22.3.6"; the device's name alone after destroy().
    std::string deviceDescription() const;

    // One-shot command buffer helper: records with `fn`, submits, waits.
    bool submitAndWait(const std::function<void(VkCommandBuffer)>& record, std::string& error);

    // internals for the debug callback
    void addMessage(std::string message);

private:
    VulkanHost() = default;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

}  // namespace demo
