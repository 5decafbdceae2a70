// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare"), animated per frame by shifting the pixel 5.588238 px per frame over a 64-frame cycle.
#ifndef POSTFX_IGN_GLSL
#define POSTFX_IGN_GLSL

float interleavedGradientNoise(uvec2 pixel, uint frameIndex) {
    float shift = 5.588238 * float(frameIndex % 64u);
    vec2 p = vec2(pixel) + shift;
    return fract(52.9829189 * fract(0.06711056 * p.x + 0.00583715 * p.y));
}

#endif
