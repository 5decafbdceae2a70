// The benchmark's baselines (bench/baseline.h) on the GPU, under the validation layer:
//  - seed-fixed-riemann converges to postfx's fog as the step length shrinks (fog_homogeneous.json on
//    the demo renderer, where postfx is exact at any step count);
//  - seed-as-written stays far from it (wrong on purpose);
//  - both match their own closed forms in a homogeneous medium on a minimal host, and the seed's phase
//    function is 0 looking straight toward or away from the sun, whatever g (numerator 1 - cos²θ).
#include "baseline.h"
#include "fog_harness.h"
#include "host/camera_math.h"
#include "host/gpu_resources.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;
constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kCopy = VK_PIPELINE_STAGE_TRANSFER_BIT;

double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}
// The seed's henyey_greenstein: numerator 1 - cos²θ.
double seedPhase(double cosTheta, double g) {
    return (1.0 - cosTheta * cosTheta) /
           (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// RGBA16F image -> buffer (after the baseline's barrier) and the host barrier; leaves it TRANSFER_SRC.
void recordReadback(VkCommandBuffer cmd, const demo::GpuImage& image, const demo::GpuBuffer& buffer) {
    demo::imageBarrier(cmd, image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute,
                       VK_ACCESS_SHADER_WRITE_BIT, kCopy, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.extent.width, image.extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
    demo::bufferBarrier(cmd, buffer, kCopy, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                        VK_ACCESS_HOST_READ_BIT);
}

std::vector<float> unpackHalf(const demo::GpuBuffer& buffer, size_t count) {
    std::vector<float> out(count);
    const uint16_t* in = static_cast<const uint16_t*>(buffer.mapped);
    for (size_t i = 0; i < count; ++i)
        out[i] = glm::unpackHalf1x16(in[i]);
    return out;
}

class BenchBaselineTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        std::string error;
        baseline = bench::BaselinePass::create(*host, 2, error);
        ASSERT_TRUE(baseline) << error;
        VkQueryPoolCreateInfo qpci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qpci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qpci.queryCount = 2;
        ASSERT_EQ(vkCreateQueryPool(host->device, &qpci, nullptr, &queryPool), VK_SUCCESS);
    }
    void TearDown() override {
        if (host) {
            vkDeviceWaitIdle(host->device);
            baseline.reset();
            if (queryPool) vkDestroyQueryPool(host->device, queryPool, nullptr);
            for (demo::GpuImage* image : {&color, &depth})
                demo::destroyImage(host->device, *image);
            demo::destroyBuffer(host->device, readback);
        }
        GpuTest::TearDown();
    }

    // Nanoseconds between the baseline's two timestamps (of the last submission).
    double dispatchMilliseconds() const {
        uint64_t ts[2] = {0, 0};
        EXPECT_EQ(vkGetQueryPoolResults(host->device, queryPool, 0, 2, sizeof ts, ts, sizeof(uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  VK_SUCCESS);
        EXPECT_GE(ts[1], ts[0]);
        return double(ts[1] - ts[0]) * double(host->properties.limits.timestampPeriod) * 1e-6;
    }

    // ---- minimal host: a constant color, every pixel without geometry (depth = far) ----

    static constexpr uint32_t kWidth = 16, kHeight = 16;

    // A camera looking down -z, homogeneous fog of 0.02/m up to 20 m, jitter off: every ray samples
    // t = 0.5, 1.5, ..., 19.5 m with a step length of 1 m.
    postfx::FrameInfo homogeneousFrame() const {
        postfx::FrameInfo frame;
        frame.frameIndex = 0;
        frame.camera = testCamera({3.0, 1.5, -7.0}, 60.0f, float(kWidth) / kHeight, 0.1f, 1000.0f, true);
        frame.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
        frame.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
        frame.ambient = {0.0f, 0.0f, 0.0f};
        postfx::FogSettings& fog = frame.fog;
        fog.enabled = true;
        fog.density = 0.02f;
        fog.albedo = {0.9f, 0.5f, 0.7f};
        fog.anisotropy = 0.5f;
        fog.heightFalloff = 0.0f;
        fog.maxDistance = 20.0f;
        fog.jitter = false;
        return frame;
    }

    // Clears color to `clearColor` and depth to 0 (reversed Z: no geometry), runs `which` over them,
    // reads the color back.
    std::vector<float> runMinimal(postfx::FrameInfo frame, bench::Baseline which, float stepLength,
                                  glm::vec4 clearColor) {
        std::string error;
        if (!color.image) {
            EXPECT_TRUE(demo::createImage(*host, VK_FORMAT_R16G16B16A16_SFLOAT, {kWidth, kHeight},
                                          VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                              VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                          color, error))
                << error;
            EXPECT_TRUE(demo::createImage(*host, VK_FORMAT_D32_SFLOAT, {kWidth, kHeight},
                                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                          depth, error))
                << error;
            EXPECT_TRUE(demo::createBuffer(*host, VkDeviceSize(kWidth) * kHeight * 8,
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, readback, error))
                << error;
        }
        const VkExtent2D extent{kWidth, kHeight};
        frame.frameIndex = frameCounter++;  // jitter is off: the index changes nothing but the frame slot
        frame.color = {color.image, color.view, color.format, extent, VK_IMAGE_LAYOUT_GENERAL, color.usage};
        frame.depth = {
            depth.image, depth.view, depth.format, extent, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
            depth.usage};
        postfx::DepthConvention convention;
        convention.reversedZ = true;
        bool recorded = false;
        std::string recordError;
        const bool ok = host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                frame.commandBuffer = cmd;
                vkCmdResetQueryPool(cmd, queryPool, 0, 2);
                const VkPipelineStageFlags top = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
                demo::imageBarrier(cmd, color, VK_IMAGE_LAYOUT_UNDEFINED,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, top | kCopy, 0, kCopy,
                                   VK_ACCESS_TRANSFER_WRITE_BIT);
                demo::imageBarrier(cmd, depth, VK_IMAGE_LAYOUT_UNDEFINED,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, top | kCompute, 0, kCopy,
                                   VK_ACCESS_TRANSFER_WRITE_BIT);
                const VkClearColorValue c{{clearColor.r, clearColor.g, clearColor.b, clearColor.a}};
                const VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
                vkCmdClearColorImage(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &c, 1,
                                     &colorRange);
                const VkClearDepthStencilValue d{0.0f, 0};
                const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
                vkCmdClearDepthStencilImage(cmd, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &d, 1,
                                            &depthRange);
                // What the baseline's caller guarantees: color GENERAL, writes visible to compute; depth
                // readable by compute.
                demo::imageBarrier(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                                   kCopy, VK_ACCESS_TRANSFER_WRITE_BIT, kCompute,
                                   VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
                demo::imageBarrier(cmd, depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kCopy,
                                   VK_ACCESS_TRANSFER_WRITE_BIT, kCompute, VK_ACCESS_SHADER_READ_BIT);
                recorded = baseline->record(cmd, frame, convention, which, stepLength, VK_NULL_HANDLE,
                                            queryPool, 0, recordError);
                recordReadback(cmd, color, readback);
            },
            error);
        EXPECT_TRUE(ok) << error;
        EXPECT_TRUE(recorded) << recordError;
        return unpackHalf(readback, size_t(kWidth) * kHeight * 4);
    }

    double runOnRenderer(demo::Renderer& renderer, const demo::RenderOptions& options,
                         const demo::Scene& hostScene, const demo::Scene& scene, bench::Baseline which,
                         float stepLength, bool noise, const demo::ImageF& expected);

    std::unique_ptr<bench::BaselinePass> baseline;
    VkQueryPool queryPool = VK_NULL_HANDLE;
    demo::GpuImage color, depth;
    demo::GpuBuffer readback;
    uint64_t frameCounter = 0;
};

// ---- (1), (2): against postfx on the demo renderer ----

// Renders frame 0 of `hostScene` on the renderer (postfx included, as hostScene.fog says), then records
// `which` over its HDR image with the inputs the renderer gives postfx for `scene` (camera, sun, ambient,
// shadow map when drawn, scene.fog; the fog's noise texture when `noise`), reads the result back and
// compares it with `expected`. Returns the relative RMSE.
double BenchBaselineTest::runOnRenderer(demo::Renderer& renderer, const demo::RenderOptions& options,
                                        const demo::Scene& hostScene, const demo::Scene& scene,
                                        bench::Baseline which, float stepLength, bool noise,
                                        const demo::ImageF& expected) {
    std::string error;
    const VkExtent2D extent{options.width, options.height};
    const size_t values = size_t(extent.width) * extent.height * 4;
    demo::GpuBuffer buffer;
    EXPECT_TRUE(demo::createBuffer(*host, values * 2, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, buffer, error))
        << error;
    const postfx::DepthConvention convention = renderer.postfxContext().createInfo().depth;
    bool recorded = false;
    std::string recordError, frameError;
    const bool ok = host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            vkCmdResetQueryPool(cmd, queryPool, 0, 2);
            if (!renderer.recordFrame(cmd, hostScene, 0, frameError)) return;
            const demo::ImageInfo& hdr = renderer.hdrImage();
            const demo::ImageInfo& depthInfo = renderer.depthImage();
            demo::GpuImage hdrImage;  // a non-owning stand-in of the renderer's image for the helpers
            hdrImage.image = hdr.image;
            hdrImage.extent = hdr.extent;
            hdrImage.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
            // What the baseline's caller guarantees: the color's writes visible to compute.
            demo::imageBarrier(cmd, hdrImage, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, kCompute,
                               VK_ACCESS_SHADER_WRITE_BIT, kCompute,
                               VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

            // The renderer's postfx inputs for frame 0 (demo/host/renderer_frame.cpp, postfxInputs).
            postfx::FrameInfo frame;
            frame.commandBuffer = cmd;
            frame.frameIndex = 0;
            frame.color = {hdr.image, hdr.view, hdr.format, extent, VK_IMAGE_LAYOUT_GENERAL, hdr.usage};
            frame.depth = {depthInfo.image,
                           depthInfo.view,
                           depthInfo.format,
                           extent,
                           VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                           depthInfo.usage};
            frame.timeSeconds = 0.0;
            frame.camera.position = glm::dvec3(scene.camera.position);
            frame.camera.view = demo::cameraView(scene.camera);
            frame.camera.projection = demo::perspectiveProjection(
                glm::radians(scene.camera.fovYDeg), float(extent.width) / extent.height,
                scene.camera.nearPlane, scene.camera.farPlane, options.reversedZ, options.infiniteFar);
            frame.sun.toSun = scene.sun.direction;
            frame.sun.illuminance = scene.sun.illuminance;
            frame.ambient = scene.ambient;
            frame.preExposure = renderer.preExposure();  // the HDR image's: its lighting wrote it pre-exposed
            const demo::ShadowMapInfo& shadow = renderer.shadowMap();
            if (shadow.enabled) {
                const demo::ImageInfo& s = shadow.image;
                frame.shadowMap.image = {s.image, s.view, s.format, s.extent, s.layout, s.usage};
                frame.shadowMap.worldToClip = glm::dmat4(shadow.viewProj);
                frame.shadowMap.reversedZ = false;
                const glm::mat4& m = shadow.viewProj;
                frame.shadowMap.depthBias =
                    shadow.texelWorldSize * glm::length(glm::vec3(m[0][2], m[1][2], m[2][2]));
            }
            frame.fog = scene.fog;
            const VkImageView noiseView =
                noise ? postfx::fogNoiseView(renderer.postfxContext()) : VK_NULL_HANDLE;
            EXPECT_EQ(noise, noiseView != VK_NULL_HANDLE);
            recorded = baseline->record(cmd, frame, convention, which, stepLength, noiseView, queryPool, 0,
                                        recordError);
            recordReadback(cmd, hdrImage, buffer);
        },
        error);
    EXPECT_TRUE(ok) << error;
    EXPECT_TRUE(frameError.empty()) << frameError;
    EXPECT_TRUE(recorded) << recordError;
    const double ms = dispatchMilliseconds();
    std::vector<float> out = unpackHalf(buffer, values);
    demo::unexpose(out, renderer.preExposure());  // physical units, as render() gives postfx's image
    demo::destroyBuffer(host->device, buffer);
    const ImageStats stats = compareImages(out, expected.rgba, extent.width, extent.height, 0.05, 1.0);
    std::printf("[ baseline ] %s, step %.3g m: vs postfx %s (dispatch %.3f ms)\n", bench::baselineName(which),
                stepLength, stats.summary().c_str(), ms);
    EXPECT_EQ(stats.nonFinite, 0u);
    return stats.relativeRmse;
}

demo::RenderOptions smallRender() {
    demo::RenderOptions options;
    options.width = 64;
    options.height = 36;
    options.shadowMapSize = 1024;
    return options;
}

TEST_F(BenchBaselineTest, RiemannConvergesToPostfxAndSeedDoesNot) {
    demo::Scene scene;
    std::string error;
    ASSERT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/fog_homogeneous.json", scene, error)) << error;
    ASSERT_TRUE(scene.fog.enabled);
    ASSERT_FALSE(scene.sun.shadows);
    ASSERT_FALSE(scene.fog.noise.enabled);
    ASSERT_EQ(scene.fog.heightFalloff, 0.0f);

    const demo::RenderOptions options = smallRender();
    auto renderer = demo::Renderer::create(*host, options, error);
    ASSERT_TRUE(renderer) << error;

    // postfx: exact at any step count in a homogeneous medium (frame 0, jittered).
    demo::ImageF postfxImage;
    ASSERT_TRUE(renderer->render(scene, postfxImage, error)) << error;

    // The baselines over the same frame without fog.
    demo::Scene clear = scene;
    clear.fog.enabled = false;
    auto run = [&](bench::Baseline which, float stepLength) {
        return runOnRenderer(*renderer, options, clear, scene, which, stepLength, false, postfxImage);
    };
    const double riemann2 = run(bench::Baseline::SeedFixedRiemann, 2.0f);
    const double riemann01 = run(bench::Baseline::SeedFixedRiemann, 0.1f);
    const double riemann005 = run(bench::Baseline::SeedFixedRiemann, 0.05f);
    const double seed1 = run(bench::Baseline::SeedAsWritten, 1.0f);
    const double seed005 = run(bench::Baseline::SeedAsWritten, 0.05f);

    EXPECT_LT(riemann01, riemann2);
    EXPECT_LT(riemann005, 0.01);
    EXPECT_GT(seed1, 0.10);
    EXPECT_GT(seed005, 0.10);  // wrong on purpose: does not converge to postfx
}

// The shadow-map and noise inputs reach the baselines as they reach postfx: on the shadowed and the noise
// scene (no analytic tail, no transmittance cut-off), seed-fixed-riemann at a short step is close to
// postfx at 512 steps. postfx runs in the baseline's frame too, with density 1e-30 /m: not an empty medium
// (density 0 would retire the fog and its noise texture, docs/frame-plan.md), so it keeps its noise
// texture alive for Context::fogNoiseView, while the color it writes rounds to the un-fogged one.
TEST_F(BenchBaselineTest, ShadowMapAndNoiseInputsMatchPostfx) {
    for (const char* name : {"fog_shadowed.json", "fog_noise.json"}) {
        SCOPED_TRACE(name);
        demo::Scene scene;
        std::string error;
        ASSERT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + name, scene, error)) << error;
        ASSERT_TRUE(scene.fog.enabled);
        ASSERT_TRUE(scene.sun.shadows || scene.fog.noise.enabled);
        scene.fog.analyticTail = false;
        scene.fog.transmittanceCutoff = 0.0f;

        const demo::RenderOptions options = smallRender();
        auto renderer = demo::Renderer::create(*host, options, error);
        ASSERT_TRUE(renderer) << error;
        demo::Scene fine = scene;
        fine.fog.steps = 512;
        fine.fog.jitter = false;
        demo::ImageF postfxImage;
        ASSERT_TRUE(renderer->render(fine, postfxImage, error)) << error;

        demo::Scene unchanged = scene;
        unchanged.fog.density = 1e-30f;
        const bool noise = scene.fog.noise.enabled;
        const double riemann = runOnRenderer(*renderer, options, unchanged, scene,
                                             bench::Baseline::SeedFixedRiemann, 0.1f, noise, postfxImage);
        const double seed = runOnRenderer(*renderer, options, unchanged, scene,
                                          bench::Baseline::SeedAsWritten, 0.5f, noise, postfxImage);
        EXPECT_LT(riemann, 0.02);
        EXPECT_GT(seed, 0.10);
        EXPECT_TRUE(renderer->shadowMap().enabled == scene.sun.shadows);
    }
}

