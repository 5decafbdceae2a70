// The fog's generated noise texture on a real device, through the context (the fog declares it as a
// persistent image built by fog.noise): its texels against the CPU port of the generator, tiling, value
// statistics, and regeneration only when (size, seed) changes. Sizes 32 and 16 keep lavapipe fast.
#include "common/noise_cpu.h"
#include "fog_harness.h"
#include "gpu_test.h"

#include <postfx/postfx.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::Result;

class FogNoiseTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        postfx::Status s = gpu.init(hostHandles());
        ASSERT_TRUE(s.ok()) << s.message;
        // A wall 20 m away over a small image: the fog samples the noise, so the texture is needed.
        images.width = 8;
        images.height = 4;
        images.color.assign(size_t(images.width) * images.height * 4, 1.0f);
        frame.camera = testCamera({0.0, 1.0, 0.0}, 60.0f, 2.0f, 0.1f, 1000.0f, true);
        for (uint32_t j = 0; j < images.height; ++j)
            for (uint32_t i = 0; i < images.width; ++i)
                images.depth.push_back(depthAtDistance(
                    frame.camera, pixelDirection(frame.camera, i, j, images.width, images.height), 20.0));
        frame.fog.enabled = true;
        frame.fog.steps = 2;
        frame.fog.noise.enabled = true;
    }

    // Records one fog frame with noise (size, seed) through `context`; returns whether its plan (and so
    // the recorded passes) generated the texture. `beforeRecord` runs in the frame's command buffer
    // just before record().
    bool render(postfx::Context& context, uint32_t size, uint32_t seed, uint64_t frameIndex,
                const std::function<void(VkCommandBuffer)>& beforeRecord = {}) {
        postfx::FrameInfo f = frame;
        f.frameIndex = frameIndex;
        f.fog.noise.textureSize = size;
        f.fog.noise.seed = seed;
        postfx::FramePlan plan;
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& recorded) {
            EXPECT_TRUE(context.plan(recorded, plan).ok());
            if (beforeRecord) beforeRecord(recorded.commandBuffer);
        };
        std::vector<float> color;
        const postfx::Status s = harness.run(context, images, f, color);
        EXPECT_TRUE(s.ok()) << s.message;
        return plan.pass("fog.noise") != nullptr;
    }

    // The context's noise texture, read back in a submission of its own.
    std::vector<uint8_t> read(const postfx::Context& context) {
        std::vector<uint8_t> texels;
        const VkImageView view = postfx::fogNoiseView(context);
        EXPECT_NE(view, VkImageView(VK_NULL_HANDLE));
        postfx::core::GpuBuffer readback;
        EXPECT_TRUE(
            readback.create(gpu, 256 * 256 * 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
        uint32_t size = 0;
        postfx::Status s;
        std::string error;
        EXPECT_TRUE(host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                s = postfx::recordFogNoiseReadback(context, cmd, readback.handle(), 0, size);
            },
            error))
            << error;
        EXPECT_TRUE(s.ok()) << s.message;
        if (!s) return texels;
        const uint8_t* mapped = static_cast<const uint8_t*>(readback.mapped());
        texels.assign(mapped, mapped + size_t(size) * size * size);
        return texels;
    }

    // A fresh context's texture for (size, seed).
    std::vector<uint8_t> generate(uint32_t size, uint32_t seed) {
        std::unique_ptr<postfx::Context> context;
        const postfx::Status s = createContext(context);
        EXPECT_TRUE(s.ok()) << s.message;
        if (!context) return {};
        EXPECT_TRUE(render(*context, size, seed, 0));
        return read(*context);
    }

    // GPU texels against the CPU port's unquantized values.
    void expectMatchesCpu(const std::vector<uint8_t>& gpuTexels, uint32_t size, uint32_t seed) {
        ASSERT_EQ(gpuTexels.size(), size_t(size) * size * size);
        size_t within1 = 0, exact = 0;
        double maxError = 0.0;
        size_t i = 0;
        for (uint32_t z = 0; z < size; ++z)
            for (uint32_t y = 0; y < size; ++y)
                for (uint32_t x = 0; x < size; ++x, ++i) {
                    const float cpu = postfx::common::noiseTexel(x, y, z, size, seed);
                    const double error = std::abs(double(gpuTexels[i]) - double(cpu) * 255.0);  // [1/255]
                    maxError = std::max(maxError, error);
                    if (error <= 1.0) ++within1;
                    if (gpuTexels[i] == uint8_t(std::floor(double(cpu) * 255.0 + 0.5))) ++exact;
                    EXPECT_LE(error, 2.0) << "texel " << x << "," << y << "," << z;
                }
        const std::vector<uint8_t> cpuTexels = postfx::common::generateNoiseCpu(size, seed);
        size_t sameBytes = 0;
        for (size_t j = 0; j < cpuTexels.size(); ++j)
            sameBytes += cpuTexels[j] == gpuTexels[j];
        EXPECT_EQ(sameBytes, exact);  // generateNoiseCpu quantizes like R8_UNORM (round to nearest)
        const double n = double(gpuTexels.size());
        std::printf(
            "[ noise ] size %u seed %u: %.4f%% within 1/255, %.4f%% identical bytes, max error %.3f/255\n",
            size, seed, 100.0 * within1 / n, 100.0 * exact / n, maxError);
        EXPECT_GE(double(within1) / n, 0.999);
    }

    postfx::core::Gpu gpu;
    FogHarnessImages images;
    postfx::FrameInfo frame;
};

