// Plain types shared by the public headers.
#pragma once

#include <postfx/export.h>
#include <postfx/version.h>
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace postfx {

// Vectors and matrices of the public structs. GLM's packed types are named explicitly, so the structs'
// layout is the same whatever GLM configuration the host compiles with (GLM_FORCE_DEFAULT_ALIGNED_GENTYPES,
// GLM_FORCE_INTRINSICS, a default precision): without them a host built with aligned GLM types would hand
// postfx structs of another layout. A host's glm::vec3 / glm::mat4 of any qualifier converts implicitly.
// In a build with GLM's defaults (as postfx's own) they are glm::vec3, glm::dvec3, glm::mat4, ...
using Vec3 = glm::vec<3, float, glm::packed_highp>;
using DVec3 = glm::vec<3, double, glm::packed_highp>;
using DVec4 = glm::vec<4, double, glm::packed_highp>;
using UVec2 = glm::vec<2, glm::uint, glm::packed_highp>;
using UVec3 = glm::vec<3, glm::uint, glm::packed_highp>;
using Mat4 = glm::mat<4, 4, float, glm::packed_highp>;
using DMat4 = glm::mat<4, 4, double, glm::packed_highp>;
static_assert(sizeof(Vec3) == 12 && alignof(Vec3) == 4, "postfx::Vec3 must be three packed floats");
static_assert(sizeof(DVec3) == 24 && alignof(DVec3) == 8, "postfx::DVec3 must be three packed doubles");
static_assert(sizeof(Mat4) == 64 && alignof(Mat4) == 4, "postfx::Mat4 must be 16 packed floats");
static_assert(sizeof(DMat4) == 128 && alignof(DMat4) == 8, "postfx::DMat4 must be 16 packed doubles");

// How the host's depth buffer maps view distance to [0, 1]. Fixed at create time.
struct DepthConvention {
    bool reversedZ = true;     // true: near plane at depth 1, far at 0 (recommended with D32_SFLOAT)
    bool infiniteFar = false;  // true: projection has no far plane (far at depth 0 / 1 reached at infinity)
};

// The host's world frame (ContextCreateInfo::world; docs/integration.md, "World frame and units"). postfx
// works y up, right-handed, in metres, with the ground at y = 0; a host whose world is z up, left-handed or
// in other units gives its own here, and hands every world-space input in its own frame and units: postfx
// converts them once per frame, and what it hands back in world space (the volumetrics lookup,
// cloudShadowTransform) is in the host's frame too. Media properties stay in metres (densities per metre,
// heights and scale heights, distances in the settings); a height is along the host's up axis, above its
// plane up = 0. Fixed at create time.
enum class UpAxis : uint32_t { Y, Z };             // another value (cast from an int) is rejected
enum class Handedness : uint32_t { Right, Left };  // another value (cast from an int) is rejected
inline constexpr double kMinUnitsPerMetre = 1e-3;  // kilometres
inline constexpr double kMaxUnitsPerMetre = 1e3;   // millimetres
struct WorldFrame {
    UpAxis up = UpAxis::Y;  // the world's up axis: Y (Vulkan, glTF, Unity) or Z (Unreal, Blender)
    Handedness handedness = Handedness::Right;  // Right (glTF, Blender) or Left (Unity, Unreal)
    // The host's world units in one metre [1]: 1 for metres, 100 for centimetres (Unreal); in [1e-3, 1e3].
    double unitsPerMetre = 1.0;
};

// One host image handed to postfx for one record() call. postfx never owns it: it uses the view the
// host created and leaves the image in `layout` when the recorded commands have run.
struct ImageInput {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D view of mip 0, layer 0
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent = {0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // layout at the point record() is recorded
    // The usage the image was created with (VkImageCreateInfo::usage): postfx checks that it allows what
    // postfx does with the image (STORAGE for color and output, SAMPLED for depth and the shadow map).
    VkImageUsageFlags usage = 0;
    // The image's sample count (VkImageCreateInfo::samples). postfx reads and writes single-sampled
    // images only: a host with multisampled color or depth resolves them first; anything else is refused
    // by name (docs/integration.md, "Depth image").
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;

    bool present() const { return image != VK_NULL_HANDLE; }
};

// The name of a resource postfx holds between frames that a host may read (an effect's generated noise
// texture, a LUT): each effect's header names its own, e.g. postfx::kFogNoiseTexture. `value` is the
// name the frame plan lists it under.
struct ResourceName {
    const char* value = "";
};

// Where quality Auto's timings were measured. They hold only for the same postfx version, device and
// driver: Context::setAutoQualityTimings skips (with a warning through the message callback) an entry
// whose fields differ from the running context's, so a host's stored cache is remeasured after an
// upgrade of postfx, a new GPU or a new driver. Context::autoQualityTimings fills every field.
struct TimingsOrigin {
    uint32_t postfxVersion = POSTFX_VERSION;  // POSTFX_VERSION of the library that measured them
    uint32_t vendorId = 0;       // VkPhysicalDeviceProperties::vendorID; 0: not recorded (any vendor)
    uint32_t deviceId = 0;       // VkPhysicalDeviceProperties::deviceID; 0: not recorded (any device)
    uint32_t driverVersion = 0;  // VkPhysicalDeviceProperties::driverVersion; 0: not recorded (any)
};

// "VK_FORMAT_R8G8B8A8_UNORM" for the formats postfx names in its messages; "VkFormat 1234" otherwise.
POSTFX_API std::string formatName(VkFormat format);

}  // namespace postfx
