#version 450
// Pass 4 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the aerial-perspective LUT, Hillaire
// 2020 section 5.4. A volume over the frustum of the camera it was built for (apClipToView, apCamera):
// texel (x, y, k) holds the in-scattered luminance per unit sun illuminance (a 3D image) and the
// transmittance (layer k of a 2D array) from where the ray enters the atmosphere (the camera, inside it) to
// the end of slice k, at depth (k + 1)/slices · distance, with apLut.w uniform steps per slice (the
// reference code's 2), through the planet's sphere: the host's geometry ends a geometry pixel's ray, so the
// march goes on below the ground (in the ground's medium) to where the ray leaves the top, and terrain below
// the sphere (a flat world's far plane) gets its aerial perspective.
// One workgroup per (x, y): each invocation marches its slices alone, then a scan composes them front to
// back ((L, T)_k = (L, T)_{k-1} ∘ (L_k, T_k), L = L0 + T0·L1, T = T0·T1; Hillis–Steele), so no invocation
// marches more than its slices' steps (the same steps as marching from the camera to each slice's end).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereApGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler3D multiScatteringLut;
layout(binding = kAtmosphereBindingApScattering, rgba16f) uniform writeonly image3D apScatteringOut;
layout(binding = kAtmosphereBindingApTransmittance,
       rgba16f) uniform writeonly image2DArray apTransmittanceOut;

#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "common/air/model.glsl"
#include "common/air/march.glsl"

const uint kMaxSlices = 256u;  // the AP LUT's largest depth (atmosphere_settings.h)
shared vec3 sharedL[kMaxSlices];
shared vec3 sharedT[kMaxSlices];

void main() {
    uvec2 xy = gl_WorkGroupID.xy;
    uint lane = gl_LocalInvocationID.x;
    uint slices = atmo.apLut.z;
    vec2 ndc = (vec2(xy) + 0.5) / vec2(atmo.apLut.xy) * 2.0 - 1.0;
    vec4 p = atmo.apClipToView * vec4(ndc, 0.5, 1.0);
    vec3 dir = normalize(p.xyz / p.w);
    vec3 origin = atmo.apCamera.xyz;
    vec2 top = raySphere(origin, dir, atmo.radii.y);
    float tBegin = max(top.x, 0.0);
    float sliceLength = atmo.apCamera.w / float(slices);

    for (uint k = lane; k < slices; k += kAtmosphereApGroupSize) {
        float a = min(tBegin + float(k) * sliceLength, top.y);
        float b = min(tBegin + float(k + 1u) * sliceLength, top.y);
        AtmosphereMarch m = atmosphereMarch(origin, dir, a, b, atmo.apLut.w, false, atmo.toSun.xyz);
        sharedL[k] = m.luminance;
        sharedT[k] = m.transmittance;
    }
    barrier();
    for (uint offset = 1u; offset < slices; offset *= 2u) {
        vec3 L[kMaxSlices / kAtmosphereApGroupSize], T[kMaxSlices / kAtmosphereApGroupSize];
        for (uint i = 0u, k = lane; k < slices; ++i, k += kAtmosphereApGroupSize) {
            L[i] = sharedL[k];
            T[i] = sharedT[k];
            if (k >= offset) {
                L[i] = sharedL[k - offset] + sharedT[k - offset] * L[i];
                T[i] = sharedT[k - offset] * T[i];
            }
        }
        barrier();
        for (uint i = 0u, k = lane; k < slices; ++i, k += kAtmosphereApGroupSize) {
            sharedL[k] = L[i];
            sharedT[k] = T[i];
        }
        barrier();
    }
    for (uint k = lane; k < slices; k += kAtmosphereApGroupSize) {
        imageStore(apScatteringOut, ivec3(xy, k), vec4(min(sharedL[k] * atmo.skyView.w, vec3(65504.0)), 1.0));
        imageStore(apTransmittanceOut, ivec3(xy, k), vec4(sharedT[k], 1.0));  // layer k
    }
}
