// The clouds on the device (docs/effects/clouds.md, "Tests"): a homogeneous layer against Beer–Lambert,
// forward scattering toward the sun, the noise textures against their CPU port, and images against the
// CPU reference in double (reference::renderClouds) from below, inside, above and grazing, and through the
// atmosphere. Small images on lavapipe.
#include "clouds/clouds_effect.h"
#include "clouds/clouds_path_tracer.h"
#include "clouds_frames.h"
#include "clouds_reference_inputs.h"
#include "common/noise_cpu.h"
#include "fog_harness.h"
#include "image_compare.h"

#include <postfx/reference.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

class CloudsGpuTest : public ReversedZContextTest {
protected:
    // `width`×`height` sky pixels (no geometry) of color `sky`.
    static FogHarnessImages images(uint32_t width, uint32_t height, float sky) {
        FogHarnessImages im;
        im.width = width;
        im.height = height;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(width) * height * 4, sky);
        im.depth.assign(size_t(width) * height, 0.0f);
        return im;
    }

    std::vector<float> render(postfx::FrameInfo frame, const FogHarnessImages& im) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    // A noise texture read back as floats in [0, 1].
    std::vector<float> readNoise(const char* name) { return heldUnormTexels(*host, gpu, *context, name); }

    std::vector<float> reference(const postfx::FrameInfo& frame, const FogHarnessImages& im,
                                 std::span<const float> base = {}, std::span<const float> detail = {}) {
        postfx::reference::CloudInputs in = referenceInputs(frame, im);
        in.baseNoise = base;
        in.detailNoise = detail;
        std::vector<float> out;
        const postfx::Status s = postfx::reference::renderClouds(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
};

// A flat homogeneous layer (noise off, coverage 1), no light: each sky pixel is the sky times
// exp(-σ·thickness / cos θ).
TEST_F(CloudsGpuTest, HomogeneousLayerSeenUpIsBeerLambert) {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, 60.0f, 1.0f);
    const FogHarnessImages im = images(8, 8, 1.0f);
    const std::vector<float> out = render(frame, im);
    for (uint32_t j = 0; j < im.height; ++j)
        for (uint32_t i = 0; i < im.width; ++i) {
            const glm::dvec3 d = pixelDirection(frame.camera, i, j, im.width, im.height);
            const double expected = std::exp(-0.002 * 1000.0 / d.y);
            EXPECT_NEAR(out[(size_t(j) * im.width + i) * 4], expected, 1e-4 + 1e-4 * expected)
                << i << "," << j;
        }
}

// Forward scattering peaks looking toward the sun: the same thin layer seen toward the sun and away from it.
TEST_F(CloudsGpuTest, ForwardScatteringPeaksTowardTheSun) {
    postfx::FrameInfo frame;
    frame.clouds.enabled = true;
    frame.clouds.noise.enabled = false;
    frame.clouds.coverage = 1.0f;
    frame.clouds.density = 0.0005f;
    frame.clouds.jitter = false;
    frame.clouds.resolutionScale = 1.0f;
    frame.clouds.temporal.enabled = false;
    frame.sun.toSun = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    frame.sun.illuminance = postfx::Vec3(1.0f);
    const FogHarnessImages im = images(4, 4, 0.0f);
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}, 20.0f, 1.0f);
    const std::vector<float> toward = render(frame, im);
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {-1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}, 20.0f, 1.0f);
    const std::vector<float> away = render(frame, im);
    const size_t centre = (size_t(2) * im.width + 2) * 4;
    std::printf("[ clouds ] toward the sun %.4g, away %.4g\n", toward[centre], away[centre]);
    EXPECT_GT(toward[centre], 3.0f * away[centre]);
    const std::vector<float> ref = reference(frame, im);
    EXPECT_NEAR(away[centre] / ref[centre], 1.0, 0.01);
}

