// The smallest complete postfx host: a Vulkan device, an HDR color image and a depth image standing in
// for a renderer's, and postfx's ray-marched fog recorded into every frame's command buffer, with
// frames in flight and a window resize. docs/integration.md quotes the four parts an integration
// writes: createPostfx, recordFrame, resizeSceneImages and destroyAll. Everything else here is the
// host's own Vulkan set-up or, below the marked line, test scaffolding.
//
// Uses only postfx's public API and the Vulkan loader. Run:
//   postfx_minimal_host [--validate]
// --validate: Khronos validation layer with synchronization validation; any message fails the run.
// POSTFX_DEVICE=<substring of the device name> picks the device (CI: llvmpipe).
// Exit status 0 when the fog matches its closed form at the image's centre, 1 otherwise.
#include <postfx/postfx.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------------------------------------------
// The host's Vulkan objects: a real renderer has all of these already.

struct Host {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // --validate only
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    uint32_t queueFamily = 0;  // graphics + compute: the host renders on it, postfx records compute
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
};

// The renderer's HDR color target and depth buffer at the window's size.
struct SceneImages {
    VkExtent2D extent{0, 0};
    Image color;  // R16G16B16A16_SFLOAT, linear radiance [cd/m²]
    Image depth;  // D32_SFLOAT, reversed Z with an infinite far plane
};

// One command buffer and fence per frame in flight.
constexpr uint32_t kFramesInFlight = 2;
struct FrameSlot {
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;  // signalled when the slot's last submission has completed
};
using Frames = std::vector<FrameSlot>;

// What this example renders: a wall facing the camera in homogeneous fog, lit only by the sky.
struct Scene {
    float nearPlane = 0.1f;                             // [m]
    float verticalFov = 1.0f;                           // [rad]
    float wallDistance = 50.0f;                         // along the view axis [m]
    float wallRadiance[3] = {1000.0f, 800.0f, 600.0f};  // the "rendered" color [cd/m²]
    postfx::Vec3 ambient{4000.0f, 5000.0f, 7000.0f};    // sky radiance [cd/m²]
    float density = 0.02f;                              // fog extinction σt [1/m]
    postfx::Vec3 albedo{0.9f};                          // [1]
    float maxDistance = 200.0f;                         // [m]
};
const Scene kScene;

bool check(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return true;
    std::fprintf(stderr, "%s failed: VkResult %d\n", what, int(result));
    return false;
}

