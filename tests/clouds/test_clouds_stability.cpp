// The clouds' stability cases (docs/stability.md, "Clouds"): the camera inside the layer and exactly on its
// boundaries (flat, curved through the atmosphere, and on a box's faces), a horizontal ray grazing the
// curved layer over hundreds of km, coverage 0 (nothing runs) and 1, density 1e3 and 1e-9, the sun at and
// below the horizon with and without the atmosphere, RGBA16F outputs, and the defaults (half resolution,
// temporal) over a few frames. Every output: no NaN or Inf, nothing beyond the color format's largest finite
// value; against a closed form or the double reference (reference::renderClouds, with the GPU's own noise
// texels and the GPU's step counts, so that both sample the same points) within each case's stated
// tolerance. Small images on lavapipe; each case prints what it measured.
#include "clouds_frames.h"
#include "clouds_reference_inputs.h"
#include "fog_harness.h"
#include "image_compare.h"

#include <postfx/reference.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace test {
namespace {

// 16×9 pixels: the middle row (j = 4) is the view's horizontal plane when the camera looks horizontally.
constexpr uint32_t kWidth = 16, kHeight = 9;
constexpr float kAspect = float(kWidth) / float(kHeight);
constexpr VkFormat kRgba32f = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kRgba16f = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr float kHalfMax = 65504.0f;

// What one comparison measured.
struct Measured {
    size_t nonFinite = 0;   // NaN/Inf channels in the GPU output
    size_t beyond = 0;      // channels beyond the format's largest finite value
    double worst = 0.0;     // largest |gpu - expected| / max(|expected|, floor) over RGB
    double rmse = 0.0;      // relative RMSE over RGB (image_compare.h)
    size_t eitherSide = 0;  // pixels along a boundary plane that counted as outside the shape
    std::string where;      // the worst pixel: position, GPU and expected red
};

class CloudsStability : public ReversedZContextTest {
protected:
    static FogHarnessImages images(float sky, VkFormat format = kRgba32f, uint32_t width = kWidth,
                                   uint32_t height = kHeight) {
        FogHarnessImages im;
        im.width = width;
        im.height = height;
        im.colorFormat = format;
        im.color.assign(size_t(width) * height * 4, sky);
        im.depth.assign(size_t(width) * height, 0.0f);  // no geometry (reversed Z)
        return im;
    }

    std::vector<float> render(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }

    // A texture postfx holds, as floats (R8_UNORM texels in [0, 1]; R32F as stored).
    std::vector<float> readHeld(const char* name, bool unorm8) {
        if (unorm8) return heldUnormTexels(*host, gpu, *context, name);
        VkExtent3D extent{};
        const std::vector<uint8_t> bytes = readHeldImage(*host, gpu, *context, name, extent);
        std::vector<float> v(bytes.size() / 4);
        std::memcpy(v.data(), bytes.data(), v.size() * 4);
        return v;
    }

    // The double reference over `im` with the GPU's step counts (the same midpoints: jitter off) and, with
    // noise, the GPU's texels (held after the last frame that ran the clouds with noise).
    std::vector<float> reference(const postfx::FrameInfo& frame, const FogHarnessImages& im) {
        std::vector<float> base, detail;
        if (frame.clouds.noise.enabled) {
            base = readHeld("clouds.base_noise", true);
            detail = readHeld("clouds.detail_noise", true);
        }
        postfx::reference::CloudInputs in =
            referenceInputs(frame, im, frame.clouds.steps, frame.clouds.lightSteps);
        in.baseNoise = base;
        in.detailNoise = detail;
        std::vector<float> out;
        const postfx::Status s = postfx::reference::renderClouds(in, out);
        EXPECT_TRUE(s.ok()) << s.message;
        if (im.colorFormat == kRgba16f)
            for (float& v : out)
                v = std::min(v, kHalfMax);  // RGBA16F clamps (docs/stability.md, "Overflow")
        return out;
    }

    // With the atmosphere on, the color the clouds composite over is the atmosphere's sky: rendered with
    // the clouds off, so that the reference composites its clouds over the same sky.
    FogHarnessImages skyOf(postfx::FrameInfo frame, const FogHarnessImages& im) {
        FogHarnessImages sky = im;
        frame.clouds.enabled = false;
        sky.color = render(frame, im);
        return sky;
    }

