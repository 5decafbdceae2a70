// Whole-frame stability cases (docs/stability.md): each case edits the base frame (stability_frame.h)
// into a hard input, runs postfx's fog on the GPU, and asserts no NaN or Inf in the output, nothing
// beyond the color format's largest finite value, and agreement with the double-precision reference
// on the same inputs and step count (clamped to the format's range) or with the known limit.
#include "gpu_test.h"
#include "stability_frame.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <ostream>
#include <string>

namespace test {
namespace {

enum class Expect {
    Reference,       // the reference with the GPU's step count, clamped to the format
    ColorUnchanged,  // the medium is empty: out = color exactly
};

struct SceneCase {
    const char* name;
    std::function<void(StabilityFrame&)> edit;
    double tolerance = 2e-3;  // relative, of max(|expected|, 1), per channel
    Expect expect = Expect::Reference;
    VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
};

void PrintTo(const SceneCase& c, std::ostream* os) {
    *os << c.name;
}

class FogStabilityScene : public GpuTest, public ::testing::WithParamInterface<SceneCase> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
    }

    // Runs `f` through a context with its depth convention; the record() status.
    postfx::Status runGpu(const StabilityFrame& f, std::vector<float>& out) {
        postfx::ContextCreateInfo info;
        info.depth = f.depth;
        std::unique_ptr<postfx::Context> context;
        if (postfx::Status s = createContext(context, info); !s) return s;
        FogHarness harness(*host, gpu);
        return harness.run(*context, f.images, f.frame, out);
    }

    postfx::core::Gpu gpu;
};

TEST_P(FogStabilityScene, FiniteAndWithinToleranceOfTheExpectation) {
    const SceneCase& c = GetParam();
    StabilityFrame f = baseFrame();
    f.images.colorFormat = c.format;
    c.edit(f);
    std::vector<float> gpuOut;
    const postfx::Status s = runGpu(f, gpuOut);
    ASSERT_TRUE(s.ok()) << s.message;
    std::vector<float> expected;
    if (c.expect == Expect::Reference) {
        const postfx::Status r = referenceOf(f, expected);
        ASSERT_TRUE(r.ok()) << r.message;
    } else {
        expected = f.images.color;
    }
    const Comparison cmp = compareToExpected(gpuOut, expected, c.format, c.tolerance);
    std::printf("[ stability ] %s: worst relative difference %.3g (tolerance %.3g)\n", c.name,
                cmp.worstRelative, c.tolerance);
    EXPECT_EQ(cmp.nonFinite, 0u) << "NaN or Inf in the output";
    EXPECT_EQ(cmp.outOfRange, 0u) << "values beyond the format's largest finite value";
    EXPECT_EQ(cmp.off, 0u) << cmp.firstOff;
}

// The sun direction through pixel (8, 9) of the base frame (a wall pixel), so that cos θ = ±1 there.
glm::vec3 sunAlongPixel(const StabilityFrame& f, double sign) {
    return glm::vec3(sign * pixelDirection(f.frame.camera, 8, 9, f.images.width, f.images.height));
}

auto anisotropyCase(const char* name, float g, double sign) {
    return SceneCase{name, [g, sign](StabilityFrame& f) {
                         f.frame.fog.anisotropy = g;
                         f.frame.sun.toSun = sunAlongPixel(f, sign);
                         f.frame.sun.illuminance = glm::vec3(1e5f);  // peak radiance far past 65504
                     }};
}

