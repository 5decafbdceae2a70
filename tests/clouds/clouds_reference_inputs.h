// What the clouds' GPU tests hand the double reference (postfx::reference::renderClouds): the GPU's noise
// texels read back, and the frame's inputs over the harness's images.
#pragma once

#include "fog_harness.h"

#include <postfx/reference.h>

#include <cstdint>
#include <vector>

namespace test {

// An R8_UNORM texture postfx holds (a noise texture, after a frame that used it) as floats in [0, 1];
// `size`, when given, gets its width.
inline std::vector<float> heldUnormTexels(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                          const postfx::Context& context, const char* name,
                                          uint32_t* size = nullptr) {
    VkExtent3D extent{};
    const std::vector<uint8_t> bytes = readHeldImage(host, gpu, context, name, extent);
    if (size) *size = extent.width;
    std::vector<float> v(bytes.size());
    for (size_t i = 0; i < v.size(); ++i)
        v[i] = float(bytes[i]) / 255.0f;
    return v;
}

// The reference's inputs for `frame` over `im` (reversed Z, as the harness's depth): its camera, sun,
// ambient, time, clouds and atmosphere; `steps` view and `lightSteps` light samples. The noise texels (and
// a coverage map) are the caller's to add.
inline postfx::reference::CloudInputs referenceInputs(const postfx::FrameInfo& frame,
                                                      const FogHarnessImages& im, uint32_t steps = 512,
                                                      uint32_t lightSteps = 64) {
    postfx::reference::CloudInputs in;
    in.width = im.width;
    in.height = im.height;
    in.color = im.color;
    in.depth = im.depth;
    in.depthConvention.reversedZ = true;
    in.camera = frame.camera;
    in.sun = frame.sun;
    in.ambient = frame.ambient;
    in.timeSeconds = frame.timeSeconds;
    in.settings = frame.clouds;
    in.atmosphere = frame.atmosphere;
    in.stepsPerPixel = steps;
    in.lightSteps = lightSteps;
    return in;
}

}  // namespace test
