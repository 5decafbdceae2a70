// The shadow map's depth range (docs/effects/fog.md, "Shadow-map visibility"): a floating slab over open
// ground, seen from the side, with a sun shadow map whose far plane ends between the slab and the ground,
// so the map holds the slab and no receiver below it. Fog under the slab beyond the far plane must be in
// shadow (the texel holds a caster), fog before the near plane lit. GPU against the CPU reference on the
// whole image, and both against the closed form of the shaft along the central ray.
#include "fog_harness.h"
#include "image_compare.h"

#include <postfx/reference.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace test {
namespace {

// The scene, in world metres (y up). The camera looks down -z from (100, y, 50); the sun is straight up.
constexpr uint32_t kWidth = 33, kHeight = 19;  // odd: the central pixel's ray is exactly -z
constexpr double kCameraX = 100.0, kCameraZ = 50.0;
// The slab: x ∈ [80, 120], y ∈ [9, 10], z ∈ [10, 34]; the ground: y = 0 (not in the shadow map).
constexpr glm::dvec3 kSlabLo{80.0, 9.0, 10.0}, kSlabHi{120.0, 10.0, 34.0};
// Shadow map: 64 × 256 texels over x ∈ [68.5, 132.5] (1 m texels, the camera's x at a texel centre) and
// z ∈ [-14, 50] (0.25 m rows); depth 0 at y = 12 (near plane), 1 at y = 5 (far plane).
constexpr uint32_t kMapWidth = 64, kMapHeight = 256;
constexpr double kMapX0 = 68.5, kMapZ0 = -14.0, kTexelX = 1.0, kTexelZ = 0.25;
constexpr double kNearY = 12.0, kFarY = 5.0;
// Fog march: 64 m in 256 steps of 0.25 m, so that along the central ray every step is one map row and
// the midpoint samples sit at row centres (never on a shadow edge): the march is then exact.
constexpr float kMaxDistance = 64.0f;
constexpr uint32_t kSteps = 256;

double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// World -> shadow clip: clip x = (x - 100.5)/32, clip y = (z - 18)/32, depth (12 - y)/7 (standard) or
// (y - 5)/7 (reversed), orthographic.
glm::dmat4 shadowMatrix(bool reversedZ) {
    glm::dmat4 m(0.0);
    m[0][0] = 2.0 / (kMapWidth * kTexelX);
    m[3][0] = -1.0 - kMapX0 * m[0][0];
    m[2][1] = 2.0 / (kMapHeight * kTexelZ);
    m[3][1] = -1.0 - kMapZ0 * m[2][1];
    const double range = kNearY - kFarY;
    m[1][2] = reversedZ ? 1.0 / range : -1.0 / range;
    m[3][2] = reversedZ ? -kFarY / range : kNearY / range;
    m[3][3] = 1.0;
    return m;
}

// The map as a sun-view raster of the slab alone stores it: the slab's top (y = 10) in the texels whose
// centre lies over the slab, the cleared far value elsewhere.
std::vector<float> shadowTexels(bool reversedZ) {
    const double top = (kNearY - kSlabHi.y) / (kNearY - kFarY);
    std::vector<float> texels(size_t(kMapWidth) * kMapHeight, reversedZ ? 0.0f : 1.0f);
    for (uint32_t j = 0; j < kMapHeight; ++j) {
        for (uint32_t i = 0; i < kMapWidth; ++i) {
            const double x = kMapX0 + (i + 0.5) * kTexelX, z = kMapZ0 + (j + 0.5) * kTexelZ;
            if (x > kSlabLo.x && x < kSlabHi.x && z > kSlabLo.z && z < kSlabHi.z)
                texels[size_t(j) * kMapWidth + i] = float(reversedZ ? 1.0 - top : top);
        }
    }
    return texels;
}

// Distance along `d` from `origin` to the first surface (slab or ground), +∞ for none.
double hitDistance(glm::dvec3 origin, glm::dvec3 d) {
    double t = std::numeric_limits<double>::infinity();
    if (d.y < 0.0) t = origin.y / -d.y;  // ground
    double enter = 0.0, exit = t;        // the slab, as the intersection of three pairs of planes
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (origin[a] < kSlabLo[a] || origin[a] > kSlabHi[a]) exit = -1.0;
            continue;
        }
        const double t0 = (kSlabLo[a] - origin[a]) / d[a], t1 = (kSlabHi[a] - origin[a]) / d[a];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return enter <= exit ? std::min(t, enter) : t;
}

