// postfx in a renderer written the way Vulkan tutorials are (Overv's VulkanTutorial: one file, plain
// Vulkan, a class that creates everything in order): a GLFW window and its swapchain, a forward render pass
// that draws a small z-up scene in centimetres (a ground quad and a few boxes, lit by Lambert's sun term
// and the sky's ambient) into the 8-bit sRGB swapchain image and a D32 depth buffer in standard Z, then
// postfx::Context::record with the swapchain image itself as the color: postfx blits it into an HDR
// image of its own, composites the atmosphere's sky and the ray-marched height fog, and blits it back.
// docs/integration.md, "A tutorial renderer", maps the integration checklist onto this file.
//
// Run:
//   postfx_tutorial_host [--frames N] [--validate] [--check]
// --frames N: present N frames, then exit (default: until the window is closed).
// --validate: Khronos validation layer with synchronization validation; any message fails the run.
// --check (with --frames): after the last frame, compare the centre pixel with the fog's closed form.
// POSTFX_DEVICE=<substring of the device name> picks the device (CI: llvmpipe). Needs an X display:
// without one, run it under xvfb-run -a. Exit status 0 when everything (and the check) passed, 1 otherwise.
#include <postfx/postfx.h>
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

// SPIR-V of tutorial.vert and tutorial.frag, compiled at build time (CMakeLists.txt).
#include "tutorial_frag.h"
#include "tutorial_vert.h"

namespace {

constexpr uint32_t kWidth = 320, kHeight = 180;  // the window [px]: small, for CI's software rasteriser
constexpr uint32_t kMaxFramesInFlight = 2;
constexpr double kPi = 3.14159265358979323846;

// The swapchain: 8-bit sRGB, as tutorials pick it. postfx reads and writes it with two blits, so it
// needs TRANSFER_SRC and TRANSFER_DST besides the render pass's COLOR_ATTACHMENT.
constexpr VkFormat kSwapchainFormat = VK_FORMAT_B8G8R8A8_SRGB;
constexpr VkImageUsageFlags kSwapchainUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// The depth buffer: postfx samples it in a compute shader, so SAMPLED besides DEPTH_STENCIL_ATTACHMENT.
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkImageUsageFlags kDepthUsage =
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;

// The world: z up, right-handed, in centimetres. postfx is told so once (ContextCreateInfo::world); the
// camera, the sun and every position are then handed over as they are. Media settings stay in metres.
const postfx::WorldFrame kWorld{postfx::UpAxis::Z, postfx::Handedness::Right, 100.0};

// The camera [cm]: 1.7 m above the ground, level, looking along +y. Standard Z: near -> 0, far -> 1.
const glm::vec3 kEye{0.0f, -1400.0f, 170.0f};
constexpr float kVerticalFov = 1.0471976f;  // 60° [rad]
constexpr float kNear = 10.0f, kFar = 200000.0f;

// The sun: the direction toward it (44.6° above the horizon, behind the camera on its left) and its
// illuminance outside the atmosphere [lux]; the atmosphere attenuates it.
const glm::vec3 kToSun = glm::normalize(glm::vec3(-0.45f, -0.55f, 0.7f));
constexpr float kSunIlluminance = 1.2e5f;

// The exposure: the swapchain holds radiance [cd/m²] × this, clipped to [0, 1] (nothing tone maps).
// A power of two, so that postfx multiplies and divides by it without rounding.
constexpr float kPreExposure = 1.0f / 16384.0f;

// The scene [cm]: a ground quad and boxes, each with an albedo.
struct Box {
    glm::vec3 min, max, albedo;
};
const Box kBoxes[] = {
    {{-150, -100, 0}, {150, 100, 250}, {0.60f, 0.45f, 0.30f}},  // the centre pixel's: front face at y = -100
    {{-750, 300, 0}, {-450, 600, 400}, {0.30f, 0.45f, 0.65f}},
    {{400, -350, 0}, {650, -150, 150}, {0.45f, 0.60f, 0.30f}},
    {{-400, 3500, 0}, {-100, 3800, 1500}, {0.70f, 0.70f, 0.70f}},  // a tower 50 m away
};
const glm::vec3 kGroundAlbedo{0.25f, 0.25f, 0.22f};
constexpr float kGroundHalfSize = 50000.0f;  // 500 m each way

struct Vertex {
    glm::vec3 position;  // [cm]
    glm::vec3 normal;
    glm::vec3 albedo;
};

struct PushConstants {  // as in both shaders
    glm::mat4 viewProjection;
    glm::vec4 toSun;
    glm::vec4 sunRadiance;
    glm::vec4 ambient;
};

// The ground and the boxes as triangles (no culling: the winding does not matter).
std::vector<Vertex> sceneVertices() {
    std::vector<Vertex> vertices;
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 normal, glm::vec3 albedo) {
        for (glm::vec3 p : {a, b, c, a, c, d})
            vertices.push_back({p, normal, albedo});
    };
    const float g = kGroundHalfSize;
    quad({-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}, {0, 0, 1}, kGroundAlbedo);
    for (const Box& box : kBoxes) {
        const glm::vec3 l = box.min, h = box.max, a = box.albedo;
        quad({l.x, l.y, l.z}, {h.x, l.y, l.z}, {h.x, l.y, h.z}, {l.x, l.y, h.z}, {0, -1, 0}, a);
        quad({l.x, h.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z}, {0, 1, 0}, a);
        quad({l.x, l.y, l.z}, {l.x, h.y, l.z}, {l.x, h.y, h.z}, {l.x, l.y, h.z}, {-1, 0, 0}, a);
        quad({h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}, {h.x, l.y, h.z}, {1, 0, 0}, a);
        quad({l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z}, {0, 0, 1}, a);
    }
    return vertices;
}

