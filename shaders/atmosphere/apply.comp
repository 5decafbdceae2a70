#version 450
// Pass 5 of the atmosphere (docs/effects/atmosphere.md, "Composite"): every pixel of the host's color.
// - Geometry: out = color·T + L·E from the aerial-perspective LUT at the surface's distance.
// - No geometry: the sky. Luminance from the sky-view LUT: its mapping from inside the atmosphere, its space
//   mapping, or (just above the top) a blend of both by radii.w. A ray that meets the planet shows its lit
//   ground and hides what the host drew there; one that does not shows the host's color (what lies beyond
//   the atmosphere) through the atmosphere's transmittance, plus the sun disk: a uniform disk of the sun's
//   angular radius and radiance E / solid angle, attenuated the same way.
// Variant: COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereApplyGroupX, local_size_y = kAtmosphereApplyGroupY) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler2D multiScatteringLut;
layout(binding = kAtmosphereBindingSkyView) uniform sampler2DArray skyViewLut;
layout(binding = kAtmosphereBindingApScattering) uniform sampler3D apScattering;
layout(binding = kAtmosphereBindingApTransmittance) uniform sampler3D apTransmittance;
layout(binding = kAtmosphereBindingDepth) uniform sampler2D depthTexture;
#ifdef COLOR_RGBA32F
layout(binding = kAtmosphereBindingColorIn, rgba32f) uniform readonly image2D colorIn;
layout(binding = kAtmosphereBindingColorOut, rgba32f) uniform writeonly image2D colorOut;
const float kColorMax = 3.402823466e38;
#else
layout(binding = kAtmosphereBindingColorIn, rgba16f) uniform readonly image2D colorIn;
layout(binding = kAtmosphereBindingColorOut, rgba16f) uniform writeonly image2D colorOut;
const float kColorMax = 65504.0;  // largest finite half: never write Inf
#endif

#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "atmosphere/model.glsl"
#include "atmosphere/march.glsl"  // sunTransmittanceAt

// out = color·T + L, as the fogs composite (fog/composite.glsl): ±Inf in the host's color counts as
// ±kColorMax, the result is clamped to the format's range, a NaN channel of the host's stays NaN.
vec3 compositeAtmosphere(vec3 color, vec3 transmittance, vec3 luminance) {
    vec3 bounded = clamp(color, vec3(-kColorMax), vec3(kColorMax));
    vec3 result = clamp(bounded * transmittance + luminance, vec3(-kColorMax), vec3(kColorMax));
    return mix(result, color, isnan(color));
}

// The transmittance LUT's T from planet-centred p along unit d to the top (d not toward the ground).
vec3 transmittanceToTop(vec3 p, vec3 d) {
    float r = length(p);
    if (r >= atmo.radii.y) return vec3(1.0);
    return textureLod(transmittanceLut, transmittanceUv(r, dot(p, d) / r), 0.0).rgb;
}

// Aerial perspective of a surface at camera-relative x: (L per unit illuminance, T). The LUT's frustum is
// the camera's it was built for, apOffset from this one: x is looked up where that camera sees it.
void aerialPerspective(vec3 x, out vec3 luminance, out vec3 transmittance) {
    vec3 xb = x + atmo.apOffset.xyz;
    float distance = length(xb);
    vec4 clip = atmo.apViewToClip * vec4(xb, 1.0);
    vec2 uv = clip.w > 0.0 ? clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0) : vec2(0.5);
    vec3 dir = xb / max(distance, 1e-30);
    // From space the LUT's slices start where each ray enters the atmosphere; inside it, at the camera.
    float entry =
        atmo.apOffset.w != 0.0 ? max(atmosphereRaySphere(atmo.apCamera.xyz, dir, atmo.radii.y).x, 0.0) : 0.0;
    float w = max(distance - entry, 0.0) / atmo.apCamera.w;  // [0, 1] over the LUT's depth
    float slices = float(atmo.apLut.z);
    // Texel k holds the end of slice k; within the first slice (L, T) run from (0, 1) at the entry.
    float z = max(w * slices - 0.5, 0.5) / slices;
    vec3 L = textureLod(apScattering, vec3(uv, z), 0.0).rgb;
    vec3 T = textureLod(apTransmittance, vec3(uv, z), 0.0).rgb;
    float first = clamp(w * slices, 0.0, 1.0);
    luminance = L * (first / atmo.skyView.w);
    transmittance = mix(vec3(1.0), T, first);
}

