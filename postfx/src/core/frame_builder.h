// What an effect declares a frame through (docs/architecture.md, "The frame graph"): the typed handles
// of the frame's resources, how a pass uses them, the declarations they become (Frame) and FrameBuilder,
// the API handed to Effect::declare. core/frame_graph.h compiles and records them.
#pragma once

#include <postfx/context.h>

#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"
#include "core/world_frame.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace postfx::core {

inline constexpr uint16_t kNoResource = 0xffff;

// Typed handles of the frame's resources (indices into the frame's declarations).
struct ImageRef {
    uint16_t index = kNoResource;
    bool valid() const { return index != kNoResource; }
};
struct BufferRef {
    uint16_t index = kNoResource;
    bool valid() const { return index != kNoResource; }
};

// The identity of a resource postfx owns, across frames and effects: one `inline constexpr` object per
// resource in its effect's header; compared by address. `name` is the frame plan's ("fog.noise").
struct ResourceId {
    const char* name;
};

// The host's images of FrameInfo.
enum class HostImage : uint8_t { Color, Depth, Output, ShadowMap, LocalShadowAtlas };
inline constexpr size_t kHostImageCount = 5;

enum class SamplerKind : uint8_t { NearestClamp, LinearRepeat, LinearClamp };

// How a pass uses a resource bound at a binding.
enum class Use : uint8_t {
    StorageRead,       // storage image, read
    StorageWrite,      // storage image, written; the pass writes every texel later passes read, so an
                       // owned image's old contents may be discarded
    StorageReadWrite,  // storage image, read and written
    Sampled,           // combined image sampler, read
    BoundOnly,         // combined image sampler bound because the pipeline's layout has it, never read
    StorageBoundOnly,  // storage image bound because the pipeline's layout has it, never accessed (the
                       // shader's code for it is off, e.g. by a specialization constant)
    Uniform,           // uniform buffer: this frame's slot (a storage buffer where the pipeline's layout
                       // declares one: data larger than a uniform buffer may hold)
    TransferRead,      // source of a transfer pass (blit or copy)
    TransferWrite,     // destination of a transfer pass: every texel written
};

// A pass that is not a dispatch: a blit (format conversion: the composite target's load and store) or a
// copy of one image into another (core/target.h).
enum class TransferOp : uint8_t { None, Blit, Copy };

struct Access {
    uint32_t binding = 0;
    uint16_t resource = kNoResource;
    Use use = Use::StorageRead;
    SamplerKind sampler = SamplerKind::NearestClamp;
};

struct ResourceDecl {
    enum class Kind : uint8_t { Host, External, Transient, Persistent, History, Uniform };
    Kind kind = Kind::Host;
    int effect = -1;  // declaring effect; -1: the context
    const char* name = "";
    const ResourceId* id = nullptr;  // owned resources
    HostImage host = HostImage::Color;
    VkImageView view = VK_NULL_HANDLE;  // external
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    ImageDesc desc;              // owned images
    uint64_t buildKey = 0;       // persistent images: the inputs their contents were built from
    uint32_t uniformOffset = 0;  // uniform: its data in Frame::uniformData
    uint32_t uniformBytes = 0;
    bool needsBuild = false;  // persistent: no held image with this desc and key (compile())
    bool held = false;        // a recorded pass uses it (compile())
    bool exported = false;    // read after the frame (by the host): its writers are live (exportImage)
};

struct PassDecl {
    const ComputePipelineDesc* pipeline = nullptr;  // static: pipelines are cached by its address
    PipelineConstants constants;                    // and by its specialization constants
    int effect = -1;
    uint32_t groups[3] = {1, 1, 1};
    std::array<std::byte, 128> push{};
    uint32_t pushBytes = 0;
    uint32_t firstAccess = 0, accessCount = 0;  // in Frame::accesses
    bool builds = false;                        // writes a persistent image
    bool live = false;                          // recorded (compile())
    // A transfer pass: `pipeline` only names it; its two accesses are the source and the destination.
    TransferOp transfer = TransferOp::None;
};

