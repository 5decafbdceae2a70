#include "core/copy_pass.h"

#include "common/shared.h"
#include "core/barriers.h"
#include "core/pass_timer.h"
#include "postfx_spirv.h"

namespace postfx::core {

namespace {
constexpr const char* kName = "postfx.copy";

uint32_t groups(uint32_t size) {
    return (size + gpu::kCopyGroupSize - 1) / gpu::kCopyGroupSize;
}
}  // namespace

PlannedPass CopyPass::plan(const FrameInfo& frame) {
    PlannedPass p;
    p.name = kName;
    p.effect = "postfx";
    p.reads = {"host.color"};
    p.writes = {"host.output"};
    p.groups[0] = groups(frame.color.extent.width);
    p.groups[1] = groups(frame.color.extent.height);
    p.groups[2] = 1;
    return p;
}

Status CopyPass::record(const Gpu& gpu, DescriptorArena& arena, PassTimer& timer, const FrameInfo& frame) {
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;
    ComputePipeline& pipeline = pipelines_[rgba32 ? 1 : 0];
    if (!pipeline.valid()) {
        static constexpr Binding kBindings[] = {{gpu::kCopyBindingIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                                {gpu::kCopyBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
        ComputePipelineDesc desc;
        desc.name = kName;
        desc.spirv = rgba32 ? spirv::core_copy_comp_COLOR_RGBA32F : spirv::core_copy_comp;
        desc.bindings = kBindings;
        desc.pushConstantBytes = 8;
        if (Status s = pipeline.create(gpu, desc); !s) return s;
    }
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (Status s = arena.allocate(pipeline.setLayout(), set); !s) return s;
    DescriptorWrites(set)
        .storageImage(gpu::kCopyBindingIn, frame.color.view)
        .storageImage(gpu::kCopyBindingOut, frame.output.view)
        .apply(gpu);

    VkCommandBuffer cmd = frame.commandBuffer;
    const ImageInput& in = frame.color;
    const ImageInput& out = frame.output;
    const HostImageUse color = useHostImage(in.image, in.format, in.layout, true, VK_ACCESS_SHADER_READ_BIT);
    const HostImageUse output =
        useHostImage(out.image, out.format, out.layout, true, VK_ACCESS_SHADER_WRITE_BIT);
    transition(gpu, cmd, color.acquire);
    transition(gpu, cmd, output.acquire);
    timer.beginPass(cmd, kName);
    const uint32_t extent[2] = {in.extent.width, in.extent.height};
    pipeline.bind(cmd, set, extent);
    gpu.fn.vkCmdDispatch(cmd, groups(in.extent.width), groups(in.extent.height), 1);
    timer.endPass(cmd);
    transition(gpu, cmd, color.release);
    transition(gpu, cmd, output.release);
    return Status::success();
}

}  // namespace postfx::core
