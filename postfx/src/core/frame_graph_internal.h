// What the frame graph's sources share (not for effects): how a Use reads and writes, what one pass does
// with one resource over its bindings, and the sizes of images and uniform slots.
#pragma once

#include "core/frame_graph.h"

#include <cstdint>

namespace postfx::core {

inline bool reads(Use u) {
    return u == Use::StorageRead || u == Use::StorageReadWrite || u == Use::Sampled || u == Use::Uniform ||
           u == Use::TransferRead;
}
inline bool writes(Use u) {
    return u == Use::StorageWrite || u == Use::StorageReadWrite || u == Use::TransferWrite;
}
inline bool transfers(Use u) {
    return u == Use::TransferRead || u == Use::TransferWrite;
}
inline bool storage(Use u) {
    return u == Use::StorageRead || u == Use::StorageWrite || u == Use::StorageReadWrite ||
           u == Use::StorageBoundOnly;
}
inline bool isImage(const ResourceDecl& r) {
    return r.kind != ResourceDecl::Kind::Uniform;
}
inline bool owned(const ResourceDecl& r) {
    return r.kind == ResourceDecl::Kind::Transient || r.kind == ResourceDecl::Kind::Persistent ||
           r.kind == ResourceDecl::Kind::History;
}
inline bool sameDesc(const ImageDesc& a, const ImageDesc& b) {
    return a.type == b.type && a.format == b.format && a.extent.width == b.extent.width &&
           a.extent.height == b.extent.height && a.extent.depth == b.extent.depth && a.layers == b.layers &&
           a.usage == b.usage;
}

inline uint64_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UNORM:
            return 1;
        case VK_FORMAT_R16_SFLOAT:
            return 2;
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        case VK_FORMAT_R8G8B8A8_UNORM:
            return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R32G32_SFLOAT:
            return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        default:
            return 0;
    }
}

// A uniform slot's size: the data rounded up to 256 bytes, the largest minUniformBufferOffsetAlignment
// Vulkan allows, so that postfx's memory is the same on every device.
inline VkDeviceSize slotBytes(uint32_t bytes) {
    return (VkDeviceSize(bytes) + 255) / 256 * 256;
}

// What one pass does with one resource, merged over its bindings.
struct Merged {
    bool read = false, write = false, storage = false, sampled = false, transfer = false, discard = true;
    // Bound but declared unaccessed (Use::BoundOnly, Use::StorageBoundOnly): not a read or write in the
    // plan, but synchronized as the shader's code could access it (validation counts every statically
    // used binding): a sampled image as a read, a storage image as a read and a write.
    bool bound = false, boundStorage = false;
    bool synchronizedRead() const { return read || bound; }
    bool synchronizedWrite() const { return write || boundStorage; }
};

inline Merged merge(const Frame& f, const PassDecl& p, uint16_t resource) {
    Merged m;
    for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
        const Access& x = f.accesses[a];
        if (x.resource != resource) continue;
        m.read |= reads(x.use);
        m.write |= writes(x.use);
        m.storage |= storage(x.use);
        m.transfer |= transfers(x.use);
        m.sampled |= x.use == Use::Sampled || x.use == Use::BoundOnly;
        m.bound |= x.use == Use::BoundOnly || x.use == Use::StorageBoundOnly;
        m.boundStorage |= x.use == Use::StorageBoundOnly;
        if (x.use != Use::StorageWrite && x.use != Use::StorageBoundOnly && x.use != Use::TransferWrite)
            m.discard = false;
    }
    m.discard = m.discard && m.write;
    return m;
}

// Whether resource index `r` appears earlier in the pass's access list (to visit each resource once).
inline bool seenBefore(const Frame& f, const PassDecl& p, uint32_t access) {
    for (uint32_t a = p.firstAccess; a < access; ++a)
        if (f.accesses[a].resource == f.accesses[access].resource) return true;
    return false;
}

// A transfer pass's source in TRANSFER_SRC_OPTIMAL, its destination in TRANSFER_DST_OPTIMAL.
inline VkImageLayout transferLayout(Use u) {
    return u == Use::TransferWrite ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL
                                   : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
}

// Storage accesses in GENERAL, sampled ones in SHADER_READ_ONLY_OPTIMAL, transfers in their own (a transfer
// pass reads or writes each of its two images, never both).
inline VkImageLayout ownedLayout(const Merged& m) {
    if (m.transfer)
        return m.write ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    return m.storage ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

// The stage and the access mask of a pass's use of a resource: the transfer stage for a transfer pass,
// the compute shader stage otherwise.
inline VkPipelineStageFlags passStage(const PassDecl& p) {
    return p.transfer != TransferOp::None ? VK_PIPELINE_STAGE_TRANSFER_BIT
                                          : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
}
inline VkAccessFlags readAccess(VkPipelineStageFlags stage) {
    return stage == VK_PIPELINE_STAGE_TRANSFER_BIT ? VK_ACCESS_TRANSFER_READ_BIT : VK_ACCESS_SHADER_READ_BIT;
}
inline VkAccessFlags writeAccess(VkPipelineStageFlags stage) {
    return stage == VK_PIPELINE_STAGE_TRANSFER_BIT ? VK_ACCESS_TRANSFER_WRITE_BIT
                                                   : VK_ACCESS_SHADER_WRITE_BIT;
}

// Adds postfx.copy (output = color) to a compiled frame whose separate output no live pass writes.
void declareOutputCopy(const FrameGraph& graph, Frame& frame);

}  // namespace postfx::core
