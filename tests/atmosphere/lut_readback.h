// Reading one of the atmosphere's LUTs back (Context::recordImageReadback), its RGBA16F texels as floats:
// for the LUT tests (test_atmosphere_gpu.cpp) and the docs' pictures (test_atmosphere_pictures.cpp).
#pragma once

#include "core/gpu_resources.h"
#include "fog_harness.h"

#include <postfx/context.h>

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <string>
#include <vector>

namespace test {

struct LutTexels {
    uint32_t width = 0, height = 0, depth = 0;
    std::vector<float> rgba;  // x fastest, then y, then z, then the layers (the sky view's: layer 0 first)
};

inline LutTexels readLutTexels(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                               const postfx::Context& context, const char* name) {
    LutTexels lut;
    VkExtent3D extent{};
    const std::vector<uint8_t> bytes = readHeldImage(host, gpu, context, name, extent);
    lut.width = extent.width;
    lut.height = extent.height;
    lut.depth = extent.depth;
    lut.rgba.resize(bytes.size() / 2);
    for (size_t i = 0; i < lut.rgba.size(); ++i) {
        uint16_t half;
        std::memcpy(&half, &bytes[2 * i], sizeof half);
        lut.rgba[i] = glm::unpackHalf1x16(half);
    }
    return lut;
}

}  // namespace test
