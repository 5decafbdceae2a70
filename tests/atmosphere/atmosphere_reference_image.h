// Reference (a) of a test's frame: the model without LUTs per pixel in double
// (postfx::reference::renderAtmosphere) over the images a test renders, multiple scattering from its fine Ψ
// table or its scattering-orders table when the frame has either on. For the GPU tests
// (test_atmosphere_gpu.cpp) and the stability suite (test_atmosphere_stability.cpp), each with its own steps
// and table sizes.
#pragma once

#include "fog_harness.h"

#include <postfx/reference.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace test {

struct AtmosphereReferenceQuality {
    uint32_t stepsPerPixel = 600;
    uint32_t psiTableSize = 32;  // μs × heights
    uint32_t psiDirections = 64;
    // The scattering orders' table: nodes (view, sun, height, azimuth), directions, steps, orders; 0 nodes:
    // the reference's own defaults (postfx::reference::AtmosphereInputs) for every field.
    uint32_t ordersView = 16, ordersSun = 16, ordersHeight = 8, ordersAzimuth = 4;
    uint32_t ordersDirections = 144, ordersSteps = 32, ordersCount = 6;
};

// The fields every reference's inputs share (postfx::reference::FogInputs, FroxelFogInputs,
// AtmosphereInputs): a test's images (reversed Z) with `color` over them, and the frame's camera and sun.
template <class Inputs>
void setReferenceImages(Inputs& in, const postfx::FrameInfo& frame, const FogHarnessImages& im,
                        const std::vector<float>& color) {
    in.width = im.width;
    in.height = im.height;
    in.color = color;
    in.depth = im.depth;
    in.depthConvention.reversedZ = true;
    in.camera = frame.camera;
    in.sun = frame.sun;
}

inline std::vector<float> atmosphereReferenceImage(const postfx::FrameInfo& frame, const FogHarnessImages& im,
                                                   const AtmosphereReferenceQuality& quality = {}) {
    postfx::reference::AtmosphereInputs in;
    setReferenceImages(in, frame, im, im.color);
    in.settings = frame.atmosphere;
    in.stepsPerPixel = quality.stepsPerPixel;
    in.psiTableMuS = quality.psiTableSize;
    in.psiTableHeights = quality.psiTableSize;
    in.psiDirections = quality.psiDirections;
    if (quality.ordersView == 0) {
        std::vector<float> out;
        const postfx::Status s = postfx::reference::renderAtmosphere(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
    in.ordersViewNodes = quality.ordersView;
    in.ordersSunNodes = quality.ordersSun;
    in.ordersHeightNodes = quality.ordersHeight;
    in.ordersAzimuthNodes = quality.ordersAzimuth;
    in.ordersDirections = quality.ordersDirections;
    in.ordersSteps = quality.ordersSteps;
    in.ordersCount = quality.ordersCount;
    std::vector<float> out;
    const postfx::Status s = postfx::reference::renderAtmosphere(in, out);
    EXPECT_TRUE(s.ok()) << s.message;
    return out;
}

}  // namespace test