    // Counts non-finite and out-of-range channels of `out` (alpha too), and compares RGB with `expected`;
    // a pixel in `eitherSide` (a ray along a boundary plane from a camera on it) may instead equal its input
    // color exactly (counted as outside the shape).
    static Measured measure(const std::vector<float>& out, const std::vector<float>& expected,
                            const FogHarnessImages& im, double floor,
                            const std::vector<bool>& eitherSide = {}) {
        Measured m;
        const float max = im.colorFormat == kRgba16f ? kHalfMax : 3.4028235e38f;
        for (float v : out) {
            m.nonFinite += !std::isfinite(v);
            m.beyond += std::abs(v) > max;
        }
        for (size_t p = 0; p < size_t(im.width) * im.height; ++p) {
            double pixel = 0.0;
            bool unchanged = true;
            for (int c = 0; c < 3; ++c) {
                const double a = out[p * 4 + c], b = expected[p * 4 + c];
                pixel = std::max(pixel, std::abs(a - b) / std::max(std::abs(b), floor));
                unchanged = unchanged && out[p * 4 + c] == im.color[p * 4 + c];
            }
            if (!eitherSide.empty() && eitherSide[p] && unchanged) {
                ++m.eitherSide;
                continue;
            }
            if (pixel > m.worst) {
                m.worst = pixel;
                m.where = "pixel (" + std::to_string(p % im.width) + ", " + std::to_string(p / im.width) +
                          ") " + std::to_string(out[p * 4]) + " vs " + std::to_string(expected[p * 4]);
            }
        }
        m.rmse = compareImages(out, expected, im.width, im.height, 0.05, floor).relativeRmse;
        return m;
    }

    // Asserts the measurement: finite, in range, worst relative difference below `tolerance` and relative
    // RMSE below `rmseTolerance`; prints it.
    static void expectMeasured(const Measured& m, const std::string& what, double tolerance,
                               double rmseTolerance = 1.0) {
        std::printf(
            "[ clouds ] %s: worst relative %.3g, rel. RMSE %.3g, non-finite %zu, beyond %zu%s\n",
            what.c_str(), m.worst, m.rmse, m.nonFinite, m.beyond,
            m.eitherSide ? (", " + std::to_string(m.eitherSide) + " boundary rays outside").c_str() : "");
        EXPECT_EQ(m.nonFinite, 0u) << what;
        EXPECT_EQ(m.beyond, 0u) << what;
        EXPECT_LT(m.worst, tolerance) << what << ": " << m.where;
        EXPECT_LT(m.rmse, rmseTolerance) << what;
    }

