// A pixel's view ray for the clouds (camera-relative). Expects `cl` and `depthTexture`.
#ifndef POSTFX_CLOUDS_RAY_GLSL
#define POSTFX_CLOUDS_RAY_GLSL

#include "common/reduced_resolution.glsl"
#include "common/view_distance.glsl"

struct CloudRay {
    vec3 dir;       // unit direction from the camera
    float surface;  // distance to the host's surface [m]: ∞ without geometry, NaN for a NaN depth
    float far;      // the march ends here: the nearer of the surface and max distance [m]
};

// Camera-relative world position of NDC `ndc` at Vulkan depth `depth`.
vec3 cloudUnproject(vec2 ndc, float depth, out float w) {
    vec4 p = cl.clipToView * vec4(ndc, depth, 1.0);
    w = p.w;
    return p.xyz / p.w;
}

// The ray through `ndc`, ending at the host's surface of full-resolution pixel `depthPixel` (the
// pixel's own centre, or for a reduced march the pixel nearest the texel's centre).
CloudRay cloudRayThrough(vec2 ndc, uvec2 depthPixel) {
    float depth = texelFetch(depthTexture, ivec2(depthPixel), 0).r;
    float w;
    vec3 far = cloudUnproject(ndc, 0.5, w);
    CloudRay ray;
    ray.dir = normalize(w < 0.0 ? -far : far);
    vec2 pixelNdc = (vec2(depthPixel) + 0.5) / vec2(cl.extent.xy) * 2.0 - 1.0;
    ray.surface = surfaceDistanceOf(depth, (cl.flags.x & kCloudFlagViewDistance) != 0u, cl.clipToView,
                                    pixelNdc, cl.march.y);
    bool noGeometry = ray.surface == kInfinity;
    ray.far = noGeometry ? cl.march.x : min(ray.surface, cl.march.x);
    return ray;
}

CloudRay cloudRay(uvec2 pixel) {
    return cloudRayThrough((vec2(pixel) + 0.5) / vec2(cl.extent.xy) * 2.0 - 1.0, pixel);
}

// The full-resolution pixel whose depth a march texel reads: the one nearest the texel's centre (the
// texel's own pixel at resolution scale 1).
uvec2 cloudSourcePixel(uvec2 texel) {
    return reducedSourcePixel(texel, cl.extent.xy, cl.marchExtent.xy);
}

// A march texel's ray: through the texel's centre (so that the upsample's bilinear footprint is where the
// ray went), ending at its source pixel's surface.
CloudRay cloudTexelRay(uvec2 texel) {
    return cloudRayThrough((vec2(texel) + 0.5) / vec2(cl.marchExtent.xy) * 2.0 - 1.0,
                           cloudSourcePixel(texel));
}

#endif
