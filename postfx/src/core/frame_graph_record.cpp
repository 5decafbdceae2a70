// The frame graph's recording: a compiled frame's descriptor sets and uniform data, then its passes with
// the barriers their declared accesses need (host images in and out once); and the readback of a held
// image into a host buffer.
#include "core/frame_graph.h"

#include "core/barriers.h"
#include "core/checks.h"
#include "core/frame_graph_internal.h"

#include <cstring>
#include <string>

namespace postfx::core {
namespace {

// Whether the pipeline's layout declares `binding` a storage buffer (else a uniform buffer).
bool declaresStorageBuffer(const ComputePipelineDesc& pipeline, uint32_t binding) {
    for (const Binding& b : pipeline.bindings)
        if (b.binding == binding) return b.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    return false;
}

}  // namespace

Status FrameGraph::record(Frame& f, VkCommandBuffer cmd, uint64_t frameIndex, DescriptorArena& arena,
                          PassTimer& timer, Retirement& retirement) {
    if (Status s = prepare(f, frameIndex, retirement); !s) return s;
    const FrameInfo& info = *f.info;

    // The host's images: the layout postfx uses each in, over all recorded passes.
    struct HostUse {
        bool used = false, storage = false;
        VkAccessFlags access = 0, written = 0;
        HostImageUse use{};
        // A transfer pass's image (core/target.h) is in TRANSFER_SRC_OPTIMAL while read, in
        // TRANSFER_DST_OPTIMAL while written, in use.layout for the other passes. `layout`: its layout
        // now, while recording (after the acquire: that of its first use).
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    };
    HostUse hostUses[kHostImageCount];
    const ImageInput* hostImages[kHostImageCount] = {&info.color, &info.depth, &info.output,
                                                     &info.shadowMap.image, &info.localShadows.image};
    for (const PassDecl& p : f.passes)
        for (uint32_t a = p.firstAccess; p.live && a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (x.resource == kNoResource || f.resources[x.resource].kind != ResourceDecl::Kind::Host)
                continue;
            HostUse& h = hostUses[size_t(f.resources[x.resource].host)];
            if (!h.used && transfers(x.use)) h.layout = transferLayout(x.use);
            h.used = true;
            h.storage |= storage(x.use);
            if (reads(x.use)) h.access |= readAccess(passStage(p));
            if (writes(x.use)) h.access |= writeAccess(passStage(p));
        }
    for (size_t i = 0; i < kHostImageCount; ++i)
        if (hostUses[i].used) {
            const ImageInput& image = *hostImages[i];
            HostUse& h = hostUses[i];
            h.use = useHostImage(image.image, image.format, image.layout, h.storage, h.access);
            if (h.layout == VK_IMAGE_LAYOUT_UNDEFINED) h.layout = h.use.layout;  // first use: no transfer
            h.use.acquire.newLayout = h.layout;
        }

    // Descriptor sets, before any command: an error leaves nothing half recorded.
    passSets_.assign(f.passes.size(), VK_NULL_HANDLE);
    for (size_t i = 0; i < f.passes.size(); ++i) {
        const PassDecl& p = f.passes[i];
        if (!p.live || p.transfer != TransferOp::None) continue;
        if (Status s = arena.allocate(passPipelines_[i]->setLayout(), passSets_[i]); !s)
            return {s.code, std::string(p.pipeline->name) + ": " + s.message};
        DescriptorWrites writes(passSets_[i]);
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            const ResourceDecl& r = f.resources[x.resource];
            if (r.kind == ResourceDecl::Kind::Uniform) {
                const OwnedBuffer* b = nullptr;
                for (const OwnedBuffer& o : buffers_)
                    if (o.id == r.id) b = &o;
                const VkDeviceSize offset = b->slotBytes * (frameIndex % framesInFlight_);
                if (declaresStorageBuffer(*p.pipeline, x.binding))
                    writes.storageBuffer(x.binding, b->buffer->handle(), offset, r.uniformBytes);
                else
                    writes.uniformBuffer(x.binding, b->buffer->handle(), offset, r.uniformBytes);
                continue;
            }
            VkImageView view = VK_NULL_HANDLE;
            VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
            if (r.kind == ResourceDecl::Kind::Host) {
                view = hostImages[size_t(r.host)]->view;
                layout = hostUses[size_t(r.host)].use.layout;
            } else if (r.kind == ResourceDecl::Kind::External) {
                view = r.view;
                layout = r.layout;
            } else {
                view = resourceImages_[x.resource]->image->view();
                layout = ownedLayout(merge(f, p, x.resource));
            }
            if (storage(x.use)) {
                writes.storageImage(x.binding, view);
            } else {
                VkSampler s = VK_NULL_HANDLE;
                if (Status st = sampler(x.sampler, s); !st) return st;
                writes.sampledImage(x.binding, view, layout, s);
            }
        }
        writes.apply(*gpu_);
    }
    // Uniform data into this frame's slots (the frame that used a slot last has completed).
    for (const ResourceDecl& r : f.resources) {
        if (!r.held || r.kind != ResourceDecl::Kind::Uniform) continue;
        for (const OwnedBuffer& b : buffers_)
            if (b.id == r.id)
                std::memcpy(
                    static_cast<char*>(b.buffer->mapped()) + b.slotBytes * (frameIndex % framesInFlight_),
                    f.uniformData.data() + r.uniformOffset, r.uniformBytes);
    }

