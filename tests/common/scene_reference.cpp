#include "scene_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

namespace test {

demo::Scene loadDemoScene(const std::string& name) {
    demo::Scene scene;
    std::string error;
    EXPECT_TRUE(
        demo::loadSceneFile(std::string(POSTFX_SOURCE_DIR) + "/demo/scenes/" + name + ".json", scene, error))
        << error;
    return scene;
}

std::unique_ptr<demo::Renderer> sceneRenderer(demo::VulkanHost& host, uint32_t width, uint32_t height,
                                              uint32_t frames) {
    demo::RenderOptions o;
    o.width = width;
    o.height = height;
    o.frames = frames;
    o.shadowMapSize = 512;
    std::string error;
    auto r = demo::Renderer::create(host, o, error);
    EXPECT_TRUE(r) << error;
    return r;
}

ReferenceDifference referenceDifference(const demo::ImageF& gpu, const demo::ImageF& reference,
                                        uint32_t blockW, uint32_t blockH) {
    ReferenceDifference d;
    std::array<double, 3> absolute{}, blocks{}, signedSum{}, total{};
    for (uint32_t by = 0; by < gpu.height; by += blockH)
        for (uint32_t bx = 0; bx < gpu.width; bx += blockW) {
            std::array<double, 3> blockGpu{}, blockRef{};
            for (uint32_t y = by; y < std::min(by + blockH, gpu.height); ++y)
                for (uint32_t x = bx; x < std::min(bx + blockW, gpu.width); ++x)
                    for (size_t c = 0; c < 3; ++c) {
                        const double g = gpu.at(x, y)[c], f = reference.at(x, y)[c];
                        if (!std::isfinite(g)) d.finite = false;
                        absolute[c] += std::abs(g - f);
                        blockGpu[c] += g;
                        blockRef[c] += f;
                    }
            for (size_t c = 0; c < 3; ++c) {
                blocks[c] += std::abs(blockGpu[c] - blockRef[c]);
                signedSum[c] += blockGpu[c] - blockRef[c];
                total[c] += blockRef[c];
            }
        }
    for (size_t c = 0; c < 3; ++c) {
        d.referenceSum[c] = total[c];
        const double t = total[c] > 0.0 ? total[c] : 1.0;
        d.perPixel[c] = absolute[c] / t;
        d.blocks[c] = blocks[c] / t;
        d.bias[c] = signedSum[c] / t;
    }
    return d;
}

std::string describe(const ReferenceDifference& d) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "R G B: per pixel %.1f%% %.1f%% %.1f%%, 8x6 blocks %.1f%% %.1f%% %.1f%%, signed %+.2f%% "
                  "%+.2f%% %+.2f%%",
                  100.0 * d.perPixel[0], 100.0 * d.perPixel[1], 100.0 * d.perPixel[2], 100.0 * d.blocks[0],
                  100.0 * d.blocks[1], 100.0 * d.blocks[2], 100.0 * d.bias[0], 100.0 * d.bias[1],
                  100.0 * d.bias[2]);
    return text;
}

}  // namespace test
