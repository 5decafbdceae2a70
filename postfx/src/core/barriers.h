// Pipeline barriers for postfx's passes.
//
// postfx does not know what the host did with an image before record() nor what it does after, so a
// host image entering postfx waits on all prior commands' writes (ALL_COMMANDS / MEMORY_WRITE) and
// leaving postfx makes postfx's writes visible to all later commands. Between postfx's own passes
// the barriers are exact (compute write -> compute read).
#pragma once

#include "core/gpu.h"

#include <vector>

namespace postfx::core {

struct ImageTransition {
    VkImage image = VK_NULL_HANDLE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout newLayout = VK_IMAGE_LAYOUT_GENERAL;
    VkPipelineStageFlags srcStage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    VkAccessFlags srcAccess = 0;
    VkPipelineStageFlags dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    VkAccessFlags dstAccess = 0;
    uint32_t layers = 1;  // array layers from the first
};

void transition(const Gpu& gpu, VkCommandBuffer cmd, const ImageTransition& t);

// Barriers collected and recorded as one vkCmdPipelineBarrier (stage masks: the union of theirs).
class BarrierBatch {
public:
    void add(const ImageTransition& t);
    // A global memory barrier compute -> compute: `srcAccess` (0: execution only) -> `dstAccess`.
    void computeMemory(VkAccessFlags srcAccess, VkAccessFlags dstAccess);
    // The same between any stages (a transfer pass's).
    void memory(VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                VkAccessFlags dstAccess);
    bool empty() const { return images_.empty() && !memory_; }
    // Records the batch (nothing when empty) and empties it.
    void record(const Gpu& gpu, VkCommandBuffer cmd);

private:
    std::vector<VkImageMemoryBarrier> images_;
    VkPipelineStageFlags src_ = 0, dst_ = 0;
    bool memory_ = false;
    VkAccessFlags memorySrc_ = 0, memoryDst_ = 0;
};

// The stages of postfx's passes that `access` names: transfer for TRANSFER_*, compute for the others.
VkPipelineStageFlags stagesOfAccess(VkAccessFlags access);
// A host image (in `hostLayout`) about to be accessed by postfx's passes in `layout` with `access`
// (shader or transfer accesses).
ImageTransition acquireHostImage(VkImage image, VkImageAspectFlags aspect, VkImageLayout hostLayout,
                                 VkImageLayout layout, VkAccessFlags access);
// The same image handed back to the host in `hostLayout` after postfx's `access`.
ImageTransition releaseHostImage(VkImage image, VkImageAspectFlags aspect, VkImageLayout layout,
                                 VkImageLayout hostLayout, VkAccessFlags access);

VkImageAspectFlags aspectOfFormat(VkFormat format);

// The layout a host image is used in by postfx's passes, and the barriers taking it there and back.
struct HostImageUse {
    VkImageLayout layout;
    ImageTransition acquire, release;
};

// Storage images (color, output) are used in GENERAL (by a transfer pass in its own: frame_graph_record.cpp);
// sampled ones (depth, shadow map) in their own layout when a shader may sample it there, else in
// SHADER_READ_ONLY_OPTIMAL.
HostImageUse useHostImage(VkImage image, VkFormat format, VkImageLayout hostLayout, bool storage,
                          VkAccessFlags access);

}  // namespace postfx::core
