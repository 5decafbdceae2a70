#version 450
// Pass 3 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the sky-view LUT, Hillaire 2020
// section 5.3. For the camera's radius and the sun's zenith angle it was built for (AtmosphereUniforms
// skyView.xy), texel (azimuth from the sun, view zenith) holds the luminance per unit sun illuminance of
// the view ray to the top or the ground, `skyViewLut.z` steps spaced quadratically from the camera.
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereGroupSize, local_size_y = kAtmosphereGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler2D multiScatteringLut;
layout(binding = kAtmosphereBindingSkyView, rgba16f) uniform writeonly image2D skyViewOut;

#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "atmosphere/model.glsl"
#include "atmosphere/march.glsl"

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, atmo.skyViewLut.xy))) return;
    float r = atmo.skyView.x, muS = atmo.skyView.y;
    vec2 view = skyViewParams(r, (vec2(texel) + 0.5) / vec2(atmo.skyViewLut.xy));
    // The local frame: zenith +y, the sun in the x-y plane toward +x.
    float sinView = sqrt(max(0.0, 1.0 - view.x * view.x));
    float sinAzimuth = sqrt(max(0.0, 1.0 - view.y * view.y));
    vec3 dir = vec3(sinView * view.y, view.x, sinView * sinAzimuth);
    vec3 toSun = vec3(sqrt(max(0.0, 1.0 - muS * muS)), muS, 0.0);
    vec3 origin = vec3(0.0, r, 0.0);
    vec3 seg = atmosphereSegment(origin, dir);
    AtmosphereMarch march = atmosphereMarch(origin, dir, seg.x, seg.y, atmo.skyViewLut.z, true, toSun);
    imageStore(skyViewOut, ivec2(texel), vec4(min(march.luminance * atmo.skyView.w, vec3(65504.0)), 1.0));
}