    // Nothing can fail from here on: the first command is recorded only now, so a failed record() leaves
    // the command buffer as the host gave it, and the "postfx" label always gets its end.
    beginLabel(gpu_->fn, cmd, "postfx");
    timer.beginFrame(cmd, frameIndex);

    // Host images in, once.
    BarrierBatch batch;
    for (const HostUse& h : hostUses)
        if (h.used) batch.add(h.use.acquire);
    batch.record(*gpu_, cmd);

    // Pending accesses of the host images within this frame (postfx's own images keep theirs in images_):
    // the stage of an unsynchronized write, and of the reads since the last write (0: none).
    VkPipelineStageFlags hostWriteStage[kHostImageCount] = {}, hostReadStages[kHostImageCount] = {};
    for (size_t i = 0; i < f.passes.size(); ++i) {
        const PassDecl& p = f.passes[i];
        if (!p.live) continue;
        const VkPipelineStageFlags stage = passStage(p);
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (seenBefore(f, p, a)) continue;
            const ResourceDecl& r = f.resources[x.resource];
            const Merged m = merge(f, p, x.resource);
            const VkAccessFlags dstAccess = (m.synchronizedRead() ? readAccess(stage) : 0) |
                                            (m.synchronizedWrite() ? writeAccess(stage) : 0);
            if (r.kind == ResourceDecl::Kind::Host) {
                const size_t h = size_t(r.host);
                const VkPipelineStageFlags waitFor =
                    (hostWriteStage[h] && (m.synchronizedRead() || m.synchronizedWrite()) ? hostWriteStage[h]
                                                                                          : 0) |
                    (m.synchronizedWrite() ? hostReadStages[h] : 0);
                HostUse& use = hostUses[h];
                const VkImageLayout layout = transfers(x.use) ? transferLayout(x.use) : use.use.layout;
                if (layout != use.layout) {
                    ImageTransition t;
                    t.image = hostImages[h]->image;
                    t.oldLayout = use.layout;
                    t.newLayout = layout;
                    t.srcStage = waitFor | hostReadStages[h] | hostWriteStage[h];
                    if (!t.srcStage) t.srcStage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
                    t.srcAccess = hostWriteStage[h] ? writeAccess(hostWriteStage[h]) : 0;
                    t.dstStage = stage;
                    t.dstAccess = dstAccess;
                    batch.add(t);
                    use.layout = layout;
                } else if (waitFor) {
                    batch.memory(waitFor, hostWriteStage[h] ? writeAccess(hostWriteStage[h]) : 0, stage,
                                 dstAccess);
                }
            } else if (owned(r)) {
                OwnedImage& o = *resourceImages_[x.resource];
                const VkImageLayout layout = ownedLayout(m);
                const bool hazard = (m.synchronizedRead() && o.pendingWrite) ||
                                    (m.synchronizedWrite() && (o.pendingWrite || o.readSinceWrite));
                if (layout != o.layout || hazard) {
                    ImageTransition t;
                    t.image = o.image->handle();
                    t.layers = o.image->desc().layers;
                    t.oldLayout = m.discard ? VK_IMAGE_LAYOUT_UNDEFINED : o.layout;
                    t.newLayout = layout;
                    // An image the host may have read since (exported): after every earlier command.
                    const VkPipelineStageFlags earlier =
                        (o.pendingWrite ? o.writeStage : 0) | (o.readSinceWrite ? o.readStages : 0);
                    t.srcStage = o.hostMayRead ? VkPipelineStageFlags(VK_PIPELINE_STAGE_ALL_COMMANDS_BIT)
                                 : earlier     ? earlier
                                               : VkPipelineStageFlags(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
                    t.srcAccess = o.pendingWrite ? writeAccess(o.writeStage) : 0;
                    t.dstStage = stage;
                    t.dstAccess = dstAccess;
                    batch.add(t);
                    o.layout = layout;
                    o.pendingWrite = false;
                    o.readSinceWrite = false;
                    o.hostMayRead = false;
                }
            }
        }
        batch.record(*gpu_, cmd);

        if (p.transfer != TransferOp::None) {
            recordTransfer(f, p, hostImages, cmd, timer);
        } else {
            const ComputePipeline& pipeline = *passPipelines_[i];
            beginLabel(gpu_->fn, cmd, pipeline.name().c_str());
            timer.beginPass(cmd, pipeline.name(), p.effect, !p.builds);
            pipeline.bind(cmd, passSets_[i], p.pushBytes ? p.push.data() : nullptr);
            gpu_->fn.vkCmdDispatch(cmd, p.groups[0], p.groups[1], p.groups[2]);
            timer.endPass(cmd);
            endLabel(gpu_->fn, cmd);
        }

        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (seenBefore(f, p, a)) continue;
            const ResourceDecl& r = f.resources[x.resource];
            const Merged m = merge(f, p, x.resource);
            if (r.kind == ResourceDecl::Kind::Host) {
                const size_t h = size_t(r.host);
                if (m.synchronizedWrite()) {
                    hostWriteStage[h] = stage;
                    hostReadStages[h] = 0;
                } else if (m.synchronizedRead()) {
                    hostReadStages[h] |= stage;
                }
                continue;
            }
            if (owned(r)) {
                OwnedImage& o = *resourceImages_[x.resource];
                // Written once: readable by the host (imageView, recordImageReadback); a history image
                // holds the frame's result (the clouds' shadow map, the fogs' accumulations).
                if (m.write && (r.kind == ResourceDecl::Kind::Persistent ||
                                r.kind == ResourceDecl::Kind::History || r.exported)) {
                    o.built = true;
                    o.builtKey = r.buildKey;
                }
                if (m.write && r.exported) o.writtenForHost = true;
                if (m.synchronizedWrite()) {
                    o.pendingWrite = true;
                    o.writeStage = stage;
                    o.readSinceWrite = false;
                    o.readStages = 0;
                } else if (m.synchronizedRead()) {
                    o.readStages = o.readSinceWrite ? o.readStages | stage : stage;
                    o.readSinceWrite = true;
                }
            }
        }
    }

    // Host images out, once, in the layouts they came in, postfx's writes visible to what follows; so are
    // the writes of the images the host reads after the frame (exported), in the layouts they are in.
    for (const HostUse& h : hostUses) {
        if (!h.used) continue;
        ImageTransition release = h.use.release;
        release.oldLayout = h.layout;  // its last use's
        batch.add(release);
    }
    for (size_t i = 0; i < f.resources.size(); ++i) {
        OwnedImage* o = resourceImages_[i];
        if (!o || !f.resources[i].exported || !o->writtenForHost) continue;
        ImageTransition t;
        t.image = o->image->handle();
        t.layers = o->image->desc().layers;
        t.oldLayout = t.newLayout = o->layout;
        t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        t.srcAccess = VK_ACCESS_SHADER_WRITE_BIT;
        t.dstStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
        t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
        batch.add(t);
        o->writtenForHost = false;
        o->pendingWrite = false;
        o->readSinceWrite = true;
        o->hostMayRead = true;
    }
    batch.record(*gpu_, cmd);
    endLabel(gpu_->fn, cmd);
    return Status::success();
}

