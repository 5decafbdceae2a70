#version 450
// postfx.copy: out = color, for frames where the host gave a separate output image (FrameInfo::output) and
// no effect writes it (all off, or every medium empty; docs/frame-plan.md).
// Variants: COLOR_RGBA32F selects the storage format of the images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "common/shared.h"

layout(local_size_x = kCopyGroupSize, local_size_y = kCopyGroupSize) in;

#ifdef COLOR_RGBA32F
layout(binding = kCopyBindingIn, rgba32f) uniform readonly image2D colorIn;
layout(binding = kCopyBindingOut, rgba32f) uniform writeonly image2D colorOut;
#else
layout(binding = kCopyBindingIn, rgba16f) uniform readonly image2D colorIn;
layout(binding = kCopyBindingOut, rgba16f) uniform writeonly image2D colorOut;
#endif
// clang-format off
layout(push_constant) uniform Push { uvec2 extent; } pc;
// clang-format on

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, pc.extent))) return;
    imageStore(colorOut, ivec2(pixel), imageLoad(colorIn, ivec2(pixel)));
}
