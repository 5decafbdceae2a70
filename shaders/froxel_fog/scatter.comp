#version 450
// Pass 1 of the froxel fog (docs/effects/froxel-fog.md, "Passes"): one invocation per froxel evaluates
// the medium and its light at the froxel's sample (jittered per frame) and stores
// (albedo · light · storage scale, σt), light = sun · phase · visibility + ambient + Σ local lights.
// Variants: LOCAL_LIGHTS loops over every light; LIGHT_LISTS over those its cluster's list holds
// (light_lists.comp); without either the frame has no local light. LOCAL_SHADOWS (with either) multiplies
// the lights that have a shadow by their visibility from the host's atlas. TEMPORAL (with any of them)
// blends the result with the previous frames' volume reprojected to the sample (froxel-fog.md#temporal).
#extension GL_GOOGLE_include_directive : require

#include "froxel_fog/froxel_shared.h"

layout(local_size_x = kFroxelGroupSize, local_size_y = kFroxelGroupSize) in;

#ifdef LIGHT_LISTS
#define LOCAL_LIGHTS
#endif

#include "froxel_fog/bindings.glsl"
#ifdef TEMPORAL
// The accumulated volume is RGBA32F: blended in half precision at 5% per frame, an update below half an
// ulp (0.05·|current - history| < 2.4e-4·history) would be lost, and the history would stop about 0.5%
// from its mean (froxel-fog.md#temporal).
layout(binding = kFroxelBindingScatter, rgba32f) uniform writeonly image3D scatterVolume;
#else
layout(binding = kFroxelBindingScatter, rgba16f) uniform writeonly image3D scatterVolume;
#endif

#include "common/integrate.glsl"
#include "common/phase.glsl"
#include "common/medium/medium.glsl"
#include "common/medium/atmosphere_light.glsl"
#include "froxel_fog/grid.glsl"
#include "froxel_fog/lights.glsl"

#ifdef LOCAL_SHADOWS
layout(binding = kFroxelBindingShadowAtlas) uniform sampler2D shadowAtlas;
layout(binding = kFroxelBindingShadowFaces, std430) readonly buffer ShadowFaces {
    FroxelShadowFace faces[];
}
shadowFaces;
#include "froxel_fog/local_shadows.glsl"
#ifdef TEMPORAL
// Where the shadowed lights' light changed since the previous frame, per block of 2×2×2 froxels
// (shadow_change.comp): 1 changed, 0 not; sampled trilinearly (LinearClamp).
layout(binding = kFroxelBindingShadowChange) uniform sampler3D shadowChange;
#endif
#endif

// The centre of froxel `id` (camera-relative): where the history is read.
vec3 froxelCentre(uvec3 id) {
    vec3 centreDir = gridRayDirection((vec2(id.xy) + 0.5) / vec2(froxel.grid.xy));
    return centreDir * sliceDepth((float(id.z) + 0.5) / float(froxel.grid.z));
}

#ifdef TEMPORAL
layout(binding = kFroxelBindingHistory) uniform sampler3D historyVolume;
layout(binding = kFroxelBindingTemporal, std140) uniform Temporal {
    TemporalUniforms temporal;
};
#include "common/history_rescale.glsl"

#include "froxel_fog/reproject.glsl"

// Whether `x` is near a local light that changed (its old or new sphere, widened by `margin`, the
// froxel's size, since the history is filtered over neighbouring froxels).
bool inRejectedSphere(vec3 x, float margin) {
    for (uint i = 0u; i < temporal.state.y; ++i) {
        vec4 s = temporal.spheres[i];
        if (distance(x, s.xyz) <= s.w + margin) return true;
    }
    return false;
}

