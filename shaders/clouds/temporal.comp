#version 450
// Temporal accumulation of the clouds' march (docs/effects/clouds.md, "Resolution and temporal"): one
// invocation per march texel blends this frame's (L, T) with the accumulated (L, T) of the previous
// frames, reprojected.
//   1. The march stored each texel's distances (clouds/distances.glsl): the reprojection distance r
//      (the clouds' extinction-weighted mean distance, or where the ray ends when it meets none) and
//      the host's surface s along the ray (+Inf: none).
//   2. That point, p = dir·r, moved back by the wind since the previous frame, is where the previous
//      camera saw it: previousClip · (p - windDelta). Off the previous image or behind the camera: no
//      history.
//   3. Of the 2×2 history texels around it, those whose own surface is within
//      kCloudTemporalDistanceTolerance of this texel's surface seen from the previous camera,
//      |dir·s + cameraDelta| (or which, like it, saw none), are blended bilinearly: geometry that moved
//      in front of the clouds, or away, matches none and gives no history. (The clouds' own mean
//      distance changes with the jitter from frame to frame, so it does not decide.)
//   4. The history is clamped to the min/max box of this frame's 3×3 neighbourhood (Karis 2014).
//   5. result = history + w·(current - history), w = cameraDelta.w (a running mean after a reset, then
//      the blend weight); without history, the current value.
// Sparse update (cl.sparse.x = k > 1): the march updated one texel of each k×k block (cl.sparse.yz); the
// history is not clamped (step 4: a box of updated texels k apart is too coarse), and the blend weight is the
// texel's own running mean after a reset (postfx/src/clouds/clouds_effect.cpp). A texel the march
// skipped keeps its reprojected history; without history it takes the bilinear mix of the updated texels
// around it. Its reprojection distance is that of the updated texels around it that saw its surface (else
// where its own ray ends), its surface its own; both are written into this frame's distances for the next
// frame (the march wrote the updated texels').
// The alpha channel accumulates the optical depth τ = -ln T, not T: each frame's jittered march gives an
// unbiased τ, and e^{-mean τ} converges to the true T, where the mean of e^{-τ} would be too bright by
// Jensen's inequality (the sun's disk through a thin cloud at sunset: +11% with 64 steps on the H100). The
// upsample takes e^{-τ} of each texel (kCloudFlagOpticalDepthHistory). The history is RGBA32F whatever the
// color format (in half, small updates would be lost). Variant COLOR_RGBA32F: the march's image is RGBA32F.
#extension GL_GOOGLE_include_directive : require

#include "clouds/clouds_shared.h"

layout(local_size_x = kCloudGroupSize, local_size_y = kCloudGroupSize) in;

layout(binding = kCloudBindingUniforms, std140) uniform Uniforms {
    CloudUniforms cl;
};
#include "clouds/images.glsl"
// Read at the updated texels, written at the skipped ones (a sparse update).
layout(binding = kCloudBindingDistance, r32ui) uniform restrict uimage2D distanceCurrent;
layout(binding = kCloudBindingDepth) uniform sampler2D depthTexture;
layout(binding = kCloudBindingHistoryIn, rgba32f) uniform restrict readonly image2D historyIn;
layout(binding = kCloudBindingHistoryOut, rgba32f) uniform restrict writeonly image2D historyOut;
layout(binding = kCloudBindingDistanceIn, r32ui) uniform restrict readonly uimage2D distanceIn;
layout(binding = kCloudBindingTemporal, std140) uniform Temporal {
    TemporalUniforms temporal;
};
#include "common/history_rescale.glsl"
#include "clouds/distances.glsl"
#include "clouds/ray.glsl"

