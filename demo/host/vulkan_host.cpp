#include "host/vulkan_host.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace demo {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string fail(const char* what, VkResult r) {
    return std::string(what) + " failed: " + vkResultName(r);
}

bool envIsOne(const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && std::strcmp(v, "1") == 0;
}

bool hasLayer(const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool hasInstanceExtension(const char* layer, const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceExtensionProperties(layer, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateInstanceExtensionProperties(layer, &n, exts.data());
    for (const auto& e : exts)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    std::string msg =
        (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "[vulkan error] " : "[vulkan warning] ";
    if (data->pMessageIdName) msg += std::string(data->pMessageIdName) + ": ";
    msg += data->pMessage ? data->pMessage : "";
    std::fprintf(stderr, "%s\n", msg.c_str());
    static_cast<VulkanHost*>(user)->addMessage(std::move(msg));
    return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(VulkanHost* host) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = debugCallback;
    info.pUserData = host;
    return info;
}

// A queue family with graphics + compute (+ present when asked), or UINT32_MAX.
uint32_t pickQueueFamily(VkInstance instance, VkPhysicalDevice pd, const HostOptions& options) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < n; ++i) {
        if ((families[i].queueFlags & need) != need) continue;
        if (options.presentSupport && !options.presentSupport(instance, pd, i)) continue;
        return i;
    }
    return UINT32_MAX;
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        default:
            return 3;
    }
}

}  // namespace

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, exts.data());
    for (const auto& e : exts)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

const char* vkResultName(VkResult result) {
#define NAME(x) \
    { x, #x }
    static constexpr std::pair<VkResult, const char*> kNames[] = {
        NAME(VK_SUCCESS),
        NAME(VK_NOT_READY),
        NAME(VK_TIMEOUT),
        NAME(VK_INCOMPLETE),
        NAME(VK_ERROR_OUT_OF_HOST_MEMORY),
        NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY),
        NAME(VK_ERROR_INITIALIZATION_FAILED),
        NAME(VK_ERROR_DEVICE_LOST),
        NAME(VK_ERROR_MEMORY_MAP_FAILED),
        NAME(VK_ERROR_LAYER_NOT_PRESENT),
        NAME(VK_ERROR_EXTENSION_NOT_PRESENT),
        NAME(VK_ERROR_FEATURE_NOT_PRESENT),
        NAME(VK_ERROR_INCOMPATIBLE_DRIVER),
        NAME(VK_ERROR_TOO_MANY_OBJECTS),
        NAME(VK_ERROR_FORMAT_NOT_SUPPORTED),
        NAME(VK_ERROR_FRAGMENTED_POOL),
        NAME(VK_ERROR_OUT_OF_POOL_MEMORY),
        NAME(VK_ERROR_SURFACE_LOST_KHR),
        NAME(VK_ERROR_OUT_OF_DATE_KHR),
        NAME(VK_SUBOPTIMAL_KHR),
        NAME(VK_ERROR_UNKNOWN),
    };
#undef NAME
    for (const auto& [code, name] : kNames)
        if (code == result) return name;
    thread_local char unknown[32];
    std::snprintf(unknown, sizeof(unknown), "VkResult(%d)", int(result));
    return unknown;
}

