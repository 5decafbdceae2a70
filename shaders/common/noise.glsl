// Tileable 3D noise for the fog's noise texture: integer hashes, gradient (Perlin) noise, cellular
// (Worley) noise, their fBm, and the Perlin–Worley combination. Ported to C++ line by line in
// postfx/src/fog/noise_cpu.cpp (tests compare the two): keep them in step.
//
// Texel (x, y, z) of a size³ texture (size a power of two), seed s. Octave o of each fBm uses a
// lattice of period_o = min(base·2^o, size) cells per tile, at lattice coordinate
//     q_o = ((x, y, z) + 0.5) · period_o / size          (texel centres; exact in float)
// and hashes cell indices modulo period_o, so every octave repeats exactly once per tile and the
// texture has no seam under REPEAT addressing.
//
//   P  = Σ_o a_o · perlin(q_o, period_o) / Σ_o a_o     4 octaves, periods 4, 8, 16, 32, a_o = 2^-o
//        perlin: improved gradient noise (Perlin 2002: 12 edge gradients, quintic fade), ~[-1, 1]
//   W  = Σ_o a_o · (1 - min(F1(q_o, period_o), 1)) / Σ_o a_o   3 octaves, periods 4, 8, 16, a_o = 2^-o
//        F1: distance to the nearest feature point, one per cell at a hashed position (inverted Worley)
//   p  = clamp(P + 0.5, 0, 1)                                (Perlin fBm in [0, 1], contrast 2)
//   PW = remap(p, W - 1, 1, 0, 1) = (p + 1 - W) / (2 - W)     (Schneider's Perlin–Worley)
//   n  = clamp(remap(PW, kNoiseRangeLow, 1, 0, 1), 0, 1)     (stretched to the range [0, 1])
// with remap(v, l0, h0, l1, h1) = l1 + (v - l0) / (h0 - l0) · (h1 - l1). Over a texture: mean ≈ 0.53,
// standard deviation ≈ 0.16.
//
// Hashes are integer only (PCG3D, Jarzynski & Olano 2020), so a CPU port gives the same lattice.
#ifndef POSTFX_NOISE_GLSL
#define POSTFX_NOISE_GLSL

#include "common/shared.h"

uvec3 noisePcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// Key of one noise layer (an octave of Perlin: layer o, of Worley: 16 + o) for a seed.
uvec3 noiseLayerKey(uint seed, uint layer) {
    return noisePcg3d(uvec3(seed, layer, 0x6E6F6973u));
}

// Hash of a lattice cell (indices already wrapped to the period) within a layer.
uvec3 noiseCellHash(uvec3 cell, uvec3 key) {
    return noisePcg3d(cell ^ key);
}

// The top 24 bits of a hash as a float in [0, 1) (exact).
float noiseUnitFloat(uint h) {
    return float(h >> 8u) * (1.0 / 16777216.0);
}

// Dot product of d with one of Perlin's 16 gradients (12 cube edges, 4 repeated), chosen by the hash's
// top 4 bits. Each term is ±d.? exactly, so the sum is rounded once.
float noiseGradDot(uint h, float dx, float dy, float dz) {
    uint k = h >> 28u;
    float u = k < 8u ? dx : dy;
    float v = k < 4u ? dy : ((k == 12u || k == 14u) ? dx : dz);
    return ((k & 1u) == 0u ? u : -u) + ((k & 2u) == 0u ? v : -v);
}