double mean(const std::vector<uint8_t>& t) {
    double s = 0.0;
    for (uint8_t v : t)
        s += v / 255.0;
    return s / double(t.size());
}

double standardDeviation(const std::vector<uint8_t>& t) {
    const double m = mean(t);
    double s = 0.0;
    for (uint8_t v : t)
        s += (v / 255.0 - m) * (v / 255.0 - m);
    return std::sqrt(s / double(t.size()));
}

TEST_F(FogNoiseTest, GpuTexelsMatchTheCpuPort) {
    expectMatchesCpu(generate(32, 7), 32, 7);
    expectMatchesCpu(generate(16, 123456789), 16, 123456789);
}

// REPEAT sampling shows no seam: neighbours across the wrap differ no more than neighbours inside.
TEST_F(FogNoiseTest, TextureTiles) {
    constexpr uint32_t kSize = 32;
    const std::vector<uint8_t> t = generate(kSize, 3);
    ASSERT_EQ(t.size(), size_t(kSize) * kSize * kSize);
    auto at = [&](uint32_t x, uint32_t y, uint32_t z) {
        return double(t[(z * kSize + y) * kSize + x]) / 255.0;
    };
    for (int axis = 0; axis < 3; ++axis) {
        double inside = 0.0, across = 0.0;
        size_t insideCount = 0, acrossCount = 0;
        for (uint32_t a = 0; a < kSize; ++a)
            for (uint32_t b = 0; b < kSize; ++b)
                for (uint32_t i = 0; i < kSize; ++i) {
                    const uint32_t j = (i + 1) % kSize;  // neighbour along `axis`, wrapping
                    const double d = axis == 0   ? std::abs(at(i, a, b) - at(j, a, b))
                                     : axis == 1 ? std::abs(at(a, i, b) - at(a, j, b))
                                                 : std::abs(at(a, b, i) - at(a, b, j));
                    if (j == 0) {
                        across += d;
                        ++acrossCount;
                    } else {
                        inside += d;
                        ++insideCount;
                    }
                }
        inside /= double(insideCount);
        across /= double(acrossCount);
        std::printf(
            "[ noise ] axis %d: mean |neighbour difference| inside %.5f, across the wrap %.5f (ratio %.3f)\n",
            axis, inside, across, across / inside);
        EXPECT_GT(inside, 0.0);
        EXPECT_LE(across, 1.5 * inside) << "axis " << axis;
    }
}

TEST_F(FogNoiseTest, ValuesUseTheRangeAndFollowTheSeed) {
    const std::vector<uint8_t> a = generate(32, 5);
    const std::vector<uint8_t> b = generate(32, 6);
    const std::vector<uint8_t> again = generate(32, 5);
    ASSERT_EQ(a.size(), 32u * 32u * 32u);
    ASSERT_EQ(b.size(), a.size());
    for (const auto* t : {&a, &b}) {
        const double m = mean(*t), sd = standardDeviation(*t);
        std::printf("[ noise ] size 32 seed %d: mean %.4f, std %.4f\n", t == &a ? 5 : 6, m, sd);
        EXPECT_GE(m, 0.3);
        EXPECT_LE(m, 0.7);
        EXPECT_GT(sd, 0.08);
    }
    EXPECT_EQ(a, again);  // same seed: identical texture
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i)
        differing += a[i] != b[i];
    std::printf("[ noise ] seeds 5 and 6: %.2f%% of texels differ\n", 100.0 * differing / a.size());
    EXPECT_GT(differing, a.size() / 2);  // another seed: another texture
}