// One frame's declarations and their compiled form. Reused from frame to frame (no allocation once warm).
struct Frame {
    const FrameInfo* info = nullptr;
    std::vector<ResourceDecl> resources;
    std::vector<PassDecl> passes;
    std::vector<Access> accesses;
    std::vector<std::byte> uniformData;
    uint16_t host[kHostImageCount] = {kNoResource, kNoResource, kNoResource, kNoResource, kNoResource};
    // Two or more of the frame's effects read the host's depth: postfx.view_distance unprojects it once
    // for all of them (FrameBuilder::depthInput); set by the context before the effects declare.
    bool shareDepth = false;
    // The host's world frame (ContextCreateInfo::world): `info` is already in postfx's; what postfx hands
    // back in world space (the volumetrics lookup's uniforms) is converted back with it.
    WorldTransform world;
    bool composited = false;  // a pass has written the composite target
    // postfx.target: the RGBA16F image the effects composite into when the host's color cannot be
    // composited in place (core/target.h); kNoResource otherwise.
    uint16_t target = kNoResource;
    // The volumetrics lookup (FrameInfo::volumetricsLookup), declared by the first lookupTarget() call:
    // its two images and uniforms, and whether a pass has written them yet.
    uint16_t lookupScattering = kNoResource, lookupTransmittance = kNoResource, lookupUniforms = kNoResource;
    bool lookupWritten = false;
    // Other names of shared persistent images (findPersistent): the later declarer's id and the image.
    std::vector<std::pair<const ResourceId*, uint16_t>> aliases;
    std::vector<uint8_t> scratch;  // compile()'s
};

class FrameGraph;

// What an effect reads for its pixels' surface distances (FrameBuilder::depthInput).
struct DepthInput {
    ImageRef image;         // sampled with texelFetch at the pixel
    bool distance = false;  // the shared surface distance [m] (R32F); false: the host's depth
};

// What an effect declares through; handed to Effect::declare.
// An image another effect may have declared earlier this frame, for a consumer's sampled binding: that
// image, sampled; or, when it did not, a stand-in bound only (the pipeline's layout has the binding; the
// shader's flag for it is off).
struct OptionalSampled {
    ImageRef image;
    Use use = Use::BoundOnly;
    SamplerKind sampler = SamplerKind::NearestClamp;  // linear for a real image (a depth stand-in may not
                                                      // filter linearly)
};

// The volumetrics lookup's volume an effect composites its (L, T) over (FrameBuilder::lookupTarget):
// bind `scattering` and `transmittance` with `use` at gpu::kLookupBinding*, `uniforms` at
// gpu::kLookupBindingUniforms, and push `push` (shaders/common/lookup.glsl).
struct LookupTarget {
    ImageRef scattering, transmittance;
    BufferRef uniforms;
    Use use = Use::StorageWrite;  // the first writer's; StorageReadWrite for the later ones
    uint32_t push[4] = {0, 0, 0, 0};
    uint32_t extent[3] = {0, 0, 0};
    bool valid() const { return scattering.valid(); }
};

class FrameBuilder {
public:
    FrameBuilder(const FrameGraph& graph, Frame& frame, int effect)
        : graph_(graph), f_(frame), effect_(effect) {}

    const FrameInfo& frame() const { return *f_.info; }
    uint32_t framesInFlight() const;
    const DepthConvention& depthConvention() const;  // the context's (ContextCreateInfo::depth)

