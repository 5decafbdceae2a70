#version 450
// Pass 2 of the atmosphere with "orders" (docs/effects/atmosphere.md, "Multiple scattering"): order n + 1 of
// the scattering-orders LUT from order n, mirroring postfx/src/atmosphere/atmosphere_orders.cpp. One
// workgroup per (sun, height) node; over n×n stratified directions ω_k in the node's frame (zenith +y, the
// sun in the x-y plane toward +x):
//   L_n(ω_k) = ∫ T·J_n dt + T·albedo/π·E_n(ground point)   (J_1: single scattering, E_1: the sun's),
//   Ψ_{n+1}(μ, φ) = Σ_k p(ω·ω_k)·L_n(ω_k) / Σ_k p(ω·ω_k)    (Rayleigh and Cornette–Shanks),
//   E_{n+1} = Σ_k L_n(ω_k)·max(0, ω_k·up)·4π/K              (the ground's nodes),
// written to `ordersOut` and added to the LUT; the last order adds the geometric tail Ψ_{N+1}·q/(1 - q),
// q = ΣΨ_{N+1} / ΣΨ_N over the node's outputs (E's own ratio for E).
#extension GL_GOOGLE_include_directive : require

#include "atmosphere/atmosphere_shared.h"

layout(local_size_x = kAtmosphereOrdersGroupSize) in;

#include "atmosphere/bindings.glsl"
layout(binding = kAtmosphereBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kAtmosphereBindingOrdersIn) uniform sampler3D ordersIn;
layout(binding = kAtmosphereBindingOrdersOut, rgba16f) uniform restrict image3D ordersOut;
layout(binding = kAtmosphereBindingMultiScattering, rgba16f) uniform restrict image3D ordersSum;
layout(push_constant) uniform Constants {
    AtmosphereOrderConstants pc;
};

#include "common/integrate.glsl"
#include "common/air/model.glsl"
#include "common/air/march.glsl"
#include "common/air/orders_lookup.glsl"
#include "common/air/march_steps.glsl"

const float kMaxTailRatio = 0.95;  // q of the geometric tail: at most this

shared vec3 sampleDir[kAtmosphereOrdersMaxDirections];
shared vec3 sampleRadiance[kAtmosphereOrdersMaxDirections];
shared vec3 sumLast[kAtmosphereOrdersGroupSize];
shared vec3 sumBefore[kAtmosphereOrdersGroupSize];