// ---- (2): the seed's phase function, in closed form ----

// Homogeneous medium, color 0, ambient 0: seed-as-written gives out = L·(1 - T) with
// L = E·pSeed(cosθ, g)·σ·Δ·N and T = exp(-σΔ)^N, N = 20 samples. With the sun exactly along (or against)
// the centre pixel's ray, cosθ = ±1 and the seed's phase is 0 for every g.
TEST_F(BenchBaselineTest, SeedPhaseMatchesClosedFormAndVanishesAtCosinePlusMinusOne) {
    const uint32_t ci = kWidth / 2, cj = kHeight / 2;
    for (const float g : {-0.9f, 0.0f, 0.5f, 0.9f}) {
        for (const double sign : {1.0, -1.0}) {
            postfx::FrameInfo frame = homogeneousFrame();
            frame.fog.anisotropy = g;
            const glm::dvec3 centre = pixelDirection(frame.camera, ci, cj, kWidth, kHeight);
            frame.sun.toSun = glm::vec3(sign * centre);
            const std::vector<float> out =
                runMinimal(frame, bench::Baseline::SeedAsWritten, 1.0f, glm::vec4(0.0f, 0.0f, 0.0f, 0.5f));
            const double sigma = frame.fog.density, steps = 20.0;
            const double T = std::exp(-sigma * steps);
            // Size of the in-scattering with a phase of 1/(4π), for the cosθ = ±1 check.
            const double typical = sigma * steps * (1.0 - T) / (4.0 * glm::pi<double>());
            for (uint32_t j = 0; j < kHeight; ++j)
                for (uint32_t i = 0; i < kWidth; ++i) {
                    const size_t p = (size_t(j) * kWidth + i) * 4;
                    const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                    const double cosTheta = glm::dot(d, glm::normalize(glm::dvec3(frame.sun.toSun)));
                    for (int c = 0; c < 3; ++c) {
                        const double e = frame.sun.illuminance[c];
                        const double expected = e * seedPhase(cosTheta, g) * sigma * steps * (1.0 - T);
                        if (i == ci && j == cj) {
                            // cosθ = ±1 up to the float rounding of the ray direction (~1e-7).
                            ASSERT_LT(std::abs(out[p + c]), 1e-3 * e * typical)
                                << "g " << g << " sign " << sign << " c" << c;
                            continue;
                        }
                        ASSERT_NEAR(out[p + c], expected, 2e-3 * expected + 1e-4 * e * typical)
                            << "g " << g << " sign " << sign << " pixel " << i << "," << j << " c" << c;
                    }
                    ASSERT_EQ(out[p + 3], 0.5f);  // alpha untouched
                }
            // Not the real Henyey–Greenstein: a pixel off the sun differs from it.
            const glm::dvec3 corner = pixelDirection(frame.camera, 0, 0, kWidth, kHeight);
            const double cosCorner = glm::dot(corner, glm::normalize(glm::dvec3(frame.sun.toSun)));
            if (g != 0.0f) {
                EXPECT_GT(std::abs(seedPhase(cosCorner, g) / hg(cosCorner, g) - 1.0), 0.1);
            }
        }
    }
    std::printf("[ baseline ] seed-as-written 16x16, 20 steps: dispatch %.3f ms\n", dispatchMilliseconds());
}

