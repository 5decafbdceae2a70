// The reduced-resolution march's output, postfx's own image (kFogBindingScatter): rgb in-scattered
// radiance L, a transmittance T. Same storage format as the color images (COLOR_RGBA32F).
#ifndef POSTFX_FOG_SCATTER_IMAGE_GLSL
#define POSTFX_FOG_SCATTER_IMAGE_GLSL

#ifdef COLOR_RGBA32F
layout(binding = kFogBindingScatter, rgba32f) uniform image2D scatterImage;
#else
layout(binding = kFogBindingScatter, rgba16f) uniform image2D scatterImage;
#endif

#endif
