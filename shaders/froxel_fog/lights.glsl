// Local lights and fog volumes at a froxel's sample (docs/effects/froxel-fog.md, "Local lights", "Local
// fog volumes"): the GPU side of reference::localLightIlluminance and reference::fogVolumeWeight.
// Expects `fog`, `froxel`, `local` (bindings.glsl) and common/phase.glsl.
#ifndef POSTFX_FROXEL_LIGHTS_GLSL
#define POSTFX_FROXEL_LIGHTS_GLSL

// Any light term above this is this: finite, so that a light's E·phase (I/r² with a tiny source radius
// at the light) never makes Inf, nor NaN where it meets a zero.
const float kMaxLightTerm = 1e30;

// smoothstep(e0, e1, x) that is a hard step at e1 when the edges meet (GLSL's is undefined there).
float smoothstepEdge(float e0, float e1, float x) {
    if (!(e1 > e0)) return x >= e1 ? 1.0 : 0.0;
    float t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Light l's cone·window at camera-relative x (0 beyond its range): window = (1 - (d/R)⁴)², cone =
// smoothstep(cos outer, cos inner, cos α). Also d² and the unit direction toward the light (0 at it).
float localLightFalloff(FroxelLight l, vec3 x, out float d2, out vec3 toLight) {
    vec3 fromLight = x - l.positionRange.xyz;
    d2 = dot(fromLight, fromLight);
    toLight = vec3(0.0);
    float range = l.positionRange.w;
    if (!(d2 < range * range)) return 0.0;
    float d = sqrt(d2);
    float q2 = d2 / (range * range);
    float window = (1.0 - q2 * q2) * (1.0 - q2 * q2);
    toLight = d > 0.0 ? -fromLight / d : vec3(0.0);
    float cone = 1.0;
    if (l.directionCosOuter.w >= -1.0)
        cone = smoothstepEdge(l.directionCosOuter.w, l.cosInnerBias.x,
                              d > 0.0 ? dot(-toLight, l.directionCosOuter.xyz) : 1.0);
    return cone * window;
}

// E_i(x)·p(d·ℓ_i)·V_i(x): light i's illuminance at camera-relative x times the phase toward the camera
// along view direction `dir` and its shadow's visibility `visibility` (1 unshadowed). E = I·cone·window/
// (d² + r²); isotropic at the light itself (d = 0).
vec3 localLightScatter(FroxelLight l, vec3 x, vec3 dir, float falloff, float d2, vec3 toLight,
                       float visibility) {
    float phase = d2 > 0.0 ? henyeyGreensteinDirections(dir, toLight, fog.medium.z) : kInvFourPi;
    float r = l.intensityRadius.w;
    // d² + r² >= 1e-30 (a radius below 1e-15 m underflows in float); the term is at most 1e30.
    float factor = falloff * phase * visibility / max(d2 + r * r, 1e-30);
    return min(l.intensityRadius.rgb * factor, vec3(kMaxLightTerm));
}

// Σ_v density_v · w_v(x): the local fog volumes' extinction at camera-relative x [1/m].
float volumesExtinction(vec3 x) {
    float sum = 0.0;
    for (uint v = 0u; v < froxel.counts.x; ++v) {
        vec4 a = froxel.volumes[2u * v], b = froxel.volumes[2u * v + 1u];
        vec3 p = x - a.xyz;
        vec3 inside = b.xyz - abs(p);
        float depth = b.y < 0.0 ? b.x - length(p) : min(inside.x, min(inside.y, inside.z));
        if (depth > 0.0) sum += b.w * (a.w > 0.0 ? smoothstepEdge(0.0, a.w, depth) : 1.0);
    }
    return sum;
}

#endif