TEST_F(FogNoiseTest, GeneratesOnlyWhenSizeOrSeedChanges) {
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context).ok());
    EXPECT_EQ(postfx::fogNoiseView(*context), VkImageView(VK_NULL_HANDLE));  // nothing before a frame

    // A size that is not a power of two in [16, 256] is rejected, naming the field; nothing is held.
    for (uint32_t bad : {0u, 8u, 24u, 512u}) {
        postfx::FrameInfo f = frame;
        f.fog.noise.textureSize = bad;
        std::vector<float> color;
        const postfx::Status s = FogHarness(*host, gpu).run(*context, images, f, color);
        EXPECT_EQ(s.code, Result::InvalidArgument) << bad;
        EXPECT_NE(s.message.find("FrameInfo.fog.noise.textureSize"), std::string::npos) << s.message;
    }
    EXPECT_EQ(postfx::fogNoiseView(*context), VkImageView(VK_NULL_HANDLE));

    uint64_t frameIndex = 0;
    EXPECT_TRUE(render(*context, 32, 1, frameIndex++));
    const std::vector<uint8_t> first = read(*context);
    const VkImageView view = postfx::fogNoiseView(*context);

    // Same (size, seed): nothing is recorded, the texture stays.
    EXPECT_FALSE(render(*context, 32, 1, frameIndex++));
    EXPECT_EQ(read(*context), first);
    EXPECT_EQ(postfx::fogNoiseView(*context), view);

    // A new seed: regenerated into the same image.
    EXPECT_TRUE(render(*context, 32, 2, frameIndex++));
    EXPECT_EQ(postfx::fogNoiseView(*context), view);
    const std::vector<uint8_t> second = read(*context);
    EXPECT_NE(second, first);
    EXPECT_EQ(second, generate(32, 2));
    EXPECT_FALSE(render(*context, 32, 2, frameIndex++));

    // Back to the first seed: the first texture again.
    EXPECT_TRUE(render(*context, 32, 1, frameIndex++));
    EXPECT_EQ(read(*context), first);

    // A new size: a new image, regenerated.
    EXPECT_TRUE(render(*context, 16, 1, frameIndex++));
    expectMatchesCpu(read(*context), 16, 1);
}

// Generate, then in one command buffer read back and regenerate with another seed, so the
// synchronization validation checks that the regeneration waits for the earlier read of the old texels.
TEST_F(FogNoiseTest, RegeneratesAfterReadsInTheSameCommandBuffer) {
    constexpr uint32_t kSize = 16;
    const VkDeviceSize bytes = kSize * kSize * kSize;
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context).ok());
    ASSERT_TRUE(render(*context, kSize, 11, 0));
    postfx::core::GpuBuffer readback;
    ASSERT_TRUE(readback.create(gpu, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
    postfx::Status readStatus;
    EXPECT_TRUE(render(*context, kSize, 12, 1, [&](VkCommandBuffer cmd) {
        uint32_t size = 0;
        readStatus = postfx::recordFogNoiseReadback(*context, cmd, readback.handle(), 0, size);
    }));
    EXPECT_TRUE(readStatus.ok()) << readStatus.message;
    const uint8_t* mapped = static_cast<const uint8_t*>(readback.mapped());
    EXPECT_EQ(std::vector<uint8_t>(mapped, mapped + bytes), postfx::common::generateNoiseCpu(kSize, 11));
    EXPECT_EQ(read(*context), postfx::common::generateNoiseCpu(kSize, 12));
}

TEST_F(FogNoiseTest, ReadbackNeedsAGeneratedTexture) {
    std::unique_ptr<postfx::Context> context;
    ASSERT_TRUE(createContext(context).ok());
    postfx::core::GpuBuffer readback;
    ASSERT_TRUE(readback.create(gpu, 16 * 16 * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
    std::string error;
    uint32_t size = 0;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            EXPECT_EQ(postfx::recordFogNoiseReadback(*context, cmd, readback.handle(), 0, size).code,
                      Result::InvalidArgument);
        },
        error))
        << error;
}

}  // namespace
}  // namespace test
