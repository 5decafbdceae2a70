// A froxel fog frame for GPU tests on the fog harness: images, lights and volumes it owns, the frame
// that points at them, and the same frame through the CPU reference (reference::renderFroxelFog).
#pragma once

#include "fog_harness.h"

#include <postfx/reference.h>

#include <vector>

namespace test {

struct FroxelCase {
    FogHarnessImages images;
    postfx::FrameInfo frame;  // lights and volumes are pointed at below by prepared()
    std::vector<postfx::LocalLight> lights;
    std::vector<postfx::FogVolume> volumes;
    postfx::DepthConvention depth;  // reversed Z, as the context the tests create
    std::vector<float> shadow;      // optional shadow map (images.shadow is set from it)
    // Local lights' shadows in images.localShadow's atlas (the lights' `shadow` index them).
    std::vector<postfx::LocalShadow> localShadows;

    // The frame with its light and volume pointers set to this case's arrays.
    postfx::FrameInfo prepared() const;
    // The reference of prepared() (noise generated on the CPU when on) with `steps` midpoint steps.
    postfx::Status reference(std::vector<float>& out, uint32_t steps = 2048) const;
};

// w × h pixels, camera at (0, cameraY, 0) looking down -z (60° vertical field of view, reversed Z, near
// 0.1 m), the left `wallColumns` columns see a wall at `wall` metres, the others nothing; color 1 + a
// gradient; froxel fog on with a homogeneous medium, no sun, no ambient, jitter off, grid = w × h × 64.
FroxelCase froxelCase(uint32_t w, uint32_t h, double cameraY, uint32_t wallColumns, double wall);

// A GPU test of froxel cases: one context (reversed Z, as froxelCase's camera) kept across renders, so
// that temporal accumulation carries from one render to the next.
class FroxelGpuFixture : public ReversedZContextTest {
protected:
    // prepared() at `frameIndex`, through the fog harness; a failed record() fails the test.
    std::vector<float> render(const FroxelCase& c, uint64_t frameIndex = 0);
};

}  // namespace test
