// The frame graph's cache of pipeline objects: a compute pipeline per description and specialization
// constants (at most kMaxVariantsPerPipeline per description, an effect's kept while it records passes;
// prewarmed ones until release()), and the samplers.
#include "core/frame_graph.h"

#include "core/frame_graph_internal.h"

#include <algorithm>
#include <string>
#include <string_view>

namespace postfx::core {

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
        if (it->desc != desc || it->prewarmed) continue;
        ++variants;
        if (it->lastUsed != frameIndex && (oldest == pipelines_.end() || it->lastUsed < oldest->lastUsed))
            oldest = it;
    }
    if (variants < kMaxVariantsPerPipeline || oldest == pipelines_.end()) return;
    retirement.retire(frameIndex, std::move(oldest->pipeline));
    pipelines_.erase(oldest);
}

Status FrameGraph::prewarm(const std::vector<PipelineUse>& uses) {
    for (const PipelineUse& use : uses) {
        auto it = std::find_if(pipelines_.begin(), pipelines_.end(), [&](const CachedPipeline& c) {
            return c.desc == use.desc && c.constants == use.constants;
        });
        if (it == pipelines_.end()) {
            auto pipeline = std::make_unique<ComputePipeline>();
            if (Status s = pipeline->create(*gpu_, *use.desc, 0, use.constants); !s) return s;
            pipelines_.push_back({use.desc, use.constants, use.effect, 0, true, std::move(pipeline)});
        } else {
            it->prewarmed = true;
        }
    }
    return Status::success();
}

size_t FrameGraph::heldPipelines(const char* name) const {
    return size_t(std::count_if(pipelines_.begin(), pipelines_.end(), [&](const CachedPipeline& c) {
        return std::string_view(c.desc->name) == name;
    }));
}

// The pipelines of the compiled frame's live passes: created when first recorded, an effect's released
// when it records none; checks that every binding of a pass's pipeline has a resource.
Status FrameGraph::preparePipelines(Frame& f, uint64_t frameIndex, Retirement& retirement) {
    // Pipelines: an effect's live as long as it records a pass; the context's own (postfx.copy) and
    // prewarmed ones always.
    for (auto it = pipelines_.begin(); it != pipelines_.end();) {
        const bool effectLive = it->effect < 0 || it->prewarmed ||
                                std::any_of(f.passes.begin(), f.passes.end(), [&](const PassDecl& p) {
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
        if (!p.live || p.transfer != TransferOp::None) continue;
        auto it = std::find_if(pipelines_.begin(), pipelines_.end(), [&](const CachedPipeline& c) {
            return c.desc == p.pipeline && c.constants == p.constants;
        });
        if (it == pipelines_.end()) {
            auto pipeline = std::make_unique<ComputePipeline>();
            if (Status s = pipeline->create(*gpu_, *p.pipeline, 0, p.constants); !s) return s;
            retireOldestVariant(p.pipeline, frameIndex, retirement);
            pipelines_.push_back({p.pipeline, p.constants, p.effect, frameIndex, false, std::move(pipeline)});
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

}  // namespace postfx::core
