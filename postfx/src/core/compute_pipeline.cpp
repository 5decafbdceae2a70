#include "core/compute_pipeline.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace postfx::core {

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& other) noexcept {
    if (this != &other) {
        reset();
        gpu_ = std::exchange(other.gpu_, nullptr);
        name_ = std::move(other.name_);
        pushConstantBytes_ = other.pushConstantBytes_;
        setLayout_ = std::exchange(other.setLayout_, VK_NULL_HANDLE);
        layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
        pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    }
    return *this;
}

Status ComputePipeline::create(const Gpu& gpu, const ComputePipelineDesc& desc, VkPipelineCreateFlags flags,
                               const PipelineConstants& constants) {
    reset();
    gpu_ = &gpu;
    name_ = desc.name;
    pushConstantBytes_ = desc.pushConstantBytes;
    if (desc.spirv.empty()) return {Result::InvalidArgument, name_ + ": empty SPIR-V"};
    if (desc.pushConstantBytes > 128)
        return {Result::InvalidArgument, name_ + ": push constants exceed the guaranteed 128 bytes"};

    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const Binding& b : desc.bindings)
        bindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
    setInfo.pBindings = bindings.data();
    // Handles are kept only from calls that succeeded: Vulkan leaves a failed call's outputs undefined.
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    Status s =
        vulkanStatus(gpu.fn.vkCreateDescriptorSetLayout(gpu.device, &setInfo, gpu.allocator, &setLayout),
                     (name_ + ": vkCreateDescriptorSetLayout").c_str());
    if (!s) return reset(), s;
    setLayout_ = setLayout;

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    layoutInfo.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    if (!(s = vulkanStatus(gpu.fn.vkCreatePipelineLayout(gpu.device, &layoutInfo, gpu.allocator, &layout),
                           (name_ + ": vkCreatePipelineLayout").c_str())))
        return reset(), s;
    layout_ = layout;

    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = desc.spirv.size_bytes();
    moduleInfo.pCode = desc.spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (!(s = vulkanStatus(gpu.fn.vkCreateShaderModule(gpu.device, &moduleInfo, gpu.allocator, &module),
                           (name_ + ": vkCreateShaderModule").c_str())))
        return reset(), s;

    std::array<VkSpecializationMapEntry, PipelineConstants::kMax> entries{};
    VkSpecializationInfo spec{};
    spec.mapEntryCount = std::min(constants.count, PipelineConstants::kMax);
    for (uint32_t i = 0; i < spec.mapEntryCount; ++i)
        entries[i] = {i, uint32_t(i * sizeof(uint32_t)), sizeof(uint32_t)};
    spec.pMapEntries = entries.data();
    spec.dataSize = spec.mapEntryCount * sizeof(uint32_t);
    spec.pData = constants.values.data();
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = spec.mapEntryCount ? &spec : nullptr;
    info.flags = flags;
    info.layout = layout_;
    VkPipeline pipeline = VK_NULL_HANDLE;
    s = vulkanStatus(
        gpu.fn.vkCreateComputePipelines(gpu.device, gpu.pipelineCache, 1, &info, gpu.allocator, &pipeline),
        (name_ + ": vkCreateComputePipelines").c_str());
    gpu.fn.vkDestroyShaderModule(gpu.device, module, gpu.allocator);
    if (!s) return reset(), s;
    pipeline_ = pipeline;
    return Status::success();
}

void ComputePipeline::reset() {
    if (!gpu_) return;
    if (pipeline_) gpu_->fn.vkDestroyPipeline(gpu_->device, pipeline_, gpu_->allocator);
    if (layout_) gpu_->fn.vkDestroyPipelineLayout(gpu_->device, layout_, gpu_->allocator);
    if (setLayout_) gpu_->fn.vkDestroyDescriptorSetLayout(gpu_->device, setLayout_, gpu_->allocator);
    gpu_ = nullptr;
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
}

void ComputePipeline::bind(VkCommandBuffer cmd, VkDescriptorSet set, const void* pushBytes) const {
    gpu_->fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    if (set)
        gpu_->fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0,
                                         nullptr);
    if (pushConstantBytes_ && pushBytes)
        gpu_->fn.vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes_,
                                    pushBytes);
}

Status DescriptorArena::create(const Gpu& gpu, uint32_t maxSetsPerFrame) {
    reset();
    gpu_ = &gpu;
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 4 * maxSetsPerFrame},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8 * maxSetsPerFrame},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4 * maxSetsPerFrame},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2 * maxSetsPerFrame},
    };
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = maxSetsPerFrame;
    info.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
    info.pPoolSizes = sizes;
    VkDescriptorPool pool = VK_NULL_HANDLE;  // kept only on success (a failed call's output is undefined)
    Status s = vulkanStatus(gpu.fn.vkCreateDescriptorPool(gpu.device, &info, gpu.allocator, &pool),
                            "vkCreateDescriptorPool");
    if (!s) return reset(), s;
    pool_ = pool;
    return s;
}

void DescriptorArena::reset() {
    if (gpu_ && pool_) gpu_->fn.vkDestroyDescriptorPool(gpu_->device, pool_, gpu_->allocator);
    gpu_ = nullptr;
    pool_ = VK_NULL_HANDLE;
}

Status DescriptorArena::beginFrame() {
    return vulkanStatus(gpu_->fn.vkResetDescriptorPool(gpu_->device, pool_, 0), "vkResetDescriptorPool");
}

Status DescriptorArena::allocate(VkDescriptorSetLayout layout, VkDescriptorSet& set) {
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool_;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    return vulkanStatus(gpu_->fn.vkAllocateDescriptorSets(gpu_->device, &info, &set),
                        "vkAllocateDescriptorSets");
}

VkWriteDescriptorSet& DescriptorWrites::next(uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet& w = writes_[count_];
    w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pImageInfo = &images_[count_];
    w.pBufferInfo = &buffers_[count_];
    ++count_;
    return w;
}

DescriptorWrites& DescriptorWrites::storageImage(uint32_t binding, VkImageView view) {
    images_[count_] = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    next(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).pBufferInfo = nullptr;
    return *this;
}

DescriptorWrites& DescriptorWrites::sampledImage(uint32_t binding, VkImageView view, VkImageLayout layout,
                                                 VkSampler sampler) {
    images_[count_] = {sampler, view, layout};
    next(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pBufferInfo = nullptr;
    return *this;
}

DescriptorWrites& DescriptorWrites::storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                                  VkDeviceSize size) {
    buffers_[count_] = {buffer, offset, size};
    next(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pImageInfo = nullptr;
    return *this;
}

DescriptorWrites& DescriptorWrites::uniformBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                                  VkDeviceSize size) {
    buffers_[count_] = {buffer, offset, size};
    next(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pImageInfo = nullptr;
    return *this;
}

void DescriptorWrites::apply(const Gpu& gpu) {
    if (count_) gpu.fn.vkUpdateDescriptorSets(gpu.device, count_, writes_, 0, nullptr);
    count_ = 0;
}

}  // namespace postfx::core