bool finite(vec4 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// (L, T) of the march as (L, τ): T below kCloudMinHistoryTransmittance counts as that.
vec4 withOpticalDepth(vec4 v) {
    return vec4(v.rgb, -log(max(v.a, kCloudMinHistoryTransmittance)));
}

// The unit direction of march texel `texel`'s view ray, through its centre (camera-relative).
vec3 rayDirection(uvec2 texel) {
    vec2 ndc = (vec2(texel) + 0.5) / vec2(cl.marchExtent.xy) * 2.0 - 1.0;
    vec4 p = cl.clipToView * vec4(ndc, 0.5, 1.0);
    return normalize(p.w < 0.0 ? -p.xyz : p.xyz);
}

// Whether a history texel that saw a surface at `seen` [m] (+Inf: none) saw the surface expected at
// `expected` (the same, from the previous camera).
bool sameSurface(float seen, float expected) {
    if (isinf(expected) || isinf(seen)) return isinf(expected) && isinf(seen);
    return abs(seen - expected) <= kCloudTemporalDistanceTolerance * expected;
}

// The history where the previous camera saw camera-relative `point` (already moved back by the wind),
// which this frame's texel `texel` sees through its centre `uvTexel`; its surface, seen from the
// previous camera, is at `expectedSurface` [m] (+Inf: none); false when no history matches.
bool reprojectedHistory(vec3 point, uvec2 texel, vec2 uvTexel, float expectedSurface, out vec4 history) {
    history = vec4(0.0);
    vec4 clip = temporal.previousClip * vec4(point, 1.0);
    if (!(clip.w > 0.0)) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThanEqual(uv, vec2(1.0)))) return false;
    ivec2 size = ivec2(cl.marchExtent.xy);
    vec2 offset = (uv - uvTexel) * vec2(size);
    // A still view reprojects each texel a rounding error beside itself: read the texel itself.
    offset = mix(offset, vec2(0.0), lessThan(abs(offset), vec2(1e-3)));
    // Catmull-Rom weights over the 4×4 texels around p (a bilinear read blurs the history a little at
    // every frame of a moving view; this keeps it sharp), over the texels whose surface matches.
    vec2 p = vec2(texel) + offset;
    ivec2 p0 = ivec2(floor(p));
    vec2 f = p - vec2(p0);
    vec2 f2 = f * f, f3 = f2 * f;
    vec2 w4[4] = vec2[4](-0.5 * f3 + f2 - 0.5 * f, 1.5 * f3 - 2.5 * f2 + 1.0, -1.5 * f3 + 2.0 * f2 + 0.5 * f,
                         0.5 * f3 - 0.5 * f2);
    vec4 sum = vec4(0.0);
    vec4 innerLo = vec4(1e30), innerHi = vec4(-1e30);  // the matching texels of the bilinear 2×2
    float weight = 0.0, positive = 0.0;
    for (int k = 0; k < 16; ++k) {
        ivec2 o = ivec2(k & 3, k >> 2);
        float w = w4[o.x].x * w4[o.y].y;
        if (w == 0.0) continue;
        ivec2 q = clamp(p0 + o - 1, ivec2(0), size - 1);
        vec4 h = imageLoad(historyIn, q);
        vec2 d = unpackCloudDistances(imageLoad(distanceIn, q).r);
        // The march's estimates are stored in the color format (images.glsl): clipped or underflowed
        // history is not rescaled to this frame's pre-exposure.
        if (finite(h) && !rescalableHistory(h.rgb, kColorMax, kColorMin)) return false;
        if (finite(h) && d.x >= 0.0 && sameSurface(d.y, expectedSurface)) {
            sum += w * h;
            weight += w;
            positive += max(w, 0.0);
            if (all(greaterThanEqual(o, ivec2(1))) && all(lessThanEqual(o, ivec2(2)))) {
                innerLo = min(innerLo, h);
                innerHi = max(innerHi, h);
            }
        }
    }
    // Too little of the footprint matched (its positive lobes mostly rejected): no history.
    if (!(weight > 0.25) || !(positive > 0.5)) return false;
    history = sum / weight;
    // A sparse update's history is not clamped to a neighbourhood box: without this, Catmull-Rom's
    // overshoot would grow frame after frame while a skipped texel is only resampled (a moving view).
    if (cl.sparse.x > 1u && innerLo.x <= innerHi.x) history = clamp(history, innerLo, innerHi);
    history.rgb *= temporal.previous.y;  // the previous frame's pre-exposure -> this one's
    return true;
}

