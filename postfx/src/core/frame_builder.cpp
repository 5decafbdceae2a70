// FrameBuilder: what an effect calls to declare its frame's resources and passes (core/frame_builder.h).
// FrameBuilder::depthInput, which declares postfx.view_distance, is in frame_graph_passes.cpp.
#include "core/frame_builder.h"

#include "core/frame_graph.h"
#include "core/frame_graph_internal.h"

#include <algorithm>
#include <cstring>

namespace postfx::core {

uint32_t FrameBuilder::framesInFlight() const {
    return graph_.framesInFlight_;
}

const DepthConvention& FrameBuilder::depthConvention() const {
    return graph_.depth_;
}

ImageRef FrameBuilder::compositeSource() const {
    if (f_.target != kNoResource) return {f_.target};
    const uint16_t output = f_.host[size_t(HostImage::Output)];
    return {f_.composited && output != kNoResource ? output : f_.host[size_t(HostImage::Color)]};
}

ImageRef FrameBuilder::compositeTarget() const {
    if (f_.target != kNoResource) return {f_.target};
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

FrameBuilder& FrameBuilder::transfer(const ComputePipelineDesc& named, TransferOp op, ImageRef source,
                                     ImageRef destination) {
    pass(named, 1, 1, 1);
    f_.passes.back().transfer = op;
    f_.accesses.push_back({0, source.index, Use::TransferRead, SamplerKind::NearestClamp});
    f_.accesses.push_back({1, destination.index, Use::TransferWrite, SamplerKind::NearestClamp});
    f_.passes.back().accessCount = 2;
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

}  // namespace postfx::core
