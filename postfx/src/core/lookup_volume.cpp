// The volumetrics lookup's declarations (core/lookup_volume.h).
#include "core/lookup_volume.h"

#include "common/lookup_shared.h"
#include "core/camera_math.h"
#include "core/frame_graph.h"
#include "core/frame_graph_internal.h"
#include "postfx_objects_spirv.h"

#include <cmath>

namespace postfx::core {
namespace {

constexpr Binding kClearBindings[] = {kLookupUniformsBinding, kLookupScatteringBinding,
                                      kLookupTransmittanceBinding};
const ComputePipelineDesc kClear{"postfx.lookup_clear", spirv::core_lookup_clear_comp, kClearBindings,
                                 kLookupPushBytes};

// `frame` in postfx's world frame; the host's shaders get its camera and its camera-relative positions back
// in its own (`world`), postfx's passes the inverse in postfx's.
gpu::LookupUniforms lookupUniforms(const FrameInfo& frame, const WorldTransform& world) {
    const VolumetricsLookupSettings& s = frame.volumetricsLookup;
    const glm::dmat4 relativeToClip = glm::dmat4(frame.camera.projection) * rotationOnly(frame.camera.view);
    gpu::LookupUniforms u{};
    u.relativeToClip = glm::mat4(relativeToClip * world.toPostfx());
    u.clipToRelative = glm::mat4(glm::inverse(relativeToClip));
    u.camera = glm::vec4(glm::vec3(world.hostPosition(frame.camera.position)), frame.preExposure);
    u.world = glm::vec4(float(1.0 / world.unitsPerMetre()), 0.0f, 0.0f, 0.0f);
    u.slices = glm::vec4(s.nearDistance, s.maxDistance,
                         float(std::log(double(s.maxDistance) / double(s.nearDistance))), float(s.extent.z));
    return u;
}

}  // namespace

LookupTarget FrameBuilder::lookupTarget() {
    LookupTarget t;
    const VolumetricsLookupSettings& s = f_.info->volumetricsLookup;
    if (!s.enabled) return t;
    if (f_.lookupScattering == kNoResource) {
        FrameBuilder context(graph_, f_, -1);  // the context's, whichever effect declares it first
        ImageDesc desc;
        desc.type = VK_IMAGE_TYPE_3D;
        desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
        desc.extent = {s.extent.x, s.extent.y, s.extent.z};
        desc.sizedBy = "FrameInfo.volumetricsLookup.extent";
        desc.usage =
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        const ImageRef scattering = context.transientImage(kLookupScattering, desc);
        const ImageRef transmittance = context.transientImage(kLookupTransmittance, desc);
        context.exportImage(scattering);
        context.exportImage(transmittance);
        const gpu::LookupUniforms u = lookupUniforms(*f_.info, f_.world);
        f_.lookupUniforms = context.uniforms(kLookupUniforms, &u, sizeof u).index;
        f_.lookupScattering = scattering.index;
        f_.lookupTransmittance = transmittance.index;
    }
    t.scattering = {f_.lookupScattering};
    t.transmittance = {f_.lookupTransmittance};
    t.uniforms = {f_.lookupUniforms};
    t.use = f_.lookupWritten ? Use::StorageReadWrite : Use::StorageWrite;
    t.push[0] = f_.lookupWritten ? 0u : 1u;
    t.extent[0] = s.extent.x;
    t.extent[1] = s.extent.y;
    t.extent[2] = s.extent.z;
    f_.lookupWritten = true;
    return t;
}

void bindLookup(FrameBuilder& b, const LookupTarget& t) {
    b.bind(gpu::kLookupBindingUniforms, t.uniforms)
        .bind(gpu::kLookupBindingScattering, t.scattering, t.use)
        .bind(gpu::kLookupBindingTransmittance, t.transmittance, t.use)
        .push(t.push, sizeof t.push);
}

void lookupGroups(const LookupTarget& t, bool columns, uint32_t (&groups)[3]) {
    const uint32_t g = columns ? gpu::kLookupColumnGroupSize : gpu::kLookupGroupSize;
    groups[0] = (t.extent[0] + g - 1) / g;
    groups[1] = (t.extent[1] + g - 1) / g;
    groups[2] = columns ? 1 : (t.extent[2] + g - 1) / g;
}

void declareLookupClear(const FrameGraph& graph, Frame& f) {
    if (!f.info->volumetricsLookup.enabled || f.lookupWritten) return;
    FrameBuilder b(graph, f, -1);
    const LookupTarget t = b.lookupTarget();
    uint32_t groups[3];
    lookupGroups(t, false, groups);
    b.pass(kClear, groups[0], groups[1], groups[2]);
    bindLookup(b, t);
}

}  // namespace postfx::core
