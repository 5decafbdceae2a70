// The ray-marched fog's temporal accumulation (docs/effects/fog.md#temporal) on the device: a still
// camera converges toward the reference, a camera cut starts over, history exists only with temporal on.
#include "fog_harness.h"
#include "gpu_test.h"
#include "host/renderer.h"
#include "image_compare.h"
#include "scene/scene.h"

#include <postfx/frame_plan.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace test {
namespace {

const std::string kSourceDir = POSTFX_SOURCE_DIR;

class FogTemporalTest : public GpuTest {
protected:
    demo::Scene load(const std::string& name) {
        demo::Scene scene;
        std::string error;
        EXPECT_TRUE(demo::loadSceneFile(kSourceDir + "/demo/scenes/" + name, scene, error)) << error;
        return scene;
    }
    std::unique_ptr<demo::Renderer> renderer(uint32_t frames) {
        demo::RenderOptions o;
        o.width = 64;
        o.height = 36;
        o.shadowMapSize = 1024;
        o.frames = frames;
        o.fixedTimeSeconds = 0.0;  // still medium: frames differ only in their jitter
        std::string error;
        auto r = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(r) << error;
        return r;
    }
    // The fog reference (1024 steps) of the last frame `r` renders.
    demo::ImageF reference(demo::Renderer& r, const demo::Scene& scene) {
        demo::ImageF image;
        std::string message;
        EXPECT_TRUE(r.renderReference(scene, image, message, 1024)) << message;
        return image;
    }
    double error(demo::Renderer& r, const demo::Scene& scene, const demo::ImageF& reference) {
        demo::ImageF image;
        std::string message;
        EXPECT_TRUE(r.render(scene, image, message)) << message;
        const ImageStats s = compareImages(image.rgba, reference.rgba, image.width, image.height, 0.05, 1.0);
        EXPECT_EQ(s.nonFinite, 0u);
        return s.relativeRmse;
    }
};

// At full and at half resolution (where each texel's ray is not at the texel's centre: a still view must
// still read each texel's own history, not blur it).
TEST_F(FogTemporalTest, StillCameraConvergesTowardTheReference) {
    for (float scale : {1.0f, 0.5f}) {
        demo::Scene scene = load("fog_shadowed.json");
        scene.fog.steps = 8;  // few steps: a single frame's jitter noise dominates its error
        scene.fog.resolutionScale = scale;
        auto one = renderer(1);
        auto many = renderer(32);
        ASSERT_TRUE(one && many);
        const demo::ImageF reference = this->reference(*one, scene);
        const double single = error(*one, scene, reference);
        scene.fog.temporal.enabled = true;
        const double accumulated = error(*many, scene, reference);
        scene.fog.temporal.enabled = false;
        const double still = error(*many, scene, reference);
        std::printf(
            "[ fog ] temporal, still camera, scale %g: 1 frame %.3g%%, 32 frames accumulated %.3g%%, "
            "frame 32 alone %.3g%%\n",
            scale, single * 100, accumulated * 100, still * 100);
        // Measured on lavapipe: scale 1: 3.9% after 32 frames, 24% for one frame.
        EXPECT_LT(accumulated, 6e-2) << "scale " << scale;
        EXPECT_LT(accumulated, 0.3 * still) << "scale " << scale;
    }
}

// In motion (walking forward and turning fast enough that the view moves about two texels per frame),
// every texel's history comes from other texels: the accumulation must still beat the frame alone
// (fog.md#temporal: the estimate is then the depth- and fog-aware mean of the texel's neighbours).
TEST_F(FogTemporalTest, MovingCameraStillAccumulates) {
    demo::Scene scene = load("fog_default.json");
    scene.fog.steps = 8;
    glm::vec3 forward = scene.camera.lookAt - scene.camera.position;
    forward.y = 0.0f;
    scene.camera.velocity = 3.0f * glm::normalize(forward);
    scene.camera.yawRateDeg = 120.0f;  // 2° per frame, about two texels at 64×36
    auto one = renderer(16);
    auto many = renderer(16);
    ASSERT_TRUE(one && many);
    const demo::ImageF reference = this->reference(*one, scene);
    const double alone = error(*one, scene, reference);
    scene.fog.temporal.enabled = true;
    const double accumulated = error(*many, scene, reference);
    std::printf("[ fog ] temporal, moving camera: frame 15 alone %.3g%%, accumulated %.3g%%\n", alone * 100,
                accumulated * 100);
    // Measured on lavapipe: 6.97% alone, 2.6% accumulated.
    EXPECT_LT(accumulated, 0.6 * alone);
}

// Frame by frame on the fog harness: one context that accumulates, and one that shows each frame alone
// through the same passes (temporal on, a camera cut every frame; the same jitter: the frame index).
class FogTemporalFrames : public GpuTest {
protected:
    static constexpr uint32_t kW = 32, kH = 18;
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(accumulating, info).ok());
        ASSERT_TRUE(createContext(alone, info).ok());
        frame.camera = testCamera({0.0, 1.0, 0.0}, 60.0f, float(kW) / float(kH), 0.1f, 1000.0f, true);
        frame.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
        frame.sun.illuminance = glm::vec3(2000.0f);
        frame.ambient = glm::vec3(50.0f);
        postfx::FogSettings& f = frame.fog;
        f.enabled = true;
        f.density = 0.05f;
        f.heightFalloff = 0.3f;  // not homogeneous: each jittered frame's march differs
        f.maxDistance = 60.0f;
        f.steps = 4;  // few steps: each jittered frame differs visibly
        f.temporal.enabled = true;
        images.width = kW;
        images.height = kH;
        images.color.assign(size_t(kW) * kH * 4, 0.5f);
        setWall(20.0);
    }
    // Every pixel sees a wall at `distance` metres; columns [first, last) see an object at `near`.
    void setWall(double distance, uint32_t first = 0, uint32_t last = 0, double near = 0.0) {
        images.depth.resize(size_t(kW) * kH);
        for (uint32_t j = 0; j < kH; ++j)
            for (uint32_t i = 0; i < kW; ++i) {
                const glm::dvec3 d = pixelDirection(frame.camera, i, j, kW, kH);
                images.depth[size_t(j) * kW + i] =
                    depthAtDistance(frame.camera, d, i >= first && i < last ? near : distance);
            }
    }
    std::vector<float> render(postfx::Context& context, uint64_t frameIndex, bool temporal,
                              bool cut = false) {
        postfx::FrameInfo f = frame;
        f.frameIndex = frameIndex;
        f.cameraCut = cut;
        f.fog.temporal.enabled = temporal;
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(context, images, f, out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
    // Σ|a - b| over RGB of the columns [first, last).
    static double sumDifference(const std::vector<float>& a, const std::vector<float>& b, uint32_t first = 0,
                                uint32_t last = kW) {
        double sum = 0.0;
        for (uint32_t j = 0; j < kH; ++j)
            for (uint32_t i = first; i < last; ++i)
                for (int c = 0; c < 3; ++c) {
                    const size_t k = (size_t(j) * kW + i) * 4 + c;
                    sum += std::abs(double(a[k]) - double(b[k]));
                }
        return sum;
    }
    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> accumulating, alone;
    postfx::FrameInfo frame;
    FogHarnessImages images;
};

TEST_F(FogTemporalFrames, AccumulatedFramesDifferFromSingleOnesAndCameraCutResetsAtOnce) {
    std::vector<float> a, b;
    for (uint64_t n = 0; n < 6; ++n)
        a = render(*accumulating, n, true);
    b = render(*alone, 5, true, true);
    EXPECT_GT(sumDifference(a, b), 1e-3 * sumDifference(b, std::vector<float>(b.size(), 0.0f)));
    a = render(*accumulating, 6, true, true);  // the cut: this frame alone, exactly
    b = render(*alone, 6, true, true);
    EXPECT_EQ(sumDifference(a, b), 0.0);
}

// An object 3 m in front of the camera over columns [8, 16) moves away: the wall behind it (20 m) is
// disoccluded. Its pixels take the new frame alone at once (documented: no trail, 0 frames), while the
// rest of the image keeps its history.
TEST_F(FogTemporalFrames, DisocclusionLeavesNoTrail) {
    setWall(20.0, 8, 16, 3.0);
    for (uint64_t n = 0; n < 8; ++n)
        render(*accumulating, n, true);
    setWall(20.0);
    const std::vector<float> a = render(*accumulating, 8, true);
    const std::vector<float> b = render(*alone, 8, true, true);
    EXPECT_EQ(sumDifference(a, b, 8, 16), 0.0);
    EXPECT_GT(sumDifference(a, b, 16, kW), 0.0);  // elsewhere the history was kept
}

// A host's NaN depth in one frame: the frames after it are finite everywhere, and those pixels start
// over from the new frame.
TEST_F(FogTemporalFrames, NanInOneFrameDoesNotStayInTheHistory) {
    for (uint64_t n = 0; n < 4; ++n)
        render(*accumulating, n, true);
    for (uint32_t j = 0; j < kH; ++j)
        for (uint32_t i = 4; i < 12; ++i)
            images.depth[size_t(j) * kW + i] = std::numeric_limits<float>::quiet_NaN();
    render(*accumulating, 4, true);
    setWall(20.0);
    for (uint64_t n = 5; n < 8; ++n) {
        const std::vector<float> a = render(*accumulating, n, true);
        for (float v : a)
            ASSERT_TRUE(std::isfinite(v)) << "frame " << n;
        if (n == 5) {
            const std::vector<float> b = render(*alone, n, true, true);
            EXPECT_EQ(sumDifference(a, b, 4, 12), 0.0);
        }
    }
}

TEST_F(FogTemporalFrames, HistoryIsHeldOnlyWithTemporalOn) {
    // The plan of each frame as record() gets it (with its images).
    auto planOf = [&](const postfx::FrameInfo& f, uint64_t frameIndex) {
        postfx::FramePlan plan;
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& g) {
            EXPECT_TRUE(accumulating->plan(g, plan).ok());
        };
        postfx::FrameInfo g = f;
        g.frameIndex = frameIndex;
        std::vector<float> out;
        EXPECT_TRUE(harness.run(*accumulating, images, g, out).ok());
        return plan;
    };
    auto names = [](const postfx::FramePlan& plan, bool history) {
        std::vector<std::string> out;
        if (history) {
            for (const postfx::PlannedResource& r : plan.resources)
                if (r.history) out.push_back(r.name);
        } else {
            for (const postfx::PlannedPass& p : plan.passes)
                out.push_back(p.name);
        }
        return out;
    };
    postfx::FrameInfo f = frame;
    postfx::FramePlan plan = planOf(f, 0);
    EXPECT_EQ(names(plan, true), (std::vector<std::string>{"fog.history_a", "fog.history_distance_a",
                                                           "fog.history_b", "fog.history_distance_b"}));
    EXPECT_EQ(names(plan, false), (std::vector<std::string>{"fog.raymarch", "fog.temporal"}));
    // 32×18: RGBA32F histories and R32F distances.
    const postfx::PlannedPass* temporal = plan.pass("fog.temporal");
    ASSERT_TRUE(temporal);
    EXPECT_EQ(temporal->writes, (std::vector<std::string>{"fog.history_a", "host.color"}));  // composites
    // The march stores this frame's ray-end distances, which the temporal pass filters by.
    EXPECT_EQ(plan.pass("fog.raymarch")->writes,
              (std::vector<std::string>{"fog.scatter", "fog.history_distance_a"}));
    plan = planOf(f, 1);
    EXPECT_EQ(plan.pass("fog.temporal")->writes, (std::vector<std::string>{"fog.history_b", "host.color"}));
    EXPECT_EQ(plan.pass("fog.raymarch")->writes,
              (std::vector<std::string>{"fog.scatter", "fog.history_distance_b"}));
    uint64_t historyBytes = 0;
    for (const postfx::PlannedResource& r : plan.resources)
        if (r.history) historyBytes += r.bytes;
    EXPECT_EQ(historyBytes, 2u * kW * kH * (16 + 4));
    f.fog.resolutionScale = 0.5f;
    EXPECT_EQ(names(planOf(f, 2), false),
              (std::vector<std::string>{"fog.raymarch", "fog.temporal", "fog.upsample"}));
    f.fog.temporal.enabled = false;
    plan = planOf(f, 3);
    EXPECT_TRUE(names(plan, true).empty());
    EXPECT_EQ(names(plan, false), (std::vector<std::string>{"fog.raymarch", "fog.upsample"}));
    f.fog.resolutionScale = 1.0f;
    EXPECT_EQ(names(planOf(f, 4), false), (std::vector<std::string>{"fog.raymarch"}));
}

}  // namespace
}  // namespace test
