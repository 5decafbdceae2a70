#version 450
// Ray-marched fog at a reduced resolution (FogSettings::resolutionScale < 1): one invocation per texel
// of the scatter image marches the view ray of the full-resolution pixel nearest the texel's centre
// (fogSourcePixel) and stores (L, T) there; upsample.comp composites them over the host's color.
// Variants: COLOR_RGBA32F selects the storage format (default rgba16f); TEMPORAL also stores the surface
// distance, which temporal.comp filters and reprojects by (this frame's distance image of the history).
#extension GL_GOOGLE_include_directive : require

#include "fog/fog_shared.h"

layout(local_size_x = kFogMarchGroupX, local_size_y = kFogMarchGroupY) in;

#include "fog/bindings.glsl"
#include "fog/scatter_image.glsl"

#include "common/ign.glsl"
#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/ray.glsl"
#include "fog/march.glsl"

#ifdef TEMPORAL
layout(binding = kFogBindingDistance, r32f) uniform writeonly image2D distanceOut;
#endif

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, fog.scatterExtent.xy))) return;
    FogRay ray = fogRay(fogSourcePixel(texel));
#ifdef TEMPORAL
    imageStore(distanceOut, ivec2(texel), vec4(fogTemporalDistance(ray)));
#endif
    FogScatter s = marchFog(ray, texel);
    imageStore(scatterImage, ivec2(texel), vec4(min(s.inScattered, vec3(kColorMax)), s.transmittance));
}
