// Descriptor bindings of the atmosphere's kernels (each pipeline's layout holds the ones it uses).
#ifndef POSTFX_ATMOSPHERE_BINDINGS_GLSL
#define POSTFX_ATMOSPHERE_BINDINGS_GLSL

layout(binding = kAtmosphereBindingUniforms, std140) uniform Uniforms {
    AtmosphereUniforms atmo;
};

#endif
