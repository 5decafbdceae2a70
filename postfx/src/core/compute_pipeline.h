// Compute pipelines from embedded SPIR-V, and per-frame descriptor sets.
#pragma once

#include "core/gpu.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace postfx::core {

struct Binding {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
};

struct ComputePipelineDesc {
    const char* name = "";  // pass name for messages, e.g. "fog.raymarch"
    std::span<const uint32_t> spirv;
    std::span<const Binding> bindings;  // descriptor set 0
    uint32_t pushConstantBytes = 0;     // 0..128
};

// A pipeline's specialization constants: value i is the shader's `constant_id = i` (32 bits: a uint, an
// int, or a float's bits through std::bit_cast).
struct PipelineConstants {
    static constexpr uint32_t kMax = 4;
    std::array<uint32_t, kMax> values{};
    uint32_t count = 0;
    bool operator==(const PipelineConstants&) const = default;
};

class ComputePipeline {
public:
    ComputePipeline() = default;
    ComputePipeline(ComputePipeline&& other) noexcept { *this = std::move(other); }
    ComputePipeline& operator=(ComputePipeline&& other) noexcept;
    ~ComputePipeline() { reset(); }

    // `flags`: VkComputePipelineCreateInfo::flags (a tool's VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR).
    // `constants`: specialization constants; a shader's constant not given keeps its default.
    Status create(const Gpu& gpu, const ComputePipelineDesc& desc, VkPipelineCreateFlags flags = 0,
                  const PipelineConstants& constants = {});
    void reset();
    bool valid() const { return pipeline_ != VK_NULL_HANDLE; }

    // Binds the pipeline and `set` (set 0) and pushes `pushBytes` (pushConstantBytes long).
    void bind(VkCommandBuffer cmd, VkDescriptorSet set, const void* pushBytes) const;

    VkDescriptorSetLayout setLayout() const { return setLayout_; }
    const std::string& name() const { return name_; }
    VkPipeline handle() const { return pipeline_; }

private:
    const Gpu* gpu_ = nullptr;
    std::string name_;
    uint32_t pushConstantBytes_ = 0;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// Descriptor sets that live for one frame: one pool per frame in flight, reset when the frame's slot
// comes round again (the host guarantees that frame's commands have completed).
class DescriptorArena {
public:
    DescriptorArena() = default;
    DescriptorArena(const DescriptorArena&) = delete;
    DescriptorArena& operator=(const DescriptorArena&) = delete;
    ~DescriptorArena() { reset(); }

    Status create(const Gpu& gpu, uint32_t maxSetsPerFrame);
    void reset();
    Status beginFrame();  // resets the pool
    Status allocate(VkDescriptorSetLayout layout, VkDescriptorSet& set);

private:
    const Gpu* gpu_ = nullptr;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

// Collects descriptor writes for one set; apply() issues them in one vkUpdateDescriptorSets call.
class DescriptorWrites {
public:
    explicit DescriptorWrites(VkDescriptorSet set) : set_(set) {}
    DescriptorWrites& storageImage(uint32_t binding, VkImageView view);
    DescriptorWrites& sampledImage(uint32_t binding, VkImageView view, VkImageLayout layout,
                                   VkSampler sampler);
    DescriptorWrites& storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                    VkDeviceSize size);
    DescriptorWrites& uniformBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                    VkDeviceSize size);
    void apply(const Gpu& gpu);

private:
    static constexpr uint32_t kMax = 16;
    VkDescriptorSet set_;
    uint32_t count_ = 0;
    VkWriteDescriptorSet writes_[kMax]{};
    VkDescriptorImageInfo images_[kMax]{};
    VkDescriptorBufferInfo buffers_[kMax]{};
    VkWriteDescriptorSet& next(uint32_t binding, VkDescriptorType type);
};

}  // namespace postfx::core