void FrameGraph::recordTransfer(const Frame& f, const PassDecl& p, const ImageInput* const* hostImages,
                                VkCommandBuffer cmd, PassTimer& timer) const {
    VkImage images[2] = {};
    for (uint32_t k = 0; k < 2; ++k) {
        const ResourceDecl& r = f.resources[f.accesses[p.firstAccess + k].resource];
        images[k] = r.kind == ResourceDecl::Kind::Host
                        ? hostImages[size_t(r.host)]->image
                        : resourceImages_[f.accesses[p.firstAccess + k].resource]->image->handle();
    }
    const VkExtent2D e = f.info->color.extent;
    const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    beginLabel(gpu_->fn, cmd, p.pipeline->name);
    timer.beginPass(cmd, p.pipeline->name, p.effect, false);
    // The barriers before the pass put the source in TRANSFER_SRC_OPTIMAL, the destination in
    // TRANSFER_DST_OPTIMAL (transferLayout).
    const VkImageLayout src = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        dst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    if (p.transfer == TransferOp::Blit) {
        VkImageBlit region{};
        region.srcSubresource = region.dstSubresource = layers;
        region.srcOffsets[1] = region.dstOffsets[1] = {int32_t(e.width), int32_t(e.height), 1};
        gpu_->fn.vkCmdBlitImage(cmd, images[0], src, images[1], dst, 1, &region, VK_FILTER_NEAREST);
    } else {
        VkImageCopy region{};
        region.srcSubresource = region.dstSubresource = layers;
        region.extent = {e.width, e.height, 1};
        gpu_->fn.vkCmdCopyImage(cmd, images[0], src, images[1], dst, 1, &region);
    }
    timer.endPass(cmd);
    endLabel(gpu_->fn, cmd);
}

