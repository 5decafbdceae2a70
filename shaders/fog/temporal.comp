#version 450
// Temporal accumulation of the ray-marched fog (docs/effects/fog.md#temporal): one invocation per texel
// of the march blends this frame's (L, T) with the previous frames' accumulated (L, T), reprojected.
//   1. The texel's ray ends at p = dir · min(surface, max distance); the previous camera saw p at
//      previousClip · p. Off the previous image, or behind the previous camera: no history.
//   2. Of the 2×2 history texels around it (this texel moved by the point's screen motion), those
//      whose own ray ended within kFogTemporalDistanceTolerance of |p - previous camera| are blended
//      bilinearly (disocclusion: none matches, no history); non-finite history never matches.
//   3. The history is clamped to the min/max box of this frame's 3×3 neighbourhood (Karis 2014), so
//      what no longer belongs (moving shadows, a changed medium) cannot stay.
//   4. result = history + w·(current - history), w = cameraDelta.w (1 without history).
// The result is what upsample.comp composites; scene color is never in it.
// The history is RGBA32F whatever the color format: blended in half precision, an update smaller than
// half an ulp (w·|current - history| < 2.4e-4·history) would be lost, and the history would stop
// converging about 0.25% from its mean (fog.md#temporal).
// Variants: COLOR_RGBA32F selects the storage format of the scatter image (this frame's march).
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = kFogGroupSize, local_size_y = kFogGroupSize) in;

#include "fog/bindings.glsl"
#include "fog/scatter_image.glsl"

layout(binding = kFogBindingHistoryIn, rgba32f) uniform readonly image2D historyIn;
layout(binding = kFogBindingHistoryOut, rgba32f) uniform writeonly image2D historyOut;
layout(binding = kFogBindingDistanceIn, r32f) uniform readonly image2D distanceIn;
layout(binding = kFogBindingDistanceOut, r32f) uniform writeonly image2D distanceOut;
layout(binding = kFogBindingTemporal, std140) uniform Temporal {
    TemporalUniforms temporal;
};

#include "fog/ray.glsl"

bool finite(vec4 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// The history at the previous frame's view of `point` (camera-relative), the end of texel `texel`'s ray
// through its source pixel's centre `uvSource`, bilinear over the texels whose ray ended at the same
// distance; false when there is none.
bool reprojectedHistory(vec3 point, uvec2 texel, vec2 uvSource, float maxDistance, out vec4 history) {
    history = vec4(0.0);
    vec4 clip = temporal.previousClip * vec4(point, 1.0);
    if (!(clip.w > 0.0)) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return false;
    float expected = min(length(point + temporal.cameraDelta.xyz), maxDistance);

    // Where the history holds it, in texels: this texel moved by the point's motion on screen. (Each texel
    // holds its source pixel's ray, which at a reduced resolution is not at the texel's centre; mapping
    // uv to texels directly would read a still view a fraction of a texel beside itself, and blur.)
    ivec2 size = ivec2(fog.scatterExtent.xy);
    vec2 p = vec2(texel) + (uv - uvSource) * vec2(size);
    ivec2 p0 = ivec2(floor(p));
    vec2 f = p - vec2(p0);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 q = clamp(p0 + o, ivec2(0), size - 1);
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        vec4 h = imageLoad(historyIn, q);
        float d = imageLoad(distanceIn, q).r;
        if (w > 0.0 && finite(h) && abs(d - expected) <= kFogTemporalDistanceTolerance * expected) {
            sum += w * h;
            weight += w;
        }
    }
    // Matching taps that carry almost none of the bilinear weight are rounding (a texel centre that
    // reprojects a hair beside itself), not a surface seen last frame.
    if (!(weight > 1e-3)) return false;
    history = sum / weight;
    return true;
}

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    ivec2 size = ivec2(fog.scatterExtent.xy);
    if (any(greaterThanEqual(texel, uvec2(size)))) return;
    vec4 current = imageLoad(scatterImage, ivec2(texel));
    uvec2 source = fogSourcePixel(texel);
    FogRay ray = fogRay(source);
    float maxDistance = fog.medium.w;
    // NaN (a host's bad depth) stores as no distance any reprojection matches.
    float distance = isnan(ray.surfaceDistance) ? -1.0 : min(ray.surfaceDistance, maxDistance);
    imageStore(distanceOut, ivec2(texel), vec4(distance));

    vec4 result = current;
    vec4 history;
    if (temporal.state.x != 0u && finite(current) && distance >= 0.0 &&
        reprojectedHistory(ray.dir * distance, texel, (vec2(source) + 0.5) / vec2(fog.extent.xy), maxDistance,
                           history)) {
        vec4 lo = current, hi = current;
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                vec4 n = imageLoad(scatterImage, clamp(ivec2(texel) + ivec2(x, y), ivec2(0), size - 1));
                if (finite(n)) {
                    lo = min(lo, n);
                    hi = max(hi, n);
                }
            }
        result = mix(clamp(history, lo, hi), current, temporal.cameraDelta.w);
    }
    imageStore(historyOut, ivec2(texel), result);
}
