#version 450
// The fog's shader functions on their own (docs/stability.md, "Shader functions"): one invocation per
// row of a table of inputs, each evaluating one function with postfx's own GLSL and writing its result
// for the test to compare against double precision (tests/fog/stability/test_shader_functions.cpp).
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = 64) in;

// The functions read the fog's uniforms through `fog`: here a per-invocation copy built from the row.
FogUniforms fog;
const float kColorMax = 65504.0;  // composite.glsl: the RGBA16F variant
// Declared for medium.glsl; the functions tested here do not read them.
layout(binding = 2) uniform sampler2D shadowMap;
layout(binding = 3) uniform sampler3D noiseTexture;

#include "common/ign.glsl"
#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/composite.glsl"
#include "common/medium/medium.glsl"

// Must match FunctionCase in test_shader_functions.cpp.
const uint kPhase = 0u;        // a.xyz view dir, b.xyz to light, c.x g     -> x: p [1/sr]
const uint kOneMinusExp = 1u;  // a.x x                                     -> x: 1 - e^-x, y: (1 - e^-x)/x
const uint kHeightTerm = 2u;   // a.x height above base, c.y falloff        -> x: h
const uint kSunTransmittance = 3u;  // a.x height, c.x density, c.y falloff, b.y toSun.y -> x: Tsun
const uint kTailDepth = 4u;         // a.x height0, a.y dirY, a.z len, c.x density, c.y falloff -> x: τ
const uint kIgn = 5u;               // op.y, op.z pixel, op.w frame              -> x: IGN
const uint kComposite = 6u;         // a.xyz color, a.w T, b.xyz L               -> xyz: out
const uint kIntegrateStep = 7u;     // a.x T, a.y light, a.z optical depth       -> x: in-scattered

struct FunctionCase {
    vec4 a;
    vec4 b;
    vec4 c;
    uvec4 op;  // x: kind; y, z, w: integer inputs
};
layout(std430, binding = 0) readonly buffer Cases {
    FunctionCase cases[];
};
layout(std430, binding = 1) writeonly buffer Results {
    vec4 results[];
};
// clang-format off
layout(push_constant) uniform Push { uint count; } pc;
// clang-format on

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    FunctionCase fc = cases[i];
    fog.medium = vec4(fc.c.x, fc.c.y, 0.0, 0.0);  // density, height falloff
    fog.toSun = vec4(fc.b.xyz, 0.0);
    fog.flags = uvec4(kFogFlagSelfShadow, 0u, 0u, 0u);
    vec4 r = vec4(0.0);
    switch (fc.op.x) {
        case kPhase:
            r.x = henyeyGreensteinDirections(fc.a.xyz, fc.b.xyz, fc.c.x);
            break;
        case kOneMinusExp:
            r.x = oneMinusExp(fc.a.x);
            r.y = oneMinusExpOverX(fc.a.x);
            break;
        case kHeightTerm:
            r.x = heightTerm(fc.a.x);
            break;
        case kSunTransmittance:
            r.x = sunTransmittance(fc.a.x);
            break;
        case kTailDepth:
            r.x = heightFogOpticalDepth(fc.a.x, fc.a.y, fc.a.z);
            break;
        case kIgn:
            r.x = interleavedGradientNoise(fc.op.yz, fc.op.w);
            break;
        case kComposite:
            r.xyz = compositeOver(fc.a.xyz, fc.a.w, fc.b.xyz);
            break;
        case kIntegrateStep:
            r.x = integrateStep(fc.a.x, vec3(fc.a.y), fc.a.z).x;
            break;
    }
    results[i] = r;
}
