// Tonemap of the windowed demo: HDR radiance (RGBA16F) -> 8-bit sRGB-encoded display values, the same
// curve as the CPU tonemap of .png files (demo/host/image_io.cpp), per RGB channel:
//   v = sRGB_OETF(ACES_fitted(L · exposure)),  stored as round(v · 255) / 255 (alpha 1).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(local_size_x = kTonemapGroupSize, local_size_y = kTonemapGroupSize) in;

layout(set = 0, binding = kTonemapBindingHdr, rgba16f) uniform readonly image2D hdr;
layout(set = 0, binding = kTonemapBindingOut, rgba8) uniform writeonly image2D display;

layout(push_constant, std430) uniform Push {
    TonemapPush push;
};

// ACES filmic curve fitted by Narkowicz (2015), input and output linear, output in [0, 1].
vec3 acesFitted(vec3 x) {
    x = max(x, vec3(0.0));
    return clamp((x * (kAcesA * x + kAcesB)) / (x * (kAcesC * x + kAcesD) + kAcesE), 0.0, 1.0);
}

vec3 srgbOetf(vec3 x) {
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThanEqual(x, vec3(kSrgbLinearLimit)));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), push.extent.xy))) return;

    vec3 radiance = imageLoad(hdr, pixel).rgb;
    vec3 v = clamp(srgbOetf(acesFitted(radiance * push.params.x)), 0.0, 1.0);
    // Exactly representable in 8 bits, so the UNORM conversion of the store cannot round differently
    // from the CPU tonemap's lround.
    v = floor(v * 255.0 + 0.5) / 255.0;
    if (push.params.y > 0.5) v = v.bgr;
    imageStore(display, pixel, vec4(v, 1.0));
}