glm::mat4 viewMatrix() {
    return glm::lookAt(kEye, kEye + glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
}

glm::mat4 projectionMatrix(VkExtent2D extent) {
    glm::mat4 p =
        glm::perspectiveRH_ZO(kVerticalFov, float(extent.width) / float(extent.height), kNear, kFar);
    p[1][1] *= -1.0f;  // Vulkan's clip y points down
    return p;
}

// The ray-marched fog: a height fog, thickest at the ground. Its settings are in metres whatever the
// world's units (1/m, m above z = 0).
postfx::FogSettings fogSettings() {
    postfx::FogSettings fog;
    fog.enabled = true;
    fog.quality = postfx::FogQuality::Medium;
    fog.density = 0.02f;       // extinction at the ground [1/m]
    fog.heightFalloff = 0.2f;  // [1/m]
    fog.baseHeight = 0.0f;     // [m]
    return fog;
}

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(what) + " failed: VkResult " + std::to_string(int(result)));
}

int gValidationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    ++gValidationMessages;
    std::fprintf(stderr, "[validation] %s\n", data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

void printPostfxMessage(postfx::MessageSeverity severity, const char* message, void*) {
    std::fprintf(stderr, "postfx %s: %s\n", severity == postfx::MessageSeverity::Error ? "error" : "warning",
                 message);
}

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
int toByte(double encoded) {
    return int(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
}

struct Options {
    uint32_t frames = 0;  // 0: until the window is closed
    bool validate = false;
    bool check = false;
};

class TutorialHost {
public:
    explicit TutorialHost(Options options) : options(options) {}

    // 0 when every frame was recorded and presented without a validation message (and --check matched).
    int run() {
        initWindow();
        initVulkan();
        createPostfx();
        mainLoop();
        const bool matched = !options.check || checkCentrePixel();
        cleanup();
        if (gValidationMessages > 0)
            std::fprintf(stderr, "FAIL: %d validation message(s)\n", gValidationMessages);
        if (postfxFailures > 0)
            std::fprintf(stderr, "FAIL: postfx record failed in %d frame(s)\n", postfxFailures);
        return gValidationMessages == 0 && postfxFailures == 0 && matched ? 0 : 1;
    }

    ~TutorialHost() { cleanup(); }

private:
    Options options;
    GLFWwindow* window = nullptr;
    bool framebufferResized = false;

    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics, compute and present: the tutorial's passes and postfx's
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;

    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkExtent2D swapchainExtent{};
    std::vector<VkImage> swapchainImages;
    std::vector<VkImageView> swapchainImageViews;
    std::vector<VkFramebuffer> framebuffers;
    std::vector<VkSemaphore> renderFinished;  // one per swapchain image: the present waits on it
    VkImage depthImage = VK_NULL_HANDLE;
    VkDeviceMemory depthMemory = VK_NULL_HANDLE;
    VkImageView depthView = VK_NULL_HANDLE;

    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkBuffer vertexBuffer = VK_NULL_HANDLE;
    VkDeviceMemory vertexMemory = VK_NULL_HANDLE;
    uint32_t vertexCount = 0;

    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffers[kMaxFramesInFlight]{};
    VkSemaphore imageAvailable[kMaxFramesInFlight]{};
    VkFence inFlight[kMaxFramesInFlight]{};

    // --check: the centre pixel of the last frame, copied here before it is presented.
    VkBuffer readbackBuffer = VK_NULL_HANDLE;
    VkDeviceMemory readbackMemory = VK_NULL_HANDLE;

    // The light, evaluated once on the CPU from postfx's atmosphere so that the surfaces and postfx's
    // effects agree: the sun through the air at the camera, the sky's ambient radiance.
    postfx::AtmosphereSettings atmosphere;  // Earth's
    postfx::Vec3 sunTransmittance{1.0f};
    postfx::Vec3 skyAmbient{0.0f};  // [cd/m²]

    std::unique_ptr<postfx::Context> postfx;
    uint64_t frameIndex = 0;  // postfx's: one per recorded frame, never reset
    int postfxFailures = 0;

    void initWindow() {
        glfwSetErrorCallback(
            [](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
        if (!glfwInit()) {
            const char* display = std::getenv("DISPLAY");
            throw std::runtime_error(std::string("no display: GLFW could not initialise (DISPLAY=") +
                                     (display ? display : "unset") +
                                     "); run under an X server, e.g. xvfb-run -a");
        }
        if (!glfwVulkanSupported()) throw std::runtime_error("GLFW found no Vulkan loader");
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        window = glfwCreateWindow(kWidth, kHeight, "postfx tutorial host", nullptr, nullptr);
        if (!window) throw std::runtime_error("glfwCreateWindow failed");
        glfwSetWindowUserPointer(window, this);
        glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) {
            static_cast<TutorialHost*>(glfwGetWindowUserPointer(w))->framebufferResized = true;
        });
    }

    void initVulkan() {
        createInstance();
        check(glfwCreateWindowSurface(instance, window, nullptr, &surface), "glfwCreateWindowSurface");
        pickPhysicalDevice();
        createLogicalDevice();
        createSwapchain();
        createRenderPass();
        createPipeline();
        createFramebuffers();
        createCommandsAndSync();
        createVertexBuffer();
        if (options.check)
            createBuffer(4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                         readbackBuffer, readbackMemory);
        sunTransmittance =
            postfx::atmosphereSunTransmittance(atmosphere, postfx::DVec3(kEye), kToSun, kWorld);
        skyAmbient = postfx::atmosphereSkyIrradiance(atmosphere, postfx::DVec3(kEye), kToSun,
                                                     postfx::Vec3(kSunIlluminance), kWorld) /
                     float(kPi);
    }

    void createInstance() {
        VkApplicationInfo app{};
        app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
        app.pApplicationName = "postfx_tutorial_host";
        app.apiVersion = VK_API_VERSION_1_0;  // postfx needs nothing beyond Vulkan 1.0
        uint32_t glfwCount = 0;
        const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
        std::vector<const char*> extensions(glfwExtensions, glfwExtensions + glfwCount);
        std::vector<const char*> layers;

        // --validate: the validation layer with synchronization validation; onValidationMessage counts
        // its messages (through pNext, vkCreateInstance's and vkDestroyInstance's too).
        VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
        messengerInfo.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
        messengerInfo.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
        messengerInfo.pfnUserCallback = onValidationMessage;
        const VkValidationFeatureEnableEXT syncValidation =
            VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
        VkValidationFeaturesEXT features{};
        features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
        features.enabledValidationFeatureCount = 1;
        features.pEnabledValidationFeatures = &syncValidation;
        if (options.validate) {
            layers.push_back("VK_LAYER_KHRONOS_validation");
            extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            messengerInfo.pNext = &features;
        }

        VkInstanceCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
        info.pNext = options.validate ? &messengerInfo : nullptr;
        info.pApplicationInfo = &app;
        info.enabledLayerCount = uint32_t(layers.size());
        info.ppEnabledLayerNames = layers.data();
        info.enabledExtensionCount = uint32_t(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        const VkResult result = vkCreateInstance(&info, nullptr, &instance);
        if (result == VK_ERROR_LAYER_NOT_PRESENT || result == VK_ERROR_EXTENSION_NOT_PRESENT)
            throw std::runtime_error(
                "--validate: VK_LAYER_KHRONOS_validation (with VK_EXT_debug_utils and "
                "VK_EXT_validation_features) is not installed");
        check(result, "vkCreateInstance");
        if (options.validate) {
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
            messengerInfo.pNext = nullptr;
            check(create(instance, &messengerInfo, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
        }
    }

    // The first device (POSTFX_DEVICE: whose name contains it) with VK_KHR_swapchain, a queue family with
    // graphics, compute and present, and the swapchain this host wants.
    void pickPhysicalDevice() {
        uint32_t count = 0;
        vkEnumeratePhysicalDevices(instance, &count, nullptr);
        std::vector<VkPhysicalDevice> devices(count);
        vkEnumeratePhysicalDevices(instance, &count, devices.data());
        const char* wanted = std::getenv("POSTFX_DEVICE");
        for (VkPhysicalDevice candidate : devices) {
            VkPhysicalDeviceProperties properties;
            vkGetPhysicalDeviceProperties(candidate, &properties);
            if (wanted && *wanted && !std::strstr(properties.deviceName, wanted)) continue;
            uint32_t extensionCount = 0;
            vkEnumerateDeviceExtensionProperties(candidate, nullptr, &extensionCount, nullptr);
            std::vector<VkExtensionProperties> extensions(extensionCount);
            vkEnumerateDeviceExtensionProperties(candidate, nullptr, &extensionCount, extensions.data());
            if (std::none_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
                    return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
                }))
                continue;
            uint32_t familyCount = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
            std::vector<VkQueueFamilyProperties> families(familyCount);
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
            for (uint32_t i = 0; i < familyCount; ++i) {
                const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
                VkBool32 present = VK_FALSE;
                vkGetPhysicalDeviceSurfaceSupportKHR(candidate, i, surface, &present);
                if ((families[i].queueFlags & needed) != needed || !present) continue;
                physicalDevice = candidate;
                queueFamily = i;
                std::printf("device: %s\n", properties.deviceName);
                return;
            }
        }
        throw std::runtime_error(
            std::string("no device with VK_KHR_swapchain and a graphics+compute+present queue") +
            (wanted && *wanted ? " whose name contains POSTFX_DEVICE=" + std::string(wanted) : ""));
    }

    void createLogicalDevice() {
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{};
        queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
        queueInfo.queueFamilyIndex = queueFamily;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        const char* extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;  // the host's; postfx needs no extension
        VkDeviceCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queueInfo;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &extension;
        check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice");
        vkGetDeviceQueue(device, queueFamily, 0, &queue);
    }

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) {
        VkPhysicalDeviceMemoryProperties memory;
        vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
        throw std::runtime_error("no suitable memory type");
    }

    VkImageView createImageView(VkImage image, VkFormat format, VkImageAspectFlags aspect) {
        VkImageViewCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        info.image = image;
        info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        info.format = format;
        info.subresourceRange = {aspect, 0, 1, 0, 1};
        VkImageView view;
        check(vkCreateImageView(device, &info, nullptr, &view), "vkCreateImageView");
        return view;
    }

    // The swapchain, its views and the depth buffer at the window's size.
    void createSwapchain() {
        VkSurfaceCapabilitiesKHR capabilities;
        check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physicalDevice, surface, &capabilities),
              "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
        uint32_t formatCount = 0;
        vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &formatCount, nullptr);
        std::vector<VkSurfaceFormatKHR> formats(formatCount);
        vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &formatCount, formats.data());
        if (std::none_of(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
                return f.format == kSwapchainFormat && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
            }))
            throw std::runtime_error("the surface offers no B8G8R8A8_SRGB swapchain");
        if ((capabilities.supportedUsageFlags & kSwapchainUsage) != kSwapchainUsage)
            throw std::runtime_error(
                "the surface's swapchain images cannot be transfer source and destination");

        swapchainExtent = capabilities.currentExtent;
        if (swapchainExtent.width == UINT32_MAX) {  // the window takes the swapchain's size
            int width = 0, height = 0;
            glfwGetFramebufferSize(window, &width, &height);
            swapchainExtent = {std::clamp(uint32_t(width), capabilities.minImageExtent.width,
                                          capabilities.maxImageExtent.width),
                               std::clamp(uint32_t(height), capabilities.minImageExtent.height,
                                          capabilities.maxImageExtent.height)};
        }
        uint32_t imageCount = capabilities.minImageCount + 1;
        if (capabilities.maxImageCount > 0) imageCount = std::min(imageCount, capabilities.maxImageCount);

        VkSwapchainCreateInfoKHR info{};
        info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
        info.surface = surface;
        info.minImageCount = imageCount;
        info.imageFormat = kSwapchainFormat;
        info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
        info.imageExtent = swapchainExtent;
        info.imageArrayLayers = 1;
        info.imageUsage = kSwapchainUsage;  // the render pass draws it, postfx blits from and into it
        info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.preTransform = capabilities.currentTransform;
        info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
        info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
        info.clipped = VK_TRUE;
        check(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain), "vkCreateSwapchainKHR");
        vkGetSwapchainImagesKHR(device, swapchain, &imageCount, nullptr);
        swapchainImages.resize(imageCount);
        vkGetSwapchainImagesKHR(device, swapchain, &imageCount, swapchainImages.data());
        for (VkImage image : swapchainImages) {
            swapchainImageViews.push_back(
                createImageView(image, kSwapchainFormat, VK_IMAGE_ASPECT_COLOR_BIT));
            VkSemaphoreCreateInfo semaphoreInfo{};
            semaphoreInfo.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
            renderFinished.push_back(VK_NULL_HANDLE);
            check(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &renderFinished.back()),
                  "vkCreateSemaphore");
        }

        VkImageCreateInfo depthInfo{};
        depthInfo.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
        depthInfo.imageType = VK_IMAGE_TYPE_2D;
        depthInfo.format = kDepthFormat;
        depthInfo.extent = {swapchainExtent.width, swapchainExtent.height, 1};
        depthInfo.mipLevels = 1;
        depthInfo.arrayLayers = 1;
        depthInfo.samples = VK_SAMPLE_COUNT_1_BIT;  // postfx reads single-sampled depth only
        depthInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
        depthInfo.usage = kDepthUsage;
        depthInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        depthInfo.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vkCreateImage(device, &depthInfo, nullptr, &depthImage), "vkCreateImage");
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device, depthImage, &requirements);
        VkMemoryAllocateInfo allocation{};
        allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        allocation.allocationSize = requirements.size;
        allocation.memoryTypeIndex =
            findMemoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        check(vkAllocateMemory(device, &allocation, nullptr, &depthMemory), "vkAllocateMemory");
        check(vkBindImageMemory(device, depthImage, depthMemory, 0), "vkBindImageMemory");
        depthView = createImageView(depthImage, kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT);
    }

    void createRenderPass() {
        VkAttachmentDescription attachments[2]{};
        attachments[0].format = kSwapchainFormat;
        attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
        attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        // Not PRESENT_SRC_KHR as in the tutorial: postfx comes between the pass and the present, and the
        // layout the pass leaves is the one the frame hands postfx.
        attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        attachments[1].format = kDepthFormat;
        attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
        attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        // STORE, not the tutorial's DONT_CARE: postfx reads the depth after the pass (DONT_CARE would leave
        // it undefined, and postfx would fog garbage without any error).
        attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        // A read-only layout a shader can sample in: postfx reads it there without a transition
        // (DEPTH_STENCIL_ATTACHMENT_OPTIMAL works too, for a transition there and back).
        attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

        VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = 1;
        subpass.pColorAttachments = &colorRef;
        subpass.pDepthStencilAttachment = &depthRef;

        // Before the pass: the acquire semaphore (waited at COLOR_ATTACHMENT_OUTPUT) and the previous
        // frame's uses of the one depth buffer, its tests and postfx's compute shader reads.
        VkSubpassDependency dependency{};
        dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
        dependency.dstSubpass = 0;
        dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        dependency.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        dependency.dstStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
        dependency.dstAccessMask =
            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

        VkRenderPassCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
        info.attachmentCount = 2;
        info.pAttachments = attachments;
        info.subpassCount = 1;
        info.pSubpasses = &subpass;
        info.dependencyCount = 1;
        info.pDependencies = &dependency;
        check(vkCreateRenderPass(device, &info, nullptr, &renderPass), "vkCreateRenderPass");
    }

    VkShaderModule createShaderModule(const uint32_t* code, size_t bytes) {
        VkShaderModuleCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
        info.codeSize = bytes;
        info.pCode = code;
        VkShaderModule module;
        check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
        return module;
    }

    void createPipeline() {
        VkShaderModule vert = createShaderModule(tutorial_vert, sizeof(tutorial_vert));
        VkShaderModule frag = createShaderModule(tutorial_frag, sizeof(tutorial_frag));
        VkPipelineShaderStageCreateInfo stages[2]{};
        stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
        stages[0].module = vert;
        stages[0].pName = "main";
        stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stages[1].module = frag;
        stages[1].pName = "main";

        VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attributes[3] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
            {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, albedo)}};
        VkPipelineVertexInputStateCreateInfo vertexInput{};
        vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
        vertexInput.vertexBindingDescriptionCount = 1;
        vertexInput.pVertexBindingDescriptions = &binding;
        vertexInput.vertexAttributeDescriptionCount = 3;
        vertexInput.pVertexAttributeDescriptions = attributes;
        VkPipelineInputAssemblyStateCreateInfo inputAssembly{};
        inputAssembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
        inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        VkPipelineViewportStateCreateInfo viewport{};
        viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;
        VkPipelineRasterizationStateCreateInfo rasterizer{};
        rasterizer.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
        rasterizer.polygonMode = VK_POLYGON_MODE_FILL;
        rasterizer.cullMode = VK_CULL_MODE_NONE;
        rasterizer.lineWidth = 1.0f;
        VkPipelineMultisampleStateCreateInfo multisampling{};
        multisampling.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
        multisampling.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        VkPipelineDepthStencilStateCreateInfo depthStencil{};
        depthStencil.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
        depthStencil.depthTestEnable = VK_TRUE;
        depthStencil.depthWriteEnable = VK_TRUE;
        depthStencil.depthCompareOp = VK_COMPARE_OP_LESS;  // standard Z: nearer is smaller
        VkPipelineColorBlendAttachmentState blendAttachment{};
        blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        VkPipelineColorBlendStateCreateInfo blend{};
        blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
        blend.attachmentCount = 1;
        blend.pAttachments = &blendAttachment;
        const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
        VkPipelineDynamicStateCreateInfo dynamic{};
        dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
        dynamic.dynamicStateCount = 2;
        dynamic.pDynamicStates = dynamicStates;

        VkPushConstantRange pushRange{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                      sizeof(PushConstants)};
        VkPipelineLayoutCreateInfo layoutInfo{};
        layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &pushRange;
        check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &pipelineLayout),
              "vkCreatePipelineLayout");

        VkGraphicsPipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
        info.stageCount = 2;
        info.pStages = stages;
        info.pVertexInputState = &vertexInput;
        info.pInputAssemblyState = &inputAssembly;
        info.pViewportState = &viewport;
        info.pRasterizationState = &rasterizer;
        info.pMultisampleState = &multisampling;
        info.pDepthStencilState = &depthStencil;
        info.pColorBlendState = &blend;
        info.pDynamicState = &dynamic;
        info.layout = pipelineLayout;
        info.renderPass = renderPass;
        check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
              "vkCreateGraphicsPipelines");
        vkDestroyShaderModule(device, frag, nullptr);
        vkDestroyShaderModule(device, vert, nullptr);
    }

    void createFramebuffers() {
        for (VkImageView view : swapchainImageViews) {
            const VkImageView attachments[2] = {view, depthView};
            VkFramebufferCreateInfo info{};
            info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
            info.renderPass = renderPass;
            info.attachmentCount = 2;
            info.pAttachments = attachments;
            info.width = swapchainExtent.width;
            info.height = swapchainExtent.height;
            info.layers = 1;
            framebuffers.push_back(VK_NULL_HANDLE);
            check(vkCreateFramebuffer(device, &info, nullptr, &framebuffers.back()), "vkCreateFramebuffer");
        }
    }

    void createCommandsAndSync() {
        VkCommandPoolCreateInfo poolInfo{};
        poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = queueFamily;
        check(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool), "vkCreateCommandPool");
        VkCommandBufferAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        allocate.commandPool = commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = kMaxFramesInFlight;
        check(vkAllocateCommandBuffers(device, &allocate, commandBuffers), "vkAllocateCommandBuffers");
        VkSemaphoreCreateInfo semaphoreInfo{};
        semaphoreInfo.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
        VkFenceCreateInfo fenceInfo{};
        fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        for (uint32_t i = 0; i < kMaxFramesInFlight; ++i) {
            check(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &imageAvailable[i]),
                  "vkCreateSemaphore");
            check(vkCreateFence(device, &fenceInfo, nullptr, &inFlight[i]), "vkCreateFence");
        }
    }

    void createBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags properties,
                      VkBuffer& buffer, VkDeviceMemory& memory) {
        VkBufferCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        info.size = size;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(device, buffer, &requirements);
        VkMemoryAllocateInfo allocation{};
        allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        allocation.allocationSize = requirements.size;
        allocation.memoryTypeIndex = findMemoryType(requirements.memoryTypeBits, properties);
        check(vkAllocateMemory(device, &allocation, nullptr, &memory), "vkAllocateMemory");
        check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    }

    // The scene's triangles in host-visible memory (small and never changed: no staging copy).
    void createVertexBuffer() {
        const std::vector<Vertex> vertices = sceneVertices();
        vertexCount = uint32_t(vertices.size());
        const VkDeviceSize size = sizeof(Vertex) * vertices.size();
        createBuffer(size, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, vertexBuffer,
                     vertexMemory);
        void* data = nullptr;
        check(vkMapMemory(device, vertexMemory, 0, size, 0, &data), "vkMapMemory");
        std::memcpy(data, vertices.data(), size_t(size));
        vkUnmapMemory(device, vertexMemory);
    }

    // postfx: once, after the device. It borrows the handles and is destroyed before them.
    void createPostfx() {
        postfx::ContextCreateInfo info;
        info.instance = instance;
        info.physicalDevice = physicalDevice;
        info.device = device;
        info.getInstanceProcAddr = vkGetInstanceProcAddr;
        info.getDeviceProcAddr = vkGetDeviceProcAddr;
        info.queueFamilyIndex = queueFamily;        // the queue the frames are submitted to
        info.maxExtent = {3840, 2160};              // the largest window it will get [px]
        info.depth.reversedZ = false;               // standard Z: the projection maps near to 0, far to 1
        info.depth.infiniteFar = false;             // with a far plane (kFar)
        info.framesInFlight = kMaxFramesInFlight;   // the tutorial's ring of command buffers and fences
        info.world = kWorld;                        // z up, right-handed, centimetres
        info.messageCallback = printPostfxMessage;  // warnings only: errors come back as the Status
        if (postfx::Status s = postfx::Context::create(info, postfx); !s)
            throw std::runtime_error(std::string("postfx::Context::create: ") + s.message);
    }

    void mainLoop() {
        uint32_t presented = 0;
        while (!glfwWindowShouldClose(window) && (options.frames == 0 || presented < options.frames)) {
            glfwPollEvents();
            if (drawFrame(options.check && presented + 1 == options.frames)) ++presented;
        }
        check(vkDeviceWaitIdle(device), "vkDeviceWaitIdle");
        std::printf("%u frames presented at %ux%u\n", presented, swapchainExtent.width,
                    swapchainExtent.height);
    }

    // One frame; false when the swapchain had to be recreated first (nothing was drawn).
    bool drawFrame(bool readCentrePixel) {
        const uint32_t slot = uint32_t(frameIndex % kMaxFramesInFlight);
        check(vkWaitForFences(device, 1, &inFlight[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences");
        uint32_t imageIndex = 0;
        VkResult result = vkAcquireNextImageKHR(device, swapchain, UINT64_MAX, imageAvailable[slot],
                                                VK_NULL_HANDLE, &imageIndex);
        if (result == VK_ERROR_OUT_OF_DATE_KHR) {
            recreateSwapchain();
            return false;
        }
        if (result != VK_SUBOPTIMAL_KHR) check(result, "vkAcquireNextImageKHR");
        check(vkResetFences(device, 1, &inFlight[slot]), "vkResetFences");
        check(vkResetCommandBuffer(commandBuffers[slot], 0), "vkResetCommandBuffer");
        recordCommandBuffer(commandBuffers[slot], imageIndex, readCentrePixel);

        const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        VkSubmitInfo submit{};
        submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &imageAvailable[slot];
        submit.pWaitDstStageMask = &waitStage;
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &commandBuffers[slot];
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &renderFinished[imageIndex];
        check(vkQueueSubmit(queue, 1, &submit, inFlight[slot]), "vkQueueSubmit");
        ++frameIndex;

        VkPresentInfoKHR present{};
        present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
        present.waitSemaphoreCount = 1;
        present.pWaitSemaphores = &renderFinished[imageIndex];
        present.swapchainCount = 1;
        present.pSwapchains = &swapchain;
        present.pImageIndices = &imageIndex;
        result = vkQueuePresentKHR(queue, &present);
        if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR || framebufferResized) {
            framebufferResized = false;
            recreateSwapchain();
        } else {
            check(result, "vkQueuePresentKHR");
        }
        return true;
    }

    void recordCommandBuffer(VkCommandBuffer cmd, uint32_t imageIndex, bool readCentrePixel) {
        VkCommandBufferBeginInfo begin{};
        begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
        check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");

        // 1. The tutorial's forward pass. Black behind everything: where the depth stays at the far value
        // (1), postfx draws the sky over what lies beyond the atmosphere.
        VkClearValue clear[2]{};
        clear[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
        clear[1].depthStencil = {1.0f, 0};  // standard Z: far
        VkRenderPassBeginInfo pass{};
        pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
        pass.renderPass = renderPass;
        pass.framebuffer = framebuffers[imageIndex];
        pass.renderArea = {{0, 0}, swapchainExtent};
        pass.clearValueCount = 2;
        pass.pClearValues = clear;
        vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        const VkViewport viewport{0.0f, 0.0f, float(swapchainExtent.width), float(swapchainExtent.height),
                                  0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, swapchainExtent};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        const PushConstants push = pushConstants();
        vkCmdPushConstants(cmd, pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
        vkCmdDraw(cmd, vertexCount, 1, 0, 0);
        vkCmdEndRenderPass(cmd);

        // 2. postfx, outside the render pass. Each image as it is at this point: the swapchain image in the
        // pass's final layout COLOR_ATTACHMENT_OPTIMAL, the depth in DEPTH_STENCIL_READ_ONLY_OPTIMAL, with
        // the usage they were created with. postfx needs no barrier before it and gives both back in those
        // layouts.
        postfx::FrameInfo frame;
        frame.commandBuffer = cmd;
        frame.frameIndex = frameIndex;
        frame.color = {.image = swapchainImages[imageIndex],
                       .view = swapchainImageViews[imageIndex],
                       .format = kSwapchainFormat,
                       .extent = swapchainExtent,
                       .layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                       .usage = kSwapchainUsage};
        frame.depth = {.image = depthImage,
                       .view = depthView,
                       .format = kDepthFormat,
                       .extent = swapchainExtent,
                       .layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                       .usage = kDepthUsage};
        frame.preExposure = kPreExposure;             // the swapchain holds radiance × this
        frame.camera.position = postfx::DVec3(kEye);  // [cm], world axes, as the tutorial's own matrices
        frame.camera.view = viewMatrix();
        frame.camera.projection = projectionMatrix(swapchainExtent);
        frame.sun.toSun = kToSun;
        frame.sun.illuminance = postfx::Vec3(kSunIlluminance);  // outside the atmosphere [lux]
        frame.ambient = skyAmbient;                             // [cd/m²]
        frame.atmosphere = atmosphere;
        frame.atmosphere.enabled = true;
        frame.fog = fogSettings();
        if (const postfx::Status status = postfx->record(frame); !status) {
            // Nothing was recorded: this frame goes on without the effects.
            std::fprintf(stderr, "postfx record, frame %llu: %s\n", (unsigned long long)frameIndex,
                         status.message.c_str());
            ++postfxFailures;
        }

        // 3. Back to the tutorial: to PRESENT_SRC_KHR, the barrier it would record after its pass without
        // postfx (postfx's last barrier made its own writes visible to every later command).
        VkImageMemoryBarrier toPresent{};
        toPresent.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        toPresent.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        toPresent.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        toPresent.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        toPresent.srcQueueFamilyIndex = toPresent.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toPresent.image = swapchainImages[imageIndex];
        toPresent.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkPipelineStageFlags srcStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        if (readCentrePixel) {
            recordCentrePixelCopy(cmd, swapchainImages[imageIndex]);
            toPresent.srcAccessMask = 0;
            toPresent.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            srcStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        }
        vkCmdPipelineBarrier(cmd, srcStage, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0, nullptr,
                             1, &toPresent);
        check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    }

    // The forward pass's light, pre-exposed: the sun through the air as postfx's atmosphere attenuates it
    // (at the camera: the scene is small), the sky's ambient.
    PushConstants pushConstants() const {
        PushConstants push;
        push.viewProjection = projectionMatrix(swapchainExtent) * viewMatrix();
        push.toSun = glm::vec4(kToSun, 0.0f);
        push.sunRadiance =
            glm::vec4(glm::vec3(sunTransmittance) * (kSunIlluminance / float(kPi) * kPreExposure), 0.0f);
        push.ambient = glm::vec4(glm::vec3(skyAmbient) * kPreExposure, 0.0f);
        return push;
    }

    void recreateSwapchain() {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        while (width == 0 || height == 0) {  // minimised: wait
            glfwWaitEvents();
            glfwGetFramebufferSize(window, &width, &height);
        }
        check(vkDeviceWaitIdle(device), "vkDeviceWaitIdle");
        cleanupSwapchain();
        createSwapchain();
        createFramebuffers();
        // Nothing to tell postfx: the next frame's images carry the new extent.
    }

    void cleanupSwapchain() {
        for (VkFramebuffer framebuffer : framebuffers)
            vkDestroyFramebuffer(device, framebuffer, nullptr);
        for (VkImageView view : swapchainImageViews)
            vkDestroyImageView(device, view, nullptr);
        for (VkSemaphore semaphore : renderFinished)
            vkDestroySemaphore(device, semaphore, nullptr);
        framebuffers.clear();
        swapchainImageViews.clear();
        renderFinished.clear();
        vkDestroyImageView(device, depthView, nullptr);
        vkDestroyImage(device, depthImage, nullptr);
        vkFreeMemory(device, depthMemory, nullptr);
        vkDestroySwapchainKHR(device, swapchain, nullptr);
        depthView = VK_NULL_HANDLE;
        depthImage = VK_NULL_HANDLE;
        depthMemory = VK_NULL_HANDLE;
        swapchain = VK_NULL_HANDLE;
    }

    void cleanup() {
        if (device) {
            vkDeviceWaitIdle(device);
            postfx.reset();  // first: it borrows the device
            cleanupSwapchain();
            vkDestroyBuffer(device, readbackBuffer, nullptr);
            vkFreeMemory(device, readbackMemory, nullptr);
            vkDestroyBuffer(device, vertexBuffer, nullptr);
            vkFreeMemory(device, vertexMemory, nullptr);
            vkDestroyPipeline(device, pipeline, nullptr);
            vkDestroyPipelineLayout(device, pipelineLayout, nullptr);
            vkDestroyRenderPass(device, renderPass, nullptr);
            for (uint32_t i = 0; i < kMaxFramesInFlight; ++i) {
                vkDestroySemaphore(device, imageAvailable[i], nullptr);
                vkDestroyFence(device, inFlight[i], nullptr);
            }
            vkDestroyCommandPool(device, commandPool, nullptr);
            vkDestroyDevice(device, nullptr);
            device = VK_NULL_HANDLE;
        }
        if (instance) {
            if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
            if (messenger) {
                auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                    vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
                destroy(instance, messenger, nullptr);
            }
            vkDestroyInstance(instance, nullptr);
            instance = VK_NULL_HANDLE;
        }
        if (window) {
            glfwDestroyWindow(window);
            glfwTerminate();
            window = nullptr;
        }
    }

    // ===============================================================================================
    // --check: not part of an integration. The centre pixel of the last frame against the closed form.

    // After postfx: the swapchain image's centre pixel into readbackBuffer, the image left in
    // TRANSFER_SRC_OPTIMAL.
    void recordCentrePixelCopy(VkCommandBuffer cmd, VkImage image) {
        VkImageMemoryBarrier toTransfer{};
        toTransfer.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        toTransfer.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        toTransfer.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        toTransfer.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        toTransfer.srcQueueFamilyIndex = toTransfer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toTransfer.image = image;
        toTransfer.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &toTransfer);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageOffset = {int32_t(swapchainExtent.width / 2), int32_t(swapchainExtent.height / 2), 0};
        region.imageExtent = {1, 1, 1};
        vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readbackBuffer, 1, &region);
        VkMemoryBarrier toHost{};
        toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                             0, nullptr, 0, nullptr);
    }

    // The centre pixel sees the first box's front face (y = -100 cm) through the height fog; with no
    // shadow map the fog's light is the same all along the ray (docs/effects/fog.md, "Model"), so
    //   out = surface·T + albedo·(E·Tsun·p(cosθ) + ambient)·(1 − T)·preExposure,   T = exp(−τ),
    //   τ = density·∫ exp(−a·z(s)) ds over the ray's D metres (z its height [m], a the height falloff),
    // exact for the march too (its steps telescope to 1 − T). surface: the forward pass's 8-bit sRGB value.
    // The air's own scattering over those metres (the atmosphere's aerial perspective) is left out.
    bool checkCentrePixel() {
        uint8_t bgra[4];
        void* mapped = nullptr;
        check(vkMapMemory(device, readbackMemory, 0, 4, 0, &mapped), "vkMapMemory");
        std::memcpy(bgra, mapped, 4);
        vkUnmapMemory(device, readbackMemory);
        const int got[3] = {bgra[2], bgra[1], bgra[0]};

        // The pixel's ray through its centre, as postfx builds it (docs/effects/fog.md, "Ray") [world, cm].
        const VkExtent2D e = swapchainExtent;
        const glm::dmat4 clipToWorld =
            glm::inverse(glm::dmat4(projectionMatrix(e)) * glm::dmat4(viewMatrix()));
        const glm::dvec4 clip((e.width / 2 + 0.5) / e.width * 2.0 - 1.0,
                              (e.height / 2 + 0.5) / e.height * 2.0 - 1.0, 0.5, 1.0);
        const glm::dvec4 point = clipToWorld * clip;
        const glm::dvec3 eye(kEye);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(point) / point.w - eye);
        const Box& box = kBoxes[0];
        const double t = (double(box.min.y) - eye.y) / dir.y;  // [cm]
        const glm::dvec3 hit = eye + dir * t;
        if (hit.x < box.min.x || hit.x > box.max.x || hit.z < box.min.z || hit.z > box.max.z) {
            std::fprintf(stderr, "FAIL: the centre pixel does not see the first box (window %ux%u)\n",
                         e.width, e.height);
            return false;
        }

        // The surface as the fragment shader lit it (in float), stored as 8-bit sRGB.
        const PushConstants push = pushConstants();
        const float cosine = std::max(glm::dot(glm::vec3(0, -1, 0), glm::vec3(push.toSun)), 0.0f);
        const glm::vec3 lit = box.albedo * (glm::vec3(push.sunRadiance) * cosine + glm::vec3(push.ambient));

        const postfx::FogSettings fog = fogSettings();
        const double distance = t / kWorld.unitsPerMetre;  // [m]
        const double a = fog.heightFalloff, z0 = eye.z / kWorld.unitsPerMetre - fog.baseHeight,
                     k = a * dir.z * distance;
        const double tau =
            fog.density * std::exp(-a * z0) * distance * (std::abs(k) < 1e-9 ? 1.0 : -std::expm1(-k) / k);
        const double transmittance = std::exp(-tau);
        const double g = fog.anisotropy, cosTheta = glm::dot(dir, glm::dvec3(kToSun));
        const double phase = (1.0 - g * g) / (4.0 * kPi * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
        const postfx::Vec3 sunThroughAir = postfx::atmosphereSunTransmittance(
            atmosphere, postfx::DVec3(eye + dir * (t / 2.0)), kToSun, kWorld);

        bool ok = true;
        int expected[3];
        for (int c = 0; c < 3; ++c) {
            const double surface = srgbDecode(toByte(srgbEncode(lit[c])) / 255.0);
            const double light = double(kSunIlluminance) * sunThroughAir[c] * phase + skyAmbient[c];
            const double fogged = surface * transmittance +
                                  fog.albedo[c] * light * (1.0 - transmittance) * double(kPreExposure);
            expected[c] = toByte(srgbEncode(fogged));
            ok = ok && std::abs(got[c] - expected[c]) <= 2;
        }
        std::printf(
            "centre pixel (%u, %u): sRGB (%d, %d, %d), closed form (%d, %d, %d): the box at %.3f m, fog "
            "transmittance %.4f; tolerance 2 steps\n",
            e.width / 2, e.height / 2, got[0], got[1], got[2], expected[0], expected[1], expected[2],
            distance, transmittance);
        if (!ok) std::fprintf(stderr, "FAIL: the centre pixel differs from the closed form\n");
        return ok;
    }
};

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            options.frames = uint32_t(std::strtoul(argv[++i], nullptr, 10));
        } else if (std::strcmp(argv[i], "--validate") == 0) {
            options.validate = true;
        } else if (std::strcmp(argv[i], "--check") == 0) {
            options.check = true;
        } else {
            std::fprintf(stderr, "usage: %s [--frames N] [--validate] [--check]\n", argv[0]);
            return 1;
        }
    }
    if (options.check && options.frames == 0) {
        std::fprintf(stderr, "--check needs --frames N (the pixel is read in the last frame)\n");
        return 1;
    }
    try {
        TutorialHost host(options);
        return host.run();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "FAIL: %s\n", error.what());
        return 1;
    }
}
