// A demo scene's GPU frame against the demo's CPU reference of the same frame (Renderer::renderReference):
// per channel the mean relative difference Σ|gpu - ref| / Σ ref per pixel (the jitter's one-frame noise
// and reduced-resolution edges included), the same over the means of blocks of pixels (what the eye sees:
// noise averaged out), and the bias Σ(gpu - ref) / Σ ref.
#pragma once

#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace test {

struct ReferenceDifference {
    std::array<double, 3> perPixel{}, blocks{}, bias{};  // fractions, per RGB channel
    std::array<double, 3> referenceSum{};                // Σ ref per channel (> 0 for a meaningful ratio)
    bool finite = true;                                  // every GPU value finite
};

// demo/scenes/<name>.json, expecting it to load.
demo::Scene loadDemoScene(const std::string& name);
// A demo renderer of width × height rendering `frames` frames (render() returns the last), with a
// 512² sun shadow map; expects it to be created.
std::unique_ptr<demo::Renderer> sceneRenderer(demo::VulkanHost& host, uint32_t width, uint32_t height,
                                              uint32_t frames = 2);

// Blocks of blockW × blockH pixels (the image's last partial blocks included).
ReferenceDifference referenceDifference(const demo::ImageF& gpu, const demo::ImageF& reference,
                                        uint32_t blockW = 8, uint32_t blockH = 6);

// "R G B: per pixel a% b% c%, 8x6 blocks ..., signed ..." for a test's log line.
std::string describe(const ReferenceDifference& d);

}  // namespace test
