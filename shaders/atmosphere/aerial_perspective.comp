#version 450
// Pass 4 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the aerial-perspective LUT, Hillaire
// 2020 section 5.4. A volume over the frustum of the camera it was built for (apClipToView, apCamera):
// texel (x, y, k) holds the in-scattered luminance per unit sun illuminance and the transmittance from
// where the ray enters the atmosphere (the camera, inside it) to the end of slice k, at depth
// (k + 1)/slices · distance, marched with (k + 1) · apLut.w uniform steps (the reference code's), through
// the planet's sphere.
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereApGroupSize, local_size_y = kAtmosphereApGroupSize,
       local_size_z = kAtmosphereApGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler2D multiScatteringLut;
layout(binding = kAtmosphereBindingApScattering, rgba16f) uniform writeonly image3D apScatteringOut;
layout(binding = kAtmosphereBindingApTransmittance, rgba16f) uniform writeonly image3D apTransmittanceOut;

#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "atmosphere/model.glsl"
#include "atmosphere/march.glsl"

void main() {
    uvec3 texel = gl_GlobalInvocationID;
    if (any(greaterThanEqual(texel, atmo.apLut.xyz))) return;
    vec2 ndc = (vec2(texel.xy) + 0.5) / vec2(atmo.apLut.xy) * 2.0 - 1.0;
    vec4 p = atmo.apClipToView * vec4(ndc, 0.5, 1.0);
    vec3 dir = normalize(p.xyz / p.w);
    vec3 origin = atmo.apCamera.xyz;
    // The host's geometry ends a geometry pixel's ray, not the planet's sphere: the march goes on below the
    // ground (in the ground's medium) to where the ray leaves the top, so terrain below the sphere (a flat
    // world's plane far away) gets its aerial perspective.
    vec2 top = atmosphereRaySphere(origin, dir, atmo.radii.y);
    float tBegin = max(top.x, 0.0);
    float sliceEnd = float(texel.z + 1u) / float(atmo.apLut.z) * atmo.apCamera.w;
    float tEnd = min(tBegin + sliceEnd, top.y);
    AtmosphereMarch march =
        atmosphereMarch(origin, dir, tBegin, tEnd, (texel.z + 1u) * atmo.apLut.w, false, atmo.toSun.xyz);
    imageStore(apScatteringOut, ivec3(texel),
               vec4(min(march.luminance * atmo.skyView.w, vec3(65504.0)), 1.0));
    imageStore(apTransmittanceOut, ivec3(texel), vec4(march.transmittance, 1.0));
}
