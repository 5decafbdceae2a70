#version 450
// Temporal accumulation of the ray-marched fog (docs/effects/fog.md#temporal): one invocation per texel
// of the march blends this frame's (L, T) with the previous frames' accumulated (L, T), reprojected.
//   1. The march stored each texel's surface distance (∞ without geometry, -1 for a NaN depth).
//   2. The ray ends at p = dir · min(surface, max distance); the previous camera saw p at
//      previousClip · p. Off the previous image, or behind the previous camera: no history.
//   3. Of the 2×2 history texels around it (this texel moved by the point's screen motion), those
//      whose own ray ended within kFogTemporalDistanceTolerance of |p - previous camera| are blended
//      bilinearly (disocclusion: none matches, no history); non-finite history never matches.
//   4. The history is clamped to the min/max box of this frame's 3×3 neighbourhood (Karis 2014), so
//      what no longer belongs (moving shadows, a changed medium) cannot stay.
//   5. This frame's estimate: a still texel's own value; a texel that moved by at least
//      kFogTemporalFilterMotion texels the mean of the 3×3 texels whose surface is within
//      kFogTemporalDistanceTolerance of its own (no fog crosses a silhouette; sky only with sky) and
//      whose fog is within kFogTemporalFilterRange of its own (similarFog); in between a mix. A
//      still texel's jitter sequence is stratified over the frames (interleaved gradient noise);
//      motion breaks it, as its history comes from other texels, but neighbouring texels' offsets
//      are spread over the step, so their mean is a stratified estimate of this frame.
//   6. result = history + w·(estimate - history), w = cameraDelta.w; without history (disoccluded, come
//      into view) the estimate alone; after a reset, every texel its own value.
// The result is the history, which upsample.comp composites at a reduced resolution; at full size this
// pass composites it too (COMPOSITE: out = color · T + L). Scene color is never in the history.
// The history is RGBA32F whatever the color format: blended in half precision, an update smaller than
// half an ulp (w·|current - history| < 2.4e-4·history) would be lost, and the history would stop
// converging about 0.25% from its mean (fog.md#temporal).
// Variants: COLOR_RGBA32F selects the storage format of the scatter and color images (this frame's march);
// COMPOSITE (resolution scale 1) also composites the result over the host's color.
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = kFogGroupSize, local_size_y = kFogGroupSize) in;

#include "fog/bindings.glsl"
#include "fog/scatter_image.glsl"
#include "common/color_format.glsl"

layout(binding = kFogBindingHistoryIn, rgba32f) uniform readonly image2D historyIn;
layout(binding = kFogBindingHistoryOut, rgba32f) uniform writeonly image2D historyOut;
layout(binding = kFogBindingDistanceIn, r32f) uniform readonly image2D distanceIn;
layout(binding = kFogBindingDistance, r32f) uniform readonly image2D distanceCurrent;  // from the march
layout(binding = kFogBindingTemporal, std140) uniform Temporal {
    TemporalUniforms temporal;
};
#include "common/history_rescale.glsl"

#include "common/medium/ray.glsl"
#ifdef COMPOSITE
#include "common/composite.glsl"
#endif

bool finite(vec4 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// The history at the previous frame's view of `point` (camera-relative), the end of texel `texel`'s ray
// through its source pixel's centre `uvSource`, bilinear over the texels whose ray ended at the same
// distance; false when there is none.
bool reprojectedHistory(vec3 point, uvec2 texel, vec2 uvSource, float maxDistance, out vec4 history,
                        out float motion) {
    history = vec4(0.0);
    motion = kInfinity;  // not seen by the previous camera: come into view
    vec4 clip = temporal.previousClip * vec4(point, 1.0);
    if (!(clip.w > 0.0)) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    vec2 offset = (uv - uvSource) * vec2(fog.scatterExtent.xy);
    // A still view reprojects each texel a rounding error beside itself: read the texel itself (one tap,
    // not four; no filter).
    offset = mix(offset, vec2(0.0), lessThan(abs(offset), vec2(1e-3)));
    motion = length(offset);
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return false;
    float expected = min(length(point + temporal.cameraDelta.xyz), maxDistance);

    // Where the history holds it, in texels: this texel moved by the point's motion on screen. (Each texel
    // holds its source pixel's ray, which at a reduced resolution is not at the texel's centre; mapping
    // uv to texels directly would read a still view a fraction of a texel beside itself, and blur.)
    ivec2 size = ivec2(fog.scatterExtent.xy);
    vec2 p = vec2(texel) + offset;
    ivec2 p0 = ivec2(floor(p));
    vec2 f = p - vec2(p0);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 q = clamp(p0 + o, ivec2(0), size - 1);
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        if (!(w > 0.0)) continue;  // not loaded
        vec4 h = imageLoad(historyIn, q);
        float d = min(imageLoad(distanceIn, q).r, maxDistance);  // where that texel's ray ended
        // The march's estimates are stored in the color format (scatterImage): clipped or underflowed
        // history is not rescaled to this frame's pre-exposure.
        if (finite(h) && !rescalableHistory(h.rgb, kColorMax, kColorMin)) return false;
        if (finite(h) && abs(d - expected) <= kFogTemporalDistanceTolerance * expected) {
            sum += w * h;
            weight += w;
        }
    }
    // Matching taps that carry almost none of the bilinear weight are rounding (a texel centre that
    // reprojects a hair beside itself), not a surface seen last frame.
    if (!(weight > 1e-3)) return false;
    history = sum / weight;
    history.rgb *= temporal.previous.y;  // the previous frame's pre-exposure -> this one's
    return true;
}