// The slab model's multiple scattering on the device against the path-traced truth (clouds::
// estimateRadiance, every scattering order) in homogeneous layers 1000–1500 m (docs/effects/clouds.md,
// "Against the path tracer"): within 10 % (plus 3 of the truth's standard errors, 20000 paths) at a pixel
// of a 1° view. The published case (optical depth 5, albedo 1, g 0.6, from the ground 60° up, the sun 45° up
// and 15° away), a thick layer under the sun overhead, a layer seen from above and a thin one from inside.
TEST_F(CloudsGpuTest, HomogeneousLayersAreNearThePathTracer) {
    struct Case {
        const char* name;
        double tau, albedo, g, cameraY, viewElevationDeg;
        glm::dvec3 toSun;
    };
    const auto direction = [](double elevationDeg, double azimuthDeg) {
        const double e = glm::radians(elevationDeg), a = glm::radians(azimuthDeg);
        return glm::dvec3(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a));
    };
    const double publishedAzimuth = glm::degrees(std::acos(
        (std::cos(glm::radians(15.0)) - std::sin(glm::radians(60.0)) * std::sin(glm::radians(45.0))) /
        (std::cos(glm::radians(60.0)) * std::cos(glm::radians(45.0)))));
    const Case cases[] = {
        {"published: optical depth 5, from the ground", 5.0, 1.0, 0.6, 0.0, 60.0,
         direction(45.0, publishedAzimuth)},
        {"optical depth 50, the sun overhead, from below", 50.0, 1.0, 0.6, 900.0, 60.0, {0.0, 1.0, 0.0}},
        {"optical depth 20, albedo 0.99, from above", 20.0, 0.99, 0.6, 1600.0, -60.0, direction(45.0, 0.0)},
        {"optical depth 0.5, the sun behind, from inside", 0.5, 1.0, 0.6, 1250.0, 20.0,
         direction(45.0, 180.0)},
    };
    const FogHarnessImages im = images(2, 2, 0.0f);
    for (const Case& c : cases) {
        postfx::FrameInfo frame;
        frame.clouds = homogeneousLayer();
        frame.clouds.bottomHeight = 1000.0f;
        frame.clouds.topHeight = 1500.0f;
        frame.clouds.density = float(c.tau / 500.0);
        frame.clouds.albedo = float(c.albedo);
        frame.clouds.anisotropyForward = float(c.g);
        frame.clouds.lobeMix = 0.0f;
        frame.clouds.steps = 256;
        frame.clouds.lightSteps = 32;
        frame.clouds.jitter = false;
        frame.clouds.lightDistance = 1e5f;
        frame.sun.toSun = postfx::Vec3(c.toSun);
        frame.sun.illuminance = postfx::Vec3(1.0f);
        const glm::dvec3 view = direction(c.viewElevationDeg, 0.0);
        frame.camera = lookCamera({0.0, c.cameraY, 0.0}, view, {0.0, 1.0, 0.0}, 1.0f, 1.0f);
        const std::vector<float> out = render(frame, im);
        const postfx::clouds::Model model = postfx::clouds::modelFrom(frame, {}, {});
        postfx::clouds::PathOptions options;
        options.samples = 20000;
        const glm::dvec3 d = pixelDirection(frame.camera, 0, 0, 2, 2);
        const postfx::clouds::PathEstimate truth =
            postfx::clouds::estimateRadiance(model, glm::dvec3(0.0), d, 1e7, options, 1);
        const double gpu = out[0], relative = gpu / truth.radiance.x - 1.0;
        std::printf("[ clouds ] %s: GPU %.5g, truth %.5g ± %.2g: %+.1f%%\n", c.name, gpu, truth.radiance.x,
                    truth.standardError.x, 100.0 * relative);
        EXPECT_LT(std::abs(relative), 0.10 + 3.0 * truth.standardError.x / truth.radiance.x) << c.name;
    }
}

// The generated noise textures against the CPU port (common/noise_cpu.h), texel by texel.
TEST_F(CloudsGpuTest, NoiseTexturesMatchTheCpuPort) {
    postfx::FrameInfo frame;
    frame.clouds.enabled = true;
    frame.clouds.noise.baseSize = 32;
    frame.clouds.noise.detailSize = 16;
    frame.clouds.noise.seed = 7;
    frame.clouds.temporal.enabled = false;
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {1.0, 0.3, 0.0}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
    render(frame, images(4, 2, 0.0f));
    const std::vector<float> base = readNoise("clouds.base_noise");
    const std::vector<float> detail = readNoise("clouds.detail_noise");
    const std::vector<uint8_t> cpuBase = postfx::common::generateNoiseCpu(32, 7);
    const std::vector<uint8_t> cpuDetail =
        postfx::common::generateWorleyNoiseCpu(16, postfx::clouds::detailSeed(7));
    ASSERT_EQ(base.size(), cpuBase.size());
    ASSERT_EQ(detail.size(), cpuDetail.size());
    size_t off = 0;
    for (size_t i = 0; i < base.size(); ++i)
        off += std::abs(base[i] * 255.0f - cpuBase[i]) > 1.01f;
    for (size_t i = 0; i < detail.size(); ++i)
        off += std::abs(detail[i] * 255.0f - cpuDetail[i]) > 1.01f;
    EXPECT_EQ(off, 0u);
}

