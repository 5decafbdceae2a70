#version 450
// Pass 3 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the sky-view LUT, Hillaire 2020
// section 5.3. For the camera's radius and the sun's zenith angle it was built for (AtmosphereUniforms
// skyView.xy), texel (azimuth from the sun, view zenith; model.glsl, skyViewParams) holds the luminance per
// unit sun illuminance of the view ray to the top or the ground (the lit ground included), `skyViewLut.z`
// steps spaced quadratically from where the ray enters the atmosphere. Each texel's steps are split among
// kAtmosphereSkyViewSplit invocations (z of the workgroup), composed front to back (L = L0 + T0·L1, T =
// T0·T1): the pass is bound by each ray's chain of dependent fetches, not by work.
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereGroupSize, local_size_y = kAtmosphereGroupSize,
       local_size_z = kAtmosphereSkyViewSplit) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingMultiScattering) uniform sampler3D multiScatteringLut;
layout(binding = kAtmosphereBindingSkyView, rgba16f) uniform writeonly image2D skyViewOut;

#define ATMOSPHERE_MS
#include "common/integrate.glsl"
#include "common/air/model.glsl"
#include "common/air/march.glsl"

shared vec3 partL[kAtmosphereSkyViewSplit][kAtmosphereGroupSize * kAtmosphereGroupSize];
shared vec3 partT[kAtmosphereSkyViewSplit][kAtmosphereGroupSize * kAtmosphereGroupSize];

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    uint part = gl_LocalInvocationID.z;
    uint slot = gl_LocalInvocationID.y * kAtmosphereGroupSize + gl_LocalInvocationID.x;
    bool inside = all(lessThan(texel, atmo.skyViewLut.xy));
    AtmosphereMarch march = AtmosphereMarch(vec3(0.0), vec3(1.0));
    float r = atmo.skyView.x, muS = atmo.skyView.y;
    vec3 origin = vec3(0.0, r, 0.0);
    vec3 toSun = vec3(sqrt(max(0.0, 1.0 - muS * muS)), muS, 0.0);
    vec3 dir = vec3(0.0, 1.0, 0.0), seg = vec3(0.0);
    if (inside) {
        vec2 uv = (vec2(texel) + 0.5) / vec2(atmo.skyViewLut.xy);
        vec2 view = skyViewParams(uv);
        // The local frame: zenith +y, the sun in the x-y plane toward +x.
        float sinView = sqrt(max(0.0, 1.0 - view.x * view.x));
        float sinAzimuth = sqrt(max(0.0, 1.0 - view.y * view.y));
        dir = vec3(sinView * view.y, view.x, sinView * sinAzimuth);
        seg = atmosphereSegment(origin, dir);
        uint steps = atmo.skyViewLut.z;
        uint first = part * steps / kAtmosphereSkyViewSplit,
             last = (part + 1u) * steps / kAtmosphereSkyViewSplit;
        march = atmosphereMarchPart(origin, dir, seg.x, seg.y, steps, first, last, true, toSun);
    }
    partL[part][slot] = march.luminance;
    partT[part][slot] = march.transmittance;
    barrier();
    if (part != 0u || !inside) return;
    vec3 L = vec3(0.0), T = vec3(1.0);
    for (uint i = 0u; i < kAtmosphereSkyViewSplit; ++i) {
        L += T * partL[i][slot];
        T *= partT[i][slot];
    }
    // A ray that ends on the ground adds the ground's Lambertian reflection seen through the air:
    // T·(Tsun·max(0, n·s) + E≥2)·albedo/π (the apply pass reads it with the sky). E≥2, the ground lit by
    // the sky, comes with the scattering orders; Hillaire's model leaves it out, as the paper does.
    if (seg.z != 0.0) {
        vec3 q = origin + seg.y * dir;
        float muG = dot(normalize(q), toSun);
        vec3 E = sunTransmittanceAt(q, toSun) * max(0.0, muG) + skyGroundIrradiance(muG);
        L += T * E * atmo.albedo.rgb / kAtmospherePi;
    }
    imageStore(skyViewOut, ivec2(texel), vec4(min(L * atmo.skyView.w, vec3(65504.0)), 1.0));
}