std::unique_ptr<VulkanHost> VulkanHost::create(const HostOptions& options, std::string& error) {
    std::unique_ptr<VulkanHost> host(new VulkanHost());
    host->validationEnabled = options.validation || envIsOne("POSTFX_VALIDATION");

    // Instance: Vulkan 1.2 where the loader has it, 1.1 at least.
    uint32_t loaderVersion = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_1) {
        error = "the Vulkan loader does not support Vulkan 1.1";
        return nullptr;
    }
    host->apiVersion = options.apiVersion                    ? options.apiVersion
                       : loaderVersion >= VK_API_VERSION_1_2 ? VK_API_VERSION_1_2
                                                             : VK_API_VERSION_1_1;

    std::vector<const char*> layers, extensions = options.instanceExtensions;
    VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(host.get());
    VkValidationFeatureEnableEXT syncValidation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncValidation;
    const void* next = nullptr;
    if (host->validationEnabled) {
        if (!hasLayer(kValidationLayer)) {
            error = std::string("validation was requested (--validation or POSTFX_VALIDATION=1) but ") +
                    kValidationLayer + " is not installed";
            return nullptr;
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        debugInfo.pNext = &features;
        if (hasInstanceExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME))
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        next = &debugInfo;  // also reports messages of vkCreateInstance / vkDestroyInstance
    } else if (hasInstanceExtension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);  // labels for RenderDoc / Nsight
    }
    host->debugUtilsEnabled = std::find_if(extensions.begin(), extensions.end(), [](const char* e) {
                                  return std::strcmp(e, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0;
                              }) != extensions.end();
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "postfx demo";
    app.pEngineName = "postfx";
    app.apiVersion = host->apiVersion;
    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pNext = next;
    ici.pApplicationInfo = &app;
    ici.enabledLayerCount = uint32_t(layers.size());
    ici.ppEnabledLayerNames = layers.data();
    ici.enabledExtensionCount = uint32_t(extensions.size());
    ici.ppEnabledExtensionNames = extensions.data();
    if (VkResult r = vkCreateInstance(&ici, nullptr, &host->instance); r != VK_SUCCESS) {
        error = fail("vkCreateInstance", r);
        return nullptr;
    }
    if (host->validationEnabled) {
        auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(host->instance, "vkCreateDebugUtilsMessengerEXT"));
        debugInfo.pNext = nullptr;
        if (!createMessenger ||
            createMessenger(host->instance, &debugInfo, nullptr, &host->messenger_) != VK_SUCCESS) {
            error = "could not create the VK_EXT_debug_utils messenger";
            return nullptr;
        }
    }

    // Physical device: POSTFX_DEVICE=<name substring> picks one; else prefer discrete GPUs.
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(host->instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(host->instance, &count, devices.data());
    const char* wanted = std::getenv("POSTFX_DEVICE");
    std::string names;
    int bestRank = 1 << 30;
    for (VkPhysicalDevice pd : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(pd, &props);
        names += std::string(names.empty() ? "" : ", ") + props.deviceName;
        uint32_t family = pickQueueFamily(host->instance, pd, options);
        if (props.apiVersion < VK_API_VERSION_1_1 || family == UINT32_MAX) continue;
        if (options.swapchain && !hasDeviceExtension(pd, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) continue;
        if (wanted && *wanted && std::strstr(props.deviceName, wanted) == nullptr) continue;
        if (typeRank(props.deviceType) < bestRank) {
            bestRank = typeRank(props.deviceType);
            host->physicalDevice = pd;
            host->queueFamily = family;
            host->properties = props;
        }
    }
    if (host->physicalDevice == VK_NULL_HANDLE) {
        error = "no usable Vulkan device (1.1, graphics+compute queue";
        error += options.swapchain ? ", swapchain" : "";
        error += wanted && *wanted ? std::string(", name containing POSTFX_DEVICE='") + wanted + "'" : "";
        error += "); devices: " + (names.empty() ? std::string("none") : names);
        return nullptr;
    }

    // Device with one queue.
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = host->queueFamily;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    std::vector<const char*> deviceExtensions;
    if (options.swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.enabledExtensionCount = uint32_t(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    if (VkResult r = vkCreateDevice(host->physicalDevice, &dci, nullptr, &host->device); r != VK_SUCCESS) {
        error = fail("vkCreateDevice", r);
        return nullptr;
    }
    vkGetDeviceQueue(host->device, host->queueFamily, 0, &host->queue);

    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = host->queueFamily;
    if (VkResult r = vkCreateCommandPool(host->device, &pci, nullptr, &host->commandPool); r != VK_SUCCESS) {
        error = fail("vkCreateCommandPool", r);
        return nullptr;
    }
    return host;
}

VulkanHost::~VulkanHost() {
    destroy();
}

void VulkanHost::destroy() {
    if (device) {
        vkDeviceWaitIdle(device);
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        // The validation layer reports objects left on the device here, through messenger_.
        vkDestroyDevice(device, nullptr);
    }
    if (messenger_) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroyMessenger) destroyMessenger(instance, messenger_, nullptr);
    }
    // Messages of vkDestroyInstance reach this host through the messenger chained to vkCreateInstance.
    if (instance) vkDestroyInstance(instance, nullptr);
    commandPool = VK_NULL_HANDLE;
    queue = VK_NULL_HANDLE;
    device = VK_NULL_HANDLE;
    messenger_ = VK_NULL_HANDLE;
    physicalDevice = VK_NULL_HANDLE;
    instance = VK_NULL_HANDLE;
}

std::vector<std::string> VulkanHost::validationMessages() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
}

std::vector<std::string> VulkanHost::takeValidationMessages() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(messages_, {});
}

size_t VulkanHost::validationMessageCount() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_.size();
}

void VulkanHost::addMessage(std::string message) {
    std::lock_guard<std::mutex> lock(mutex_);
    messages_.push_back(std::move(message));
}

std::string VulkanHost::deviceDescription() const {
    std::string name = properties.deviceName;
    if (physicalDevice == VK_NULL_HANDLE) return name;  // after destroy()
    // vkGetPhysicalDeviceProperties2 is Vulkan 1.1's: not on a 1.0 instance.
    if (apiVersion < VK_API_VERSION_1_1 || (properties.apiVersion < VK_API_VERSION_1_2 &&
                                            !hasDeviceExtension(physicalDevice, "VK_KHR_driver_properties")))
        return name;
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physicalDevice, &props2);
    const char* info = driver.driverInfo[0] ? driver.driverInfo : driver.driverName;
    return info[0] ? name + ", " + info : name;
}

bool VulkanHost::submitAndWait(const std::function<void(VkCommandBuffer)>& record, std::string& error) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (VkResult r = vkAllocateCommandBuffers(device, &ai, &cmd); r != VK_SUCCESS) {
        error = fail("vkAllocateCommandBuffers", r);
        return false;
    }
    VkFence fence = VK_NULL_HANDLE;
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkResult r = vkCreateFence(device, &fci, nullptr, &fence);
    const char* what = "vkCreateFence";
    if (r == VK_SUCCESS) {
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &bi);
        record(cmd);
        r = vkEndCommandBuffer(cmd);
        what = "vkEndCommandBuffer";
    }
    if (r == VK_SUCCESS) {
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        r = vkQueueSubmit(queue, 1, &si, fence);
        what = "vkQueueSubmit";
    }
    if (r == VK_SUCCESS) {
        r = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
        what = "vkWaitForFences";
    }
    if (fence) vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, commandPool, 1, &cmd);
    if (r != VK_SUCCESS) error = fail(what, r);
    return r == VK_SUCCESS;
}

}  // namespace demo
