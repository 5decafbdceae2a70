// The frame graph: what a frame's effects declare (resources and passes), compiled into the frame plan
// and recorded with barriers derived from the declarations (docs/architecture.md, "The frame graph").
//
// Each frame the context asks every active effect, in composite order, to declare through a
// FrameBuilder (core/frame_builder.h): the resources it reads and writes (the host's images, views the host
// lends through settings, images postfx owns, per-frame uniform data) as typed handles, and its passes (a
// compute pipeline, which resource is bound at which binding and how it is used, the workgroups). compile()
// then drops every pass whose outputs nothing reads (and a build of a persistent image whose inputs did
// not change), and adds postfx.copy when a separate output would otherwise stay unwritten. plan() and
// record() both read that compiled frame, so they cannot disagree.
//
// Barriers: the host's images are transitioned in once before the first pass (from whatever the host
// did, ALL_COMMANDS / MEMORY_WRITE) and back once after the last; between passes a barrier is recorded
// only where a declared read or write follows a write (or a write follows a read) of the same resource;
// postfx's own images carry their layout and pending accesses from frame to frame.
//
// The class is defined across: frame_builder.cpp (the declarations), frame_graph.cpp (compile, plan and
// the images and buffers a frame holds), frame_graph_pipelines.cpp (the pipeline and sampler cache),
// frame_graph_record.cpp (recording with barriers, readback) and frame_graph_passes.cpp (postfx.copy and
// postfx.view_distance).
#pragma once

#include <postfx/frame_plan.h>

#include "core/compute_pipeline.h"
#include "core/frame_builder.h"
#include "core/gpu_resources.h"
#include "core/pass_timer.h"
#include "core/retirement.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace postfx::core {

class FrameGraph {
public:
    FrameGraph() = default;
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;
    ~FrameGraph() { release(); }

    Status create(const Gpu& gpu, uint32_t framesInFlight, const DepthConvention& depth);
    void setEffectNames(std::vector<const char*> names) { effectNames_ = std::move(names); }
    void release();
    uint32_t framesInFlight() const { return framesInFlight_; }

    // Starts `frame`'s declarations: the host's images of `info` (validated).
    void begin(Frame& frame, const FrameInfo& info) const;
    // Culls passes, marks the resources recorded passes use, adds postfx.copy where needed.
    void compile(Frame& frame) const;
    // The compiled frame as the public plan.
    void plan(const Frame& frame, FramePlan& out) const;
    // Creates and releases what the compiled frame needs, then records it: host images in, every live
    // pass with its barriers, timestamps and dispatch, host images out (starting `timer`'s frame first).
    // Every call that can fail comes before the first command: on error nothing is recorded.
    Status record(Frame& frame, VkCommandBuffer cmd, uint64_t frameIndex, DescriptorArena& arena,
                  PassTimer& timer, Retirement& retirement);

    // A held persistent image by plan name, or by the name of an effect sharing it in the last recorded
    // frame (built, else null).
    struct HeldImage {
        const GpuImage* image = nullptr;
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
        bool pendingWrite = false;
    };
    HeldImage heldImage(const char* name) const;
    Status recordReadback(const char* name, VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset,
                          VkExtent3D& extent, VkDeviceSize& bytes) const;

    // A held uniform ring's slot of `frameIndex` (the volumetrics lookup's, for the host): false if none.
    bool uniformSlot(const ResourceId& id, uint64_t frameIndex, VkBuffer& buffer, VkDeviceSize& offset) const;
    // The sampler of `kind`, created on first use.
    Status sampler(SamplerKind kind, VkSampler& out);