// Whether a neighbour's surface distance `d` is this texel's `own` within kFogTemporalDistanceTolerance,
// surfaces beyond the fog's reach included: sky against ground beyond max distance differ (their rays end
// at the same distance, but one goes up through no fog and the other down through the densest).
bool sameSurface(float d, float own) {
    return isinf(own) ? isinf(d) : abs(d - own) <= kFogTemporalDistanceTolerance * own;
}

// Whether a neighbour's (L, T) `n` is within kFogTemporalFilterRange of this texel's `own` (T absolute,
// the sum of L's channels relative to the larger): more than the jitter's noise, less than an edge in the
// fog that depth does not show (a shadow's edge; a ray just above a fog layer beside one just inside).
bool similarFog(vec4 n, vec4 own) {
    float l = n.r + n.g + n.b, lOwn = own.r + own.g + own.b;
    return abs(n.a - own.a) <= kFogTemporalFilterRange &&
           abs(l - lOwn) <= kFogTemporalFilterRange * max(abs(l), abs(lOwn));
}

// This group's texels and a one-texel border: this frame's march result and its ray-end distance.
shared vec4 tileScatter[kFogGroupSize + 2][kFogGroupSize + 2];
shared float tileDistance[kFogGroupSize + 2][kFogGroupSize + 2];

void loadTile(ivec2 size) {
    const int edge = int(kFogGroupSize) + 2;
    ivec2 origin = ivec2(gl_WorkGroupID.xy * kFogGroupSize) - 1;
    for (uint i = gl_LocalInvocationIndex; i < uint(edge * edge); i += kFogGroupSize * kFogGroupSize) {
        ivec2 local = ivec2(int(i) % edge, int(i) / edge);
        ivec2 q = clamp(origin + local, ivec2(0), size - 1);
        tileScatter[local.y][local.x] = imageLoad(scatterImage, q);
        tileDistance[local.y][local.x] = imageLoad(distanceCurrent, q).r;
    }
    barrier();
}

void main() {
    ivec2 size = ivec2(fog.scatterExtent.xy);
    loadTile(size);  // every invocation takes part, before any returns
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, uvec2(size)))) return;
    ivec2 local = ivec2(gl_LocalInvocationID.xy) + 1;
    vec4 current = tileScatter[local.y][local.x];
    float distance = tileDistance[local.y][local.x];

    // The 3×3 neighbourhood's min/max box clamps the history.
    vec4 lo = current, hi = current;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 n = tileScatter[local.y + y][local.x + x];
            if (finite(n)) {
                lo = min(lo, n);
                hi = max(hi, n);
            }
        }

    vec4 result = current;
    vec4 history;
    float motion;
    uvec2 source = fogSourcePixel(texel);
    if (temporal.state.x != 0u && finite(current) && distance >= 0.0) {
        bool found =
            reprojectedHistory(fogRayDirection(source) * min(distance, fog.medium.w), texel,
                               (vec2(source) + 0.5) / vec2(fog.extent.xy), fog.medium.w, history, motion);
        // A still texel keeps its own jitter sequence, stratified over the frames: its own value, so a
        // still view converges to the unfiltered mean; a moving one (or one come into view) the mean of
        // its neighbours with its surface and its fog (step 5 above).
        vec4 estimate = current;
        if (motion > 0.0) {
            vec4 sum = vec4(0.0);
            float count = 0.0;
            for (int y = -1; y <= 1; ++y)
                for (int x = -1; x <= 1; ++x) {
                    vec4 n = tileScatter[local.y + y][local.x + x];
                    if (finite(n) && sameSurface(tileDistance[local.y + y][local.x + x], distance) &&
                        similarFog(n, current)) {
                        sum += n;
                        count += 1.0;
                    }
                }
            if (count > 0.0)
                estimate = mix(current, sum / count, min(motion / kFogTemporalFilterMotion, 1.0));
        }
        result = found ? mix(clamp(history, lo, hi), estimate, temporal.cameraDelta.w) : estimate;
    }
    imageStore(historyOut, ivec2(texel), result);
#ifdef COMPOSITE
    vec4 color = imageLoad(colorIn, ivec2(texel));
    imageStore(colorOut, ivec2(texel), vec4(compositeOver(color.rgb, result.a, result.rgb), color.a));
#endif
}
