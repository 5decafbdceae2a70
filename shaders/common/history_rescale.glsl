// Whether a temporal history texel may be rescaled to this frame's pre-exposure (docs/temporal.md, "What
// resets history, and what rejects it"). Expects TemporalUniforms `temporal` (common/shared.h).
//   rgb:      the texel's radiance as stored, pre-exposed with the previous frame's pre-exposure
//   largest:  the largest finite value of the format the estimates were stored in (they were clamped to it)
//   smallest: that format's smallest normal value (below it half keeps less than its 2^-11 precision)
// A texel at or near `largest` clipped: after a pre-exposure drop its rescaled value would be far below
// this frame's, a ghost that fades only with the blend. A texel below `smallest` (or flushed to 0) lost
// its digits: after a rise its rescaled rounding would show. Both take this frame's estimate alone.
#ifndef POSTFX_HISTORY_RESCALE_GLSL
#define POSTFX_HISTORY_RESCALE_GLSL

bool rescalableHistory(vec3 rgb, float largest, float smallest) {
    float scale = temporal.previous.y;
    float m = max(rgb.r, max(rgb.g, rgb.b));
    if (scale < 1.0) return m < kTemporalClipFraction * largest;
    if (scale > 1.0) return m >= smallest;
    return true;
}

#endif