    // The host's depth and shadow map (invalid when absent).
    ImageRef host(HostImage image) const { return {f_.host[size_t(image)]}; }
    // The image an effect reads its pixels' surface distances from (docs/architecture.md, "Shared
    // inputs"): when two or more of the frame's effects read the host's depth, postfx.view_distance's
    // R32F image (declared, with its pass, by the first call of the frame; the distance along the pixel
    // centre's ray, +∞ without geometry, NaN for a NaN depth); otherwise the host's depth, which the effect
    // unprojects itself. Call it before declaring a pass, not between a pass and its bindings.
    DepthInput depthInput();
    // The volumetrics lookup this effect composites into, in composite order, after its own composite
    // (invalid when the host did not ask for it). Each call is one writer: call it once per lookup pass,
    // before declaring the pass.
    LookupTarget lookupTarget();
    // Compositing into color: the image the next composite reads (host color, or the separate output
    // once an earlier pass has written it) and the one it writes (the output when given, else color); both
    // postfx.target when the host's color is not composited in place (core/target.h).
    ImageRef compositeSource() const;
    ImageRef compositeTarget() const;
    // A view the host lends through settings (e.g. its own noise texture): bound in `layout`, which the
    // host guarantees; postfx records no barrier for it.
    ImageRef external(const char* name, VkImageView view, VkImageLayout layout);
    // An image postfx owns whose contents live only within the frame; kept across frames (recreated when
    // `desc` changes) while declared, released in the first frame that does not declare it.
    ImageRef transientImage(const ResourceId& id, const ImageDesc& desc);
    // An image postfx owns whose contents persist: the passes writing it run only when no image built
    // from `buildKey` (and `desc`) is held and something reads it this frame.
    ImageRef persistentImage(const ResourceId& id, const ImageDesc& desc, uint64_t buildKey);
    // An image postfx owns whose contents are carried to the next frame (a temporal history): kept while
    // declared (recreated, contents undefined, when `desc` changes), released in the first frame that
    // does not declare it. Passes writing it are live when a later pass reads it, like a transient's;
    // whether its contents are valid is the declaring effect's to know (core/temporal.h).
    ImageRef historyImage(const ResourceId& id, const ImageDesc& desc);
    // Marks an owned image as read after the frame (by the host, through Context::imageView, like the
    // clouds' shadow map): the passes writing it are live even when no later pass of the frame reads it.
    void exportImage(ImageRef image);
    // An image another effect declared earlier this frame (invalid if it did not).
    ImageRef find(const ResourceId& id) const;
    // A persistent image declared earlier this frame with `desc` and `buildKey` (invalid if none): for
    // contents several effects would build alike (a noise texture of one formula, size and seed), so that
    // they share one image and one build. When found, `alias` becomes another name of it: the host finds
    // it by either name (Context::imageView, recordImageReadback).
    ImageRef findPersistent(const ResourceId& alias, const ImageDesc& desc, uint64_t buildKey);
    // Uniform data another effect declared earlier this frame (invalid if it did not).
    BufferRef findUniforms(const ResourceId& id) const;
    // Uniform data for this frame: `bytes` copied into a ring of framesInFlight slots.
    BufferRef uniforms(const ResourceId& id, const void* data, uint32_t bytes);

    // Declares a pass; add its bindings with the calls below before declaring the next pass.
    FrameBuilder& pass(const ComputePipelineDesc& pipeline, uint32_t x, uint32_t y, uint32_t z);
    FrameBuilder& bind(uint32_t binding, ImageRef image, Use use,
                       SamplerKind sampler = SamplerKind::NearestClamp);
    FrameBuilder& bind(uint32_t binding, BufferRef buffer);
    FrameBuilder& push(const void* data, uint32_t bytes);  // at most 128 bytes
    // The pass's specialization constants (constant_id 0, 1, ...): one pipeline per distinct set, created
    // the first frame it is recorded; the last 4 used of a description are kept.
    FrameBuilder& constants(const PipelineConstants& constants);
    // Declares a transfer pass named by `named` (its name only): `source` into `destination`, whole.
    FrameBuilder& transfer(const ComputePipelineDesc& named, TransferOp op, ImageRef source,
                           ImageRef destination);

private:
    ImageRef ownedImage(const ResourceId& id, const ImageDesc& desc, ResourceDecl::Kind kind, uint64_t key);
    const FrameGraph& graph_;
    Frame& f_;
    int effect_;
};

}  // namespace postfx::core
