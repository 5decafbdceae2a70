// The view ray of a pixel, camera-relative (docs/effects/fog.md, "Ray"). Expects `fog` and `depthTexture`.
#ifndef POSTFX_FOG_RAY_GLSL
#define POSTFX_FOG_RAY_GLSL

#include "common/medium/flags.glsl"
#include "common/reduced_resolution.glsl"

struct FogRay {
    vec3 dir;               // unit direction from the camera
    float surfaceDistance;  // to the reconstructed surface [m]; infinite for pixels with no geometry
};

// The unit direction of pixel `pixel`'s view ray, camera-relative (no depth read).
vec3 fogRayDirection(uvec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(fog.extent.xy) * 2.0 - 1.0;
    vec4 p = fog.clipToView * vec4(ndc, 0.5, 1.0);
    return normalize(p.xyz / p.w);
}

// With kFogFlagViewDistance the depth binding holds the surface distance itself (∞ without geometry).
FogRay fogRay(uvec2 pixel) {
    float depth = texelFetch(depthTexture, ivec2(pixel), 0).r;
    if (fogFlag(kFogFlagViewDistance)) return FogRay(fogRayDirection(pixel), depth);
    bool noGeometry = depth == fog.march.y;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(fog.extent.xy) * 2.0 - 1.0;
    vec4 p = fog.clipToView * vec4(ndc, noGeometry ? 0.5 : depth, 1.0);
    vec3 surface = p.xyz / p.w;
    float distance = length(surface);
    return FogRay(surface / distance, noGeometry ? kInfinity : distance);
}

// The surface distance the temporal pass compares (∞ without geometry); -1 for a NaN depth (a host's
// bad depth), a distance no reprojection and no neighbour matches.
float fogTemporalDistance(FogRay ray) {
    return isnan(ray.surfaceDistance) ? -1.0 : ray.surfaceDistance;
}

// Reduced resolution: the full-resolution pixel whose ray the scatter texel `texel` marches
// (common/reduced_resolution.glsl).
uvec2 fogSourcePixel(uvec2 texel) {
    return reducedSourcePixel(texel, fog.extent.xy, fog.scatterExtent.xy);
}

#endif
