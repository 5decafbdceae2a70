// A pixel's surface distance along its view ray, from the frame's depth input (docs/architecture.md,
// "Shared inputs"): either the host's depth, unprojected here, or the distance postfx.view_distance
// already computed once for every effect of the frame (`isDistance`).
#ifndef POSTFX_COMMON_VIEW_DISTANCE_GLSL
#define POSTFX_COMMON_VIEW_DISTANCE_GLSL

// The distance [m] from the camera to the surface at NDC `ndc` (the pixel's centre) of Vulkan depth
// `depth`: |p.xyz / p.w| with p = clipToView · (ndc, depth, 1). +∞ where depth is the no-geometry value,
// NaN for a NaN depth.
float unprojectedDistance(mat4 clipToView, vec2 ndc, float depth, float noGeometryDepth) {
    if (depth == noGeometryDepth) return kInfinity;
    vec4 p = clipToView * vec4(ndc, depth, 1.0);
    return length(p.xyz / p.w);
}

// The surface distance of the depth input's texel `value`.
float surfaceDistanceOf(float value, bool isDistance, mat4 clipToView, vec2 ndc, float noGeometryDepth) {
    return isDistance ? value : unprojectedDistance(clipToView, ndc, value, noGeometryDepth);
}

#endif