// ---- both composites, in closed form ----

TEST_F(BenchBaselineTest, CompositesMatchClosedForm) {
    postfx::FrameInfo frame = homogeneousFrame();
    frame.ambient = {30.0f, 20.0f, 10.0f};
    const glm::vec4 background(100.0f, 50.0f, 25.0f, 0.25f);
    const double sigma = frame.fog.density, g = frame.fog.anisotropy;
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(frame.sun.toSun));

    // seed-as-written: mix(color, L + albedo·ambient, 1 - T), L = E·pSeed·σ·Δ·N (20 samples).
    const std::vector<float> seed = runMinimal(frame, bench::Baseline::SeedAsWritten, 1.0f, background);
    // seed-fixed-riemann: samples at t = 0.5 + k (k = 0..19), the last clipped to 0.5 m:
    //   L = albedo·(E·pHG + ambient)·σ·Σ T_k δ_k, T_k = exp(-σ·(k)), δ_k = 1 (k < 19), 0.5 (k = 19);
    //   T = exp(-σ·19.5); out = color·T + L.
    const std::vector<float> riemann = runMinimal(frame, bench::Baseline::SeedFixedRiemann, 1.0f, background);
    double riemannSum = 0.0;
    for (int k = 0; k < 20; ++k)
        riemannSum += std::exp(-sigma * k) * (k < 19 ? 1.0 : 0.5);
    const double riemannT = std::exp(-sigma * 19.5);
    const double seedT = std::exp(-sigma * 20.0);
    for (uint32_t j = 0; j < kHeight; ++j)
        for (uint32_t i = 0; i < kWidth; ++i) {
            const size_t p = (size_t(j) * kWidth + i) * 4;
            const double cosTheta = glm::dot(pixelDirection(frame.camera, i, j, kWidth, kHeight), toSun);
            for (int c = 0; c < 3; ++c) {
                const double e = frame.sun.illuminance[c], a = frame.ambient[c], albedo = frame.fog.albedo[c];
                const double col = background[c];
                const double fogColor = e * seedPhase(cosTheta, g) * sigma * 20.0 + albedo * a;
                const double seedExpected = col + (fogColor - col) * (1.0 - seedT);
                ASSERT_NEAR(seed[p + c], seedExpected, 2e-3 * seedExpected) << "seed pixel " << i << "," << j;
                const double riemannExpected =
                    col * riemannT + albedo * (e * hg(cosTheta, g) + a) * sigma * riemannSum;
                ASSERT_NEAR(riemann[p + c], riemannExpected, 2e-3 * riemannExpected)
                    << "riemann pixel " << i << "," << j;
            }
            ASSERT_EQ(seed[p + 3], background.a);
            ASSERT_EQ(riemann[p + 3], background.a);
        }
}

// Bad inputs are rejected with a message, nothing recorded.
TEST_F(BenchBaselineTest, RejectsBadStepLength) {
    postfx::FrameInfo frame = homogeneousFrame();
    frame.color = {VK_NULL_HANDLE,
                   VK_NULL_HANDLE,
                   VK_FORMAT_R16G16B16A16_SFLOAT,
                   {kWidth, kHeight},
                   VK_IMAGE_LAYOUT_GENERAL};
    std::string error;
    const postfx::DepthConvention convention;
    for (const float step : {0.0f, -1.0f, std::nanf(""), INFINITY}) {
        error.clear();
        EXPECT_FALSE(baseline->record(VK_NULL_HANDLE, frame, convention, bench::Baseline::SeedFixedRiemann,
                                      step, VK_NULL_HANDLE, queryPool, 0, error));
        EXPECT_NE(error.find("step length"), std::string::npos) << error;
    }
}

}  // namespace
}  // namespace test