    // The GPU against the reference on the same inputs: per pixel within `tolerance` of max(|expected|,
    // floor), and within `rmseTolerance` in relative RMSE.
    Measured expectMatchesReference(const postfx::FrameInfo& frame, const FogHarnessImages& im,
                                    const std::string& what, double tolerance, double floor,
                                    const std::vector<bool>& eitherSide = {}, double rmseTolerance = 1.0) {
        const FogHarnessImages under = frame.atmosphere.enabled ? skyOf(frame, im) : im;
        const std::vector<float> out = render(frame, im);
        const Measured m = measure(out, reference(frame, under), under, floor, eitherSide);
        expectMeasured(m, what, tolerance, rmseTolerance);
        return m;
    }
};

// A homogeneous layer lit by the sun (30° up) and the ambient, marched without jitter.
postfx::FrameInfo litHomogeneousFrame() {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.clouds.jitter = false;
    frame.clouds.castShadows = false;
    frame.sun.toSun = glm::normalize(glm::vec3(0.8f, 0.5f, 0.3f));
    frame.sun.illuminance = postfx::Vec3(10.0f);
    frame.ambient = postfx::Vec3(0.3f, 0.4f, 0.6f);
    return frame;
}

// Pixels whose ray stays within 1 mm of the plane through the camera with normal `n` over `far` metres: from
// a camera on a boundary plane, such a ray lies along the boundary, inside or outside by a rounding.
std::vector<bool> alongPlane(const postfx::CameraInput& camera, glm::dvec3 n, double far) {
    std::vector<bool> along(size_t(kWidth) * kHeight);
    for (uint32_t j = 0; j < kHeight; ++j)
        for (uint32_t i = 0; i < kWidth; ++i)
            along[size_t(j) * kWidth + i] =
                std::abs(glm::dot(pixelDirection(camera, i, j, kWidth, kHeight), n)) * far < 1e-3;
    return along;
}

// The length of ray y0 + t·d, t in [0, far], between the planes y = bottom and y = top.
double slabPath(double y0, glm::dvec3 d, double bottom, double top, double far) {
    if (d.y == 0.0) return y0 >= bottom && y0 <= top ? far : 0.0;
    const double ta = (bottom - y0) / d.y, tb = (top - y0) / d.y;
    return std::max(0.0, std::min(far, std::max(ta, tb)) - std::max(0.0, std::min(ta, tb)));
}

const glm::dvec3 kUp{0.0, 1.0, 0.0};
// Looking 40° up, at the horizon and 40° down (and a little sideways).
const glm::dvec3 kLooks[] = {{1.0, 0.84, 0.3}, {1.0, 0.0, 0.3}, {1.0, -0.84, 0.3}};
const char* const kLookNames[] = {"up", "horizontal", "down"};

// A flat homogeneous layer without light, the camera inside it and exactly on its bottom and top, looking
// up, horizontally and down: each pixel is the sky times exp(-σ·path), the path through the slab to max
// distance in closed form. Where that is below the march's cutoff (1e-3) the march stops early: T lies
// between the closed form and the cutoff. From a camera on a boundary, the rays of the horizontal row run
// along the boundary plane: inside (the closed form) or outside (the sky, unchanged) by a rounding.
TEST_F(CloudsStability, FlatLayerCameraInsideAndOnItsBoundariesIsBeerLambert) {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.clouds.jitter = false;
    frame.clouds.castShadows = false;
    const double sigma = frame.clouds.density, far = frame.clouds.maxDistance;
    const FogHarnessImages im = images(1.0f);
    for (double y : {1500.0, 1000.0, 2000.0})
        for (int l = 0; l < 3; ++l) {
            frame.camera = lookCamera({0.0, y, 0.0}, kLooks[l], kUp, 60.0f, kAspect);
            const std::vector<float> out = render(frame, im);
            const std::vector<bool> along = alongPlane(frame.camera, kUp, far);
            std::vector<float> expected(out.size(), 1.0f);
            for (uint32_t j = 0; j < kHeight; ++j)
                for (uint32_t i = 0; i < kWidth; ++i) {
                    const size_t p = size_t(j) * kWidth + i;
                    const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                    const double T = std::exp(-sigma * slabPath(y, d, 1000.0, 2000.0, far));
                    // Past the cutoff: any T in [closed form, 1e-3] is right; expect the GPU's own if so.
                    const bool cut = T < 1e-3 && out[p * 4] >= T * (1.0 - 1e-3) && out[p * 4] < 1e-3;
                    for (int c = 0; c < 3; ++c)
                        expected[p * 4 + c] = cut ? out[p * 4] : float(T);
                }
            const std::string what =
                "flat layer, camera at " + std::to_string(int(y)) + " m looking " + kLookNames[l];
            expectMeasured(measure(out, expected, im, 1e-6, along), what, 1e-4);
        }
}

// The same camera positions with the sun and the ambient, against the reference (and the same boundary
// rule): the light march from samples on the boundary, the ambient's slabs at h = 0 and 1. Tolerance 1%:
// the march stops at T < 1e-3 (the reference does not), dropping the light behind, up to ~7× brighter
// deep in the layer toward the sun (measured 0.65%).
TEST_F(CloudsStability, FlatLayerLitFromInsideAndOnItsBoundariesMatchesReference) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    const FogHarnessImages im = images(0.5f);
    for (double y : {1500.0, 1000.0, 2000.0})
        for (int l = 0; l < 3; ++l) {
            frame.camera = lookCamera({0.0, y, 0.0}, kLooks[l], kUp, 60.0f, kAspect);
            const std::string what =
                "lit flat layer, camera at " + std::to_string(int(y)) + " m looking " + kLookNames[l];
            expectMatchesReference(frame, im, what, 1e-2, 1e-3,
                                   alongPlane(frame.camera, kUp, frame.clouds.maxDistance));
        }
}

