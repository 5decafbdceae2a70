// The clouds' host textures (docs/effects/clouds.md, "Density"), on the device: a host's 2D coverage map
// placed by its size and origin and moved by the wind, against the reference reading the same texels; and
// host noise textures holding the generated texels giving the generated image, with no noise generated.
#include "clouds_frames.h"
#include "clouds_reference_inputs.h"
#include "fog_harness.h"
#include "image_compare.h"

#include <postfx/reference.h>

#include <cstdio>
#include <vector>

namespace test {
namespace {

class CloudsHostTexturesTest : public ReversedZContextTest {
protected:
    static FogHarnessImages images(uint32_t width, uint32_t height) {
        FogHarnessImages im;
        im.width = width;
        im.height = height;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(width) * height * 4, 0.5f);
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

    std::vector<float> noiseTexels(const char* name, uint32_t& size) {
        return heldUnormTexels(*host, gpu, *context, name, &size);
    }

    static postfx::FrameInfo litFrame(const postfx::CloudSettings& clouds) {
        postfx::FrameInfo frame;
        frame.clouds = clouds;
        frame.clouds.castShadows = false;
        frame.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
        frame.sun.illuminance = postfx::Vec3(10.0f);
        frame.ambient = postfx::Vec3(0.3f, 0.4f, 0.6f);
        frame.timeSeconds = 40.0;
        // Looking up at 60° from 100 m: the layer's base spans a few km of the map.
        frame.camera = lookCamera({300.0, 100.0, -200.0}, {0.3, 1.0, 0.4}, {0.0, 0.0, 1.0}, 70.0f, 1.5f);
        return frame;
    }
};

// A 4×4 R8 map of 0 and 1 (a checkerboard with one half-grey texel) over 3 km, offset from the origin,
// on a homogeneous layer and on noisy clouds: each against the reference with the same map; the layer's
// transmittance is exp(-σ·path) only over the map's lit squares.
TEST_F(CloudsHostTexturesTest, CoverageMapMatchesTheReference) {
    const uint8_t texels[16] = {255, 0, 255, 0, 0, 255, 0, 128, 255, 0, 255, 0, 0, 255, 0, 255};
    postfx::core::ImageDesc desc;
    desc.format = VK_FORMAT_R8_UNORM;
    desc.extent = {4, 4, 1};
    const postfx::core::GpuImage map = uploadSampledImage(*host, gpu, desc, texels, sizeof texels);
    std::vector<float> values(16);
    for (int i = 0; i < 16; ++i)
        values[i] = float(texels[i]) / 255.0f;

    postfx::CloudSettings homogeneous = homogeneousLayer();
    postfx::CloudSettings noisy = finelyMarchedNoisyClouds();
    noisy.coverage = 0.9f;
    for (postfx::CloudSettings* s : {&homogeneous, &noisy}) {
        s->coverageMap.texture = map.view();
        s->coverageMap.size = 3000.0f;
        s->coverageMap.originX = -700.0;
        s->coverageMap.originZ = 1234.5;
        s->wind = {15.0f, 0.0f, -5.0f};
    }
    for (const postfx::CloudSettings& s : {homogeneous, noisy}) {
        const postfx::FrameInfo frame = litFrame(s);
        const FogHarnessImages im = images(24, 16);
        const std::vector<float> out = render(frame, im);
        uint32_t baseSize = 0, detailSize = 0;
        std::vector<float> base, detail;
        if (s.noise.enabled) {
            base = noiseTexels("clouds.base_noise", baseSize);
            detail = noiseTexels("clouds.detail_noise", detailSize);
        }
        postfx::reference::CloudInputs in = referenceInputs(frame, im);
        in.baseNoise = base;
        in.detailNoise = detail;
        in.coverageMap = values;
        in.coverageMapWidth = in.coverageMapHeight = 4;
        std::vector<float> ref;
        const postfx::Status st = postfx::reference::renderClouds(in, ref);
        ASSERT_TRUE(st.ok()) << st.message;
        // The map must matter: the reference without it differs.
        in.coverageMap = {};
        std::vector<float> unmapped;
        ASSERT_TRUE(postfx::reference::renderClouds(in, unmapped).ok());
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-2);
        const ImageStats without = compareImages(out, unmapped, im.width, im.height, 0.05, 1e-2);
        std::printf("[ clouds ] coverage map, %s: GPU vs reference %s; vs the reference without the map %s\n",
                    s.noise.enabled ? "noisy clouds" : "homogeneous layer", stats.summary().c_str(),
                    without.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.02);
        EXPECT_GT(without.relativeRmse, 0.1);
    }
}

// The generated noise read back and handed over as the host's textures: the same image, to float
// rounding, and the frame generates no noise.
TEST_F(CloudsHostTexturesTest, HostNoiseTexturesGiveTheGeneratedImage) {
    postfx::CloudSettings s = finelyMarchedNoisyClouds();
    const postfx::FrameInfo generatedFrame = litFrame(s);
    const FogHarnessImages im = images(24, 16);
    const std::vector<float> generated = render(generatedFrame, im);
    uint32_t baseSize = 0, detailSize = 0;
    const std::vector<float> base = noiseTexels("clouds.base_noise", baseSize);
    const std::vector<float> detail = noiseTexels("clouds.detail_noise", detailSize);
    auto bytes = [](const std::vector<float>& v) {
        std::vector<uint8_t> b(v.size());
        for (size_t i = 0; i < v.size(); ++i)
            b[i] = uint8_t(v[i] * 255.0f + 0.5f);
        return b;
    };
    postfx::core::ImageDesc desc;
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = VK_FORMAT_R8_UNORM;
    desc.extent = {baseSize, baseSize, baseSize};
    const std::vector<uint8_t> baseBytes = bytes(base), detailBytes = bytes(detail);
    const postfx::core::GpuImage baseImage =
        uploadSampledImage(*host, gpu, desc, baseBytes.data(), baseBytes.size());
    desc.extent = {detailSize, detailSize, detailSize};
    const postfx::core::GpuImage detailImage =
        uploadSampledImage(*host, gpu, desc, detailBytes.data(), detailBytes.size());

    postfx::FrameInfo frame = generatedFrame;
    frame.clouds.noise.hostBaseTexture = baseImage.view();
    frame.clouds.noise.hostDetailTexture = detailImage.view();
    frame.clouds.noise.baseSize = 256;  // ignored with host textures
    const postfx::FramePlan plan = planAndRecord(*host, gpu, *context, im, frame);
    for (const std::string& pass : passNames(plan)) {
        EXPECT_NE(pass, "clouds.base_noise");
        EXPECT_NE(pass, "clouds.detail_noise");
    }
    const std::vector<float> hosted = render(frame, im);
    const ImageStats stats = compareImages(hosted, generated, im.width, im.height, 1e-5, 1e-6);
    std::printf("[ clouds ] host noise textures vs generated: %s\n", stats.summary().c_str());
    EXPECT_EQ(stats.fractionOff, 0.0);
}

}  // namespace
}  // namespace test
