#include "core/frame_graph.h"

#include "common/shared.h"
#include "core/barriers.h"
#include "core/camera_math.h"
#include "core/checks.h"
#include "postfx_objects_spirv.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace postfx::core {
namespace {

const char* const kHostNames[] = {"host.color", "host.depth", "host.output", "host.shadow_map"};

// postfx.copy (shaders/core/copy.comp): output = color, for a frame with a separate output image that no
// effect writes.
constexpr Binding kCopyBindings[] = {{gpu::kCopyBindingIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {gpu::kCopyBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
const ComputePipelineDesc kCopy16{"postfx.copy", spirv::core_copy_comp, kCopyBindings, 8};
const ComputePipelineDesc kCopy32{"postfx.copy", spirv::core_copy_comp_COLOR_RGBA32F, kCopyBindings, 8};

// postfx.view_distance (shaders/core/view_distance.comp): the host's depth as surface distances, once for
// every effect that reads it.
constexpr Binding kViewDistanceBindings[] = {
    {gpu::kViewDistanceBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
    {gpu::kViewDistanceBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
const ComputePipelineDesc kViewDistance{"postfx.view_distance", spirv::core_view_distance_comp,
                                        kViewDistanceBindings, sizeof(gpu::ViewDistancePush)};
inline constexpr ResourceId kViewDistanceImage{"postfx.view_distance"};

bool reads(Use u) {
    return u == Use::StorageRead || u == Use::StorageReadWrite || u == Use::Sampled || u == Use::Uniform;
}
bool writes(Use u) {
    return u == Use::StorageWrite || u == Use::StorageReadWrite;
}
bool storage(Use u) {
    return u == Use::StorageRead || u == Use::StorageWrite || u == Use::StorageReadWrite;
}
bool isImage(const ResourceDecl& r) {
    return r.kind != ResourceDecl::Kind::Uniform;
}
bool owned(const ResourceDecl& r) {
    return r.kind == ResourceDecl::Kind::Transient || r.kind == ResourceDecl::Kind::Persistent ||
           r.kind == ResourceDecl::Kind::History;
}
bool sameDesc(const ImageDesc& a, const ImageDesc& b) {
    return a.type == b.type && a.format == b.format && a.extent.width == b.extent.width &&
           a.extent.height == b.extent.height && a.extent.depth == b.extent.depth && a.layers == b.layers &&
           a.usage == b.usage;
}

uint64_t texelBytes(VkFormat format) {
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
VkDeviceSize slotBytes(uint32_t bytes) {
    return (VkDeviceSize(bytes) + 255) / 256 * 256;
}

// What one pass does with one resource, merged over its bindings.
struct Merged {
    bool read = false, write = false, storage = false, sampled = false, discard = true;
    bool bound = false;  // bound but declared unread (Use::BoundOnly): not a read in the plan, but
                         // synchronized as one (validation counts every statically used binding)
    bool synchronizedRead() const { return read || bound; }
};

Merged merge(const Frame& f, const PassDecl& p, uint16_t resource) {
    Merged m;
    for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
        const Access& x = f.accesses[a];
        if (x.resource != resource) continue;
        m.read |= reads(x.use);
        m.write |= writes(x.use);
        m.storage |= storage(x.use);
        m.sampled |= x.use == Use::Sampled || x.use == Use::BoundOnly;
        m.bound |= x.use == Use::BoundOnly;
        if (x.use != Use::StorageWrite) m.discard = false;
    }
    m.discard = m.discard && m.write;
    return m;
}

// Whether resource index `r` appears earlier in the pass's access list (to visit each resource once).
bool seenBefore(const Frame& f, const PassDecl& p, uint32_t access) {
    for (uint32_t a = p.firstAccess; a < access; ++a)
        if (f.accesses[a].resource == f.accesses[access].resource) return true;
    return false;
}

VkImageLayout ownedLayout(const Merged& m) {
    return m.storage ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

}  // namespace

// ---- FrameBuilder ----

uint32_t FrameBuilder::framesInFlight() const {
    return graph_.framesInFlight_;
}

const DepthConvention& FrameBuilder::depthConvention() const {
    return graph_.depth_;
}

ImageRef FrameBuilder::compositeSource() const {
    const uint16_t output = f_.host[size_t(HostImage::Output)];
    return {f_.composited && output != kNoResource ? output : f_.host[size_t(HostImage::Color)]};
}

ImageRef FrameBuilder::compositeTarget() const {
    const uint16_t output = f_.host[size_t(HostImage::Output)];
    return {output != kNoResource ? output : f_.host[size_t(HostImage::Color)]};
}

ImageRef FrameBuilder::external(const char* name, VkImageView view, VkImageLayout layout) {
    ResourceDecl r;
    r.kind = ResourceDecl::Kind::External;
    r.effect = effect_;
    r.name = name;
    r.view = view;
    r.layout = layout;
    f_.resources.push_back(r);
    return {uint16_t(f_.resources.size() - 1)};
}

ImageRef FrameBuilder::ownedImage(const ResourceId& id, const ImageDesc& desc, ResourceDecl::Kind kind,
                                  uint64_t key) {
    ResourceDecl r;
    r.kind = kind;
    r.effect = effect_;
    r.name = id.name;
    r.id = &id;
    r.desc = desc;
    r.buildKey = key;
    if (kind == ResourceDecl::Kind::Persistent) {
        const FrameGraph::OwnedImage* held = graph_.findImage(&id);
        r.needsBuild = !held || !sameDesc(held->image->desc(), desc) || !held->built || held->builtKey != key;
    }
    f_.resources.push_back(r);
    return {uint16_t(f_.resources.size() - 1)};
}

ImageRef FrameBuilder::transientImage(const ResourceId& id, const ImageDesc& desc) {
    return ownedImage(id, desc, ResourceDecl::Kind::Transient, 0);
}

ImageRef FrameBuilder::persistentImage(const ResourceId& id, const ImageDesc& desc, uint64_t buildKey) {
    return ownedImage(id, desc, ResourceDecl::Kind::Persistent, buildKey);
}

ImageRef FrameBuilder::historyImage(const ResourceId& id, const ImageDesc& desc) {
    return ownedImage(id, desc, ResourceDecl::Kind::History, 0);
}

void FrameBuilder::exportImage(ImageRef image) {
    if (image.valid()) f_.resources[image.index].exported = true;
}

DepthInput FrameBuilder::depthInput() {
    const ImageRef depth = host(HostImage::Depth);
    if (!f_.shareDepth) return {depth, false};
    if (const ImageRef shared = find(kViewDistanceImage); shared.valid()) return {shared, true};
    // Declared by the context (effect -1), before the first reader's passes.
    FrameBuilder context(graph_, f_, -1);
    const VkExtent2D e = f_.info->color.extent;
    ImageDesc desc;
    desc.format = VK_FORMAT_R32_SFLOAT;
    desc.extent = {e.width, e.height, 1};
    const ImageRef distance = context.transientImage(kViewDistanceImage, desc);
    gpu::ViewDistancePush push{};
    const FrameInfo& info = *f_.info;
    push.clipToView =
        glm::mat4(glm::inverse(glm::dmat4(info.camera.projection) * rotationOnly(info.camera.view)));
    push.params = glm::vec4(depthConvention().reversedZ ? 0.0f : 1.0f, float(e.width), float(e.height), 0.0f);
    const uint32_t g = gpu::kViewDistanceGroupSize, rows = g * gpu::kViewDistanceRows;
    context.pass(kViewDistance, (e.width + g - 1) / g, (e.height + rows - 1) / rows, 1)
        .bind(gpu::kViewDistanceBindingDepth, depth, Use::Sampled)
        .bind(gpu::kViewDistanceBindingOut, distance, Use::StorageWrite)
        .push(&push, sizeof push);
    return {distance, true};
}

ImageRef FrameBuilder::find(const ResourceId& id) const {
    for (size_t i = 0; i < f_.resources.size(); ++i)
        if (f_.resources[i].id == &id && isImage(f_.resources[i])) return {uint16_t(i)};
    return {};
}

ImageRef FrameBuilder::findPersistent(const ResourceId& alias, const ImageDesc& desc, uint64_t buildKey) {
    for (size_t i = 0; i < f_.resources.size(); ++i) {
        const ResourceDecl& r = f_.resources[i];
        if (r.kind == ResourceDecl::Kind::Persistent && r.buildKey == buildKey && sameDesc(r.desc, desc)) {
            if (r.id != &alias) f_.aliases.emplace_back(&alias, uint16_t(i));
            return {uint16_t(i)};
        }
    }
    return {};
}

BufferRef FrameBuilder::findUniforms(const ResourceId& id) const {
    for (size_t i = 0; i < f_.resources.size(); ++i)
        if (f_.resources[i].id == &id && f_.resources[i].kind == ResourceDecl::Kind::Uniform)
            return {uint16_t(i)};
    return {};
}

BufferRef FrameBuilder::uniforms(const ResourceId& id, const void* data, uint32_t bytes) {
    ResourceDecl r;
    r.kind = ResourceDecl::Kind::Uniform;
    r.effect = effect_;
    r.name = id.name;
    r.id = &id;
    r.uniformOffset = uint32_t(f_.uniformData.size());
    r.uniformBytes = bytes;
    f_.uniformData.resize(f_.uniformData.size() + bytes);
    std::memcpy(f_.uniformData.data() + r.uniformOffset, data, bytes);
    f_.resources.push_back(r);
    return {uint16_t(f_.resources.size() - 1)};
}

FrameBuilder& FrameBuilder::pass(const ComputePipelineDesc& pipeline, uint32_t x, uint32_t y, uint32_t z) {
    PassDecl p;
    p.pipeline = &pipeline;
    p.effect = effect_;
    p.groups[0] = x;
    p.groups[1] = y;
    p.groups[2] = z;
    p.firstAccess = uint32_t(f_.accesses.size());
    f_.passes.push_back(p);
    return *this;
}

FrameBuilder& FrameBuilder::bind(uint32_t binding, ImageRef image, Use use, SamplerKind sampler) {
    PassDecl& p = f_.passes.back();
    f_.accesses.push_back({binding, image.index, use, sampler});
    ++p.accessCount;
    if (!image.valid()) return *this;
    const ResourceDecl& r = f_.resources[image.index];
    if (writes(use)) {
        if (r.kind == ResourceDecl::Kind::Persistent) p.builds = true;
        if (image.index == compositeTarget().index) f_.composited = true;
    }
    return *this;
}

FrameBuilder& FrameBuilder::bind(uint32_t binding, BufferRef buffer) {
    PassDecl& p = f_.passes.back();
    f_.accesses.push_back({binding, buffer.index, Use::Uniform, SamplerKind::NearestClamp});
    ++p.accessCount;
    return *this;
}

FrameBuilder& FrameBuilder::push(const void* data, uint32_t bytes) {
    PassDecl& p = f_.passes.back();
    p.pushBytes = std::min<uint32_t>(bytes, uint32_t(p.push.size()));
    std::memcpy(p.push.data(), data, p.pushBytes);
    return *this;
}

FrameBuilder& FrameBuilder::constants(const PipelineConstants& constants) {
    f_.passes.back().constants = constants;
    return *this;
}

// ---- FrameGraph ----

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

void FrameGraph::begin(Frame& f, const FrameInfo& info) const {
    f.info = &info;
    f.resources.clear();
    f.passes.clear();
    f.accesses.clear();
    f.uniformData.clear();
    f.aliases.clear();
    f.composited = false;
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
        if (!written) {
            const VkExtent2D e = f.info->color.extent;
            const ComputePipelineDesc& copy =
                f.info->color.format == VK_FORMAT_R32G32B32A32_SFLOAT ? kCopy32 : kCopy16;
            FrameBuilder b(*this, f, -1);
            const uint32_t g = gpu::kCopyGroupSize;
            const uint32_t extent[2] = {e.width, e.height};
            b.pass(copy, (e.width + g - 1) / g, (e.height + g - 1) / g, 1)
                .bind(gpu::kCopyBindingIn, {f.host[size_t(HostImage::Color)]}, Use::StorageRead)
                .bind(gpu::kCopyBindingOut, {output}, Use::StorageWrite)
                .push(extent, sizeof extent);
            f.passes.back().live = true;
        }
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
        const uint64_t bytes = r.kind == ResourceDecl::Kind::Uniform
                                   ? slotBytes(r.uniformBytes) * framesInFlight_
                                   : uint64_t(r.desc.extent.width) * r.desc.extent.height *
                                         r.desc.extent.depth * r.desc.layers * texelBytes(r.desc.format);
        out.resources.push_back({r.name, effectName(r.effect), bytes, r.kind == ResourceDecl::Kind::History,
                                 r.kind == ResourceDecl::Kind::Persistent && !out.writes(r.name)});
    }
}

Status FrameGraph::sampler(SamplerKind kind, VkSampler& out) {
    VkSampler& s = samplers_[size_t(kind)];
    if (!s) {
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        const bool linear = kind != SamplerKind::NearestClamp;
        info.magFilter = info.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
        info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        info.addressModeU = info.addressModeV = info.addressModeW =
            kind == SamplerKind::LinearRepeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT
                                              : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        VkSampler created = VK_NULL_HANDLE;  // kept only on success (a failed call's output is undefined)
        if (Status st = vulkanStatus(gpu_->fn.vkCreateSampler(gpu_->device, &info, gpu_->allocator, &created),
                                     "vkCreateSampler");
            !st)
            return st;
        s = created;
    }
    out = s;
    return Status::success();
}

void FrameGraph::retireOldestVariant(const ComputePipelineDesc* desc, uint64_t frameIndex,
                                     Retirement& retirement) {
    size_t variants = 0;
    auto oldest = pipelines_.end();
    for (auto it = pipelines_.begin(); it != pipelines_.end(); ++it) {
        if (it->desc != desc) continue;
        ++variants;
        if (it->lastUsed != frameIndex && (oldest == pipelines_.end() || it->lastUsed < oldest->lastUsed))
            oldest = it;
    }
    if (variants < kMaxVariantsPerPipeline || oldest == pipelines_.end()) return;
    retirement.retire(frameIndex, std::move(oldest->pipeline));
    pipelines_.erase(oldest);
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
                if (Status s = buffer->create(*gpu_, slot * framesInFlight_,
                                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true, r.name);
                    !s)
                    return s;
                buffers_.push_back({r.id, std::move(buffer), slot, false});
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
    // Pipelines: an effect's live as long as it records a pass; the context's own (postfx.copy) always.
    for (auto it = pipelines_.begin(); it != pipelines_.end();) {
        const bool effectLive =
            it->effect < 0 || std::any_of(f.passes.begin(), f.passes.end(), [&](const PassDecl& p) {
                return p.live && p.effect == it->effect;
            });
        if (!effectLive) {
            retirement.retire(frameIndex, std::move(it->pipeline));
            it = pipelines_.erase(it);
        } else {
            ++it;
        }
    }
    passPipelines_.assign(f.passes.size(), nullptr);
    for (size_t i = 0; i < f.passes.size(); ++i) {
        const PassDecl& p = f.passes[i];
        if (!p.live) continue;
        auto it = std::find_if(pipelines_.begin(), pipelines_.end(), [&](const CachedPipeline& c) {
            return c.desc == p.pipeline && c.constants == p.constants;
        });
        if (it == pipelines_.end()) {
            auto pipeline = std::make_unique<ComputePipeline>();
            if (Status s = pipeline->create(*gpu_, *p.pipeline, 0, p.constants); !s) return s;
            retireOldestVariant(p.pipeline, frameIndex, retirement);
            pipelines_.push_back({p.pipeline, p.constants, p.effect, frameIndex, std::move(pipeline)});
            it = pipelines_.end() - 1;
        }
        it->lastUsed = frameIndex;
        passPipelines_[i] = it->pipeline.get();
        // Every binding of the pipeline's layout gets a resource (an unwritten descriptor is undefined).
        for (const Binding& binding : p.pipeline->bindings) {
            bool bound = false;
            for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a)
                bound |= f.accesses[a].binding == binding.binding && f.accesses[a].resource != kNoResource;
            if (!bound)
                return {Result::InvalidArgument, std::string(p.pipeline->name) + ": binding " +
                                                     std::to_string(binding.binding) +
                                                     " has no resource declared"};
        }
    }
    return Status::success();
}

Status FrameGraph::record(Frame& f, VkCommandBuffer cmd, uint64_t frameIndex, DescriptorArena& arena,
                          PassTimer& timer, Retirement& retirement) {
    if (Status s = prepare(f, frameIndex, retirement); !s) return s;
    const FrameInfo& info = *f.info;

    // The host's images: the layout postfx uses each in, over all recorded passes.
    struct HostUse {
        bool used = false, storage = false;
        VkAccessFlags access = 0, written = 0;
        HostImageUse use{};
    };
    HostUse hostUses[4];
    const ImageInput* hostImages[4] = {&info.color, &info.depth, &info.output, &info.shadowMap.image};
    for (const PassDecl& p : f.passes)
        for (uint32_t a = p.firstAccess; p.live && a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (x.resource == kNoResource || f.resources[x.resource].kind != ResourceDecl::Kind::Host)
                continue;
            HostUse& h = hostUses[size_t(f.resources[x.resource].host)];
            h.used = true;
            h.storage |= storage(x.use);
            if (reads(x.use)) h.access |= VK_ACCESS_SHADER_READ_BIT;
            if (writes(x.use)) h.access |= VK_ACCESS_SHADER_WRITE_BIT;
        }
    for (size_t i = 0; i < 4; ++i)
        if (hostUses[i].used) {
            const ImageInput& image = *hostImages[i];
            hostUses[i].use = useHostImage(image.image, image.format, image.layout, hostUses[i].storage,
                                           hostUses[i].access);
        }

    // Descriptor sets, before any command: an error leaves nothing half recorded.
    passSets_.assign(f.passes.size(), VK_NULL_HANDLE);
    for (size_t i = 0; i < f.passes.size(); ++i) {
        const PassDecl& p = f.passes[i];
        if (!p.live) continue;
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
                writes.uniformBuffer(x.binding, b->buffer->handle(),
                                     b->slotBytes * (frameIndex % framesInFlight_), r.uniformBytes);
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

    // Pending accesses of the host images within this frame (postfx's own images keep theirs in images_).
    bool hostPendingWrite[4] = {}, hostReadSinceWrite[4] = {};
    for (size_t i = 0; i < f.passes.size(); ++i) {
        const PassDecl& p = f.passes[i];
        if (!p.live) continue;
        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (seenBefore(f, p, a)) continue;
            const ResourceDecl& r = f.resources[x.resource];
            const Merged m = merge(f, p, x.resource);
            if (r.kind == ResourceDecl::Kind::Host) {
                const size_t h = size_t(r.host);
                if ((m.synchronizedRead() && hostPendingWrite[h]) ||
                    (m.write && (hostPendingWrite[h] || hostReadSinceWrite[h])))
                    batch.computeMemory(hostPendingWrite[h] ? VK_ACCESS_SHADER_WRITE_BIT : 0,
                                        (m.synchronizedRead() ? VK_ACCESS_SHADER_READ_BIT : 0) |
                                            (m.write ? VK_ACCESS_SHADER_WRITE_BIT : 0));
            } else if (owned(r)) {
                OwnedImage& o = *resourceImages_[x.resource];
                const VkImageLayout layout = ownedLayout(m);
                const bool hazard = (m.synchronizedRead() && o.pendingWrite) ||
                                    (m.write && (o.pendingWrite || o.readSinceWrite));
                if (layout != o.layout || hazard) {
                    ImageTransition t;
                    t.image = o.image->handle();
                    t.layers = o.image->desc().layers;
                    t.oldLayout = m.discard ? VK_IMAGE_LAYOUT_UNDEFINED : o.layout;
                    t.newLayout = layout;
                    t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
                    t.srcAccess = o.pendingWrite ? VK_ACCESS_SHADER_WRITE_BIT : 0;
                    t.dstStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
                    t.dstAccess = (m.synchronizedRead() ? VK_ACCESS_SHADER_READ_BIT : 0) |
                                  (m.write ? VK_ACCESS_SHADER_WRITE_BIT : 0);
                    batch.add(t);
                    o.layout = layout;
                    o.pendingWrite = false;
                    o.readSinceWrite = false;
                }
            }
        }
        batch.record(*gpu_, cmd);

        const ComputePipeline& pipeline = *passPipelines_[i];
        beginLabel(gpu_->fn, cmd, pipeline.name().c_str());
        timer.beginPass(cmd, pipeline.name(), p.effect, !p.builds);
        pipeline.bind(cmd, passSets_[i], p.pushBytes ? p.push.data() : nullptr);
        gpu_->fn.vkCmdDispatch(cmd, p.groups[0], p.groups[1], p.groups[2]);
        timer.endPass(cmd);
        endLabel(gpu_->fn, cmd);

        for (uint32_t a = p.firstAccess; a < p.firstAccess + p.accessCount; ++a) {
            const Access& x = f.accesses[a];
            if (seenBefore(f, p, a)) continue;
            const ResourceDecl& r = f.resources[x.resource];
            const Merged m = merge(f, p, x.resource);
            bool* pending = nullptr;
            bool* readSince = nullptr;
            if (r.kind == ResourceDecl::Kind::Host) {
                pending = &hostPendingWrite[size_t(r.host)];
                readSince = &hostReadSinceWrite[size_t(r.host)];
            } else if (owned(r)) {
                OwnedImage& o = *resourceImages_[x.resource];
                pending = &o.pendingWrite;
                readSince = &o.readSinceWrite;
                // Written once: readable by the host (imageView, recordImageReadback); a history image
                // holds the frame's result (the clouds' shadow map, the fogs' accumulations).
                if (m.write &&
                    (r.kind == ResourceDecl::Kind::Persistent || r.kind == ResourceDecl::Kind::History)) {
                    o.built = true;
                    o.builtKey = r.buildKey;
                }
            }
            if (!pending) continue;
            if (m.write) {
                *pending = true;
                *readSince = false;
            } else if (m.synchronizedRead()) {
                *readSince = true;
            }
        }
    }

    // Host images out, once, in the layouts they came in, postfx's writes visible to what follows.
    for (const HostUse& h : hostUses)
        if (h.used) batch.add(h.use.release);
    batch.record(*gpu_, cmd);
    endLabel(gpu_->fn, cmd);
    return Status::success();
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
