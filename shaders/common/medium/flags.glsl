// The fog's flags (FogUniforms.flags.x, fog_shared.h) and its shadow kernel's radius. Expects `fog`.
#ifndef POSTFX_FOG_FLAGS_GLSL
#define POSTFX_FOG_FLAGS_GLSL

// The flags and the shadow kernel's radius as specialization constants (fog_shared.h): 12-29% of the
// march on the H100 (docs/accuracy-cost/README.md, "What paid"). Defaults: read from the uniforms.
layout(constant_id = kFogConstantFlags) const uint kFogFlags = kFogFlagsFromUniforms;
layout(constant_id = kFogConstantShadowRadius) const int kFogShadowRadius = -1;

bool fogFlag(uint flag) {
    if ((kFogFlags & kFogFlagsFromUniforms) != 0u) return (fog.flags.x & flag) != 0u;
    return (kFogFlags & flag) != 0u;
}

int fogShadowRadius() {
    return kFogShadowRadius >= 0 ? kFogShadowRadius : int(fog.shadow.y);
}

#endif
