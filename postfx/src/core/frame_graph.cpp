// The frame graph's compilation: a frame's declarations begun, culled to the passes whose results are
// read, the public plan, and the images and uniform rings the compiled frame holds (created, recreated
// and released before recording).
#include "core/frame_graph.h"

#include "core/frame_graph_internal.h"
#include "core/memory_budget.h"

#include <algorithm>
#include <string>

namespace postfx::core {
namespace {

const char* const kHostNames[] = {"host.color", "host.depth", "host.output", "host.shadow_map",
                                  "host.local_shadow_atlas"};

}  // namespace

Status FrameGraph::create(const Gpu& gpu, uint32_t framesInFlight, const DepthConvention& depth) {
    release();
    gpu_ = &gpu;
    framesInFlight_ = framesInFlight;
    depth_ = depth;
    return Status::success();
}

void FrameGraph::release() {
    images_.clear();
    aliases_.clear();
    buffers_.clear();
    pipelines_.clear();
    if (gpu_)
        for (VkSampler& s : samplers_)
            if (s) gpu_->fn.vkDestroySampler(gpu_->device, s, gpu_->allocator);
    for (VkSampler& s : samplers_)
        s = VK_NULL_HANDLE;
}

const FrameGraph::OwnedImage* FrameGraph::findImage(const ResourceId* id) const {
    for (const OwnedImage& o : images_)
        if (o.id == id) return &o;
    return nullptr;
}

bool FrameGraph::uniformSlot(const ResourceId& id, uint64_t frameIndex, VkBuffer& buffer,
                             VkDeviceSize& offset) const {
    for (const OwnedBuffer& b : buffers_)
        if (b.id == &id) {
            buffer = b.buffer->handle();
            offset = b.slotBytes * (frameIndex % framesInFlight_);
            return true;
        }
    return false;
}

void FrameGraph::begin(Frame& f, const FrameInfo& info) const {
    f.info = &info;
    f.resources.clear();
    f.passes.clear();
    f.accesses.clear();
    f.uniformData.clear();
    f.aliases.clear();
    f.composited = false;
    f.target = kNoResource;
    f.lookupScattering = f.lookupTransmittance = f.lookupUniforms = kNoResource;
    f.lookupWritten = false;
    auto add = [&](HostImage which, bool present) {
        f.host[size_t(which)] = kNoResource;
        if (!present) return;
        ResourceDecl r;
        r.kind = ResourceDecl::Kind::Host;
        r.host = which;
        r.name = kHostNames[size_t(which)];
        f.resources.push_back(r);
        f.host[size_t(which)] = uint16_t(f.resources.size() - 1);
    };
    add(HostImage::Color, true);
    add(HostImage::Depth, true);
    add(HostImage::Output, info.output.present());
    add(HostImage::ShadowMap, info.shadowMap.image.present());
    add(HostImage::LocalShadowAtlas, info.localShadows.image.present());
}

void FrameGraph::compile(Frame& f) const {
    // Backwards: a pass is live when it writes a host image (the frame's result) or something a later
    // live pass reads; a build of a persistent image only when that image also needs building.
    std::vector<uint8_t>& readLater = f.scratch;
    readLater.assign(f.resources.size(), 0);
    for (size_t i = f.passes.size(); i-- > 0;) {
        PassDecl& p = f.passes[i];
        p.live = false;
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (!writes(x.use) || x.resource == kNoResource) continue;
            const ResourceDecl& r = f.resources[x.resource];
            // An exported persistent image (read by the host after the frame) is built like any
            // persistent image: only when its key changed.
            if (r.kind == ResourceDecl::Kind::Host)
                p.live = true;
            else if (r.kind == ResourceDecl::Kind::Persistent)
                p.live |= (readLater[x.resource] || r.exported) && r.needsBuild;
            else
                p.live |= readLater[x.resource] || r.exported;
        }
        if (!p.live) continue;
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (x.resource != kNoResource && reads(x.use)) readLater[x.resource] = 1;
        }
    }
    // A separate output that no pass writes still gets the host's color.
    const uint16_t output = f.host[size_t(HostImage::Output)];
    if (output != kNoResource) {
        bool written = false;
        for (const PassDecl& p : f.passes)
            for (uint32_t a = p.firstAccess; p.live && a < p.firstAccess + p.accessCount; ++a)
                written |= f.accesses[a].resource == output && writes(f.accesses[a].use);
        if (!written) declareOutputCopy(*this, f);
    }
    // Held: what a live pass touches, and an exported image (the host reads it after the frame, even when
    // no pass of this frame touched it: a persistent image not rebuilt).
    for (ResourceDecl& r : f.resources)
        r.held = r.exported;
    for (const PassDecl& p : f.passes)
        for (uint32_t a = p.firstAccess; p.live && a < p.firstAccess + p.accessCount; ++a)
            if (f.accesses[a].resource != kNoResource) f.resources[f.accesses[a].resource].held = true;
}