    // The pipelines of `uses` not held yet are created, and all of them are kept until release(): not
    // retired with their effect's passes, nor by the variants' limit (Context::prewarm).
    struct PipelineUse {
        const ComputePipelineDesc* desc = nullptr;
        PipelineConstants constants;
        int effect = -1;
        bool operator==(const PipelineUse&) const = default;
    };
    Status prewarm(const std::vector<PipelineUse>& uses);
    // Device memory of the images and buffers held now, added per owner: index 0 the context's, 1 + e
    // effect e's (Context::memoryUsage; `owners` has 1 + the effects' count entries).
    void memoryUsage(std::vector<MemoryUsage::Owner>& owners) const;

    // Objects held now (for tests): owned images, uniform rings and pipelines.
    size_t heldObjects() const { return images_.size() + buffers_.size() + pipelines_.size(); }
    // Pipelines held now whose description is named `name` (for tests): its specializations, for every
    // description of that name.
    size_t heldPipelines(const char* name) const;

private:
    friend class FrameBuilder;
    struct OwnedImage {
        const ResourceId* id = nullptr;
        int effect = -1;  // the declaring effect; -1: the context
        std::unique_ptr<GpuImage> image;
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
        bool pendingWrite = false;    // written since its writes were last made visible
        bool readSinceWrite = false;  // read since the last write (a write must wait for it)
        // The stage of that write, and of those reads (compute, or transfer for the composite target).
        VkPipelineStageFlags writeStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        VkPipelineStageFlags readStages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        bool built = false;  // persistent: contents built from builtKey
        uint64_t builtKey = 0;
        bool used = false;  // declared and held this frame
        // Exported: written this frame (made visible to the host's commands at the end of record), and
        // possibly read by the host since (the next write waits for every earlier command).
        bool writtenForHost = false;
        bool hostMayRead = false;
    };
    struct OwnedBuffer {
        const ResourceId* id = nullptr;
        int effect = -1;
        std::unique_ptr<GpuBuffer> buffer;
        VkDeviceSize slotBytes = 0;
        bool used = false;
    };
    struct CachedPipeline {
        const ComputePipelineDesc* desc = nullptr;
        PipelineConstants constants;
        int effect = -1;
        uint64_t lastUsed = 0;   // frame index
        bool prewarmed = false;  // kept until release() (prewarm)
        std::unique_ptr<ComputePipeline> pipeline;
    };
    // Specializations of one pipeline kept at once besides the prewarmed ones (a host switching between a
    // few settings keeps each compiled); the least recently used beyond these is released.
    static constexpr size_t kMaxVariantsPerPipeline = 4;
    const OwnedImage* findImage(const ResourceId* id) const;
    Status prepare(Frame& frame, uint64_t frameIndex, Retirement& retirement);
    Status preparePipelines(Frame& frame, uint64_t frameIndex, Retirement& retirement);
    // Records a transfer pass (a blit or a copy of the whole color extent) with its label and timestamps.
    void recordTransfer(const Frame& frame, const PassDecl& pass, const ImageInput* const* hostImages,
                        VkCommandBuffer cmd, PassTimer& timer) const;
    // Before a new specialization of `desc` is cached: releases its least recently used one when
    // kMaxVariantsPerPipeline are held (never one this frame uses, nor a prewarmed one).
    void retireOldestVariant(const ComputePipelineDesc* desc, uint64_t frameIndex, Retirement& retirement);

    const Gpu* gpu_ = nullptr;
    uint32_t framesInFlight_ = 1;
    DepthConvention depth_;
    std::vector<const char*> effectNames_;
    std::vector<OwnedImage> images_;
    // The last recorded frame's other names of held images (Frame::aliases): the alias and the owner.
    std::vector<std::pair<const ResourceId*, const ResourceId*>> aliases_;
    std::vector<OwnedBuffer> buffers_;
    std::vector<CachedPipeline> pipelines_;
    VkSampler samplers_[3] = {};
    // Per-frame scratch of record(), kept to avoid allocation.
    std::vector<ComputePipeline*> passPipelines_;
    std::vector<VkDescriptorSet> passSets_;
    std::vector<OwnedImage*> resourceImages_;  // by resource index: the owned image, or null
};

}  // namespace postfx::core