// The curved layer (atmosphere on: spheres around the planet's centre, 6.36e6 m away, in float), the
// camera inside it and exactly on its bottom and top spheres, against the reference: the sun through the
// atmosphere's LUT, the aerial perspective in front of the clouds.
TEST_F(CloudsStability, CurvedLayerCameraInsideAndOnItsBoundariesMatchesReference) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    frame.atmosphere.enabled = true;
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
    frame.sun.illuminance = postfx::Vec3(1e5f);
    const FogHarnessImages im = images(0.0f);
    for (double y : {1500.0, 1000.0, 2000.0})
        for (int l = 0; l < 3; ++l) {
            frame.camera = lookCamera({0.0, y, 0.0}, kLooks[l], kUp, 60.0f, kAspect);
            const std::string what =
                "curved layer, camera at " + std::to_string(int(y)) + " m looking " + kLookNames[l];
            expectMatchesReference(frame, im, what, 2e-2, 1.0);
        }
}

// A box (CloudShape::Box), the camera exactly on its bottom face and on its +x face, looking along the
// face, into the box and out of it, against the reference. Rays along the face from a camera on it may
// count as inside or outside: the direction's component along the face's normal is a rounding error (on
// lavapipe all 16 such rays of each view came out outside, the sky unchanged; the reference's, inside).
TEST_F(CloudsStability, CameraOnABoxFaceMatchesReference) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    frame.clouds.shape = postfx::CloudShape::Box;
    frame.clouds.box.center = {0.0, 2000.0, 0.0};
    frame.clouds.box.halfSize = {2000.0f, 500.0f, 2000.0f};
    const FogHarnessImages im = images(0.5f);
    struct Case {
        const char* name;
        glm::dvec3 position, forward, up, normal;
    };
    const Case cases[] = {
        {"bottom face, along it", {0.0, 1500.0, 0.0}, {1.0, 0.0, 0.3}, kUp, kUp},
        {"bottom face, into the box", {0.0, 1500.0, 0.0}, {1.0, 0.84, 0.3}, kUp, kUp},
        {"bottom face, out of it", {0.0, 1500.0, 0.0}, {1.0, -0.84, 0.3}, kUp, kUp},
        {"+x face, along it", {2000.0, 2000.0, 0.0}, {0.0, 0.3, 1.0}, {1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
        {"+x face, into the box", {2000.0, 2000.0, 0.0}, {-1.0, 0.2, 0.3}, kUp, {1.0, 0.0, 0.0}},
        {"corner edge (-x, bottom)", {-2000.0, 1500.0, 0.0}, {1.0, 0.0, 0.3}, kUp, kUp},
    };
    for (const Case& c : cases) {
        frame.camera = lookCamera(c.position, c.forward, c.up, 60.0f, kAspect);
        expectMatchesReference(frame, im, std::string("box, camera on its ") + c.name, 1e-2, 1e-3,
                               alongPlane(frame.camera, c.normal, frame.clouds.maxDistance));
    }
}

// A horizontal ray grazing the curved layer: the camera 1 m under its bottom and inside it, looking at the
// horizon, max distance 1e6 m: paths of ~180 km through the layer, where float's 0.5 m at the planet's
// radius decides where the ray leaves the bottom sphere. Without light (sun and ambient 0: the air adds
// nothing) each pixel is the sky times the clouds' T = e^{-σ·path} of a thin homogeneous layer (optical
// depth ~0.4): T measures the path, against the reference's path in double. Lit, homogeneous and noisy,
// with the aerial perspective's LUT reaching 200 km (at its default 32 km, the air in front of clouds
// ~100 km away is the LUT's last slice where the reference integrates it up to them: 3% and 8% off).
TEST_F(CloudsStability, HorizontalRayGrazingTheCurvedLayerMatchesReference) {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.clouds.jitter = false;
    frame.clouds.castShadows = false;
    frame.atmosphere.enabled = true;
    frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
    frame.sun.illuminance = postfx::Vec3(0.0f);
    frame.clouds.bottomHeight = 1500.0f;
    frame.clouds.topHeight = 4000.0f;
    frame.clouds.maxDistance = 1e6f;
    frame.clouds.density = 2e-6f;
    const FogHarnessImages im = images(1.0f);
    for (double y : {1499.0, 2500.0}) {
        frame.camera = lookCamera({0.0, y, 0.0}, {1.0, 0.0, 0.3}, kUp, 30.0f, kAspect);
        expectMatchesReference(frame, im, "grazing, T alone, camera at " + std::to_string(int(y)) + " m",
                               1e-2, 1e-3);
    }
    frame.sun = litHomogeneousFrame().sun;
    frame.sun.illuminance = postfx::Vec3(1e5f);
    frame.ambient = litHomogeneousFrame().ambient;
    expectMatchesReference(frame, im, "grazing, lit, camera at 2500 m", 1e-2, 1e-2);
    frame.clouds = finelyMarchedNoisyClouds();
    frame.clouds.maxDistance = 1e6f;
    frame.clouds.castShadows = false;
    frame.camera = lookCamera({0.0, 1499.0, 0.0}, {1.0, 0.0, 0.3}, kUp, 30.0f, kAspect);
    expectMatchesReference(frame, im, "grazing, lit, noisy, camera at 1499 m", 1.0, 1e-2, {}, 0.02);
}

// Coverage 0: the frame plan records no clouds pass and the color comes back bit for bit. Coverage 1
// with noise: the field is the base shape times the profile, eroded, everywhere; against the reference.
TEST_F(CloudsStability, CoverageZeroRunsNothingAndCoverageOneMatchesReference) {
    postfx::FrameInfo frame;
    frame.clouds = finelyMarchedNoisyClouds();
    frame.clouds.steps = 64;
    frame.clouds.castShadows = false;
    frame.clouds.coverage = 0.0f;
    frame.sun.toSun = glm::normalize(glm::vec3(0.6f, 0.7f, 0.3f));
    frame.sun.illuminance = postfx::Vec3(10.0f);
    frame.ambient = postfx::Vec3(0.3f, 0.4f, 0.6f);
    frame.camera = lookCamera({0.0, 200.0, 0.0}, {1.0, 0.6, 0.2}, kUp, 60.0f, kAspect);
    const FogHarnessImages im = images(0.5f, kRgba16f);
    EXPECT_EQ(passNames(planAndRecord(*host, gpu, *context, im, frame)), std::vector<std::string>{});
    const std::vector<float> out = render(frame, im);
    EXPECT_EQ(out, im.color);
    std::printf("[ clouds ] coverage 0: no pass, color unchanged %s\n", out == im.color ? "yes" : "no");
    frame.clouds.coverage = 1.0f;
    for (VkFormat format : {kRgba32f, kRgba16f})
        expectMatchesReference(frame, images(0.5f, format), "coverage 1", 1.0, 1e-2, {}, 1e-2);
}

// Density 1e3 /m: opaque. A 1 km layer seen from below in 64 steps: the first step's optical depth is
// ~1.6e4, T underflows to 0, the sample is 8 m inside the cloud (its light e^{-1e4}): out = 0 exactly.
// A 1 cm layer (1 m up, where float resolves it to 1e-5 of its thickness) in 1024 steps: optical depth
// ~10 per step, the first sample 5 µm inside, so that the light comes from the first step; against the
// reference from below (RGBA32F) and from above with a 2e6 lux sun behind the camera (RGBA16F: radiance
// beyond half floats, up to 8.3e4: clamped at 65504, never Inf). Where the march stops (T < 1e-3)
// its T stays there: up to 1e-3 of the sky shows through (0.7% of these dark pixels).
TEST_F(CloudsStability, DensityThousandIsOpaqueAndFinite) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    frame.clouds.density = 1e3f;
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {1.0, 1.0, 0.3}, kUp, 60.0f, kAspect);
    const FogHarnessImages im = images(0.5f);
    const std::vector<float> thick = render(frame, im);
    expectMeasured(measure(thick, std::vector<float>(thick.size(), 0.0f), im, 1e-30),
                   "density 1e3, 1 km layer, against 0", 1e-30);
    frame.clouds.bottomHeight = 1.0f;
    frame.clouds.topHeight = 1.01f;
    frame.clouds.steps = 1024;
    frame.camera = lookCamera({0.0, 0.0, 0.0}, {0.8, 0.5, 0.3}, kUp, 20.0f, kAspect);
    expectMatchesReference(frame, im, "density 1e3, 1 cm layer from below", 1e-2, 1e-6);
    frame.camera = lookCamera({0.0, 3.0, 0.0}, {0.8, -0.6, 0.3}, kUp, 20.0f, kAspect);
    frame.sun.toSun = glm::normalize(glm::vec3(-0.8f, 0.6f, -0.3f));
    frame.sun.illuminance = postfx::Vec3(2e6f);
    const std::vector<float> full = render(frame, im);
    const auto beyondHalf = std::count_if(full.begin(), full.end(), [](float v) { return v > kHalfMax; });
    std::printf(
        "[ clouds ] density 1e3, 1 cm layer from above, 2e6 lux: largest RGBA32F value %.4g, %td "
        "channels beyond 65504\n",
        *std::max_element(full.begin(), full.end()), beyondHalf);
    EXPECT_GT(beyondHalf, 0);
    expectMatchesReference(frame, images(0.5f, kRgba16f), "density 1e3, 1 cm layer from above, RGBA16F", 2e-3,
                           1e-3);
}

