// Forward pass, after postfx: a transparent surface lit as the deferred lighting lights the G-buffer
// (surface_light.glsl), seen through postfx's volumetrics (surface·T + L, postfx/volumetrics.glsl) and
// blended over the frame with its opacity α: out = (surface·T + L)·α + dst·(1 − α). The depth test is
// done here against the G-buffer's depth (read as a texture: the depth image stays read-only, no
// attachment); nothing writes depth.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "demo_shared.h"

layout(set = 0, binding = kBindingFrame, std140) uniform FrameBlock {
    FrameUniforms frame;
};
layout(set = 0, binding = kBindingDepth) uniform sampler2D gDepth;
layout(set = 0, binding = kBindingShadowMap) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = kBindingCloudShadow) uniform sampler2D cloudShadowMap;
layout(set = 0, binding = kBindingLights, std140) uniform LightsBlock {
    LightsUniforms lightList;
};
layout(set = 0, binding = kBindingLocalShadowAtlas) uniform sampler2D localShadowAtlas;
layout(set = 0, binding = kBindingLocalShadowFaces, std430) readonly buffer LocalShadowFacesBlock {
    LocalShadowFaces shadowFaces;
};
layout(push_constant) uniform PushBlock {
    ForwardPush draw;
};

#define POSTFX_LOOKUP_SET kForwardLookupSet
#define POSTFX_LOOKUP_BINDING_UNIFORMS kForwardBindingLookupUniforms
#define POSTFX_LOOKUP_BINDING_SCATTERING kForwardBindingLookupScattering
#define POSTFX_LOOKUP_BINDING_TRANSMITTANCE kForwardBindingLookupTransmittance
// Quoted: glslangValidator resolves only quoted includes through its -I directories.
#include "postfx/volumetrics.glsl"

#include "local_shadow.glsl"
#include "shadow.glsl"
#include "surface_light.glsl"

layout(location = 0) in vec3 inRelative;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inCorner;

layout(location = 0) out vec4 outColor;

const float kPi = 3.14159265358979;

void main() {
    // Behind the opaque surface at this pixel (reversed Z: nearer is larger): hidden.
    float opaque = texelFetch(gDepth, ivec2(gl_FragCoord.xy), 0).r;
    bool reversedZ = frame.depthParams.x == 0.0;
    if (reversedZ ? gl_FragCoord.z < opaque : gl_FragCoord.z > opaque) discard;

    uint kind = uint(draw.params.x);
    vec3 n = normalize(inNormal);
    if (kind == kForwardClosedSurface && dot(n, inRelative) > 0.0) discard;  // a back face
    float alpha = draw.albedoOpacity.a;
    if (kind == kForwardParticle) {  // a soft disc: α (1 - r²)²
        float r2 = dot(inCorner, inCorner);
        if (r2 >= 1.0) discard;
        alpha *= (1.0 - r2) * (1.0 - r2);
    }

    vec3 world = inRelative + frame.cameraPosition.xyz;
    vec3 albedo = draw.albedoOpacity.rgb;
    vec3 irradiance = surfaceIrradiance(inRelative, world, n, kind == kForwardParticle, draw.cloudShadowU,
                                        draw.cloudShadowV);
    vec3 radiance = albedo / kPi * irradiance + albedo * frame.ambient.rgb;
    // params.y: the benchmark times the pass without the lookup too, for the lookup's share of it.
    if (draw.params.y == 0.0) {
        PostfxVolumetrics v = postfxVolumetricsRelative(inRelative);
        radiance = radiance * v.transmittance + v.radiance;
    }
    outColor = vec4(min(radiance, vec3(kHalfMax)), alpha);
}
