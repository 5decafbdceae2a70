// postfx's volumetrics lookup for a host's forward pass (docs/integration.md, "Transparent surfaces";
// postfx/volumetrics_lookup.h). Define the descriptor set and binding numbers the host chose, then include:
//
//   #define POSTFX_LOOKUP_SET 1
//   #define POSTFX_LOOKUP_BINDING_UNIFORMS 0
//   #define POSTFX_LOOKUP_BINDING_SCATTERING 1
//   #define POSTFX_LOOKUP_BINDING_TRANSMITTANCE 2
//   #include "postfx/volumetrics.glsl"
//   ...
//   PostfxVolumetrics v = postfxVolumetrics(worldPosition);
//   color.rgb = color.rgb * v.transmittance + v.radiance;  // before blending over the frame
//
// Requires GL_GOOGLE_include_directive, with the installed include directory on the include path
// (glslangValidator -I<prefix>/include; glslang 12 resolves only quoted includes there).
#ifndef POSTFX_VOLUMETRICS_GLSL
#define POSTFX_VOLUMETRICS_GLSL

// The lookup's uniforms (postfx's C++ writes the same std140 layout). World positions are the host's, in
// its world frame and units (ContextCreateInfo::world); distances along the view are in metres.
struct PostfxLookupUniforms {
    mat4 relativeToClip;  // camera-relative world position [host units] -> the camera's clip space (Vulkan,
                          // y down)
    mat4 clipToRelative;  // postfx's passes: clip space -> camera-relative position in postfx's frame [m]
    vec4 camera;  // xyz: the camera's world position [host units] (float); w: the frame's pre-exposure
    vec4 slices;  // x: the first slice's end [m], y: the last's, z: ln(y / x), w: slice count
    vec4 world;   // x: metres per host unit (1 / unitsPerMetre); y, z, w: 0
};

// Texture z of distance t [m] >= x (slices.x): texel k holds (L, T) at the end of slice k, the slices'
// ends at x·(y/x)^(k / (count - 1)).
float postfxLookupSliceZ(PostfxLookupUniforms u, float t) {
    float k = log(clamp(t, u.slices.x, u.slices.y) / u.slices.x) / u.slices.z * (u.slices.w - 1.0);
    return (k + 0.5) / u.slices.w;
}

#ifdef POSTFX_LOOKUP_BINDING_UNIFORMS
#ifndef POSTFX_LOOKUP_SET
#define POSTFX_LOOKUP_SET 0
#endif

layout(set = POSTFX_LOOKUP_SET, binding = POSTFX_LOOKUP_BINDING_UNIFORMS, std140) uniform PostfxLookupBlock {
    PostfxLookupUniforms postfxLookup;
};
layout(set = POSTFX_LOOKUP_SET, binding = POSTFX_LOOKUP_BINDING_SCATTERING) uniform sampler3D postfxLookupL;
layout(set = POSTFX_LOOKUP_SET,
       binding = POSTFX_LOOKUP_BINDING_TRANSMITTANCE) uniform sampler3D postfxLookupT;

struct PostfxVolumetrics {
    vec3 radiance;       // L: light scattered toward the camera in front of the point [pre-exposed radiance]
    vec3 transmittance;  // T: from the camera to the point [1]
};

// (L, T) between the camera and the point at camera-relative position x [host units] (world axes).
PostfxVolumetrics postfxVolumetricsRelative(vec3 x) {
    vec4 clip = postfxLookup.relativeToClip * vec4(x, 1.0);
    float t = length(x) * postfxLookup.world.x;                           // [m]
    if (!(clip.w > 0.0)) return PostfxVolumetrics(vec3(0.0), vec3(1.0));  // behind the camera
    vec2 uv = clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0);
    float near = postfxLookup.slices.x;
    vec3 p = vec3(uv, postfxLookupSliceZ(postfxLookup, t));
    vec3 L = textureLod(postfxLookupL, p, 0.0).rgb;
    vec3 T = textureLod(postfxLookupT, p, 0.0).rgb;
    if (t < near) {  // the first slice: from (0, 1) at the camera
        float f = t / near;
        L *= f;
        T = mix(vec3(1.0), T, f);
    }
    return PostfxVolumetrics(L, T);
}

// (L, T) between the camera and the point at world position p [host units].
PostfxVolumetrics postfxVolumetrics(vec3 p) {
    return postfxVolumetricsRelative(p - postfxLookup.camera.xyz);
}

// A surface's radiance at world position p seen through postfx's volumetrics: surface·T + L.
vec3 postfxApplyVolumetrics(vec3 surface, vec3 p) {
    PostfxVolumetrics v = postfxVolumetrics(p);
    return surface * v.transmittance + v.radiance;
}

#endif  // POSTFX_LOOKUP_BINDING_UNIFORMS
#endif  // POSTFX_VOLUMETRICS_GLSL