FrameGraph::HeldImage FrameGraph::heldImage(const char* name) const {
    const ResourceId* id = nullptr;
    for (const OwnedImage& o : images_)
        if (std::strcmp(o.id->name, name) == 0) id = o.id;
    for (const auto& [alias, owner] : aliases_)
        if (!id && std::strcmp(alias->name, name) == 0) id = owner;
    const OwnedImage* o = id ? findImage(id) : nullptr;
    if (o && o->built) return {o->image.get(), o->layout, o->pendingWrite};
    return {};
}

Status FrameGraph::recordReadback(const char* name, VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset,
                                  VkExtent3D& extent, VkDeviceSize& bytes) const {
    const HeldImage held = heldImage(name);
    if (!held.image)
        return invalid(std::string("recordImageReadback: ") + name + " is not held or not built yet");
    const ImageDesc& d = held.image->desc();
    if (!(d.usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) || texelBytes(d.format) == 0)
        return invalid(std::string("recordImageReadback: ") + name + " cannot be read back");
    extent = d.extent;
    bytes = VkDeviceSize(d.extent.width) * d.extent.height * d.extent.depth * d.layers * texelBytes(d.format);

    // Its layout -> TRANSFER_SRC after the earlier compute accesses, the copy, and back for the compute
    // passes of later frames.
    ImageTransition t;
    t.image = held.image->handle();
    t.layers = d.layers;
    t.oldLayout = held.layout;
    t.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.srcAccess = VK_ACCESS_SHADER_WRITE_BIT;
    t.dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    t.dstAccess = VK_ACCESS_TRANSFER_READ_BIT;
    transition(*gpu_, cmd, t);

    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, d.layers};  // layers one after another
    region.imageExtent = d.extent;
    gpu_->fn.vkCmdCopyImageToBuffer(cmd, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);

    t.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.newLayout = held.layout;
    t.srcStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    t.srcAccess = 0;
    t.dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    t.dstAccess = VK_ACCESS_SHADER_READ_BIT;
    transition(*gpu_, cmd, t);

    // The copied bytes -> host reads after the submission's fence.
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = buffer;
    toHost.offset = offset;
    toHost.size = bytes;
    gpu_->fn.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                                  nullptr, 1, &toHost, 0, nullptr);
    return Status::success();
}

}  // namespace postfx::core