void FrameGraph::plan(const Frame& f, FramePlan& out) const {
    out = {};
    auto effectName = [&](int e) { return e < 0 ? "postfx" : effectNames_[size_t(e)]; };
    for (const PassDecl& p : f.passes) {
        if (!p.live) continue;
        PlannedPass planned;
        planned.name = p.pipeline->name;
        planned.effect = effectName(p.effect);
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (x.resource == kNoResource || seenBefore(f, p, a)) continue;
            const Merged m = merge(f, p, x.resource);
            const std::string name = f.resources[x.resource].name;
            if (m.read) planned.reads.push_back(name);
            if (m.write) planned.writes.push_back(name);
        }
        std::copy(std::begin(p.groups), std::end(p.groups), planned.groups);
        out.passes.push_back(std::move(planned));
    }
    for (const ResourceDecl& r : f.resources) {
        if (!r.held || !(owned(r) || r.kind == ResourceDecl::Kind::Uniform)) continue;
        const bool image = r.kind != ResourceDecl::Kind::Uniform;
        out.resources.push_back({r.name, effectName(r.effect), resourceBytes(r, framesInFlight_),
                                 r.kind == ResourceDecl::Kind::History,
                                 r.kind == ResourceDecl::Kind::Persistent && !out.writes(r.name),
                                 image && r.desc.sizedBy ? r.desc.sizedBy : ""});
    }
}

void FrameGraph::memoryUsage(std::vector<MemoryUsage::Owner>& owners) const {
    for (const OwnedImage& o : images_) {
        MemoryUsage::Owner& owner = owners[size_t(o.effect + 1)];
        owner.bytes += o.image->bytes();
        ++owner.images;
    }
    for (const OwnedBuffer& b : buffers_) {
        MemoryUsage::Owner& owner = owners[size_t(b.effect + 1)];
        owner.bytes += b.buffer->bytes();
        ++owner.buffers;
    }
}

// Creates what the compiled frame holds and releases what it no longer does; no command is recorded.
Status FrameGraph::prepare(Frame& f, uint64_t frameIndex, Retirement& retirement) {
    for (OwnedImage& o : images_)
        o.used = false;
    for (OwnedBuffer& b : buffers_)
        b.used = false;
    resourceImages_.assign(f.resources.size(), nullptr);
    for (size_t i = 0; i < f.resources.size(); ++i) {
        const ResourceDecl& r = f.resources[i];
        if (!r.held) continue;
        if (owned(r)) {
            auto it = std::find_if(images_.begin(), images_.end(),
                                   [&](const OwnedImage& o) { return o.id == r.id; });
            if (it != images_.end() && !sameDesc(it->image->desc(), r.desc)) {
                retirement.retire(frameIndex, std::move(it->image));  // frames in flight may still use it
                images_.erase(it);
                it = images_.end();
            }
            if (it == images_.end()) {
                auto image = std::make_unique<GpuImage>();
                if (Status s = image->create(*gpu_, r.desc, r.name); !s) return s;
                OwnedImage o;
                o.id = r.id;
                o.effect = r.effect;
                o.image = std::move(image);
                images_.push_back(std::move(o));
                it = images_.end() - 1;
            }
            it->used = true;
        } else if (r.kind == ResourceDecl::Kind::Uniform) {
            auto it = std::find_if(buffers_.begin(), buffers_.end(),
                                   [&](const OwnedBuffer& b) { return b.id == r.id; });
            const VkDeviceSize slot = slotBytes(r.uniformBytes);
            if (it != buffers_.end() && it->slotBytes != slot) {
                retirement.retire(frameIndex, std::move(it->buffer));
                buffers_.erase(it);
                it = buffers_.end();
            }
            if (it == buffers_.end()) {
                auto buffer = std::make_unique<GpuBuffer>();
                if (Status s = buffer->create(
                        *gpu_, slot * framesInFlight_,
                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true,
                        r.name);
                    !s)
                    return s;
                buffers_.push_back({r.id, r.effect, std::move(buffer), slot, false});
                it = buffers_.end() - 1;
            }
            it->used = true;
        }
    }
    // What this frame does not hold goes once the frames in flight that may use it are done.
    for (auto it = images_.begin(); it != images_.end();)
        if (!it->used) {
            retirement.retire(frameIndex, std::move(it->image));
            it = images_.erase(it);
        } else {
            ++it;
        }
    for (auto it = buffers_.begin(); it != buffers_.end();)
        if (!it->used) {
            retirement.retire(frameIndex, std::move(it->buffer));
            it = buffers_.erase(it);
        } else {
            ++it;
        }
    for (size_t i = 0; i < f.resources.size(); ++i)
        if (f.resources[i].held && owned(f.resources[i]))
            for (OwnedImage& o : images_)
                if (o.id == f.resources[i].id) resourceImages_[i] = &o;
    aliases_.clear();
    for (const auto& [alias, resource] : f.aliases)
        if (f.resources[resource].held) aliases_.emplace_back(alias, f.resources[resource].id);
    return preparePipelines(f, frameIndex, retirement);
}

}  // namespace postfx::core