void main() {
    uint sunNode = gl_WorkGroupID.x, heightNode = gl_WorkGroupID.y, lane = gl_LocalInvocationID.x;
    uvec4 n = atmo.ordersLut;
    float y = float(heightNode) / float(n.z - 1u);
    float r = atmo.radii.x + y * y * (atmo.radii.y - atmo.radii.x);
    float muS = ordersCosineFromUnit(float(sunNode) / float(n.y - 1u));
    vec3 origin = vec3(0.0, r, 0.0);
    vec3 toSun = vec3(sqrt(max(0.0, 1.0 - muS * muS)), muS, 0.0);
    uint side = atmo.ordersMarch.x, count = side * side, steps = atmo.ordersMarch.y;
    bool first = pc.order == 1u;

    // The field is symmetric about the sun's vertical plane: azimuth column i and side - 1 - i (z and -z)
    // see the same light, so the first ceil(side/2) columns are marched and mirrored.
    uint marched = (side + 1u) / 2u * side;
    for (uint k = lane; k < marched; k += kAtmosphereOrdersGroupSize) {
        // Stratified uniform directions: azimuth 2π·a, cos(polar) = 1 - 2b.
        float a = (float(k / side) + 0.5) / float(side), b = (float(k % side) + 0.5) / float(side);
        float phi = 2.0 * kAtmospherePi * a, cosPolar = 1.0 - 2.0 * b;
        float sinPolar = sqrt(max(0.0, 1.0 - cosPolar * cosPolar));
        vec3 d = vec3(cos(phi) * sinPolar, cosPolar, sin(phi) * sinPolar);
        sampleDir[k] = d;
        vec3 L = vec3(0.0);
        vec3 seg = atmosphereSegment(origin, d);
        if (seg.y > seg.x || seg.z != 0.0) {
            float cosSun = dot(d, toSun);
            float phaseR = rayleighPhase(cosSun), phaseM = cornetteShanksPhase(cosSun, atmo.mie.w);
            float tLow = -r * d.y;
            vec3 T = vec3(1.0);
            uint stepCount = seg.y > seg.x ? marchStepCount(steps, seg.x, seg.y, tLow) : 0u;
            for (uint i = 0u; i < stepCount; ++i) {
                vec2 st = marchStep(i, steps, seg.x, seg.y, tLow);
                vec3 p = origin + st.x * d;
                float rp = length(p);
                AtmosphereMedium m = atmosphereMedium(rp - atmo.radii.x);
                vec3 J = first ? sunTransmittanceAt(p, toSun) *
                                     (m.rayleighScattering * phaseR + m.mieScattering * phaseM)
                               : ordersSource(ordersIn, p, rp, d, toSun, m);
                L += T * J * atmosphereStepIntegral(m.extinction, st.y);
                T *= exp(-m.extinction * st.y);
            }
            if (seg.z != 0.0) {
                vec3 g = origin + seg.y * d;
                float muG = dot(normalize(g), toSun);
                vec3 E = first ? sunTransmittanceAt(g, toSun) * max(0.0, muG)
                               : ordersGroundIrradiance(ordersIn, muG);
                L += T * E * atmo.albedo.rgb / kAtmospherePi;
            }
        }
        uint mirror = (side - 1u - k / side) * side + k % side;
        sampleRadiance[k] = L;
        sampleRadiance[mirror] = L;
        sampleDir[mirror] = vec3(d.xy, -d.z);
    }
    barrier();

    float scale = atmo.radii.w;
    uint outputs = n.x * n.w;
    vec3 last = vec3(0.0), before = vec3(0.0);
    for (uint o = lane; o < outputs; o += kAtmosphereOrdersGroupSize) {
        uint viewNode = o / n.w, azimuthNode = o % n.w;
        float mu = ordersCosineFromUnit(float(viewNode) / float(n.x - 1u));
        float phi = kAtmospherePi * float(azimuthNode) / float(n.w - 1u);
        float sinView = sqrt(max(0.0, 1.0 - mu * mu));
        vec3 w = vec3(sinView * cos(phi), mu, sinView * sin(phi));
        vec3 sumR = vec3(0.0), sumM = vec3(0.0);
        float weightR = 0.0, weightM = 0.0;
        for (uint k = 0u; k < count; ++k) {
            float c = dot(w, sampleDir[k]);
            float pR = rayleighPhase(c), pM = cornetteShanksPhase(c, atmo.mie.w);
            sumR += pR * sampleRadiance[k];
            sumM += pM * sampleRadiance[k];
            weightR += pR;
            weightM += pM;
        }
        vec3 psiR = sumR / weightR * scale, psiM = sumM / weightM * scale;
        ivec3 tR = ivec3(viewNode + n.x * azimuthNode, sunNode, heightNode), tM = tR + ivec3(0, 0, n.z);
        imageStore(ordersOut, tR, vec4(min(psiR, vec3(65504.0)), 1.0));
        imageStore(ordersOut, tM, vec4(min(psiM, vec3(65504.0)), 1.0));
        vec3 totalR = first ? psiR : imageLoad(ordersSum, tR).rgb + psiR;
        vec3 totalM = first ? psiM : imageLoad(ordersSum, tM).rgb + psiM;
        imageStore(ordersSum, tR, vec4(min(totalR, vec3(65504.0)), 1.0));
        imageStore(ordersSum, tM, vec4(min(totalM, vec3(65504.0)), 1.0));
        if (pc.last != 0u && !first) {
            last += psiR + psiM;
            before += texelFetch(ordersIn, tR, 0).rgb + texelFetch(ordersIn, tM, 0).rgb;
        }
    }

    // The ground's E_{n+1}, summed over the directions by the lanes.
    ivec3 groundTexel = ivec3(0, sunNode, 2u * n.z);
    if (heightNode == 0u) {
        vec3 E = vec3(0.0);
        for (uint k = lane; k < count; k += kAtmosphereOrdersGroupSize)
            E += sampleRadiance[k] * max(0.0, sampleDir[k].y);
        sumBefore[lane] = E;
    }
    barrier();
    for (uint stride = kAtmosphereOrdersGroupSize / 2u; stride > 0u; stride /= 2u) {
        if (heightNode == 0u && lane < stride) sumBefore[lane] += sumBefore[lane + stride];
        barrier();
    }
    vec3 groundNext = vec3(0.0), groundTotal = vec3(0.0);
    if (heightNode == 0u) {
        groundNext = sumBefore[0] * (4.0 * kAtmospherePi / float(count)) * scale;
        groundTotal = first ? groundNext : imageLoad(ordersSum, groundTexel).rgb + groundNext;
    }
    barrier();

    if (pc.last != 0u && !first) {
        // The tail: every output of the node scaled alike, q from the node's sums.
        sumLast[lane] = last;
        sumBefore[lane] = before;
        barrier();
        for (uint stride = kAtmosphereOrdersGroupSize / 2u; stride > 0u; stride /= 2u) {
            if (lane < stride) {
                sumLast[lane] += sumLast[lane + stride];
                sumBefore[lane] += sumBefore[lane + stride];
            }
            barrier();
        }
        vec3 q = clamp(sumLast[0] / max(sumBefore[0], vec3(1e-30)), 0.0, kMaxTailRatio);
        vec3 tail = mix(vec3(0.0), q / (1.0 - q), greaterThan(sumBefore[0], vec3(0.0)));
        for (uint o = lane; o < outputs; o += kAtmosphereOrdersGroupSize) {
            ivec3 tR = ivec3(o / n.w + n.x * (o % n.w), sunNode, heightNode), tM = tR + ivec3(0, 0, n.z);
            vec3 totalR = imageLoad(ordersSum, tR).rgb + imageLoad(ordersOut, tR).rgb * tail;
            vec3 totalM = imageLoad(ordersSum, tM).rgb + imageLoad(ordersOut, tM).rgb * tail;
            imageStore(ordersSum, tR, vec4(min(totalR, vec3(65504.0)), 1.0));
            imageStore(ordersSum, tM, vec4(min(totalM, vec3(65504.0)), 1.0));
        }
        if (heightNode == 0u) {
            vec3 groundBefore = texelFetch(ordersIn, groundTexel, 0).rgb;
            vec3 qg = clamp(groundNext / max(groundBefore, vec3(1e-30)), 0.0, kMaxTailRatio);
            groundTotal += groundNext * mix(vec3(0.0), qg / (1.0 - qg), greaterThan(groundBefore, vec3(0.0)));
        }
    }
    if (heightNode == 0u)
        for (uint x = lane; x < outputs; x += kAtmosphereOrdersGroupSize) {
            imageStore(ordersOut, ivec3(x, groundTexel.yz), vec4(min(groundNext, vec3(65504.0)), 1.0));
            imageStore(ordersSum, ivec3(x, groundTexel.yz), vec4(min(groundTotal, vec3(65504.0)), 1.0));
        }
}
