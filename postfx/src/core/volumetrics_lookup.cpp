// The volumetrics lookup's public calls (postfx/volumetrics_lookup.h): the host's layout bindings, and the
// last recorded frame's lookup as descriptors.
#include <postfx/context.h>

#include "common/lookup_shared.h"
#include "core/checks.h"
#include "core/context_impl.h"
#include "core/lookup_volume.h"

#include <string>

namespace postfx {

void volumetricsLookupLayout(const VolumetricsLookupBindings& bindings, VkShaderStageFlags stages,
                             VkDescriptorSetLayoutBinding (&out)[kVolumetricsLookupBindingCount]) {
    out[0] = {bindings.uniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr};
    out[1] = {bindings.scattering, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr};
    out[2] = {bindings.transmittance, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr};
}

Status Context::volumetricsLookup(VolumetricsLookup& out) const {
    out = {};
    Impl& impl = *impl_;
    if (!impl.lookupRecorded)
        return core::invalid(
            "volumetricsLookup: the last record() did not build it (FrameInfo.volumetricsLookup.enabled was "
            "false, or no frame was recorded)");
    const core::FrameGraph::HeldImage scattering = impl.graph.heldImage(core::kLookupScattering.name);
    const core::FrameGraph::HeldImage transmittance = impl.graph.heldImage(core::kLookupTransmittance.name);
    if (!scattering.image || !transmittance.image ||
        !impl.graph.uniformSlot(core::kLookupUniforms, impl.lookupFrame, out.uniformBuffer,
                                out.uniformOffset))
        return core::invalid("volumetricsLookup: its images are not held");
    if (Status s = impl.graph.sampler(core::SamplerKind::LinearClamp, out.sampler); !s) return s;
    out.frameIndex = impl.lookupFrame;
    out.uniformRange = sizeof(gpu::LookupUniforms);
    out.scattering = scattering.image->view();
    out.transmittance = transmittance.image->view();
    out.layout = scattering.layout;
    out.extent = scattering.image->desc().extent;
    return Status::success();
}

Status Context::writeVolumetricsLookup(VkDescriptorSet set, const VolumetricsLookupBindings& bindings) const {
    if (!set) return core::invalid("writeVolumetricsLookup: set is VK_NULL_HANDLE");
    if (bindings.uniforms == bindings.scattering || bindings.uniforms == bindings.transmittance ||
        bindings.scattering == bindings.transmittance)
        return core::invalid("writeVolumetricsLookup: bindings " + std::to_string(bindings.uniforms) + ", " +
                             std::to_string(bindings.scattering) + ", " +
                             std::to_string(bindings.transmittance) + " are not distinct");
    VolumetricsLookup lookup;
    if (Status s = volumetricsLookup(lookup); !s) return s;
    const VkDescriptorBufferInfo buffer{lookup.uniformBuffer, lookup.uniformOffset, lookup.uniformRange};
    const VkDescriptorImageInfo images[2] = {{lookup.sampler, lookup.scattering, lookup.layout},
                                             {lookup.sampler, lookup.transmittance, lookup.layout}};
    VkWriteDescriptorSet writes[3] = {};
    const uint32_t numbers[3] = {bindings.uniforms, bindings.scattering, bindings.transmittance};
    for (int i = 0; i < 3; ++i) {
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = set;
        writes[i].dstBinding = numbers[i];
        writes[i].descriptorCount = 1;
        writes[i].descriptorType =
            i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        if (i == 0)
            writes[i].pBufferInfo = &buffer;
        else
            writes[i].pImageInfo = &images[i - 1];
    }
    impl_->gpu.fn.vkUpdateDescriptorSets(impl_->gpu.device, 3, writes, 0, nullptr);
    return Status::success();
}

}  // namespace postfx
