// The clouds' color and march images (clouds_shared.h's bindings). COLOR_RGBA32F selects the color
// format (common/color_format.glsl, which declares kColorMax); the march's image has the color's
// format, its accumulation (SCATTER_RGBA32F: the temporal history, which upsample.comp reads) RGBA32F.
#ifndef POSTFX_CLOUDS_IMAGES_GLSL
#define POSTFX_CLOUDS_IMAGES_GLSL

#include "common/color_format.glsl"
#if defined(COLOR_RGBA32F) || defined(SCATTER_RGBA32F)
#define CLOUD_SCATTER_FORMAT rgba32f
#else
#define CLOUD_SCATTER_FORMAT rgba16f
#endif

layout(binding = kCloudBindingColorIn, COLOR_FORMAT) uniform restrict readonly image2D colorIn;
layout(binding = kCloudBindingColorOut, COLOR_FORMAT) uniform restrict writeonly image2D colorOut;
layout(binding = kCloudBindingScatter, CLOUD_SCATTER_FORMAT) uniform restrict image2D scatterImage;

#endif