const SceneCase kCases[] = {
    // Extinction and albedo.
    {"ExtinctionZero", [](StabilityFrame& f) { f.frame.fog.density = 0.0f; }, 0.0, Expect::ColorUnchanged},
    {"ExtinctionTiny", [](StabilityFrame& f) { f.frame.fog.density = 1e-12f; }},
    {"ExtinctionHuge", [](StabilityFrame& f) { f.frame.fog.density = 1e6f; }},
    {"AlbedoZero", [](StabilityFrame& f) { f.frame.fog.albedo = glm::vec3(0.0f); }},
    {"AlbedoOne", [](StabilityFrame& f) { f.frame.fog.albedo = glm::vec3(1.0f); }},
    {"StepsOne", [](StabilityFrame& f) { f.frame.fog.steps = 1; }},
    {"Steps4096", [](StabilityFrame& f) { f.frame.fog.steps = 4096; }},
    // Phase: g = ±0.999 (the ends of the range) and 0 at cos θ = +1 and -1; a 1e5 lux sun.
    anisotropyCase("AnisotropyMinus0999Forward", -0.999f, 1.0),
    anisotropyCase("AnisotropyMinus0999Backward", -0.999f, -1.0),
    anisotropyCase("AnisotropyZeroForward", 0.0f, 1.0),
    anisotropyCase("Anisotropy0999Forward", 0.999f, 1.0),
    anisotropyCase("Anisotropy0999Backward", 0.999f, -1.0),
    {"Anisotropy0999ForwardRgba32f",
     [](StabilityFrame& f) {
         f.frame.fog.anisotropy = 0.999f;
         f.frame.sun.toSun = sunAlongPixel(f, 1.0);
         f.frame.sun.illuminance = glm::vec3(1e5f);
     },
     2e-3, Expect::Reference, VK_FORMAT_R32G32B32A32_SFLOAT},
    // Depth conventions: the wall at the near plane (depth 1 reversed, 0 standard), no geometry
    // (0 reversed, 1 standard), infinite far plane.
    {"StandardZ",
     [](StabilityFrame& f) {
         f.depth.reversedZ = false;
         rebuildCameraAndDepth(f);
     }},
    {"ReversedZInfiniteFar",
     [](StabilityFrame& f) {
         f.depth.infiniteFar = true;
         rebuildCameraAndDepth(f);
     }},
    {"StandardZInfiniteFar",
     [](StabilityFrame& f) {
         f.depth.reversedZ = false;
         f.depth.infiniteFar = true;
         rebuildCameraAndDepth(f);
     }},
    {"DepthAtNearPlaneReversedZ",
     [](StabilityFrame& f) {
         for (uint32_t i = 0; i < f.images.width * 4; ++i)
             f.images.depth[i] = 1.0f;  // top rows
     }},
    {"DepthAtNearPlaneStandardZ",
     [](StabilityFrame& f) {
         f.depth.reversedZ = false;
         rebuildCameraAndDepth(f);
         for (uint32_t i = 0; i < f.images.width * 4; ++i)
             f.images.depth[i] = 0.0f;
     }},
    {"NoGeometryAnywhere",
     [](StabilityFrame& f) { std::fill(f.images.depth.begin(), f.images.depth.end(), 0.0f); }},
    // Camera placement and projection.
    {"CameraInsideDenseFog",
     [](StabilityFrame& f) {
         f.frame.fog.density = 50.0f;
         f.frame.fog.baseHeight = 10.0f;  // the camera 8 m below the base: σt = 50·e^0.8 per metre
     }},
    {"CameraTouchingSurface",
     [](StabilityFrame& f) {
         f.wallDistance = 1e-4;  // the top row's wall at 0.1 mm, the near plane at 0.1 m is moved in
         f.nearPlane = 1e-5f;
         rebuildCameraAndDepth(f);
     }},
    {"NearPlane1e-4FarPlane1e7",
     [](StabilityFrame& f) {
         f.nearPlane = 1e-4f;
         f.farPlane = 1e7f;
         rebuildCameraAndDepth(f);
     }},
    {"FieldOfView1Degree",
     [](StabilityFrame& f) {
         f.fovYDeg = 1.0f;
         rebuildCameraAndDepth(f);
     }},
    {"FieldOfView170Degrees",
     [](StabilityFrame& f) {
         f.fovYDeg = 170.0f;
         rebuildCameraAndDepth(f);
     }},
    {"MillionMetresFromOrigin",
     [](StabilityFrame& f) {
         f.cameraPosition = {1.0e6, 2.0, -1.0e6};
         rebuildCameraAndDepth(f);
     }},
    {"MaxDistance1e5",
     [](StabilityFrame& f) {
         f.frame.fog.maxDistance = 1e5f;
         f.frame.fog.heightFalloff = 0.001f;
     }},
    // Sun.
    {"SunAtZenithSelfShadow",
     [](StabilityFrame& f) {
         f.frame.sun.toSun = {0.0f, 1.0f, 0.0f};
         f.frame.fog.selfShadow = true;
     }},
    {"SunOnHorizonSelfShadow",
     [](StabilityFrame& f) {
         f.frame.sun.toSun = {1.0f, 0.0f, 0.0f};
         f.frame.fog.selfShadow = true;
     }},
    {"SunBelowHorizonSelfShadow",
     [](StabilityFrame& f) {
         f.frame.sun.toSun = {0.2f, -1.0f, 0.1f};
         f.frame.fog.selfShadow = true;
     }},
    {"SunIlluminanceZero", [](StabilityFrame& f) { f.frame.sun.illuminance = glm::vec3(0.0f); }},
    {"SunIlluminance1e5", [](StabilityFrame& f) { f.frame.sun.illuminance = glm::vec3(1e5f); }},
    // Empty media.
    {"NoiseThresholdAboveMaximum",
     [](StabilityFrame& f) {
         f.frame.fog.noise.enabled = true;
         f.frame.fog.noise.textureSize = 16;
         f.frame.fog.noise.threshold = 1.0f;  // texels are at most 1: clamp(n - 1, 0, 1) = 0
     },
     0.0, Expect::ColorUnchanged},
    {"NoiseMultiplierZero",
     [](StabilityFrame& f) {
         f.frame.fog.noise.enabled = true;
         f.frame.fog.noise.textureSize = 16;
         f.frame.fog.noise.multiplier = 0.0f;
     },
     0.0, Expect::ColorUnchanged},
    // Reduced resolution with the hard depth layout (wall edge, sky).
    {"ResolutionScaleQuarter", [](StabilityFrame& f) { f.frame.fog.resolutionScale = 0.25f; }},
};

