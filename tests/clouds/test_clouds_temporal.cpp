// The clouds at a reduced resolution and with temporal accumulation (docs/effects/clouds.md, "Resolution
// and temporal"), on the device: a half-resolution march upsampled against the full-resolution reference;
// a still view of a coarse jittered march converging toward the reference over the frames; a panning view
// that does not ghost (its last frame against the reference of its own view); and geometry in front of
// the clouds that keeps its silhouette; the still and the panning view also with the sparse update
// (update_block 2 and 4), whose first frame is a full march. Small images on lavapipe.
#include "clouds_frames.h"
#include "clouds_reference_inputs.h"
#include "fog_harness.h"
#include "image_compare.h"

#include <postfx/reference.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace test {
namespace {

class CloudsTemporalTest : public ReversedZContextTest {
protected:
    // A narrow view: the clouds span several pixels of these small images (and texels at half size).
    static constexpr float kFovDeg = 20.0f;

    static FogHarnessImages images(uint32_t width, uint32_t height, float sky) {
        FogHarnessImages im;
        im.width = width;
        im.height = height;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(width) * height * 4, sky);
        im.depth.assign(size_t(width) * height, 0.0f);
        return im;
    }

    std::vector<float> render(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    // The reference with the GPU's noise texels (held after a frame with noise).
    std::vector<float> reference(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
        const std::vector<float> base = heldUnormTexels(*host, gpu, *context, "clouds.base_noise"),
                                 detail = heldUnormTexels(*host, gpu, *context, "clouds.detail_noise");
        postfx::reference::CloudInputs in = referenceInputs(frame, im);
        in.baseNoise = base;
        in.detailNoise = detail;
        std::vector<float> out;
        const postfx::Status s = postfx::reference::renderClouds(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    static postfx::FrameInfo cloudyFrame() {
        postfx::FrameInfo frame;
        frame.clouds = finelyMarchedNoisyClouds();
        // Clouds a few pixels wide at this size (a half-resolution march resolves them).
        frame.clouds.noise.tiling = 40000.0f;
        frame.clouds.castShadows = false;
        frame.sun.toSun = glm::normalize(glm::vec3(0.6f, 0.7f, 0.3f));
        frame.sun.illuminance = postfx::Vec3(10.0f);
        frame.ambient = postfx::Vec3(0.3f, 0.4f, 0.6f);
        frame.timeSeconds = 12.0;
        frame.camera = lookCamera({0.0, 200.0, 0.0}, {1.0, 0.6, 0.2}, {0.0, 1.0, 0.0}, kFovDeg, 2.0f);
        return frame;
    }
};

// Half resolution, one frame: the depth-aware upsample of a finely marched image against the full-
// resolution reference. What remains is the upsample's blur of the clouds' edges.
TEST_F(CloudsTemporalTest, HalfResolutionMatchesReference) {
    postfx::FrameInfo frame = cloudyFrame();
    frame.clouds.resolutionScale = 0.5f;
    const FogHarnessImages im = images(32, 16, 0.5f);
    const std::vector<float> out = render(frame, im);
    const ImageStats stats = compareImages(out, reference(frame, im), im.width, im.height, 0.05, 1e-2);
    std::printf("[ clouds ] half resolution vs reference %s\n", stats.summary().c_str());
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_LT(stats.relativeRmse, 0.06);
}

// A still view of a coarse jittered march (12 steps): one frame is noisy, the accumulation of 32 frames
// converges toward the reference (the jitter's stratified mean).
// With a sparse update each texel gets a sample every block² frames: block 4 runs 128 frames for as many
// samples per texel as block 2 in 32.
TEST_F(CloudsTemporalTest, StillViewConverges) {
    std::vector<float> firstFull;
    for (uint32_t block : {1u, 2u, 4u}) {
        postfx::FrameInfo frame = cloudyFrame();
        frame.clouds.steps = 12;
        frame.clouds.lightSteps = 32;
        frame.clouds.jitter = true;
        frame.clouds.resolutionScale = 1.0f;
        frame.clouds.temporal.enabled = true;
        frame.clouds.updateBlock = block;
        const FogHarnessImages im = images(32, 16, 0.5f);
        std::vector<float> first, last;
        const uint64_t frames = block == 4 ? 128 : 32;
        for (uint64_t i = 0; i < frames; ++i) {
            frame.frameIndex = i;
            frame.cameraCut = i == 0;  // the previous block's history is not this one's
            last = render(frame, im);
            if (i == 0) first = last;
        }
        // The first frame has no history: a full march whatever the block.
        if (block == 1) firstFull = first;
        EXPECT_EQ(first, firstFull) << "update_block " << block << ": frame 0 is not a full march";
        const std::vector<float> ref = reference(frame, im);
        const ImageStats one = compareImages(first, ref, im.width, im.height, 0.05, 1e-2);
        const ImageStats many = compareImages(last, ref, im.width, im.height, 0.05, 1e-2);
        std::printf("[ clouds ] still view, update_block %u: 1 frame %s; %u frames %s\n", block,
                    one.summary().c_str(), unsigned(frames), many.summary().c_str());
        EXPECT_EQ(many.nonFinite, 0u);
        EXPECT_LT(many.relativeRmse, 0.5 * one.relativeRmse) << "update_block " << block;
        EXPECT_LT(many.relativeRmse, 0.03) << "update_block " << block;
    }
}

// A camera panning 0.2° per frame (a march texel every ~12 frames at half size), half resolution with
// temporal: its last frame against the reference of its own view, and against the same frame marched
// without temporal. A history that did not follow the view (ghosting) would leave the clouds where earlier
// frames saw them: with the reprojection off the error is 12.9%, with the motion doubled 10.4%. What
// remains is the history's resampling (measured 7.4% against 4.8% without temporal on these 16×8 texels).
TEST_F(CloudsTemporalTest, PanningViewDoesNotGhost) {
    const FogHarnessImages im = images(32, 16, 0.5f);
    uint32_t block = 1;
    auto pan = [&](bool temporal, postfx::FrameInfo& frame) {
        frame = cloudyFrame();
        frame.clouds.steps = 64;
        frame.clouds.resolutionScale = 0.5f;
        frame.clouds.temporal.enabled = temporal;
        frame.clouds.updateBlock = block;
        std::vector<float> out;
        for (uint64_t i = 0; i < 24; ++i) {
            const double yaw = glm::radians(0.2 * double(i));
            frame.frameIndex = i;
            frame.cameraCut = i == 0;
            frame.timeSeconds = 12.0 + double(i) / 30.0;
            frame.camera = lookCamera({0.0, 200.0, 0.0}, {std::cos(yaw), 0.6, 0.2 + std::sin(yaw)},
                                      {0.0, 1.0, 0.0}, kFovDeg, 2.0f);
            out = render(frame, im);
        }
        return out;
    };
    postfx::FrameInfo frame;
    const std::vector<float> still = pan(false, frame);
    const std::vector<float> ref = reference(frame, im);
    const ImageStats without = compareImages(still, ref, im.width, im.height, 0.05, 1e-2);
    for (uint32_t b : {1u, 2u}) {
        block = b;
        const std::vector<float> accumulated = pan(true, frame);
        const ImageStats with = compareImages(accumulated, ref, im.width, im.height, 0.05, 1e-2);
        std::printf(
            "[ clouds ] panning view, update_block %u, last frame vs its reference: temporal %s; "
            "without %s\n",
            b, with.summary().c_str(), without.summary().c_str());
        EXPECT_EQ(with.nonFinite, 0u);
        // A sparse update's skipped texels are only resampled while the view pans (measured 8.4% with
        // block 2 against 6.2% with block 1).
        EXPECT_LT(with.relativeRmse, (b == 1 ? 1.75 : 2.2) * without.relativeRmse) << "update_block " << b;
        EXPECT_LT(with.relativeRmse, 0.09) << "update_block " << b;
    }
}

// Geometry 50 m away covering the left half of the image, in front of the clouds, with a half-resolution
// temporal march: the geometry's pixels keep their color exactly (the upsample takes no cloud texel
// across the silhouette) and the sky's pixels next to it get their clouds.
TEST_F(CloudsTemporalTest, GeometryInFrontKeepsItsSilhouette) {
    postfx::FrameInfo frame = cloudyFrame();
    frame.clouds.resolutionScale = 0.5f;
    frame.clouds.temporal.enabled = true;
    FogHarnessImages im = images(32, 16, 0.5f);
    for (uint32_t j = 0; j < im.height; ++j)
        for (uint32_t i = 0; i < 15; ++i) {
            const size_t p = size_t(j) * im.width + i;
            im.depth[p] =
                depthAtDistance(frame.camera, pixelDirection(frame.camera, i, j, im.width, im.height), 50.0);
            for (int c = 0; c < 3; ++c)
                im.color[p * 4 + c] = 2.0f;
        }
    std::vector<float> out;
    for (uint64_t i = 0; i < 4; ++i) {
        frame.frameIndex = i;
        out = render(frame, im);
    }
    const std::vector<float> ref = reference(frame, im);
    for (uint32_t j = 0; j < im.height; ++j)
        for (uint32_t i = 0; i < 15; ++i)
            EXPECT_EQ(out[(size_t(j) * im.width + i) * 4], 2.0f) << i << "," << j;
    const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-2);
    std::printf("[ clouds ] geometry in front, vs reference %s\n", stats.summary().c_str());
    EXPECT_LT(stats.relativeRmse, 0.06);
}

}  // namespace
}  // namespace test