// The texel the march updated in block `block` of the sparse grid, the block clamped to those whose
// updated texel lies inside the image (every block's, with a full update).
ivec2 updatedTexel(ivec2 block) {
    ivec2 k = ivec2(cl.sparse.x), offset = ivec2(cl.sparse.yz);
    ivec2 last = (ivec2(cl.marchExtent.xy) - 1 - offset) / k;
    return clamp(block, ivec2(0), last) * k + offset;
}

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, cl.marchExtent.xy))) return;
    // Where the texel lies in the grid of updated texels: between blocks b0 and b0 + 1 by f.
    vec2 grid = (vec2(texel) - vec2(cl.sparse.yz)) / float(cl.sparse.x);
    ivec2 b0 = ivec2(floor(grid)), nearest = ivec2(round(grid));
    vec2 f = grid - vec2(b0);
    bool updated = all(equal(texel % cl.sparse.x, cl.sparse.yz));

    // The 3×3 updated texels' min/max box clamps the history.
    vec4 lo = vec4(1e30), hi = vec4(-1e30);
    vec4 sum = vec4(0.0), sumSquares = vec4(0.0);
    float count = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 n = withOpticalDepth(imageLoad(scatterImage, updatedTexel(nearest + ivec2(x, y))));
            if (finite(n)) {
                lo = min(lo, n);
                hi = max(hi, n);
                sum += n;
                sumSquares += n * n;
                count += 1.0;
            }
        }
    // Variance clipping (Salvi 2016): the box mean ± γ·σ, inside the min/max box (none finite: 0).
    vec4 mean = sum / max(count, 1.0);
    vec4 sigma = sqrt(max(sumSquares / max(count, 1.0) - mean * mean, vec4(0.0)));
    lo = count > 0.0 ? max(lo, mean - kCloudTemporalClipGamma * sigma) : vec4(0.0);
    hi = count > 0.0 ? min(hi, mean + kCloudTemporalClipGamma * sigma) : vec4(0.0);

    vec4 current;
    vec2 distances;
    vec3 dir;
    if (updated) {
        current = withOpticalDepth(imageLoad(scatterImage, ivec2(texel)));
        distances = unpackCloudDistances(imageLoad(distanceCurrent, ivec2(texel)).r);
        dir = rayDirection(texel);
    } else {
        // Skipped: the bilinear mix of the updated texels around it, and their reprojection distance
        // where they saw its surface.
        CloudRay ray = cloudTexelRay(texel);
        dir = ray.dir;
        current = vec4(0.0);
        float weight = 0.0, reprojection = 0.0, matched = 0.0;
        for (int k = 0; k < 4; ++k) {
            ivec2 o = ivec2(k & 1, k >> 1);
            ivec2 q = updatedTexel(b0 + o);
            float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
            vec4 n = withOpticalDepth(imageLoad(scatterImage, q));
            if (finite(n)) {
                current += w * n;
                weight += w;
            }
            vec2 d = unpackCloudDistances(imageLoad(distanceCurrent, q).r);
            if (d.x >= 0.0 && sameSurface(d.y, ray.surface)) {
                reprojection += (w + 1e-3) * d.x;
                matched += w + 1e-3;
            }
        }
        current = weight > 0.0 ? current / weight : mean;
        distances = vec2(matched > 0.0 ? reprojection / matched : ray.far, ray.surface);
        if (isnan(ray.surface)) distances.x = -1.0;
        imageStore(distanceCurrent, ivec2(texel), uvec4(packCloudDistances(distances.x, distances.y)));
    }

    vec4 result = current;
    if (temporal.state.x != 0u && finite(current) && distances.x >= 0.0) {
        vec3 point = dir * distances.x - cl.windDelta.xyz;
        float expectedSurface =
            isinf(distances.y) ? distances.y : length(dir * distances.y + temporal.cameraDelta.xyz);
        vec4 history;
        if (reprojectedHistory(point, texel, (vec2(texel) + 0.5) / vec2(cl.marchExtent.xy), expectedSurface,
                               history))
            // A sparse update's box (updated texels k apart) is too coarse to clamp by: its history is
            // kept as reprojected (surfaces checked), as a skipped texel's.
            result = updated ? mix(cl.sparse.x == 1u ? clamp(history, lo, hi) : history, current,
                                   temporal.cameraDelta.w)
                             : history;
    }
    imageStore(historyOut, ivec2(texel), result);
}
