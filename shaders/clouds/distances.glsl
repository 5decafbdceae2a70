// The two distances a temporal march texel keeps, packed as two halfs in one r32ui texel (km: a half's
// range and 2^-11 relative precision cover 6 cm to 65,000 km):
//   x: the reprojection distance: the clouds' extinction-weighted mean distance, or where the ray ends
//      when it meets none; negative: no history (a NaN depth);
//   y: the host's surface along the ray; +Inf for no geometry.
// The temporal pass reprojects at x and accepts a history texel only where the surface it saw is the
// one this texel's surface was (geometry that moved in front of the clouds, or away, rejects it); the
// clouds' own mean distance varies from frame to frame with the jitter, so it does not decide.
#ifndef POSTFX_CLOUDS_DISTANCES_GLSL
#define POSTFX_CLOUDS_DISTANCES_GLSL

uint packCloudDistances(float reprojection, float surface) {
    return packHalf2x16(vec2(reprojection, surface) * 1e-3);
}

vec2 unpackCloudDistances(uint packed) {
    return unpackHalf2x16(packed) * 1e3;
}

#endif