float noiseFade(float t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

float noiseLerp(float a, float b, float t) {
    return a + (b - a) * t;
}

float noiseRemap(float v, float lo, float hi, float newLo, float newHi) {
    return newLo + (v - lo) / (hi - lo) * (newHi - newLo);
}

// Gradient noise at lattice coordinate q in [0, period)³, periodic with `period` cells.
float perlinNoise(vec3 q, uint period, uvec3 key) {
    vec3 c = floor(q);
    vec3 f = q - c;
    uvec3 i0 = uvec3(c) % period;
    uvec3 i1 = (i0 + 1u) % period;
    float g = f.x - 1.0;
    float h = f.y - 1.0;
    float k = f.z - 1.0;
    float n000 = noiseGradDot(noiseCellHash(uvec3(i0.x, i0.y, i0.z), key).x, f.x, f.y, f.z);
    float n100 = noiseGradDot(noiseCellHash(uvec3(i1.x, i0.y, i0.z), key).x, g, f.y, f.z);
    float n010 = noiseGradDot(noiseCellHash(uvec3(i0.x, i1.y, i0.z), key).x, f.x, h, f.z);
    float n110 = noiseGradDot(noiseCellHash(uvec3(i1.x, i1.y, i0.z), key).x, g, h, f.z);
    float n001 = noiseGradDot(noiseCellHash(uvec3(i0.x, i0.y, i1.z), key).x, f.x, f.y, k);
    float n101 = noiseGradDot(noiseCellHash(uvec3(i1.x, i0.y, i1.z), key).x, g, f.y, k);
    float n011 = noiseGradDot(noiseCellHash(uvec3(i0.x, i1.y, i1.z), key).x, f.x, h, k);
    float n111 = noiseGradDot(noiseCellHash(uvec3(i1.x, i1.y, i1.z), key).x, g, h, k);
    vec3 u = vec3(noiseFade(f.x), noiseFade(f.y), noiseFade(f.z));
    float x00 = noiseLerp(n000, n100, u.x);
    float x10 = noiseLerp(n010, n110, u.x);
    float x01 = noiseLerp(n001, n101, u.x);
    float x11 = noiseLerp(n011, n111, u.x);
    float y0 = noiseLerp(x00, x10, u.y);
    float y1 = noiseLerp(x01, x11, u.y);
    return noiseLerp(y0, y1, u.z);
}

// Distance (in cells) from q to the nearest feature point, one per cell, periodic with `period` cells.
float worleyF1(vec3 q, uint period, uvec3 key) {
    vec3 c = floor(q);
    vec3 f = q - c;
    int p = int(period);
    ivec3 ic = ivec3(c);
    float d2 = 1e4;
    for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                uvec3 cell = uvec3((ic + ivec3(dx, dy, dz) + p) % p);
                uvec3 h = noiseCellHash(cell, key);
                float rx = (float(dx) + noiseUnitFloat(h.x)) - f.x;
                float ry = (float(dy) + noiseUnitFloat(h.y)) - f.y;
                float rz = (float(dz) + noiseUnitFloat(h.z)) - f.z;
                d2 = min(d2, rx * rx + ry * ry + rz * rz);
            }
        }
    }
    return sqrt(d2);
}

// Lattice coordinate of a texel centre for a lattice of `period` cells over `size` texels.
vec3 noiseLatticeCoord(uvec3 texel, uint period, uint size) {
    float scale = float(period) / float(size);
    return (vec3(texel) + 0.5) * scale;
}

// P: Perlin fBm, ~[-0.6, 0.6].
float perlinFbm(uvec3 texel, uint size, uint seed) {
    float sum = 0.0;
    float amplitude = 1.0;
    float total = 0.0;
    for (uint o = 0u; o < kNoisePerlinOctaves; ++o) {
        uint period = min(kNoisePerlinBasePeriod << o, size);
        sum +=
            amplitude * perlinNoise(noiseLatticeCoord(texel, period, size), period, noiseLayerKey(seed, o));
        total += amplitude;
        amplitude *= 0.5;
    }
    return sum / total;
}

// W: inverted Worley fBm, [0, 1], 1 at feature points.
float worleyFbm(uvec3 texel, uint size, uint seed) {
    float sum = 0.0;
    float amplitude = 1.0;
    float total = 0.0;
    for (uint o = 0u; o < kNoiseWorleyOctaves; ++o) {
        uint period = min(kNoiseWorleyBasePeriod << o, size);
        float f1 = worleyF1(noiseLatticeCoord(texel, period, size), period, noiseLayerKey(seed, 16u + o));
        sum += amplitude * (1.0 - min(f1, 1.0));
        total += amplitude;
        amplitude *= 0.5;
    }
    return sum / total;
}

// n: the texture's value at `texel`, [0, 1].
float perlinWorleyNoise(uvec3 texel, uint size, uint seed) {
    float p = clamp(perlinFbm(texel, size, seed) + 0.5, 0.0, 1.0);
    float w = worleyFbm(texel, size, seed);
    float perlinWorley = noiseRemap(p, w - 1.0, 1.0, 0.0, 1.0);
    return clamp(noiseRemap(perlinWorley, kNoiseRangeLow, 1.0, 0.0, 1.0), 0.0, 1.0);
}

#endif  // POSTFX_NOISE_GLSL
