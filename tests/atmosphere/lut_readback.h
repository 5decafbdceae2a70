// Reading one of the atmosphere's LUTs back (Context::recordImageReadback), its RGBA16F texels as floats:
// for the LUT tests (test_atmosphere_gpu.cpp) and the docs' pictures (test_atmosphere_pictures.cpp).
#pragma once

#include "core/gpu_resources.h"
#include "gpu_test.h"

#include <postfx/context.h>

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

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
    postfx::core::GpuBuffer buffer;
    EXPECT_TRUE(buffer.create(gpu, 64u << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "lut readback").ok());
    VkExtent3D extent{};
    VkDeviceSize bytes = 0;
    postfx::Status status;
    std::string error;
    EXPECT_TRUE(host.submitAndWait(
        [&](VkCommandBuffer cmd) {
            status = context.recordImageReadback({name}, cmd, buffer.handle(), 0, extent, bytes);
        },
        error))
        << error;
    EXPECT_TRUE(status.ok()) << status.message;
    lut.width = extent.width;
    lut.height = extent.height;
    lut.depth = extent.depth;
    const auto* half = static_cast<const uint16_t*>(buffer.mapped());
    lut.rgba.resize(bytes / 2);
    for (size_t i = 0; i < lut.rgba.size(); ++i)
        lut.rgba[i] = glm::unpackHalf1x16(half[i]);
    return lut;
}

}  // namespace test
