// The volumetrics lookup's frame declarations (postfx/volumetrics_lookup.h): its images and uniforms,
// which FrameBuilder::lookupTarget declares for the first effect that composites into it, and
// postfx.lookup_clear for a frame none does.
#pragma once

#include "common/lookup_shared.h"
#include "core/frame_builder.h"

namespace postfx::core {

class FrameGraph;

inline constexpr ResourceId kLookupScattering{"postfx.lookup_scattering"};
inline constexpr ResourceId kLookupTransmittance{"postfx.lookup_transmittance"};
inline constexpr ResourceId kLookupUniforms{"postfx.lookup"};

// The bindings of a lookup pass's part of the volume (shaders/common/lookup.glsl), for its layout.
inline constexpr Binding kLookupUniformsBinding{gpu::kLookupBindingUniforms,
                                                VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
inline constexpr Binding kLookupScatteringBinding{gpu::kLookupBindingScattering,
                                                  VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
inline constexpr Binding kLookupTransmittanceBinding{gpu::kLookupBindingTransmittance,
                                                     VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
inline constexpr uint32_t kLookupPushBytes = sizeof(gpu::LookupPush);

// Binds `target` (its images, uniforms and push constants) to the pass just declared.
void bindLookup(FrameBuilder& builder, const LookupTarget& target);
// Workgroups of a pass over every froxel of `target` (per column: over x and y only).
void lookupGroups(const LookupTarget& target, bool columns, uint32_t (&groups)[3]);

// Declares postfx.lookup_clear when the frame asks for the lookup and no effect wrote it.
void declareLookupClear(const FrameGraph& graph, Frame& frame);

}  // namespace postfx::core
