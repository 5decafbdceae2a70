#include "core/barriers.h"

namespace postfx::core {

namespace {

VkImageMemoryBarrier imageBarrier(const ImageTransition& t) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = t.srcAccess;
    barrier.dstAccessMask = t.dstAccess;
    barrier.oldLayout = t.oldLayout;
    barrier.newLayout = t.newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = t.image;
    barrier.subresourceRange = {t.aspect, 0, 1, 0, t.layers};
    return barrier;
}

}  // namespace

void transition(const Gpu& gpu, VkCommandBuffer cmd, const ImageTransition& t) {
    const VkImageMemoryBarrier barrier = imageBarrier(t);
    gpu.fn.vkCmdPipelineBarrier(cmd, t.srcStage, t.dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void BarrierBatch::add(const ImageTransition& t) {
    images_.push_back(imageBarrier(t));
    src_ |= t.srcStage;
    dst_ |= t.dstStage;
}

void BarrierBatch::computeMemory(VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
    memory(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, srcAccess, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dstAccess);
}

void BarrierBatch::memory(VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                          VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    memory_ = true;
    memorySrc_ |= srcAccess;
    memoryDst_ |= dstAccess;
    src_ |= srcStage;
    dst_ |= dstStage;
}

void BarrierBatch::record(const Gpu& gpu, VkCommandBuffer cmd) {
    if (empty()) return;
    VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    memory.srcAccessMask = memorySrc_;
    memory.dstAccessMask = memoryDst_;
    gpu.fn.vkCmdPipelineBarrier(cmd, src_, dst_, 0, memory_ ? 1 : 0, &memory, 0, nullptr,
                                uint32_t(images_.size()), images_.data());
    images_.clear();
    src_ = dst_ = 0;
    memory_ = false;
    memorySrc_ = memoryDst_ = 0;
}

VkPipelineStageFlags stagesOfAccess(VkAccessFlags access) {
    VkPipelineStageFlags stages = 0;
    if (access & (VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT))
        stages |= VK_PIPELINE_STAGE_TRANSFER_BIT;
    if (access & ~(VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT) || !stages)
        stages |= VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    return stages;
}

ImageTransition acquireHostImage(VkImage image, VkImageAspectFlags aspect, VkImageLayout hostLayout,
                                 VkImageLayout layout, VkAccessFlags access) {
    ImageTransition t;
    t.image = image;
    t.aspect = aspect;
    t.oldLayout = hostLayout;
    t.newLayout = layout;
    t.srcStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    t.srcAccess = VK_ACCESS_MEMORY_WRITE_BIT;
    t.dstStage = stagesOfAccess(access);
    t.dstAccess = access;
    return t;
}

ImageTransition releaseHostImage(VkImage image, VkImageAspectFlags aspect, VkImageLayout layout,
                                 VkImageLayout hostLayout, VkAccessFlags access) {
    ImageTransition t;
    t.image = image;
    t.aspect = aspect;
    t.oldLayout = layout;
    t.newLayout = hostLayout;
    t.srcStage = stagesOfAccess(access);
    // Reads need no availability, but a layout change must still wait for them (execution dependency).
    t.srcAccess =
        access & (VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    t.dstStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    t.dstAccess = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    return t;
}

VkImageAspectFlags aspectOfFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
            return VK_IMAGE_ASPECT_DEPTH_BIT;
        case VK_FORMAT_D16_UNORM_S8_UINT:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
        default:
            return VK_IMAGE_ASPECT_COLOR_BIT;
    }
}

namespace {

// Layouts a compute shader can sample a (depth) image in without a transition.
bool sampleableLayout(VkImageLayout l) {
    return l == VK_IMAGE_LAYOUT_GENERAL || l == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL;
}

}  // namespace

HostImageUse useHostImage(VkImage image, VkFormat format, VkImageLayout hostLayout, bool storage,
                          VkAccessFlags access) {
    const VkImageLayout layout =
        storage ? VK_IMAGE_LAYOUT_GENERAL
                : (sampleableLayout(hostLayout) ? hostLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    // Layout transitions of depth/stencil images cover both aspects; the host's view selects depth.
    const VkImageAspectFlags aspect = aspectOfFormat(format);
    return {layout, acquireHostImage(image, aspect, hostLayout, layout, access),
            releaseHostImage(image, aspect, layout, hostLayout, access)};
}

}  // namespace postfx::core
