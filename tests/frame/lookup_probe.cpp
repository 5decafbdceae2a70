#include "lookup_probe.h"

#include "core/compute_pipeline.h"
#include "frame_test_shaders_spirv.h"

#include <cstring>

namespace test {
namespace {

constexpr postfx::VolumetricsLookupBindings kBindings{3, 5, 7};  // lookup_probe.comp's

}  // namespace

postfx::Status runLookupProbe(demo::VulkanHost& host, const postfx::core::Gpu& gpu, postfx::Context& context,
                              postfx::FrameInfo f, const FogHarnessImages& images,
                              const std::vector<glm::vec4>& points, std::vector<float>& color,
                              LookupProbe& probe) {
    using namespace postfx::core;
    VkDescriptorSetLayoutBinding lookup[postfx::kVolumetricsLookupBindingCount];
    postfx::volumetricsLookupLayout(kBindings, VK_SHADER_STAGE_COMPUTE_BIT, lookup);
    std::vector<Binding> bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    for (const VkDescriptorSetLayoutBinding& b : lookup)
        bindings.push_back({b.binding, b.descriptorType});
    ComputePipelineDesc desc;
    desc.name = "test.lookup_probe";
    desc.spirv = frame_test_spirv::lookup_probe_comp;
    desc.bindings = bindings;
    ComputePipeline pipeline;
    if (postfx::Status s = pipeline.create(gpu, desc); !s) return s;
    DescriptorArena arena;
    if (postfx::Status s = arena.create(gpu, 1); !s) return s;
    if (postfx::Status s = arena.beginFrame(); !s) return s;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (postfx::Status s = arena.allocate(pipeline.setLayout(), set); !s) return s;
    GpuBuffer in, out;
    const VkDeviceSize bytes = points.size() * sizeof(glm::vec4);
    if (postfx::Status s = in.create(gpu, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "points"); !s)
        return s;
    if (postfx::Status s = out.create(gpu, 2 * bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "results");
        !s)
        return s;
    std::memcpy(in.mapped(), points.data(), bytes);
    DescriptorWrites(set)
        .storageBuffer(0, in.handle(), 0, VK_WHOLE_SIZE)
        .storageBuffer(1, out.handle(), 0, VK_WHOLE_SIZE)
        .apply(gpu);

    postfx::Status written;
    FogHarness harness(host, gpu);
    harness.onAfterRecord = [&](VkCommandBuffer cmd) {
        written = context.writeVolumetricsLookup(set, kBindings);
        if (!written) return;
        pipeline.bind(cmd, set, nullptr);
        vkCmdDispatch(cmd, uint32_t(points.size() + 63) / 64, 1, 1);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                             &toHost, 0, nullptr, 0, nullptr);
    };
    f.volumetricsLookup.enabled = true;
    f.cameraCut = true;
    if (postfx::Status s = harness.run(context, images, f, color); !s) return s;
    if (!written) return written;
    const glm::vec4* r = static_cast<const glm::vec4*>(out.mapped());
    probe = {};
    for (size_t p = 0; p < points.size(); ++p) {
        probe.L.push_back(glm::vec3(r[2 * p]));
        probe.T.push_back(glm::vec3(r[2 * p + 1]));
    }
    return postfx::Status::success();
}

}  // namespace test
