// The volumetrics lookup for transparent surfaces (docs/integration.md, "Transparent surfaces").
//
// A deferred renderer draws glass, water and particles after postfx, in a forward pass, because they are
// not in the depth buffer postfx read. With FrameInfo::volumetricsLookup on, record() also builds a
// camera-frustum volume holding, at every distance along every view ray, the (L, T) of everything postfx
// composited in that frame (the aerial perspective, the clouds in front of that distance, the ray-marched or
// the froxel fog), composed in postfx's composite order. The host's forward pass binds it (a descriptor set
// it allocates from the layout below, with binding numbers it chooses) and includes
// "postfx/volumetrics.glsl": postfxVolumetrics(worldPos) returns (L, T) at a world position in the host's
// world frame and units (ContextCreateInfo::world), and the surface is composited as surface·T + L,
// pre-exposed like everything postfx writes. The settings' distances are in metres.
#pragma once

#include <postfx/export.h>
#include <postfx/types.h>
#include <vulkan/vulkan.h>

#include <cstdint>

namespace postfx {

// The ranges of VolumetricsLookupSettings.
inline constexpr uint32_t kMaxLookupExtentXY = 1024;     // froxels across and down
inline constexpr uint32_t kMaxLookupExtentZ = 512;       // slices
inline constexpr uint64_t kMaxLookupFroxels = 1u << 24;  // x·y·z: 256 MiB of images at most
inline constexpr float kMinLookupNear = 0.01f;           // [m]
inline constexpr float kMaxLookupNear = 1e5f;            // [m]
inline constexpr float kMaxLookupDistance = 1e7f;        // [m]

// FrameInfo::volumetricsLookup. Off (the default): no pass, no image, no memory.
struct VolumetricsLookupSettings {
    bool enabled = false;
    // Froxels across, down and along the view [1]: x, y in [1, 1024], z in [2, 512], x·y·z ≤ 2^24. The
    // ray-marched fog's medium is integrated at this resolution; the other effects are sampled at it
    // (matching the froxel fog's grid in x and y samples it exactly there).
    UVec3 extent{160, 90, 64};
    // Where the first slice ends [m], in [0.01, 1e5] and below maxDistance; from the camera to it, (L, T)
    // run linearly from (0, 1). Slices then follow a geometric series up to maxDistance.
    float nearDistance = 1.0f;
    // Where the last slice ends [m], in (nearDistance, 1e7]: a surface farther gets the value at it.
    float maxDistance = 10000.0f;
};

// The binding numbers the host chose for the lookup's three descriptors (any distinct numbers).
struct VolumetricsLookupBindings {
    uint32_t uniforms = 0;       // uniform buffer (std140 PostfxLookupUniforms)
    uint32_t scattering = 1;     // combined image sampler, 3D: L (rgb) [pre-exposed radiance]
    uint32_t transmittance = 2;  // combined image sampler, 3D: T (rgb) [1]
};
inline constexpr uint32_t kVolumetricsLookupBindingCount = 3;

// What the last recorded frame's lookup is made of (Context::volumetricsLookup), for a host that writes
// its own descriptors. Valid in commands submitted after that record()'s and before the next record()'s,
// on the same queue: the next record() waits for every earlier command (ALL_COMMANDS) before it writes
// them again. The images are in `layout` (GENERAL), their writes visible to every later stage.
struct VolumetricsLookup {
    uint64_t frameIndex = 0;  // the frame it holds
    VkBuffer uniformBuffer = VK_NULL_HANDLE;
    VkDeviceSize uniformOffset = 0;
    VkDeviceSize uniformRange = 0;
    VkImageView scattering = VK_NULL_HANDLE;
    VkImageView transmittance = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
    VkSampler sampler = VK_NULL_HANDLE;  // linear, clamped to the edge; postfx owns it
    VkExtent3D extent = {0, 0, 0};
};

// The layout bindings of the lookup's descriptors, numbered as `bindings` says, readable in `stages`:
// what the host puts into its VkDescriptorSetLayoutCreateInfo (with any bindings of its own).
POSTFX_API void volumetricsLookupLayout(const VolumetricsLookupBindings& bindings, VkShaderStageFlags stages,
                                        VkDescriptorSetLayoutBinding (&out)[kVolumetricsLookupBindingCount]);

}  // namespace postfx
