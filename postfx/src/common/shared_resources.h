// The resources one effect declares for others to read, each declared once here (docs/architecture.md,
// "Shared resources"): the exporter declares its image or uniforms under the handle's id, and a reader
// finds it by the handle, never through the exporter's headers. The contents' contract (format, layout
// of the texels) is written beside each handle; the GLSL that samples them is in shaders/common/.
// Found only when the exporter declared it earlier this frame (composite order, postfx/src/effects.cpp).
#pragma once

#include "core/frame_graph.h"

namespace postfx::common {

// An image an effect exports.
struct SharedImage {
    core::ResourceId id;
};
// Uniform data an effect exports.
struct SharedUniforms {
    core::ResourceId id;
};

// The atmosphere's (docs/effects/atmosphere.md), with the atmosphere on:
// AtmosphereUniforms (shaders/common/air_shared.h).
inline constexpr SharedUniforms kAirUniforms{{"atmosphere.uniforms"}};
// rgba16f 2D: the transmittance from a point toward the sun (shaders/common/air/transmittance_lut.glsl).
inline constexpr SharedImage kSunTransmittanceLut{{"atmosphere.transmittance"}};
// rgba16f 3D: Hillaire's Ψ (one slice) or the scattering orders' source (air/orders_lookup.glsl).
inline constexpr SharedImage kAirMultipleScatteringLut{{"atmosphere.multiple_scattering"}};
// With multiple scattering off: a 1×1×1 transient at the same binding (samplers are 3D), never read.
inline constexpr SharedImage kAirMultipleScatteringStandIn{{"atmosphere.multiple_scattering_off"}};
// rgba16f 3D and 2D array: the aerial perspective's in-scattering and transmittance
// (air/aerial_perspective_lookup.glsl).
inline constexpr SharedImage kAerialPerspectiveLut{{"atmosphere.aerial_perspective"}};
inline constexpr SharedImage kAerialTransmittanceLut{{"atmosphere.aerial_transmittance"}};

// The clouds' (docs/effects/clouds.md, "Shadows"), when they cast shadows (common/cloud_shadow.h):
// r32f 2D, the transmittance toward the sun through the clouds (shaders/common/cloud_shadow.glsl).
inline constexpr SharedImage kCloudShadowMap{{"clouds.shadow_map"}};

// The image under `handle` declared earlier this frame; invalid when it was not.
inline core::ImageRef find(const core::FrameBuilder& builder, const SharedImage& handle) {
    return builder.find(handle.id);
}
inline core::BufferRef find(const core::FrameBuilder& builder, const SharedUniforms& handle) {
    return builder.findUniforms(handle.id);
}

// For a reader's sampled binding: the image under `handle`, linearly filtered; or, when it was not
// declared this frame, `standIn` bound only (the pipeline's layout has the binding; the shader's flag
// for it is off).
inline core::OptionalSampled sampledOrStandIn(const core::FrameBuilder& builder, const SharedImage& handle,
                                              core::ImageRef standIn) {
    const core::ImageRef image = find(builder, handle);
    if (image.valid()) return {image, core::Use::Sampled, core::SamplerKind::LinearClamp};
    return {standIn, core::Use::BoundOnly, core::SamplerKind::NearestClamp};
}

}  // namespace postfx::common
