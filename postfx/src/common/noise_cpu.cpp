// Mirrors shaders/common/noise.glsl function by function; keep the two in step (the formula is
// documented there). Float operations are written in the shader's order; only fused multiply-adds the
// GPU compiler may form differ (by an ulp or so).
#include "common/noise_cpu.h"

#include "common/medium_shared.h"

#include <algorithm>
#include <cmath>

namespace postfx::common {
namespace {

struct U3 {
    uint32_t x, y, z;
};
struct F3 {
    float x, y, z;
};

U3 pcg3d(U3 v) {
    v.x = v.x * 1664525u + 1013904223u;
    v.y = v.y * 1664525u + 1013904223u;
    v.z = v.z * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.x ^= v.x >> 16u;
    v.y ^= v.y >> 16u;
    v.z ^= v.z >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

U3 layerKey(uint32_t seed, uint32_t layer) {
    return pcg3d({seed, layer, 0x6E6F6973u});
}

U3 cellHash(U3 cell, U3 key) {
    return pcg3d({cell.x ^ key.x, cell.y ^ key.y, cell.z ^ key.z});
}

float unitFloat(uint32_t h) {
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

float gradDot(uint32_t h, float dx, float dy, float dz) {
    const uint32_t k = h >> 28u;
    const float u = k < 8u ? dx : dy;
    const float v = k < 4u ? dy : (k == 12u || k == 14u ? dx : dz);
    return ((k & 1u) == 0u ? u : -u) + ((k & 2u) == 0u ? v : -v);
}

float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float a, float b, float t) {
    return a + (b - a) * t;
}

float remap(float v, float lo, float hi, float newLo, float newHi) {
    return newLo + (v - lo) / (hi - lo) * (newHi - newLo);
}

float perlinNoise(F3 q, uint32_t period, U3 key) {
    const F3 c{std::floor(q.x), std::floor(q.y), std::floor(q.z)};
    const F3 f{q.x - c.x, q.y - c.y, q.z - c.z};
    const U3 i0{uint32_t(c.x) % period, uint32_t(c.y) % period, uint32_t(c.z) % period};
    const U3 i1{(i0.x + 1u) % period, (i0.y + 1u) % period, (i0.z + 1u) % period};
    const float g = f.x - 1.0f, h = f.y - 1.0f, k = f.z - 1.0f;
    const float n000 = gradDot(cellHash({i0.x, i0.y, i0.z}, key).x, f.x, f.y, f.z);
    const float n100 = gradDot(cellHash({i1.x, i0.y, i0.z}, key).x, g, f.y, f.z);
    const float n010 = gradDot(cellHash({i0.x, i1.y, i0.z}, key).x, f.x, h, f.z);
    const float n110 = gradDot(cellHash({i1.x, i1.y, i0.z}, key).x, g, h, f.z);
    const float n001 = gradDot(cellHash({i0.x, i0.y, i1.z}, key).x, f.x, f.y, k);
    const float n101 = gradDot(cellHash({i1.x, i0.y, i1.z}, key).x, g, f.y, k);
    const float n011 = gradDot(cellHash({i0.x, i1.y, i1.z}, key).x, f.x, h, k);
    const float n111 = gradDot(cellHash({i1.x, i1.y, i1.z}, key).x, g, h, k);
    const F3 u{fade(f.x), fade(f.y), fade(f.z)};
    const float x00 = lerp(n000, n100, u.x);
    const float x10 = lerp(n010, n110, u.x);
    const float x01 = lerp(n001, n101, u.x);
    const float x11 = lerp(n011, n111, u.x);
    const float y0 = lerp(x00, x10, u.y);
    const float y1 = lerp(x01, x11, u.y);
    return lerp(y0, y1, u.z);
}

float worleyF1(F3 q, uint32_t period, U3 key) {
    const F3 c{std::floor(q.x), std::floor(q.y), std::floor(q.z)};
    const F3 f{q.x - c.x, q.y - c.y, q.z - c.z};
    const int32_t p = int32_t(period);
    float d2 = 1e4f;
    for (int32_t dz = -1; dz <= 1; ++dz)
        for (int32_t dy = -1; dy <= 1; ++dy)
            for (int32_t dx = -1; dx <= 1; ++dx) {
                const U3 cell{uint32_t((int32_t(c.x) + dx + p) % p), uint32_t((int32_t(c.y) + dy + p) % p),
                              uint32_t((int32_t(c.z) + dz + p) % p)};
                const U3 h = cellHash(cell, key);
                const float rx = (float(dx) + unitFloat(h.x)) - f.x;
                const float ry = (float(dy) + unitFloat(h.y)) - f.y;
                const float rz = (float(dz) + unitFloat(h.z)) - f.z;
                d2 = std::min(d2, rx * rx + ry * ry + rz * rz);
            }
    return std::sqrt(d2);
}

F3 latticeCoord(uint32_t x, uint32_t y, uint32_t z, uint32_t period, uint32_t size) {
    const float scale = float(period) / float(size);
    return {(float(x) + 0.5f) * scale, (float(y) + 0.5f) * scale, (float(z) + 0.5f) * scale};
}

float perlinFbm(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed) {
    float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
    for (uint32_t o = 0; o < gpu::kNoisePerlinOctaves; ++o) {
        const uint32_t period = std::min(gpu::kNoisePerlinBasePeriod << o, size);
        sum += amplitude * perlinNoise(latticeCoord(x, y, z, period, size), period, layerKey(seed, o));
        total += amplitude;
        amplitude *= 0.5f;
    }
    return sum / total;
}

float worleyFbm(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed) {
    float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
    for (uint32_t o = 0; o < gpu::kNoiseWorleyOctaves; ++o) {
        const uint32_t period = std::min(gpu::kNoiseWorleyBasePeriod << o, size);
        const float f1 = worleyF1(latticeCoord(x, y, z, period, size), period, layerKey(seed, 16u + o));
        sum += amplitude * (1.0f - std::min(f1, 1.0f));
        total += amplitude;
        amplitude *= 0.5f;
    }
    return sum / total;
}

}  // namespace

float noiseTexel(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed) {
    const float p = std::clamp(perlinFbm(x, y, z, size, seed) + 0.5f, 0.0f, 1.0f);
    const float w = worleyFbm(x, y, z, size, seed);
    const float perlinWorley = remap(p, w - 1.0f, 1.0f, 0.0f, 1.0f);
    return std::clamp(remap(perlinWorley, gpu::kNoiseRangeLow, 1.0f, 0.0f, 1.0f), 0.0f, 1.0f);
}

float worleyTexel(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed) {
    return worleyFbm(x, y, z, size, seed);
}

namespace {
template <class Texel>
std::vector<uint8_t> quantized(uint32_t size, uint32_t seed, const Texel& texel) {
    std::vector<uint8_t> texels(size_t(size) * size * size);
    size_t i = 0;
    for (uint32_t z = 0; z < size; ++z)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const float v = std::clamp(texel(x, y, z, size, seed), 0.0f, 1.0f);
                texels[i++] = uint8_t(std::floor(v * 255.0f + 0.5f));
            }
    return texels;
}
}  // namespace

std::vector<uint8_t> generateNoiseCpu(uint32_t size, uint32_t seed) {
    return quantized(size, seed, noiseTexel);
}

std::vector<uint8_t> generateWorleyNoiseCpu(uint32_t size, uint32_t seed) {
    return quantized(size, seed, worleyTexel);
}

}  // namespace postfx::common
