#version 450
// Ray-marched fog over the host's color at full resolution (docs/effects/fog.md): one invocation per
// pixel marches its view ray (march.glsl) and writes out = color · T + L.
// Variants: COLOR_RGBA32F selects the storage format of the color images (default rgba16f).
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = kFogMarchGroupX, local_size_y = kFogMarchGroupY) in;

#include "fog/bindings.glsl"

#include "common/ign.glsl"
#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/ray.glsl"
#include "common/composite.glsl"
#include "fog/march.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, fog.extent.xy))) return;
    vec4 color = imageLoad(colorIn, ivec2(pixel));
    FogScatter s = marchFog(fogRay(pixel), pixel);
    imageStore(colorOut, ivec2(pixel),
               vec4(compositeOver(color.rgb, s.transmittance, s.inScattered), color.a));
}