// The slab model's extremes (docs/effects/clouds.md, "Multiple scattering"): a layer of optical depth 10⁴
// (density 10 /m over 1 km) at albedo 1 exactly, seen from below, inside and above, where the δ-Eddington
// closed form has k -> 0 and slabs 10⁴ deep (it is written with decaying exponentials only); and the phase
// at g = 0.99 and -0.99 (one lobe each, δ-scaling's f -> 1) through a layer of optical depth 2. Finite,
// within range and against the reference in double.
TEST_F(CloudsStability, SlabModelExtremesMatchReference) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    frame.clouds.albedo = 1.0f;
    frame.clouds.density = 10.0f;
    frame.clouds.steps = 256;
    const FogHarnessImages im = images(0.5f);
    for (double y : {500.0, 1500.0, 2500.0}) {
        frame.camera = lookCamera({0.0, y, 0.0},
                                  {1.0,
                                   y < 1000.0   ? 1.0
                                   : y > 2000.0 ? -1.0
                                                : 0.2,
                                   0.3},
                                  kUp, 60.0f, kAspect);
        expectMatchesReference(frame, im,
                               "optical depth 1e4, albedo 1, camera at " + std::to_string(int(y)) + " m",
                               2e-2, 1e-3, alongPlane(frame.camera, kUp, frame.clouds.maxDistance));
    }
    frame.clouds.density = 0.002f;
    frame.camera = lookCamera({0.0, 10.0, 0.0}, {1.0, 1.0, 0.3}, kUp, 60.0f, kAspect);
    for (float g : {0.99f, -0.99f}) {
        frame.clouds.anisotropyForward = std::max(g, 0.0f);
        frame.clouds.anisotropyBack = std::min(g, 0.0f);
        frame.clouds.lobeMix = g < 0.0f ? 1.0f : 0.0f;
        expectMatchesReference(frame, im, "g " + std::to_string(g) + ", albedo 1", 1e-2, 1e-3);
    }
}