struct RangeCase {
    double cameraY;  // 2: below the far plane (y 5); 15: above the near plane (y 12)
    bool shadowReversedZ;
    uint32_t kernel;
};

std::string caseName(const RangeCase& c) {
    return "camera" + std::to_string(int(c.cameraY)) + (c.shadowReversedZ ? "_reversed" : "_standard") +
           "_kernel" + std::to_string(c.kernel);
}

void PrintTo(const RangeCase& c, std::ostream* os) {
    *os << caseName(c);
}

struct SlabFrame {
    postfx::FrameInfo frame;
    FogHarnessImages images;
};

SlabFrame slabFrame(const RangeCase& c) {
    SlabFrame f;
    postfx::FrameInfo& frame = f.frame;
    const glm::dvec3 camera(kCameraX, c.cameraY, kCameraZ);
    frame.camera = testCamera(camera, 60.0f, float(kWidth) / float(kHeight), 0.1f, 1000.0f, true);
    frame.sun.toSun = {0.0f, 1.0f, 0.0f};
    frame.sun.illuminance = {1000.0f, 800.0f, 600.0f};
    frame.ambient = glm::vec3(0.0f);
    postfx::FogSettings& fog = frame.fog;
    fog.enabled = true;
    fog.density = 0.02f;
    fog.albedo = {0.9f, 0.6f, 0.3f};
    fog.anisotropy = 0.5f;
    fog.heightFalloff = 0.0f;  // homogeneous
    fog.maxDistance = kMaxDistance;
    fog.steps = kSteps;
    fog.jitter = false;
    fog.transmittanceCutoff = 0.0f;
    fog.analyticTail = false;
    fog.shadowKernel = c.kernel;
    frame.shadowMap.worldToClip = shadowMatrix(c.shadowReversedZ);
    frame.shadowMap.reversedZ = c.shadowReversedZ;
    frame.shadowMap.depthBias = 0.001f;

    FogHarnessImages& im = f.images;
    im.width = kWidth;
    im.height = kHeight;
    im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    im.color.assign(size_t(kWidth) * kHeight * 4, 0.0f);  // black: the output is the fog's own radiance
    im.depth.resize(size_t(kWidth) * kHeight);
    for (uint32_t j = 0; j < kHeight; ++j) {
        for (uint32_t i = 0; i < kWidth; ++i) {
            const size_t p = size_t(j) * kWidth + i;
            im.color[p * 4 + 3] = 1.0f;
            const glm::dvec3 d = pixelDirection(frame.camera, i, j, kWidth, kHeight);
            const double t = hitDistance(camera, d);
            im.depth[p] = std::isinf(t) ? 0.0f : depthAtDistance(frame.camera, d, t);  // reversed Z: 0 = sky
        }
    }
    im.shadow = shadowTexels(c.shadowReversedZ);
    im.shadowWidth = kMapWidth;
    im.shadowHeight = kMapHeight;
    return f;
}

postfx::Status reference(const SlabFrame& f, uint32_t steps, std::vector<float>& out) {
    postfx::reference::FogInputs in;
    in.width = f.images.width;
    in.height = f.images.height;
    in.color = f.images.color;
    in.depth = f.images.depth;
    in.depthConvention.reversedZ = true;
    in.camera = f.frame.camera;
    in.sun = f.frame.sun;
    in.ambient = f.frame.ambient;
    in.settings = f.frame.fog;
    in.shadowDepth = f.images.shadow;
    in.shadowWidth = f.images.shadowWidth;
    in.shadowHeight = f.images.shadowHeight;
    in.shadowWorldToClip = f.frame.shadowMap.worldToClip;
    in.shadowReversedZ = f.frame.shadowMap.reversedZ;
    in.shadowDepthBias = f.frame.shadowMap.depthBias;
    in.stepsPerPixel = steps;
    return postfx::reference::renderFog(in, out);
}

