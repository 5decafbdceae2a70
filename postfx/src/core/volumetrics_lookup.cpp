// The volumetrics lookup's public calls (postfx/volumetrics_lookup.h): the host's layout bindings, and the
// last recorded frame's lookup as descriptors.
#include <postfx/context.h>

#include "core/checks.h"
#include "core/context_impl.h"

namespace postfx {

void volumetricsLookupLayout(const VolumetricsLookupBindings& bindings, VkShaderStageFlags stages,
                             VkDescriptorSetLayoutBinding (&out)[kVolumetricsLookupBindingCount]) {
    out[0] = {bindings.uniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr};
    out[1] = {bindings.scattering, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr};
    out[2] = {bindings.transmittance, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr};
}

Status Context::volumetricsLookup(VolumetricsLookup& out) const {
    out = {};
    return impl_->report(core::invalid("volumetricsLookup: not built yet"));
}

Status Context::writeVolumetricsLookup(VkDescriptorSet set, const VolumetricsLookupBindings& bindings) const {
    VolumetricsLookup lookup;
    if (Status s = volumetricsLookup(lookup); !s) return s;
    (void)set;
    (void)bindings;
    return Status::success();
}

}  // namespace postfx
