// One stability case's frame: a small image (a wall whose distance grows down the image on the left,
// no geometry on the right), the fog and lights, optional shadow map; run through postfx on the GPU and
// through the double-precision reference on the same inputs.
#pragma once

#include "fog_harness.h"

#include <postfx/reference.h>

#include <string>
#include <vector>

namespace test {

struct StabilityFrame {
    postfx::FrameInfo frame;
    FogHarnessImages images;
    postfx::DepthConvention depth;  // the context's convention
    float nearPlane = 0.1f, farPlane = 1000.0f, fovYDeg = 60.0f;
    glm::dvec3 cameraPosition{0.0, 2.0, 0.0};
    double wallDistance = 20.0;  // [m] at the top row; + 1 m per row
};

// The base frame: 32×18, reversed Z, density 0.02, height falloff 0.1, g 0.6, 64 steps without jitter
// or early cutoff (so that the GPU's march samples exactly where the reference's midpoint march does).
StabilityFrame baseFrame();

// Recomputes camera and depth from the frame's camera fields (call after changing them).
void rebuildCameraAndDepth(StabilityFrame& f);

// The reference of `f` with the GPU's own step count (FogInputs.stepsPerPixel = fog.steps).
postfx::Status referenceOf(const StabilityFrame& f, std::vector<float>& out);

// Largest finite value of the color format (65504 for RGBA16F).
float colorMax(VkFormat format);

struct Comparison {
    size_t nonFinite = 0;      // channels NaN or Inf in the GPU output (RGB and alpha)
    size_t outOfRange = 0;     // channels beyond ±colorMax
    size_t off = 0;            // channels outside tolerance of the expectation
    double worstRelative = 0;  // largest |gpu - expected| / max(|expected|, 1)
    std::string firstOff;      // where and how the first off channel is off
};

// GPU against `expected` (clamped to ±colorMax first: the documented behaviour of RGBA16F outputs),
// relative tolerance `tolerance` of max(|expected|, 1) per channel.
Comparison compareToExpected(const std::vector<float>& gpu, const std::vector<float>& expected,
                             VkFormat format, double tolerance);

}  // namespace test