// Closed form of the central pixel's in-scattered radiance (channel c). Its ray runs along -z at the
// camera's height through homogeneous fog of extinction σ, t ∈ [0, 64] (no surface, no tail), so
//   L = ∫ T(t) σs p(θ) E V(t) dt = albedo · p(0) · E · Σ_rows V_row · (e^{-σ·t_a} - e^{-σ·t_b})
// over the map rows [t_a, t_b] the ray crosses (θ = 90° to the sun). V_row is the fraction of the
// kernel's rows whose texels hold no caster, read off the geometry: a row holds the slab when its centre
// is over [10, 34] in z. Below the far plane the slab's rows shadow (that is the rule under test); above
// the near plane (camera at y 15) nothing does. Geometric, not a reuse of either implementation.
double centralRadiance(const RangeCase& c, const postfx::FrameInfo& frame, int channel, bool shadowRule) {
    const double sigma = frame.fog.density;
    const double light = double(frame.fog.albedo[channel]) * hg(0.0, frame.fog.anisotropy) *
                         double(frame.sun.illuminance[channel]);
    const bool shadows = shadowRule && c.cameraY < kFarY;  // below the far plane, under the slab
    const int r = int(c.kernel - 1) / 2;
    auto slabRow = [](int row) {
        const double z = kMapZ0 + (row + 0.5) * kTexelZ;
        return row >= 0 && row < int(kMapHeight) && z > kSlabLo.z && z < kSlabHi.z;
    };
    double L = 0.0;
    const int rows = int(std::lround(kMaxDistance / kTexelZ));
    for (int k = 0; k < rows; ++k) {
        const double ta = k * kTexelZ, tb = ta + kTexelZ;
        // The row under t ∈ [ta, tb]: z = 50 - t, row = (z - z0)/0.25, clamped to the map like the taps.
        const int row = int(std::floor((kCameraZ - 0.5 * (ta + tb) - kMapZ0) / kTexelZ));
        int shadowed = 0;
        for (int b = -r; b <= r; ++b)
            shadowed += shadows && slabRow(std::clamp(row + b, 0, int(kMapHeight) - 1));
        const double V = 1.0 - double(shadowed) / double(2 * r + 1);
        L += light * V * (std::exp(-sigma * ta) - std::exp(-sigma * tb));
    }
    return L;
}

class FogShadowRangeTest : public GpuTest, public ::testing::WithParamInterface<RangeCase> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
    }
    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
};

// (a) The GPU against the reference on the whole image. Both march the same 256 midpoint samples (no
// jitter), so they differ by float against double only, and by a sample that lands on a shadow edge or
// the far plane in one and not the other (a few pixels at most).
TEST_P(FogShadowRangeTest, GpuMatchesReference) {
    const RangeCase& c = GetParam();
    const SlabFrame f = slabFrame(c);
    std::vector<float> gpuOut, referenceOut;
    FogHarness harness(*host, gpu);
    const postfx::Status s = harness.run(*context, f.images, f.frame, gpuOut);
    ASSERT_TRUE(s.ok()) << s.message;
    const postfx::Status r = reference(f, kSteps, referenceOut);
    ASSERT_TRUE(r.ok()) << r.message;
    const ImageStats stats = compareImages(gpuOut, referenceOut, kWidth, kHeight, 1e-3, 1.0);
    std::printf("[ fog ] shadow range %s: GPU vs reference %s\n", caseName(c).c_str(),
                stats.summary().c_str());
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_LT(stats.relativeRmse, 1e-3) << stats.summary();
    EXPECT_LT(stats.fractionOff, 0.02) << stats.summary();
}

