// The clouds' color and march images (clouds_shared.h's bindings). COLOR_RGBA32F selects the color
// format (default rgba16f); the march's image has the color's format, its accumulation (SCATTER_RGBA32F:
// the temporal history, which upsample.comp reads) RGBA32F. Declares kColorMax: the color format's
// largest finite value (never write Inf).
#ifndef POSTFX_CLOUDS_IMAGES_GLSL
#define POSTFX_CLOUDS_IMAGES_GLSL

#ifdef COLOR_RGBA32F
#define CLOUD_COLOR_FORMAT rgba32f
const float kColorMax = 3.402823466e38;
#else
#define CLOUD_COLOR_FORMAT rgba16f
const float kColorMax = 65504.0;  // largest finite half
#endif
#if defined(COLOR_RGBA32F) || defined(SCATTER_RGBA32F)
#define CLOUD_SCATTER_FORMAT rgba32f
#else
#define CLOUD_SCATTER_FORMAT rgba16f
#endif

layout(binding = kCloudBindingColorIn, CLOUD_COLOR_FORMAT) uniform restrict readonly image2D colorIn;
layout(binding = kCloudBindingColorOut, CLOUD_COLOR_FORMAT) uniform restrict writeonly image2D colorOut;
layout(binding = kCloudBindingScatter, CLOUD_SCATTER_FORMAT) uniform restrict image2D scatterImage;

#endif
