// The reduced-resolution march's output, postfx's own image (kFogBindingScatter): rgb in-scattered
// radiance L, a transmittance T. Same storage format as the color images (COLOR_RGBA32F); SCATTER_RGBA32F:
// RGBA32F whatever the color format (the temporal history, which upsample.comp then composites).
#ifndef POSTFX_FOG_SCATTER_IMAGE_GLSL
#define POSTFX_FOG_SCATTER_IMAGE_GLSL

#if defined(COLOR_RGBA32F) || defined(SCATTER_RGBA32F)
layout(binding = kFogBindingScatter, rgba32f) uniform image2D scatterImage;
#else
layout(binding = kFogBindingScatter, rgba16f) uniform image2D scatterImage;
#endif

#endif