// (b) The central ray's shaft against its closed form: the GPU to float precision (RGBA32F, exact march),
// the reference (4096 steps, also aligned to the rows) to double. (c) The shaft matters: fog under the
// slab counted as lit (the rule before the fix, which lit every sample beyond the far plane) would be off
// by far more than the tolerance.
TEST_P(FogShadowRangeTest, CentralShaftMatchesClosedForm) {
    const RangeCase& c = GetParam();
    const SlabFrame f = slabFrame(c);
    std::vector<float> gpuOut, referenceOut;
    FogHarness harness(*host, gpu);
    const postfx::Status s = harness.run(*context, f.images, f.frame, gpuOut);
    ASSERT_TRUE(s.ok()) << s.message;
    const postfx::Status r = reference(f, 4096, referenceOut);
    ASSERT_TRUE(r.ok()) << r.message;
    const size_t p = (size_t(kHeight / 2) * kWidth + kWidth / 2) * 4;
    ASSERT_EQ(f.images.depth[p / 4], 0.0f) << "the central ray must see no surface";
    constexpr double kGpuTolerance = 1e-4, kReferenceTolerance = 1e-6;  // relative
    for (int ch = 0; ch < 3; ++ch) {
        const double expected = centralRadiance(c, f.frame, ch, true);
        const double allLit = centralRadiance(c, f.frame, ch, false);
        std::printf(
            "[ fog ] shadow range %s channel %d: closed form %.7g (all lit %.7g), GPU %.7g, "
            "reference %.7g\n",
            caseName(c).c_str(), ch, expected, allLit, gpuOut[p + ch], referenceOut[p + ch]);
        EXPECT_NEAR(gpuOut[p + ch], expected, kGpuTolerance * expected) << "channel " << ch;
        EXPECT_NEAR(referenceOut[p + ch], expected, kReferenceTolerance * expected) << "channel " << ch;
        if (c.cameraY < kFarY) {
            EXPECT_GT(allLit - expected, 100.0 * kGpuTolerance * expected);
        }
    }
    EXPECT_EQ(gpuOut[p + 3], 1.0f);
}

// (d) The march's pipeline is specialized for each frame's flags and kernel (fog_shared.h,
// kFogConstant*), and for an orthographic map skips the divide by clip w. The same map as a projective
// matrix (every row × 2: clip w = 2, the divide taken, exact in float) gives the same bits; and frames
// that switch the kernel and the shadow map's convention in one context give each what a fresh context
// gives (each frame gets its own specialization, none another's).
TEST_P(FogShadowRangeTest, SpecializationsAgree) {
    const RangeCase& c = GetParam();
    const SlabFrame f = slabFrame(c);
    FogHarness harness(*host, gpu);
    std::vector<float> first, projective, switched, again;
    postfx::Status s = harness.run(*context, f.images, f.frame, first);
    ASSERT_TRUE(s.ok()) << s.message;

    SlabFrame scaled = f;
    scaled.frame.shadowMap.worldToClip = 2.0 * f.frame.shadowMap.worldToClip;
    ASSERT_TRUE((s = harness.run(*context, scaled.images, scaled.frame, projective)).ok()) << s.message;
    EXPECT_EQ(projective, first) << "the projective matrix's march differs from the orthographic one's";

    // Another kernel and the other depth convention (its own texels), then the first frame again.
    const SlabFrame other = slabFrame({c.cameraY, !c.shadowReversedZ, c.kernel == 1 ? 3u : 1u});
    ASSERT_TRUE((s = harness.run(*context, other.images, other.frame, switched)).ok()) << s.message;
    ASSERT_TRUE((s = harness.run(*context, f.images, f.frame, again)).ok()) << s.message;
    EXPECT_EQ(again, first) << "the first frame's settings again, in the same context";

    std::unique_ptr<postfx::Context> fresh;
    postfx::ContextCreateInfo info;
    info.depth.reversedZ = true;
    ASSERT_TRUE(createContext(fresh, info).ok());
    std::vector<float> freshSwitched;
    ASSERT_TRUE((s = harness.run(*fresh, other.images, other.frame, freshSwitched)).ok()) << s.message;
    EXPECT_EQ(switched, freshSwitched) << "the switched frame against a fresh context's";
    EXPECT_NE(switched, first);
}

INSTANTIATE_TEST_SUITE_P(Slab, FogShadowRangeTest,
                         ::testing::Values(RangeCase{2.0, false, 1}, RangeCase{2.0, true, 1},
                                           RangeCase{2.0, false, 3}, RangeCase{2.0, true, 3},
                                           RangeCase{15.0, false, 1}, RangeCase{15.0, true, 3}),
                         [](const auto& info) { return caseName(info.param); });

}  // namespace
}  // namespace test
