// The composite target (docs/integration.md, "Color targets"). The effects composite in place into the
// host's color when it is RGBA16F or RGBA32F with STORAGE usage. Any other color target a renderer draws
// into (8-bit UNORM or sRGB, a swapchain image, B10G11R11, A2B10G10R10, or a float image without STORAGE)
// is blitted into postfx.target (RGBA16F; RGBA32F for an RGBA32F host image) before the first composite,
// composited there, and blitted back into the host's image (or its separate output) after the last: the
// blits do the sRGB decode and encode, the packing and the channel order, so no effect needs a variant
// per format.
#pragma once

#include "core/frame_graph.h"
#include "core/target_formats.h"

#include <string>

namespace postfx::core {

inline constexpr ResourceId kTargetImage{"postfx.target"};

// How postfx.target goes back into the host's image: a blit, or (a device that cannot blit into the
// format, as lavapipe for B10G11R11) a compute pass storing into it, which needs STORAGE usage and the
// format's storage feature.
enum class TargetStore : uint8_t { Blit, Compute };

// The device's format features for the frame's color and output through postfx.target: BLIT_SRC for the
// image loaded (optimal tiling); BLIT_DST for the one written, else its storage (`store` says which).
// Nothing to check when composited in place.
Status checkTargetFeatures(const Gpu& gpu, const FrameInfo& frame, TargetStore& store);

// Declares postfx.target and postfx.target_load (the host's color into it), before the effects declare,
// when the color is not composited in place. Culled when no effect composites.
void declareTargetLoad(const FrameGraph& graph, Frame& frame);
// Declares postfx.target_store (postfx.target into the host's output, else its color) after the effects,
// when one of them composited into postfx.target.
void declareTargetStore(const FrameGraph& graph, Frame& frame, TargetStore store);

}  // namespace postfx::core