// The sky-view LUT's luminance per unit illuminance along unit d, cosView = dot(d, the camera's zenith):
// layer 0 (the mapping from inside) weighted 1 - radii.w, layer 1 (the space mapping) radii.w.
vec3 skyViewLuminance(vec3 d, float cosView) {
    vec3 up = atmo.camera.xyz / atmo.camera.w;
    vec3 viewHorizontal = d - up * cosView;
    float viewLength = length(viewHorizontal);
    float cosAzimuth = atmo.sunHorizontal.w != 0.0 && viewLength > 1e-6
                           ? dot(atmo.sunHorizontal.xyz, viewHorizontal) / viewLength
                           : 1.0;
    float space = atmo.radii.w;
    vec3 L = vec3(0.0);
    if (space < 1.0) {
        vec2 uv = skyViewUvAtHorizon(atmo.skyHorizon.x, atmo.skyHorizon.y, cosView, cosAzimuth);
        L = (1.0 - space) * textureLod(skyViewLut, vec3(uv, 0.0), 0.0).rgb;
    }
    if (space > 0.0 && -cosView >= cos(atmo.skyHorizon.w)) {  // else it misses the atmosphere
        vec2 uv = skyViewSpaceUv(atmo.skyHorizon.z, atmo.skyHorizon.w, cosView, cosAzimuth);
        L += space * textureLod(skyViewLut, vec3(uv, 1.0), 0.0).rgb;
    }
    return L / atmo.skyView.w;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, atmo.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    float depth = texelFetch(depthTexture, ivec2(pixel), 0).r;
    bool noGeometry = depth == atmo.skyView.z;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(atmo.extent.xy) * 2.0 - 1.0;
    vec4 p = atmo.clipToView * vec4(ndc, noGeometry ? 0.5 : depth, 1.0);
    vec3 x = p.xyz / p.w;
    vec3 E = atmo.sun.rgb;
    vec3 result;
    if (!noGeometry) {
        vec3 L, T;
        aerialPerspective(x, L, T);
        result = compositeAtmosphere(color.rgb, T, L * E);
    } else {
        vec3 d = normalize(x);
        vec3 o = atmo.camera.xyz;
        float r = atmo.camera.w, g = atmo.radii.x;
        float mu = dot(o, d) / r;
        bool ground;
        vec3 L = skyViewLuminance(d, mu), T = vec3(1.0), q = vec3(0.0);
        if (r < atmo.radii.y) {
            // The camera inside the atmosphere: T from the transmittance LUT: to the top, or to the ground
            // as T(ground → top along -d) / T(camera → top along -d).
            ground = rayMeetsGround(r, mu, g);
            if (ground) {
                float t = max(0.0, -r * mu - sqrt(max(0.0, (g - r) * (g + r) + r * r * mu * mu)));
                q = o + t * d;
                vec3 num = transmittanceToTop(q, -d), den = transmittanceToTop(o, -d);
                T = all(greaterThan(den, vec3(0.0))) ? clamp(num / den, 0.0, 1.0) : vec3(0.0);
            } else {
                T = textureLod(transmittanceLut, transmittanceUv(r, mu), 0.0).rgb;
            }
        } else {
            // Above the top: T from where the ray enters the atmosphere.
            vec3 seg = atmosphereSegment(o, d);
            ground = seg.z != 0.0;
            q = o + seg.y * d;
            vec3 entry = o + seg.x * d;
            if (seg.y > seg.x) {
                if (ground) {
                    vec3 num = transmittanceToTop(q, -d), den = transmittanceToTop(entry, -d);
                    T = all(greaterThan(den, vec3(0.0))) ? clamp(num / den, 0.0, 1.0) : vec3(0.0);
                } else {
                    T = transmittanceToTop(entry, d);
                }
            }
        }
        vec3 background = color.rgb;
        if (ground) {
            float nDotL = max(0.0, dot(normalize(q), atmo.toSun.xyz));
            L += T * sunTransmittanceAt(q, atmo.toSun.xyz) * nDotL * atmo.albedo.rgb / kAtmospherePi;
            background = vec3(0.0);  // the planet hides what lies beyond it
        } else if (dot(d, atmo.toSun.xyz) >= atmo.toSun.w) {
            L += T * atmo.sun.w;  // the disk: E / solid angle, per unit illuminance
        }
        result = compositeAtmosphere(mix(background, color.rgb, isnan(color.rgb)), T, L * E);
    }
    imageStore(colorOut, ivec2(pixel), vec4(result, color.a));
}