bool finiteVec(vec4 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// Blends two (albedo·light, σt) of a slice of length `dt` so that what the integration makes of the
// result is the blend of what it makes of each: the slice's opacity a = 1 - e^{-σt·dt} and its
// in-scattered light albedo·light·a (integrate.comp) are blended, and σt and light solved back from
// them. Blending σt itself would give e^{-mean σt·dt}, not the mean transmittance (Jensen's
// inequality): with noise in the medium the accumulated image would miss the mean of its frames.
vec4 blendSlices(vec4 history, vec4 current, float w, float dt) {
    float aHistory = oneMinusExp(history.a * dt), aCurrent = oneMinusExp(current.a * dt);
    float a = mix(aHistory, aCurrent, w);
    vec3 light = a > 0.0 ? mix(history.rgb * aHistory, current.rgb * aCurrent, w) / a
                         : mix(history.rgb, current.rgb, w);
    // σt = -ln(1 - a)/dt; for small a by its series a + a²/2 + a³/3 (1 - a loses a's digits).
    float opticalDepth = a < 1e-3 ? a * (1.0 + a * (0.5 + a / 3.0)) : -log(1.0 - a);
    return vec4(light, dt > 0.0 ? opticalDepth / dt : mix(history.a, current.a, w));
}

// This frame's (albedo·light·scale, σt) blended with the history (docs/temporal.md). The history is read
// where the previous grid held this froxel's centre (not its jittered sample): a still view reads each
// froxel's own texel, so the accumulation averages the jittered samples without blurring the volume.
// With local shadows, the history is also dropped where a caster or a shadowed light moved
// (shadow_change.comp).
vec4 accumulate(vec4 current, vec3 x, uvec3 id, vec3 centre, float start, float end) {
    if (temporal.state.x == 0u) return current;
    vec3 centreDir = normalize(centre);
    if (temporal.state.y > 0u) {
        vec3 side = gridRayDirection((vec2(id.xy) + 1.5) / vec2(froxel.grid.xy));
        float margin = 2.0 * max(end - start, length(side - centreDir) * end);
        if (inRejectedSphere(x, margin)) return current;
    }
    vec3 uvw;
    if (!previousGridCoordinate(centre, uvw)) return current;
    // Trilinear by hand (8 texel fetches): linear filtering of RGBA32F is optional in Vulkan.
    vec3 p = uvw * vec3(froxel.grid.xyz) - 0.5;
    ivec3 p0 = ivec3(floor(p));
    vec3 f = p - vec3(p0);
    ivec3 last = ivec3(froxel.grid.xyz) - 1;
    vec4 history = vec4(0.0);
    for (int k = 0; k < 8; ++k) {
        ivec3 o = ivec3(k & 1, (k >> 1) & 1, k >> 2);
        vec3 w = mix(1.0 - f, f, vec3(o));
        if (!(w.x * w.y * w.z > 0.0)) continue;  // not read
        vec4 h = texelFetch(historyVolume, clamp(p0 + o, ivec3(0), last), 0);
        // Stored clamped to kFroxelHalfMax, in RGBA32F (no underflow): a clipped froxel is not rescaled.
        if (!rescalableHistory(h.rgb, kFroxelHalfMax, 0.0)) return current;
        history += w.x * w.y * w.z * h;
    }
    // The previous frame's storage scale and pre-exposure -> this one's.
    history.rgb *= temporal.previous.y;
    if (!finiteVec(history)) return current;  // a host's NaN once in the volume: not kept
#ifdef LOCAL_SHADOWS
    // The blocks whose centres enclose this froxel's centre (shadow_change.comp): the froxel's centre
    // (k + 0.5 froxels) is (k + 0.5)/2 in block texels, between two block centres with weights 1/4 and 3/4
    // on each axis, so each of the eight weighs at least 1/64 and any changed one is seen.
    uvec3 blocks = (froxel.grid.xyz + 1u) / 2u;
    if (texture(shadowChange, (vec3(id) + 0.5) / vec3(2u * blocks)).r > 0.5 / 64.0) return current;
#endif
    // Each trilinear resample blurs the history by a variance of b = Σ f(1 - f) froxel² (0 for a still
    // view, which reads each froxel's own texel); an exponential blend of weight w adds these up to
    // (1 - w)/w · b. The weight is raised to w ≥ b/(b + B), so the accumulated blur stays below
    // B = kFroxelTemporalBlurBudget while the view moves (the blend weight alone, 0.05: up to 19·b).
    float b = dot(f * (1.0 - f), vec3(1.0));
    float w = max(temporal.cameraDelta.w, b / (b + kFroxelTemporalBlurBudget));
    return blendSlices(history, current, w, end - start);
}
#endif

#ifdef LOCAL_LIGHTS
// Light i's E·p·V at the sample x.
vec3 localLightTerm(uint i, vec3 x, vec3 dir) {
    FroxelLight l = local.lights[i];
    float d2;
    vec3 toLight;
    float falloff = localLightFalloff(l, x, d2, toLight);
    if (!(falloff > 0.0)) return vec3(0.0);
    float visibility = 1.0;
#ifdef LOCAL_SHADOWS
    if (l.shadow.x != kFroxelNoShadow) visibility = localShadowVisibility(l, x);
#endif
    return localLightScatter(l, x, dir, falloff, d2, toLight, visibility);
}

// Σ over the lights the froxel's cluster lists (LIGHT_LISTS), or over all of them.
vec3 localLightsScatter(uvec3 froxelId, vec3 x, vec3 dir) {
    vec3 sum = vec3(0.0);
#ifdef LIGHT_LISTS
    uint words = froxel.counts.z;
    uvec3 cluster = froxelId / uvec3(kFroxelClusterSize, kFroxelClusterSize, kFroxelClusterSlices);
    for (uint w = 0u; w < words; ++w) {
        uint bits = imageLoad(lightLists, ivec3(cluster.xy, cluster.z * words + w)).r;
        while (bits != 0u) {
            int i = findLSB(bits);
            bits &= bits - 1u;
            sum += localLightTerm(w * 32u + uint(i), x, dir);
        }
    }
#else
    for (uint i = 0u; i < froxel.grid.w; ++i)
        sum += localLightTerm(i, x, dir);
#endif
    return sum;
}
#endif

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (any(greaterThanEqual(id, froxel.grid.xyz))) return;
    vec3 offset = froxel.jitter.xyz;
    vec3 dir = gridRayDirection((vec2(id.xy) + offset.xy) / vec2(froxel.grid.xy));
    float start = sliceStart(id.z), end = sliceStart(id.z + 1u);
    vec3 x = dir * mix(start, end, offset.z);

    // σt: the shared medium plus the volumes (+Inf stays +Inf: an opaque froxel, stored as the half max).
    float sigmaT = extinction(x) + volumesExtinction(x);
    vec3 light = vec3(0.0);
    if (sigmaT > 0.0) {
        light = fog.ambient.rgb;
        vec3 sun = fog.sunIlluminance.rgb;
        if (any(greaterThan(sun, vec3(0.0))))
            light += sun * henyeyGreensteinDirections(dir, fog.toSun.xyz, fog.medium.z) *
                     shadowVisibility(x) * sunTransmittance(fog.heights.x + x.y) *
                     atmosphereSunTransmittance(x) * cloudShadowVisibility(x);
#ifdef LOCAL_LIGHTS
        light += localLightsScatter(id, x, dir);
#endif
    }
    vec4 stored = min(vec4(fog.albedo.rgb * light * froxel.jitter.w, sigmaT), vec4(kFroxelHalfMax));
#ifdef TEMPORAL
    stored = min(accumulate(stored, x, id, froxelCentre(id), start, end), vec4(kFroxelHalfMax));
#endif
    imageStore(scatterVolume, ivec3(id), stored);
}