INSTANTIATE_TEST_SUITE_P(Cases, FogStabilityScene, ::testing::ValuesIn(kCases), [](const auto& info) {
    std::string name = info.param.name;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
});

}  // namespace
}  // namespace test

namespace test {
namespace {

class FogStabilityInputs : public FogStabilityScene {};

// NaN, ±Inf and negative values in the host's color (docs/stability.md, "Host color"): NaN stays in
// its pixel's channel, ±Inf counts as the format's largest finite value (never Inf out), negative values
// are composited as given; every other pixel is exactly what it is with clean color, at full and at
// reduced resolution (the upsample reads no other pixel's color).
TEST_F(FogStabilityInputs, HostColorNanInfAndNegativeStayInTheirPixel) {
    for (VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT}) {
        for (float scale : {1.0f, 0.5f}) {
            SCOPED_TRACE(std::string(format == VK_FORMAT_R16G16B16A16_SFLOAT ? "rgba16f" : "rgba32f") +
                         " scale " + std::to_string(scale));
            StabilityFrame clean = baseFrame();
            clean.images.colorFormat = format;
            clean.frame.fog.resolutionScale = scale;
            StabilityFrame dirty = clean;
            const uint32_t w = clean.images.width;
            const size_t nanPixel = 3 * w + 4, infPixel = 3 * w + 5, minusInfPixel = 4 * w + 20,
                         negativePixel = 10 * w + 6;
            dirty.images.color[nanPixel * 4 + 0] = std::numeric_limits<float>::quiet_NaN();
            for (int c = 0; c < 3; ++c) {
                dirty.images.color[infPixel * 4 + c] = std::numeric_limits<float>::infinity();
                dirty.images.color[minusInfPixel * 4 + c] = -std::numeric_limits<float>::infinity();
                dirty.images.color[negativePixel * 4 + c] = -5.0f;
            }
            std::vector<float> a, b, reference;
            ASSERT_TRUE(runGpu(clean, a).ok());
            ASSERT_TRUE(runGpu(dirty, b).ok());
            ASSERT_TRUE(referenceOf(dirty, reference).ok());
            for (size_t p = 0; p < a.size() / 4; ++p) {
                for (size_t c = 0; c < 4; ++c) {
                    const float v = b[p * 4 + c];
                    if (p == nanPixel && c == 0) {
                        EXPECT_TRUE(std::isnan(v)) << "the host's NaN stays NaN";
                    } else if (p == infPixel && c < 3) {
                        // +Inf counts as the largest finite value: finite, at least the clean pixel's.
                        EXPECT_TRUE(std::isfinite(v) && v >= a[p * 4 + c]) << v;
                    } else if (p == minusInfPixel && c < 3) {
                        EXPECT_TRUE(std::isfinite(v) && v < 0.0f) << v;
                    } else if (p == negativePixel && c < 3) {
                        EXPECT_NEAR(v, reference[p * 4 + c],
                                    2e-3 * std::max(1.0f, std::abs(reference[p * 4 + c])));
                    } else {
                        ASSERT_EQ(std::memcmp(&v, &a[p * 4 + c], sizeof v), 0)
                            << "pixel " << p << " channel " << c << ": " << v << " vs clean " << a[p * 4 + c];
                    }
                }
            }
        }
    }
}

// Shadow map: an orthographic sun from above, x, z in [-100, 100] m -> [-1, 1], depth (50 - y) / 100
// (standard: lit when depth - bias <= stored).
void addShadowMap(StabilityFrame& f, uint32_t size, float stored) {
    f.images.shadowWidth = f.images.shadowHeight = size;
    f.images.shadow.assign(size_t(size) * size, stored);
    glm::dmat4 m(0.0);
    m[0][0] = 1.0 / 100.0;   // x
    m[2][1] = 1.0 / 100.0;   // z -> clip y
    m[1][2] = -1.0 / 100.0;  // y -> depth
    m[3][2] = 0.5;
    m[3][3] = 1.0;
    f.frame.shadowMap.worldToClip = m;
    f.frame.shadowMap.reversedZ = false;
    f.frame.shadowMap.depthBias = 0.0f;
    f.frame.fog.shadowKernel = 3;
}

// A 1×1 shadow map (the occluder plane y = 0 everywhere): against the reference.
TEST_F(FogStabilityInputs, OneTexelShadowMapMatchesReference) {
    StabilityFrame f = baseFrame();
    addShadowMap(f, 1, 0.5f);
    std::vector<float> gpuOut, reference;
    ASSERT_TRUE(runGpu(f, gpuOut).ok());
    ASSERT_TRUE(referenceOf(f, reference).ok());
    const Comparison cmp = compareToExpected(gpuOut, reference, f.images.colorFormat, 2e-3);
    EXPECT_EQ(cmp.nonFinite, 0u);
    EXPECT_EQ(cmp.off, 0u) << cmp.firstOff;
}

// Every texel stores exactly the depth of the camera's height, so the samples of the rows near the
// horizon compare equal (or within an ulp) to it: float on the GPU and double in the reference may
// decide differently, so each pixel must lie between the all-lit and all-shadowed frames, finite.
TEST_F(FogStabilityInputs, ShadowTexelOnTheComparisonBoundaryStaysBetweenLitAndShadowed) {
    StabilityFrame f = baseFrame();
    const float cameraDepth = float((50.0 - f.cameraPosition.y) / 100.0);
    std::vector<float> boundary, lit, shadowed;
    addShadowMap(f, 8, cameraDepth);
    ASSERT_TRUE(runGpu(f, boundary).ok());
    addShadowMap(f, 8, 1.0f);
    ASSERT_TRUE(runGpu(f, lit).ok());
    addShadowMap(f, 8, 0.0f);
    ASSERT_TRUE(runGpu(f, shadowed).ok());
    size_t different = 0;
    for (size_t k = 0; k < boundary.size(); ++k) {
        ASSERT_TRUE(std::isfinite(boundary[k])) << k;
        const float lo = std::min(lit[k], shadowed[k]), hi = std::max(lit[k], shadowed[k]);
        EXPECT_GE(boundary[k], lo - 1e-3f * std::abs(lo)) << k;
        EXPECT_LE(boundary[k], hi + 1e-3f * std::abs(hi)) << k;
        different += lit[k] != shadowed[k];
    }
    EXPECT_GT(different, boundary.size() / 4) << "the shadow map must matter in this frame";
}

}  // namespace
}  // namespace test
