// Double-precision CPU references of postfx's effects, for tests, benchmarks and `postfx-render
// --reference`. They evaluate the same model as the GPU passes (docs/effects/*.md) with the same input
// data, so that the difference between the two is integration and precision error only.
#pragma once

#include <postfx/export.h>
#include <postfx/fog.h>
#include <postfx/inputs.h>
#include <postfx/result.h>
#include <postfx/types.h>

#include <cstdint>
#include <span>
#include <vector>

namespace postfx::reference {

// Everything the fog reference reads: the host's images as plain arrays, and the frame's inputs.
struct FogInputs {
    uint32_t width = 0, height = 0;
    std::span<const float> color;  // RGBA, width·height·4, row-major, top row first
    std::span<const float> depth;  // width·height depth values as the GPU samples them
    DepthConvention depthConvention;

    CameraInput camera;
    SunInput sun;
    Vec3 ambient{0.0f};
    double timeSeconds = 0.0;
    FogSettings settings;

    // Shadow map texels (row-major, top row = v 0), empty for none.
    std::span<const float> shadowDepth;
    uint32_t shadowWidth = 0, shadowHeight = 0;
    DMat4 shadowWorldToClip{1.0};
    bool shadowReversedZ = false;
    float shadowDepthBias = 0.0f;

    // Noise texels in [0, 1], noiseSize³ of them, x fastest then y then z. Required when
    // settings.noise.enabled.
    std::span<const float> noise;
    uint32_t noiseSize = 0;

    uint32_t stepsPerPixel = 4096;  // midpoint steps of the march (the tail is exact)
    uint32_t threads = 0;           // 0: all hardware threads
};

// Renders the fog over `inputs.color` into `out` (RGBA, same layout). Validates like Context::record.
POSTFX_API Status renderFog(const FogInputs& inputs, std::vector<float>& out);

// The model's pieces, exposed for tests.
POSTFX_API double henyeyGreenstein(double cosTheta, double g);  // [1/sr]; g clamped to [-0.999, 0.999]

}  // namespace postfx::reference
