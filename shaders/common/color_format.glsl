// The storage format of the host's color images, for every effect's composite. COLOR_RGBA32F selects
// rgba32f (default rgba16f). Declares COLOR_FORMAT (the layout qualifier) and kColorMax: the format's
// largest finite value (composite.glsl clamps to it: never write Inf), and kColorMin: below it rgba16f
// keeps less than its 2^-11 precision (2^-14, its smallest normal; 0 for rgba32f, whose range postfx's
// radiance does not leave).
#ifndef POSTFX_COLOR_FORMAT_GLSL
#define POSTFX_COLOR_FORMAT_GLSL

#ifdef COLOR_RGBA32F
#define COLOR_FORMAT rgba32f
const float kColorMax = 3.402823466e38;
const float kColorMin = 0.0;
#else
#define COLOR_FORMAT rgba16f
const float kColorMax = 65504.0;         // largest finite half
const float kColorMin = 6.103515625e-5;  // smallest normal half
#endif

#endif