// Noisy clouds against the reference with the GPU's own noise texels, from below the layer, inside it,
// above it and grazing its bottom toward the horizon; the GPU with many steps (and no jitter) so that what
// remains is the model's agreement and float precision.
TEST_F(CloudsGpuTest, MatchesReferenceFromBelowInsideAboveAndGrazing) {
    struct View {
        const char* name;
        glm::dvec3 position, forward;
    };
    const View views[] = {{"below", {0.0, 200.0, 0.0}, {1.0, 0.6, 0.2}},
                          {"inside", {0.0, 2500.0, 0.0}, {1.0, 0.05, 0.3}},
                          {"above", {0.0, 6000.0, 0.0}, {1.0, -0.5, 0.1}},
                          {"grazing", {0.0, 200.0, 0.0}, {1.0, 0.02, -0.3}}};
    for (const View& v : views) {
        postfx::FrameInfo frame;
        frame.clouds = finelyMarchedNoisyClouds();
        frame.clouds.noise.tiling = 8000.0f;
        frame.sun.toSun = glm::normalize(glm::vec3(0.6f, 0.7f, 0.3f));
        frame.sun.illuminance = postfx::Vec3(10.0f);
        frame.ambient = postfx::Vec3(0.3f, 0.4f, 0.6f);
        frame.timeSeconds = 12.0;
        frame.camera = lookCamera(v.position, v.forward, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
        const FogHarnessImages im = images(24, 12, 0.5f);
        const std::vector<float> out = render(frame, im);
        const std::vector<float> base = readNoise("clouds.base_noise");
        const std::vector<float> detail = readNoise("clouds.detail_noise");
        const std::vector<float> ref = reference(frame, im, base, detail);
        const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-2);
        std::printf("[ clouds ] %s: GPU vs reference %s\n", v.name, stats.summary().c_str());
        EXPECT_EQ(stats.nonFinite, 0u);
        EXPECT_LT(stats.relativeRmse, 0.02) << v.name;
    }
}

// A curved layer (atmosphere on) from the ground: the sun through the atmosphere's transmittance LUT and
// the aerial perspective in front of the clouds, against the reference's double integration.
TEST_F(CloudsGpuTest, CurvedLayerThroughTheAtmosphereMatchesReference) {
    postfx::FrameInfo frame;
    frame.atmosphere.enabled = true;
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
    frame.clouds = finelyMarchedNoisyClouds();
    frame.sun.toSun = glm::normalize(glm::vec3(0.6f, 0.3f, 0.3f));
    frame.sun.illuminance = postfx::Vec3(10.0f);
    frame.camera = lookCamera({0.0, 200.0, 0.0}, {1.0, 0.25, 0.2}, {0.0, 1.0, 0.0}, 60.0f, 2.0f);
    // The whole frame (the atmosphere's sky, then the clouds over it) from a black background; the
    // reference composites its clouds over the GPU's sky alone, so that the comparison is the clouds'.
    FogHarnessImages im = images(24, 12, 0.0f);
    const std::vector<float> out = render(frame, im);
    postfx::FrameInfo skyOnly = frame;
    skyOnly.clouds.enabled = false;
    im.color = render(skyOnly, im);
    render(frame, images(4, 2, 0.0f));  // holds the noise textures again for the read-back
    const std::vector<float> base = readNoise("clouds.base_noise");
    const std::vector<float> detail = readNoise("clouds.detail_noise");
    const std::vector<float> ref = reference(frame, im, base, detail);
    const ImageStats stats = compareImages(out, ref, im.width, im.height, 0.05, 1e-2);
    std::printf("[ clouds ] curved layer through the atmosphere: GPU vs reference %s\n",
                stats.summary().c_str());
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_LT(stats.relativeRmse, 0.03);
}

}  // namespace
}  // namespace test
