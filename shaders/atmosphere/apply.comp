#version 450
// Pass 5 of the atmosphere (docs/effects/atmosphere.md, "Composite"): every pixel of the host's color.
// - Geometry: out = color·T + L·E from the aerial-perspective LUT at the surface's distance.
// - No geometry: the sky. Luminance from the sky-view LUT, which holds the planet's lit ground too.
//   A ray that meets the planet hides what the host drew there; one that does not shows the host's color
//   (what lies beyond the atmosphere) through the atmosphere's transmittance, plus the sun disk: a uniform
//   disk of the sun's angular radius and radiance E / solid angle, attenuated the same way.
// Variant: COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereApplyGroupX, local_size_y = kAtmosphereApplyGroupY) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler3D multiScatteringLut;
layout(binding = kAtmosphereBindingSkyView) uniform sampler2D skyViewLut;
layout(binding = kAtmosphereBindingApScattering) uniform sampler3D apScattering;
layout(binding = kAtmosphereBindingApTransmittance) uniform sampler2DArray apTransmittance;
layout(binding = kAtmosphereBindingDepth) uniform sampler2D depthTexture;
#include "common/color_format.glsl"
layout(binding = kAtmosphereBindingColorIn, COLOR_FORMAT) uniform restrict readonly image2D colorIn;
layout(binding = kAtmosphereBindingColorOut, COLOR_FORMAT) uniform restrict writeonly image2D colorOut;

#include "common/air/model.glsl"
#include "common/composite.glsl"
#include "common/air/aerial_perspective_lookup.glsl"

// The transmittance LUT's T from planet-centred p along unit d to the top (d not toward the ground).
vec3 transmittanceToTop(vec3 p, vec3 d) {
    float r = length(p);
    if (r >= atmo.radii.y) return vec3(1.0);
    return textureLod(transmittanceLut, transmittanceUv(r, dot(p, d) / r), 0.0).rgb;
}

// The sky-view LUT's luminance per unit illuminance along unit d, cosView = dot(d, the camera's zenith): the
// mapping of model.glsl (skyViewParams) forward, with the frame's reciprocals. Above the horizon
// v = (1 - √(min(1, (Z - θ)/D)))/2, below it (1 + √((θ - Z)/β))/2.
vec3 skyViewLuminance(vec3 d, float cosView) {
    if (cosView > atmo.applyScale.z) return vec3(0.0);  // from above the top, a ray that misses the air
    vec3 viewHorizontal = d - atmo.camera.xyz * (atmo.applyScale.x * cosView);
    float lengthSquared = dot(viewHorizontal, viewHorizontal);
    float cosAzimuth = atmo.sunHorizontal.w != 0.0 && lengthSquared > 1e-12
                           ? dot(atmo.sunHorizontal.xyz, viewHorizontal) * inversesqrt(lengthSquared)
                           : 1.0;
    float u = sqrt(clamp(0.5 - 0.5 * cosAzimuth, 0.0, 1.0));
    float theta = acos(clamp(cosView, -1.0, 1.0));  // from the zenith
    float fromHorizon = theta - atmo.skyHorizon.y;
    float v = 0.5 + 0.5 * sign(fromHorizon) *
                        sqrt(min(1.0, abs(fromHorizon) *
                                          (fromHorizon < 0.0 ? atmo.applySkyView.x : atmo.applySkyView.y)));
    vec2 uv = vec2(u, v) * atmo.applySkyTexel.xy + atmo.applySkyTexel.zw;
    return textureLod(skyViewLut, uv, 0.0).rgb * atmo.applyScale.y;
}

// `depth`: the host's depth, or with kAtmosphereFlagViewDistance the surface distance (∞ without geometry).
void applyPixel(uvec2 pixel, vec2 ndc, vec4 color, float depth) {
    bool isDistance = (atmo.flags.x & kAtmosphereFlagViewDistance) != 0u;
    bool noGeometry = isDistance ? depth == kInfinity : depth == atmo.skyView.z;
    vec4 p = atmo.clipToView * vec4(ndc, noGeometry || isDistance ? 0.5 : depth, 1.0);
    vec3 E = atmo.sun.rgb;
    vec3 result;
    if (!noGeometry) {
        vec3 L, T;
        aerialPerspective(isDistance ? normalize(p.w < 0.0 ? -p.xyz : p.xyz) * depth : p.xyz / p.w, L, T);
        result = compositeOver(color.rgb, T, L * E);
    } else {
        vec3 d = normalize(p.w < 0.0 ? -p.xyz : p.xyz);  // p.xyz / p.w, normalised
        vec3 o = atmo.camera.xyz;
        float r = atmo.camera.w;
        float mu = dot(o, d) * atmo.applyScale.x;
        // L: the sky-view LUT's, the lit ground included where the ray ends on it. T: the view ray's
        // transmittance, for what lies beyond the atmosphere (the host's color, the sun disk); fetched only
        // where that shows (a host that clears its sky to black needs none outside the disk).
        vec3 L = skyViewLuminance(d, mu), T = vec3(1.0);
        bool ground = rayMeetsGround(r, mu, atmo.radii.x);
        vec3 background = color.rgb;
        if (ground) {
            background = vec3(0.0);  // the planet hides what lies beyond it
        } else {
            bool disk = dot(d, atmo.toSun.xyz) >= atmo.toSun.w;
            if (disk || any(notEqual(color.rgb, vec3(0.0)))) {
                if (r < atmo.radii.y) {
                    T = textureLod(transmittanceLut, transmittanceUv(r, mu), 0.0).rgb;
                } else {  // above the top: from where the ray enters the atmosphere
                    vec3 seg = atmosphereSegment(o, d);
                    if (seg.y > seg.x) T = transmittanceToTop(o + seg.x * d, d);
                }
            }
            if (disk) L += T * atmo.sun.w;  // the disk: E / solid angle, per unit illuminance
        }
        result = compositeOver(mix(background, color.rgb, isnan(color.rgb)), T, L * E);
    }
    imageStore(colorOut, ivec2(pixel), vec4(result, color.a));
}

// Each invocation composites kAtmosphereApplyRows pixels, kAtmosphereApplyGroupY rows apart (more loads in
// flight per invocation; docs/effects/atmosphere.md, "Benchmark").
void main() {
    uvec2 base = uvec2(gl_WorkGroupID.x * kAtmosphereApplyGroupX,
                       gl_WorkGroupID.y * (kAtmosphereApplyGroupY * kAtmosphereApplyRows)) +
                 gl_LocalInvocationID.xy;
    vec2 ndc = vec2(base) * atmo.applyNdc.xy + atmo.applyNdc.zw;  // the pixel centre's
    // Every row's loads first, then the LUT fetches that depend on them.
    vec4 colors[kAtmosphereApplyRows];
    float depths[kAtmosphereApplyRows];
    for (uint k = 0u; k < kAtmosphereApplyRows; ++k) {
        ivec2 pixel = ivec2(min(base + uvec2(0u, k * kAtmosphereApplyGroupY), atmo.extent.xy - 1u));
        colors[k] = imageLoad(colorIn, pixel);
        depths[k] = texelFetch(depthTexture, pixel, 0).r;
    }
    for (uint k = 0u; k < kAtmosphereApplyRows; ++k) {
        uvec2 pixel = base + uvec2(0u, k * kAtmosphereApplyGroupY);
        if (all(lessThan(pixel, atmo.extent.xy)))
            applyPixel(pixel, ndc + vec2(0.0, float(k * kAtmosphereApplyGroupY) * atmo.applyNdc.y), colors[k],
                       depths[k]);
    }
}