// Density 1e-9 /m: T = e^{-τ} with τ ~ 1e-6 (1 km up) to 1e-4 (100 km along the layer), where float keeps
// 1 - T only to ~6e-8: T within 2 ulps of 1 - τ (closed form); the radiance (black sky: L alone, ~1e-7
// of the sun) tiny, not negative, and within 1e-3 of the reference relatively (oneMinusExp keeps 1 - e^{-x}).
TEST_F(CloudsStability, DensityOneNanoIsNearlyTransparent) {
    postfx::FrameInfo frame;
    frame.clouds = homogeneousLayer();
    frame.clouds.jitter = false;
    frame.clouds.castShadows = false;
    frame.clouds.density = 1e-9f;
    const double sigma = frame.clouds.density, far = frame.clouds.maxDistance;
    const FogHarnessImages sky = images(1.0f);
    for (double y : {10.0, 1500.0}) {
        frame.camera = lookCamera({0.0, y, 0.0}, {1.0, 0.4, 0.3}, kUp, 60.0f, kAspect);
        const std::vector<float> out = render(frame, sky);
        std::vector<float> expected(out.size(), 1.0f);
        double worstUlps = 0.0;
        for (uint32_t j = 0; j < kHeight; ++j)
            for (uint32_t i = 0; i < kWidth; ++i) {
                const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
                const double T = 1.0 - sigma * slabPath(y, d, 1000.0, 2000.0, far);
                const size_t p = size_t(j) * kWidth + i;
                worstUlps = std::max(worstUlps, std::abs(out[p * 4] - T) / 0x1p-24);
            }
        const std::string what = "density 1e-9, camera at " + std::to_string(int(y)) + " m";
        std::printf("[ clouds ] %s: T against 1 - σ·path: worst %.3g half-ulps of 1\n", what.c_str(),
                    worstUlps);
        EXPECT_LE(worstUlps, 4.0) << what;
        postfx::FrameInfo lit = frame;
        lit.sun = litHomogeneousFrame().sun;
        lit.ambient = litHomogeneousFrame().ambient;
        const FogHarnessImages black = images(0.0f);
        const std::vector<float> L = render(lit, black);
        EXPECT_EQ(std::count_if(L.begin(), L.end(), [](float v) { return v < 0.0f; }), 0) << what;
        expectMeasured(measure(L, reference(lit, black), black, 1e-30), what + ", radiance", 1e-3);
    }
}

