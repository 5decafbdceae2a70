// The storage format of the host's color images, for every effect's composite. COLOR_RGBA32F selects
// rgba32f (default rgba16f). Declares COLOR_FORMAT (the layout qualifier) and kColorMax: the format's
// largest finite value (composite.glsl clamps to it: never write Inf).
#ifndef POSTFX_COLOR_FORMAT_GLSL
#define POSTFX_COLOR_FORMAT_GLSL

#ifdef COLOR_RGBA32F
#define COLOR_FORMAT rgba32f
const float kColorMax = 3.402823466e38;
#else
#define COLOR_FORMAT rgba16f
const float kColorMax = 65504.0;  // largest finite half
#endif

#endif
