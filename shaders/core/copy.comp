#version 450
// postfx.copy: out = color, for frames where the host gave a separate output image (FrameInfo::output) and
// no effect writes it (all off, or every medium empty; docs/frame-plan.md).
// Also postfx.target_store where the device cannot blit into the host's color target but can store to it
// (core/target.h): postfx.target (rgba16f) into the host's format, OUT_R11G11B10 (B10G11R11_UFLOAT),
// OUT_RGB10A2 (A2B10G10R10_UNORM), OUT_RGBA8 (R8G8B8A8_UNORM) or OUT_RGBA16 (R16G16B16A16_UNORM); the
// image store converts (rounding as the device's format conversion).
// Variants: COLOR_RGBA32F selects the storage format of the images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "common/shared.h"

layout(local_size_x = kCopyGroupSize, local_size_y = kCopyGroupSize) in;

#ifdef COLOR_RGBA32F
layout(binding = kCopyBindingIn, rgba32f) uniform readonly image2D colorIn;
layout(binding = kCopyBindingOut, rgba32f) uniform writeonly image2D colorOut;
#elif defined(OUT_R11G11B10) || defined(OUT_RGB10A2) || defined(OUT_RGBA8) || defined(OUT_RGBA16)
layout(binding = kCopyBindingIn, rgba16f) uniform readonly image2D colorIn;
#if defined(OUT_R11G11B10)
layout(binding = kCopyBindingOut, r11f_g11f_b10f) uniform writeonly image2D colorOut;
#elif defined(OUT_RGB10A2)
layout(binding = kCopyBindingOut, rgb10_a2) uniform writeonly image2D colorOut;
#elif defined(OUT_RGBA8)
layout(binding = kCopyBindingOut, rgba8) uniform writeonly image2D colorOut;
#else
layout(binding = kCopyBindingOut, rgba16) uniform writeonly image2D colorOut;
#endif
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