// The sun exactly on the horizon (toSun.y = 0: the light march runs along the layer to light distance)
// and below it (y < 0: toward the layer's bottom), the camera inside a homogeneous layer, without the
// atmosphere (flat layer) and with it (curved layer: the planet hides the sun from some of the clouds,
// the transmittance LUT's horizon), max distance 30 km (inside the aerial perspective's LUT). The shadow
// map (16² here) holds 1 everywhere: no sun above the horizon, nothing to shadow.
TEST_F(CloudsStability, SunOnAndBelowTheHorizonMatchesReference) {
    postfx::FrameInfo frame = litHomogeneousFrame();
    frame.clouds.density = 5e-4f;
    frame.clouds.maxDistance = 30000.0f;
    frame.clouds.castShadows = true;
    frame.clouds.shadowMap.size = 16;
    frame.sun.illuminance = postfx::Vec3(1e3f);
    frame.camera = lookCamera({0.0, 1500.0, 0.0}, {1.0, 0.1, 0.3}, kUp, 60.0f, kAspect);
    const FogHarnessImages im = images(0.5f);
    for (bool atmosphere : {false, true}) {
        frame.atmosphere.enabled = atmosphere;
        frame.atmosphere.multipleScattering = postfx::AtmosphereMultipleScattering::Off;
        for (float y : {0.0f, -0.02f, -0.5f}) {
            frame.sun.toSun = glm::normalize(glm::vec3(0.8f, y, 0.3f));
            if (y == 0.0f) frame.sun.toSun.y = 0.0f;
            const std::string what = std::string(atmosphere ? "atmosphere on" : "atmosphere off") +
                                     ", sun y = " + std::to_string(y);
            expectMatchesReference(frame, im, what, 1e-2, 1e-2);
            const std::vector<float> shadow = readHeld("clouds.shadow_map", false);
            EXPECT_EQ(std::count(shadow.begin(), shadow.end(), 1.0f), 256) << what;
        }
    }
}

// The defaults (half resolution, temporal accumulation, the shadow map, the default noise), the camera
// inside the layer at the horizon, the sun low and strong: four frames (the camera tilting) in RGBA16F
// and RGBA32F, each finite and in range.
TEST_F(CloudsStability, DefaultsOverFourFramesStayFinite) {
    for (VkFormat format : {kRgba16f, kRgba32f}) {
        postfx::FrameInfo frame;
        frame.clouds.enabled = true;
        frame.sun.toSun = glm::normalize(glm::vec3(0.8f, 0.1f, 0.3f));
        frame.sun.illuminance = postfx::Vec3(1e5f);
        frame.ambient = postfx::Vec3(1e3f);
        const FogHarnessImages im = images(0.5f, format);
        Measured worst;
        for (uint64_t i = 0; i < 4; ++i) {
            frame.frameIndex = i;
            frame.timeSeconds = double(i) / 30.0;
            frame.camera = lookCamera({0.0, 2500.0, 0.0}, {1.0, 0.02 * double(i), 0.3}, kUp, 60.0f, kAspect);
            const std::vector<float> out = render(frame, im);
            const Measured m = measure(out, out, im, 1.0);
            worst.nonFinite += m.nonFinite;
            worst.beyond += m.beyond;
        }
        expectMeasured(
            worst, format == kRgba16f ? "defaults, 4 frames, RGBA16F" : "defaults, 4 frames, RGBA32F", 1.0);
    }
}

}  // namespace
}  // namespace test
