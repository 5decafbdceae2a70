// The small fog frames the fault-injection and leak-cycle tests record: a homogeneous or noisy fog over
// a half-wall, with the options that make postfx allocate (noise texture, shadow map, reduced resolution,
// separate output, color format), or the froxel fog with local lights.
#pragma once

#include "fog_harness.h"

namespace test {

struct FaultSceneOptions {
    uint32_t width = 8, height = 8;
    VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
    bool noise = false;
    uint32_t noiseSize = 16;
    bool shadowMap = false;
    float resolutionScale = 1.0f;
    bool separateOutput = false;
    bool autoQuality = false;  // fog quality Auto (presets measured in turn, timings read in record())
    bool froxel = false;       // the froxel fog (a 4×4×8 grid) with the same medium instead of the fog
    uint32_t lights = 0;       // local lights in view (at most 16; 8 or more: light lists)
    bool temporal = false;     // temporal accumulation (either fog): history images carried across frames
};

// The frame (fog on; the harness fills in the command buffer and images) and the host's images.
postfx::FrameInfo faultSceneFrame(const FaultSceneOptions& options, uint64_t frameIndex);
FogHarnessImages faultSceneImages(const FaultSceneOptions& options);

}  // namespace test