uint32_t findMemoryType(const Host& host, uint32_t typeBits, VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(host.physicalDevice, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    return UINT32_MAX;
}

bool createImage(const Host& host, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect, Image& out) {
    out.format = format;
    out.usage = usage;
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (!check(vkCreateImage(host.device, &info, nullptr, &out.image), "vkCreateImage")) return false;
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(host.device, out.image, &requirements);
    VkMemoryAllocateInfo allocation{};
    allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocation.allocationSize = requirements.size;
    allocation.memoryTypeIndex =
        findMemoryType(host, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (allocation.memoryTypeIndex == UINT32_MAX)
        allocation.memoryTypeIndex = findMemoryType(host, requirements.memoryTypeBits, 0);
    if (!check(vkAllocateMemory(host.device, &allocation, nullptr, &out.memory), "vkAllocateMemory") ||
        !check(vkBindImageMemory(host.device, out.image, out.memory, 0), "vkBindImageMemory"))
        return false;
    VkImageViewCreateInfo view{};
    view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    view.image = out.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    return check(vkCreateImageView(host.device, &view, nullptr, &out.view), "vkCreateImageView");
}

void destroyImage(const Host& host, Image& image) {
    vkDestroyImageView(host.device, image.view, nullptr);
    vkDestroyImage(host.device, image.image, nullptr);
    vkFreeMemory(host.device, image.memory, nullptr);
    image = {};
}

// The host's color and depth targets, as postfx needs them: color a storage image (postfx composites
// into it; TRANSFER_DST/SRC are this host's own clear and read-back), depth sampled.
bool createSceneImages(const Host& host, VkExtent2D extent, SceneImages& out) {
    out.extent = extent;
    return createImage(
               host, extent, VK_FORMAT_R16G16B16A16_SFLOAT,
               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
               VK_IMAGE_ASPECT_COLOR_BIT, out.color) &&
           createImage(host, extent, VK_FORMAT_D32_SFLOAT,
                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                       VK_IMAGE_ASPECT_DEPTH_BIT, out.depth);
}

void destroySceneImages(const Host& host, SceneImages& images) {
    destroyImage(host, images.color);
    destroyImage(host, images.depth);
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                  VkImageLayout to, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

// Stands in for the host's rendering: the color target cleared to the wall's radiance and the depth
// buffer to the wall's depth, left in the layouts the host hands postfx: color GENERAL (as after a
// deferred renderer's compute lighting), depth SHADER_READ_ONLY_OPTIMAL (a depth buffer created with
// DEPTH_STENCIL_ATTACHMENT usage, as a rasterising host's is, may stay in DEPTH_STENCIL_READ_ONLY_OPTIMAL).
void renderScene(VkCommandBuffer cmd, const SceneImages& images) {
    // Last frame's contents are discarded once the commands that used them are done.
    imageBarrier(cmd, images.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    imageBarrier(cmd, images.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkClearColorValue radiance{};
    std::copy(std::begin(kScene.wallRadiance), std::end(kScene.wallRadiance), radiance.float32);
    radiance.float32[3] = 1.0f;
    const VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, images.color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &radiance, 1,
                         &colorRange);
    // Reversed Z, infinite far plane: a point at distance z along the view axis has depth near / z.
    const VkClearDepthStencilValue wall{kScene.nearPlane / kScene.wallDistance, 0};
    const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    vkCmdClearDepthStencilImage(cmd, images.depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &wall, 1,
                                &depthRange);
    imageBarrier(cmd, images.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    imageBarrier(cmd, images.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT);
}

// The camera: at 1.7 m eye height looking down -z; projection to Vulkan clip space (y down) with
// reversed Z and an infinite far plane, as ContextCreateInfo::depth says.
postfx::CameraInput camera(VkExtent2D extent) {
    postfx::CameraInput camera;
    camera.position = {0.0, 1.7, 0.0};           // [m]
    camera.view = postfx::Mat4(1.0f);            // world -> view: no rotation,
    camera.view[3] = {0.0f, -1.7f, 0.0f, 1.0f};  // and the translation by -position
    const float f = 1.0f / std::tan(kScene.verticalFov / 2.0f);
    const float aspect = float(extent.width) / float(extent.height);
    camera.projection = postfx::Mat4(0.0f);
    camera.projection[0][0] = f / aspect;
    camera.projection[1][1] = -f;
    // clip w = the distance along -z, depth = near / that distance: 1 at the near plane, 0 at infinity.
    camera.projection[2][3] = -1.0f;
    camera.projection[3][2] = kScene.nearPlane;
    return camera;
}

// ===================================================================================================
// The integration: what a host writes to use postfx. docs/integration.md quotes these four functions.

void printPostfxMessage(postfx::MessageSeverity severity, const char* message, void* /*userData*/) {
    std::fprintf(stderr, "postfx %s: %s\n", severity == postfx::MessageSeverity::Error ? "error" : "warning",
                 message);
}

// Create: once, after the device. The context borrows the host's handles and must be destroyed before
// them.
std::unique_ptr<postfx::Context> createPostfx(const Host& host) {
    postfx::ContextCreateInfo info;
    info.instance = host.instance;
    info.physicalDevice = host.physicalDevice;
    info.device = host.device;
    info.getInstanceProcAddr = vkGetInstanceProcAddr;  // postfx loads every Vulkan function through these
    info.getDeviceProcAddr = vkGetDeviceProcAddr;
    info.queueFamilyIndex = host.queueFamily;  // the family whose queue runs the recorded commands
    info.maxExtent = {1920, 1080};             // the largest color/depth extent record() will get [px]
    info.depth.reversedZ = true;               // the host's depth convention, fixed for the context
    info.depth.infiniteFar = true;
    info.framesInFlight = kFramesInFlight;  // must match the host's frame ring
    info.messageCallback = printPostfxMessage;
    std::unique_ptr<postfx::Context> context;
    if (postfx::Status s = postfx::Context::create(info, context); !s)
        std::fprintf(stderr, "postfx::Context::create: %s: %s\n", postfx::resultName(s.code),
                     s.message.c_str());
    return context;  // empty on failure
}

// Per frame: wait for the frame that used this slot framesInFlight frames ago, record the host's work,
// then postfx's, then submit. frameIndex increases by one per frame, across resizes too.
bool recordFrame(const Host& host, const Frames& frames, postfx::Context& postfx, const SceneImages& images,
                 uint64_t frameIndex) {
    const FrameSlot& slot = frames[frameIndex % frames.size()];
    if (!check(vkWaitForFences(host.device, 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences") ||
        !check(vkResetFences(host.device, 1, &slot.fence), "vkResetFences") ||
        !check(vkResetCommandBuffer(slot.commandBuffer, 0), "vkResetCommandBuffer"))
        return false;
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (!check(vkBeginCommandBuffer(slot.commandBuffer, &begin), "vkBeginCommandBuffer")) return false;

    renderScene(slot.commandBuffer, images);  // the host's own passes

    postfx::FrameInfo frame;
    frame.commandBuffer = slot.commandBuffer;  // recording, outside a render pass
    frame.frameIndex = frameIndex;
    // Each image as it is at this point of the command buffer: its layout, and the usage it was created with.
    frame.color = {.image = images.color.image,
                   .view = images.color.view,
                   .format = images.color.format,
                   .extent = images.extent,
                   .layout = VK_IMAGE_LAYOUT_GENERAL,
                   .usage = images.color.usage};
    frame.depth = {.image = images.depth.image,
                   .view = images.depth.view,
                   .format = images.depth.format,
                   .extent = images.extent,
                   .layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   .usage = images.depth.usage};
    frame.camera = camera(images.extent);
    frame.sun.illuminance = postfx::Vec3(0.0f);  // night: no sun [lux]
    frame.ambient = kScene.ambient;              // sky radiance [cd/m²]
    frame.fog.enabled = true;
    frame.fog.density = kScene.density;  // [1/m]
    frame.fog.albedo = kScene.albedo;
    frame.fog.heightFalloff = 0.0f;  // homogeneous
    frame.fog.maxDistance = kScene.maxDistance;
    frame.fog.jitter = false;  // with jitter off and no tail, the image has a closed form (below)
    frame.fog.analyticTail = false;
    const postfx::Status status = postfx.record(frame);
    if (!status)  // nothing was recorded: the host's frame goes on without fog
        std::fprintf(stderr, "postfx record, frame %llu: %s\n", (unsigned long long)frameIndex,
                     status.message.c_str());
    // postfx returned color and depth in the layouts they came in; its writes are visible to what follows.

    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &slot.commandBuffer;
    return check(vkEndCommandBuffer(slot.commandBuffer), "vkEndCommandBuffer") &&
           check(vkQueueSubmit(host.queue, 1, &submit, slot.fence), "vkQueueSubmit") && status.ok();
}

// Resize: the host recreates its images at the new size; the context stays. postfx's own
// size-dependent resources follow the next frame's extent (any size up to maxExtent; beyond it,
// create a new context).
bool resizeSceneImages(const Host& host, SceneImages& images, VkExtent2D extent) {
    // The frames in flight may still use the old images.
    if (!check(vkDeviceWaitIdle(host.device), "vkDeviceWaitIdle")) return false;
    destroySceneImages(host, images);
    return createSceneImages(host, extent, images);
}

// Destroy: the context first, once the device is idle (postfx frees its objects at once), then what
// it borrowed.
void destroyAll(Host& host, Frames& frames, std::unique_ptr<postfx::Context>& postfx, SceneImages& images) {
    if (host.device) {
        vkDeviceWaitIdle(host.device);
        postfx.reset();
        destroySceneImages(host, images);
        for (FrameSlot& slot : frames)
            vkDestroyFence(host.device, slot.fence, nullptr);
        vkDestroyCommandPool(host.device, host.commandPool, nullptr);
        vkDestroyDevice(host.device, nullptr);
    }
    if (host.messenger) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(host.instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroyMessenger) destroyMessenger(host.instance, host.messenger, nullptr);
    }
    if (host.instance) vkDestroyInstance(host.instance, nullptr);
    host = {};
}

// ===================================================================================================
// Test scaffolding, not part of an integration: the host's instance and device with optional
// validation, the read-back of the centre pixel, and the closed form it is checked against.

int gValidationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT /*severity*/,
                                                   VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* /*userData*/) {
    ++gValidationMessages;
    std::fprintf(stderr, "[validation] %s\n", data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

bool hasInstanceExtension(const char* layer, const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

bool createHost(bool validate, Host& host, Frames& frames) {
    const char* layer = "VK_LAYER_KHRONOS_validation";
    std::vector<const char*> layers, extensions;
    VkDebugUtilsMessengerCreateInfoEXT messenger{};
    messenger.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onValidationMessage;
    const VkValidationFeatureEnableEXT syncValidation =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncValidation;
    if (validate) {
        if (!hasInstanceExtension(layer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
            !hasInstanceExtension(layer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
            std::fprintf(stderr,
                         "--validate: %s with VK_EXT_debug_utils and VK_EXT_validation_features is not "
                         "installed\n",
                         layer);
            return false;
        }
        layers.push_back(layer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        messenger.pNext = &features;  // also covers vkCreateInstance / vkDestroyInstance
    }
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "postfx_minimal_host";
    app.apiVersion = VK_API_VERSION_1_0;  // postfx needs Vulkan 1.0
    VkInstanceCreateInfo instanceInfo{};
    instanceInfo.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    instanceInfo.pNext = validate ? &messenger : nullptr;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = uint32_t(layers.size());
    instanceInfo.ppEnabledLayerNames = layers.data();
    instanceInfo.enabledExtensionCount = uint32_t(extensions.size());
    instanceInfo.ppEnabledExtensionNames = extensions.data();
    if (!check(vkCreateInstance(&instanceInfo, nullptr, &host.instance), "vkCreateInstance")) return false;
    if (validate) {
        auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(host.instance, "vkCreateDebugUtilsMessengerEXT"));
        messenger.pNext = nullptr;
        if (!createMessenger || !check(createMessenger(host.instance, &messenger, nullptr, &host.messenger),
                                       "vkCreateDebugUtilsMessengerEXT"))
            return false;
    }

    // The first device (with POSTFX_DEVICE set: whose name contains it) that has a queue
    // family with graphics and compute.
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(host.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(host.instance, &count, devices.data());
    const char* wanted = std::getenv("POSTFX_DEVICE");
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        if (wanted && *wanted && !std::strstr(properties.deviceName, wanted)) continue;
        uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
        for (uint32_t i = 0; i < familyCount && !host.physicalDevice; ++i) {
            const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
            if ((families[i].queueFlags & needed) != needed) continue;
            host.physicalDevice = device;
            host.properties = properties;
            host.queueFamily = i;
        }
        if (host.physicalDevice) break;
    }
    if (!host.physicalDevice) {
        std::fprintf(stderr, "no Vulkan device with a graphics+compute queue%s%s\n",
                     wanted && *wanted ? " whose name contains POSTFX_DEVICE=" : "", wanted ? wanted : "");
        return false;
    }

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = host.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    if (!check(vkCreateDevice(host.physicalDevice, &deviceInfo, nullptr, &host.device), "vkCreateDevice"))
        return false;
    vkGetDeviceQueue(host.device, host.queueFamily, 0, &host.queue);

    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = host.queueFamily;
    if (!check(vkCreateCommandPool(host.device, &poolInfo, nullptr, &host.commandPool),
               "vkCreateCommandPool"))
        return false;
    frames.resize(kFramesInFlight);
    for (FrameSlot& slot : frames) {
        VkCommandBufferAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        allocate.commandPool = host.commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        VkFenceCreateInfo fence{};
        fence.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first wait on each slot returns at once
        if (!check(vkAllocateCommandBuffers(host.device, &allocate, &slot.commandBuffer),
                   "vkAllocateCommandBuffers") ||
            !check(vkCreateFence(host.device, &fence, nullptr, &slot.fence), "vkCreateFence"))
            return false;
    }
    return true;
}

float halfToFloat(uint16_t h) {
    const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(float(mantissa + 1024), exponent - 25);
}

// Copies the centre pixel of the color image (GENERAL, as postfx left it) into host memory.
bool readCenterPixel(const Host& host, const SceneImages& images, float rgb[3]) {
    VkBufferCreateInfo bufferInfo{};
    bufferInfo.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bufferInfo.size = 8;  // one RGBA16F texel
    bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    bool ok = check(vkCreateBuffer(host.device, &bufferInfo, nullptr, &buffer), "vkCreateBuffer");
    if (ok) {
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(host.device, buffer, &requirements);
        VkMemoryAllocateInfo allocation{};
        allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        allocation.allocationSize = requirements.size;
        allocation.memoryTypeIndex =
            findMemoryType(host, requirements.memoryTypeBits,
                           VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        ok = check(vkAllocateMemory(host.device, &allocation, nullptr, &memory), "vkAllocateMemory") &&
             check(vkBindBufferMemory(host.device, buffer, memory, 0), "vkBindBufferMemory");
    }
    VkCommandBufferAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocate.commandPool = host.commandPool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    ok = ok && check(vkAllocateCommandBuffers(host.device, &allocate, &cmd), "vkAllocateCommandBuffers") &&
         check(vkCreateFence(host.device, &fenceInfo, nullptr, &fence), "vkCreateFence");
    if (ok) {
        VkCommandBufferBeginInfo begin{};
        begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &begin);
        // After postfx, as after any compute pass of the host's: compute writes -> transfer read.
        imageBarrier(cmd, images.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageOffset = {int32_t(images.extent.width / 2), int32_t(images.extent.height / 2), 0};
        region.imageExtent = {1, 1, 1};
        vkCmdCopyImageToBuffer(cmd, images.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1,
                               &region);
        VkMemoryBarrier toHost{};
        toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                             0, nullptr, 0, nullptr);
        VkSubmitInfo submit{};
        submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        void* mapped = nullptr;
        ok = check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer") &&
             check(vkQueueSubmit(host.queue, 1, &submit, fence), "vkQueueSubmit") &&
             check(vkWaitForFences(host.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences") &&
             check(vkMapMemory(host.device, memory, 0, 8, 0, &mapped), "vkMapMemory");
        if (ok) {
            uint16_t texel[4];
            std::memcpy(texel, mapped, sizeof(texel));
            for (int c = 0; c < 3; ++c)
                rgb[c] = halfToFloat(texel[c]);
            vkUnmapMemory(host.device, memory);
        }
    }
    vkDestroyFence(host.device, fence, nullptr);
    if (cmd) vkFreeCommandBuffers(host.device, host.commandPool, 1, &cmd);
    vkDestroyBuffer(host.device, buffer, nullptr);
    vkFreeMemory(host.device, memory, nullptr);
    return ok;
}

// Homogeneous fog, no sun, ambient only, no jitter, no tail (docs/effects/fog.md, "Model"): along the
// centre pixel's ray to the wall at distance D, T = exp(-σt·D) and the in-scattered radiance is
// albedo·ambient·(1 - T) (the phase function integrates to 1 over the sphere), so
// out = color·T + albedo·ambient·(1 - T). Each march step is integrated exactly, so this holds at any
// step count. Tolerance: relative 2e-3, four RGBA16F rounding steps (2^-11 each).
constexpr double kTolerance = 2e-3;

bool checkCenterPixel(const SceneImages& images, const float rgb[3], double& worstError) {
    // Pixel (W/2, H/2)'s ray through its centre: ndc = (i + 0.5)/W·2 - 1; in view space (x, y, -1)·z with
    // x = ndc_x·aspect/f, y = -ndc_y/f (Vulkan clip y points down). The wall is the plane z = wallDistance.
    const double w = images.extent.width, h = images.extent.height;
    const double f = 1.0 / std::tan(double(kScene.verticalFov) / 2.0);
    const double ndcX = (std::floor(w / 2) + 0.5) / w * 2.0 - 1.0,
                 ndcY = (std::floor(h / 2) + 0.5) / h * 2.0 - 1.0;
    const double x = ndcX * (w / h) / f, y = ndcY / f;
    const double surface = double(kScene.wallDistance) * std::sqrt(1.0 + x * x + y * y);  // [m]
    const double distance = std::min(surface, double(kScene.maxDistance));
    const double t = std::exp(-double(kScene.density) * distance);
    bool ok = true;
    worstError = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double expected = double(kScene.wallRadiance[c]) * t +
                                double(kScene.albedo[c]) * double(kScene.ambient[c]) * (1.0 - t);
        const double error = std::abs(double(rgb[c]) - expected) / expected;
        worstError = std::max(worstError, error);
        std::printf(
            "  %ux%u channel %d: got %.6g, expected %.6g (T = %.6f over %.4f m), relative error %.2e\n",
            images.extent.width, images.extent.height, c, double(rgb[c]), expected, t, distance, error);
        ok = ok && error <= kTolerance;
    }
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    bool validate = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--validate") == 0) {
            validate = true;
        } else {
            std::fprintf(stderr, "usage: %s [--validate]\n", argv[0]);
            return 1;
        }
    }

    Host host;
    Frames frames;
    SceneImages images;
    std::unique_ptr<postfx::Context> postfx;
    bool ok = createHost(validate, host, frames) && createSceneImages(host, {640, 360}, images);
    if (ok) postfx = createPostfx(host);
    ok = ok && postfx != nullptr;

    // Three frames at 640×360, a window resize to 800×450, three more frames; the centre pixel is
    // checked after each size.
    uint64_t frameIndex = 0;
    double worst = 0.0, error = 0.0;
    for (VkExtent2D extent : {VkExtent2D{640, 360}, VkExtent2D{800, 450}}) {
        if (ok && (extent.width != images.extent.width || extent.height != images.extent.height))
            ok = resizeSceneImages(host, images, extent);
        for (int i = 0; i < 3 && ok; ++i)
            ok = recordFrame(host, frames, *postfx, images, frameIndex++);
        float rgb[3] = {};
        ok = ok && check(vkDeviceWaitIdle(host.device), "vkDeviceWaitIdle") &&
             readCenterPixel(host, images, rgb);
        ok = ok && checkCenterPixel(images, rgb, error);
        worst = std::max(worst, error);
    }
    const std::string device = host.properties.deviceName;
    destroyAll(host, frames, postfx, images);

    if (gValidationMessages > 0) {
        std::fprintf(stderr, "FAIL: %d validation message(s)\n", gValidationMessages);
        return 1;
    }
    if (!ok) {
        std::fprintf(stderr,
                     "FAIL: the fog does not match its closed form within relative %.0e (or a step "
                     "failed above)\n",
                     kTolerance);
        return 1;
    }
    std::printf(
        "OK: %s, %llu frames, 640x360 then 800x450: centre pixel within relative %.2e of the closed "
        "form (tolerance %.0e)%s\n",
        device.c_str(), (unsigned long long)frameIndex, worst, kTolerance,
        validate ? ", no validation messages" : "");
    return 0;
}
