// The stability suite's temporal cases (docs/stability.md, "Temporal"), for both fogs: the camera
// teleports or turns 180° in one frame, the frame index wraps (2^32 and 2^64). Asserts: every frame
// finite; a frame whose history does not belong (teleport, turn) is exactly that frame alone; the
// accumulation goes on across the wraps.
#include "froxel_case.h"
#include "gpu_test.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace test {
namespace {

enum class Fog { RayMarched, Froxel };
enum class Event { Teleport, Turn180, IndexWraps32, IndexWraps64 };

struct TemporalCase {
    Fog fog;
    Event event;
};

void PrintTo(const TemporalCase& c, std::ostream* os) {
    *os << (c.fog == Fog::Froxel ? "froxel fog, " : "ray-marched fog, ")
        << (c.event == Event::Teleport       ? "teleport"
            : c.event == Event::Turn180      ? "180 degree turn"
            : c.event == Event::IndexWraps32 ? "frame index past 2^32"
                                             : "frame index up to 2^64 - 1");
}

std::string caseName(const ::testing::TestParamInfo<TemporalCase>& info) {
    static const char* const events[] = {"Teleport", "Turn180", "IndexWraps32", "IndexWraps64"};
    return std::string(info.param.fog == Fog::Froxel ? "Froxel" : "RayMarched") +
           events[int(info.param.event)];
}

class FroxelFogTemporalStability : public GpuTest, public ::testing::WithParamInterface<TemporalCase> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(accumulating, info).ok());
        ASSERT_TRUE(createContext(alone, info).ok());
        // A wall at 20 m on the left half, sky on the right; sun and ambient light; jittered.
        base = froxelCase(32, 18, 1.0, 16, 20.0);
        base.frame.sun.illuminance = glm::vec3(2000.0f);
        base.frame.ambient = glm::vec3(50.0f);
        postfx::FrameInfo& f = base.frame;
        f.froxelFog.jitter = true;
        f.froxelFog.grid = {8, 6, 16};
        f.froxelFog.heightFalloff = 0.3f;  // each jittered frame differs
        f.froxelFog.anisotropy = 0.6f;
        if (GetParam().fog == Fog::RayMarched) {
            static_cast<postfx::FogMedium&>(f.fog) = f.froxelFog;
            f.froxelFog.enabled = false;
            f.fog.enabled = true;
            f.fog.steps = 4;
        }
    }
    // `alone`: the frame by itself through the same passes (temporal on, a camera cut).
    std::vector<float> render(postfx::Context& context, const FroxelCase& c, uint64_t frameIndex,
                              bool alone) {
        postfx::FrameInfo frame = c.prepared();
        frame.frameIndex = frameIndex;
        frame.fog.temporal.enabled = frame.fog.enabled;
        frame.froxelFog.temporal.enabled = frame.froxelFog.enabled;
        frame.cameraCut = alone;
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(context, c.images, frame, out);
        EXPECT_TRUE(s.ok()) << s.message;
        for (float v : out)
            EXPECT_TRUE(std::isfinite(v)) << "frame " << frameIndex;
        return out;
    }
    static double sumDifference(const std::vector<float>& a, const std::vector<float>& b) {
        double sum = 0.0;
        for (size_t i = 0; i < a.size(); ++i)
            if (i % 4 != 3) sum += std::abs(double(a[i]) - double(b[i]));
        return sum;
    }
    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> accumulating, alone;
    FroxelCase base;
};

TEST_P(FroxelFogTemporalStability, EveryFrameFiniteAndHistoryThatDoesNotBelongIsDropped) {
    const TemporalCase& c = GetParam();
    uint64_t first = 0;
    if (c.event == Event::IndexWraps32) first = (uint64_t(1) << 32) - 4;
    if (c.event == Event::IndexWraps64) first = ~uint64_t(0) - 7;
    for (uint64_t n = first; n < first + 4; ++n)
        render(*accumulating, base, n, false);
    const uint64_t next = first + 4;  // past the wrap of the 32-bit index the shaders see, or 2^64 - 4
    FroxelCase moved = base;
    if (c.event == Event::Teleport) {
        moved.frame.camera.position += glm::dvec3(1e5, 0.0, -3e4);
    } else if (c.event == Event::Turn180) {
        moved.frame.camera.view =
            glm::rotate(glm::mat4(1.0f), glm::pi<float>(), glm::vec3(0.0f, 1.0f, 0.0f)) *
            base.frame.camera.view;
    } else {
        // The accumulation goes on: frames after the wrap still blend (differ from the frame alone).
        std::vector<float> a;
        for (uint64_t n = next; n < next + 3; ++n)
            a = render(*accumulating, base, n, false);
        const std::vector<float> b = render(*alone, base, next + 2, true);
        EXPECT_GT(sumDifference(a, b), 0.0);
        return;
    }
    // No history belongs to the new view: the frame is the same whatever history the context held. The
    // other context accumulated other frames (other jitter offsets, so another history) before the same
    // move. (Not compared with a camera cut: the ray-marched fog takes the filtered estimate where a
    // texel has come into view, its own march after a cut; fog.md#temporal.)
    for (uint64_t n = first + 100; n < first + 104; ++n)
        render(*alone, base, n, false);
    const std::vector<float> a = render(*accumulating, moved, next, false);
    const std::vector<float> b = render(*alone, moved, next, false);
    EXPECT_EQ(sumDifference(a, b), 0.0);
    render(*accumulating, moved, next + 1, false);  // and on from there
}

INSTANTIATE_TEST_SUITE_P(Cases, FroxelFogTemporalStability,
                         ::testing::Values(TemporalCase{Fog::RayMarched, Event::Teleport},
                                           TemporalCase{Fog::RayMarched, Event::Turn180},
                                           TemporalCase{Fog::RayMarched, Event::IndexWraps32},
                                           TemporalCase{Fog::RayMarched, Event::IndexWraps64},
                                           TemporalCase{Fog::Froxel, Event::Teleport},
                                           TemporalCase{Fog::Froxel, Event::Turn180},
                                           TemporalCase{Fog::Froxel, Event::IndexWraps32},
                                           TemporalCase{Fog::Froxel, Event::IndexWraps64}),
                         caseName);

}  // namespace
}  // namespace test
