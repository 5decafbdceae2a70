// CPU port of the shared noise generator (shaders/common/noise.glsl, shaders/common/noise_generate.comp):
// the same integer hashes and the same float operations in the same order, so a texel computed here
// matches the GPU's to within float rounding (tests compare the two). Tests and tools only.
#pragma once

#include <cstdint>
#include <vector>

namespace postfx::common {

// The generator's value at texel (x, y, z) of a size³ texture for `seed`, in [0, 1], before the
// R8_UNORM quantization. `size` is a power of two.
float noiseTexel(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed);

// The inverted Worley fBm alone at that texel (the clouds' detail texture), in [0, 1].
float worleyTexel(uint32_t x, uint32_t y, uint32_t z, uint32_t size, uint32_t seed);

// The whole texture as R8_UNORM bytes (round to nearest), x fastest, then y, then z: size³ bytes.
std::vector<uint8_t> generateNoiseCpu(uint32_t size, uint32_t seed);
// The same for worleyTexel.
std::vector<uint8_t> generateWorleyNoiseCpu(uint32_t size, uint32_t seed);

}  // namespace postfx::common
