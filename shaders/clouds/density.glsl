// The clouds' shape and density field (docs/effects/clouds.md, "Shape" and "Density"), mirrored in double
// by postfx/src/clouds/clouds_model.cpp. Expects `cl` (CloudUniforms) and the samplers baseNoise and
// detailNoise. Positions are camera-relative [m].
#ifndef POSTFX_CLOUDS_DENSITY_GLSL
#define POSTFX_CLOUDS_DENSITY_GLSL

#include "common/ray_sphere.glsl"

// The part of ray o + t·d inside the shape, t in [0, far]: (begin, end), end <= begin when none. Rays
// that cross a curved layer twice (from above it, through the space under it) are marched over both
// crossings and what lies between (where the field is 0).
vec2 cloudSegment(vec3 x0, vec3 d, float far) {
    vec2 seg = vec2(0.0, far);
    uint flags = cl.flags.x;
    if ((flags & kCloudFlagBox) != 0u) {
        vec3 o = (cl.boxFromView * vec4(x0, 1.0)).xyz;
        vec3 dir = mat3(cl.boxFromView) * d;
        vec3 inv = 1.0 / dir;  // ±Inf along an axis the ray is parallel to
        vec3 a = (-cl.boxHalf.xyz - o) * inv, b = (cl.boxHalf.xyz - o) * inv;
        vec3 lo = min(a, b), hi = max(a, b);
        // A parallel axis gives NaN only for an origin exactly on a face: treat as inside that slab.
        lo = mix(lo, vec3(-kInfinity), isnan(lo));
        hi = mix(hi, vec3(kInfinity), isnan(hi));
        seg = vec2(max(seg.x, max(lo.x, max(lo.y, lo.z))), min(seg.y, min(hi.x, min(hi.y, hi.z))));
    } else if ((flags & kCloudFlagCurved) != 0u) {
        vec3 o = cl.origin.xyz + x0;
        float ground = cl.layer.z;
        vec2 outer = raySphere(o, d, ground + cl.layer.y);
        if (outer.y <= 0.0) return vec2(1.0, 0.0);  // misses it (-1, -1) or it lies behind
        seg = vec2(max(seg.x, outer.x), min(seg.y, outer.y));
        // Inside the bottom sphere at the start: begin where the ray leaves it.
        vec2 inner = raySphere(o, d, ground + cl.layer.x);
        if (inner.y > inner.x && inner.x <= seg.x && inner.y > seg.x) seg.x = inner.y;
        // A ray that meets the ground ends where it enters the bottom sphere before it: below the layer the
        // field is 0 (from 6 km up, the march's steps no longer spend 40% of themselves between the
        // layer and the ground). A ray that passes under the layer without meeting the ground keeps the
        // gap between its two crossings.
        vec2 planet = raySphere(o, d, ground);
        if (planet.y > planet.x && planet.x > 0.0) seg.y = min(seg.y, min(inner.x, planet.x));
    } else {
        float y = cl.origin.y + x0.y;
        float bottom = cl.layer.x, top = cl.layer.y;
        if (d.y == 0.0) {
            if (y < bottom || y > top) return vec2(1.0, 0.0);
        } else {
            float ta = (bottom - y) / d.y, tb = (top - y) / d.y;
            seg = vec2(max(seg.x, min(ta, tb)), min(seg.y, max(ta, tb)));
        }
    }
    return seg;
}

// The height fraction of camera-relative x in the shape: 0 at its bottom, 1 at its top (outside: < 0
// or > 1), and the distances to its top and bottom [m].
float cloudHeightFraction(vec3 x) {
    uint flags = cl.flags.x;
    if ((flags & kCloudFlagBox) != 0u) {
        float y = (cl.boxFromView * vec4(x, 1.0)).y;
        return (y + cl.boxHalf.y) / (2.0 * cl.boxHalf.y);
    }
    float altitude =
        (flags & kCloudFlagCurved) != 0u ? length(cl.origin.xyz + x) - cl.layer.z : cl.origin.y + x.y;
    return (altitude - cl.layer.x) * cl.layer.w;
}

// The density profile over the height fraction h (cloud type): a ramp from 0 at the bottom over
// kCloudBottomRamp, times a fall to 0 at the top over the type's top falloff.
float cloudHeightProfile(float h) {
    return clamp(h * (1.0 / kCloudBottomRamp), 0.0, 1.0) * clamp((1.0 - h) * cl.shape.y, 0.0, 1.0);
}

// The density field in [0, 1] at camera-relative x, height fraction h (inside the shape): the base
// shape N·profile(h) thresholded by the coverage c, (shape - (1 - c)) / c clamped, then eroded by the
// detail D·strength = e: (field - e) / (1 - e) clamped (Schneider 2015's remaps), c times the coverage map's
// value where one is given. Noise off: 1 (the map's value with a map).
float cloudField(vec3 x, float h) {
    if (h < -kCloudHeightSlack || h > 1.0 + kCloudHeightSlack) return 0.0;
    h = clamp(h, 0.0, 1.0);
    // The host's coverage map m at the point's world (x, z): coverage·m, no noise read where m = 0.
    float map = 1.0;
    if ((cl.flags.x & kCloudFlagCoverageMap) != 0u) {
        map = textureLod(coverageMap, (x.xz + cl.coverageMap.xy) * cl.coverageMap.zw, 0.0).r;
        if (!(map > 0.0)) return 0.0;
    }
    if ((cl.flags.x & kCloudFlagNoise) == 0u) return map;
    float coverage = cl.shape.x * map;
    float shape =
        textureLod(baseNoise, (x + cl.noiseBase.xyz) * cl.noiseBase.w, 0.0).r * cloudHeightProfile(h);
    float field = clamp((shape - (1.0 - coverage)) / coverage, 0.0, 1.0);
    if (field <= 0.0 || cl.shape.z <= 0.0) return field;
    float e = cl.shape.z * textureLod(detailNoise, (x + cl.noiseDetail.xyz) * cl.noiseDetail.w, 0.0).r;
    return clamp((field - e) / max(1.0 - e, 1e-6), 0.0, 1.0);
}

// Extinction σt at camera-relative x [1/m].
float cloudExtinction(vec3 x) {
    return cl.shape.w * cloudField(x, cloudHeightFraction(x));
}

#endif
