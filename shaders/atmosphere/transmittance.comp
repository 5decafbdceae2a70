#version 450
// Pass 1 of the atmosphere (docs/effects/atmosphere.md, "Passes"): the transmittance LUT. Texel (x_μ, x_r)
// holds exp(-∫ σt dt) from radius r along cosine μ to the top boundary, with `transmittanceLut.z` midpoint
// steps crowded toward the ray's lowest point (Hillaire 2020, section 4; Bruneton's parameterisation).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereGroupSize, local_size_y = kAtmosphereGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance, rgba16f) uniform writeonly image2D transmittanceOut;

#include "common/air/model.glsl"
#include "common/air/march_steps.glsl"

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, atmo.transmittanceLut.xy))) return;
    vec2 rMu = transmittanceParams((vec2(texel) + 0.5) / vec2(atmo.transmittanceLut.xy));
    float r = rMu.x, mu = rMu.y;
    float distance = atmosphereDistanceToTop(r, mu);
    uint steps = atmo.transmittanceLut.z;
    // Steps crowded toward the ray's lowest point (march_steps.glsl): uniform steps of a ray near the
    // horizon are tens of km long where the air thins over kilometres.
    float tLow = -r * mu;
    uint count = marchStepCount(steps, 0.0, distance, tLow);
    vec3 opticalDepth = vec3(0.0);
    for (uint i = 0u; i < count; ++i) {
        vec2 st = marchStep(i, steps, 0.0, distance, tLow);
        // Altitude of r·zenith + t·direction: √(r² + t² + 2rtμ) - ground.
        float radius = sqrt(max(0.0, r * r + st.x * st.x + 2.0 * r * st.x * mu));
        opticalDepth += atmosphereMedium(radius - atmo.radii.x).extinction * st.y;
    }
    imageStore(transmittanceOut, ivec2(texel), vec4(exp(-opticalDepth), 1.0));
}
