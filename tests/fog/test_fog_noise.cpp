// The fog's generated noise texture (postfx/src/fog/fog_noise.h) on a real device: its texels against
// the CPU port of the generator, tiling, value statistics, and regeneration only when (size, seed)
// changes. Sizes 32 and 16 keep lavapipe fast.
#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"
#include "fog/fog_noise.h"
#include "fog/noise_cpu.h"
#include "gpu_test.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::Result;
using postfx::fog::FogNoise;

class FogNoiseTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        postfx::Status s = gpu.init(hostHandles());
        ASSERT_TRUE(s.ok()) << s.message;
        s = arena.create(gpu, 4);
        ASSERT_TRUE(s.ok()) << s.message;
    }
    void TearDown() override {
        arena.reset();
        GpuTest::TearDown();
    }

    // One submission: recordGenerate (its return value in `generated`), then a read-back of the texture.
    std::vector<uint8_t> generateAndRead(FogNoise& noise, bool* generated = nullptr) {
        std::vector<uint8_t> texels;
        if (!noise.ready() && noise.size() == 0) {
            ADD_FAILURE() << "prepare() first";
            return texels;
        }
        postfx::core::GpuBuffer readback;
        postfx::Status s = readback.create(gpu, noise.texelBytes(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                                           "noise readback");
        EXPECT_TRUE(s.ok()) << s.message;
        if (!s) return texels;
        EXPECT_TRUE(arena.beginFrame().ok());
        std::string error;
        bool recorded = false;
        postfx::Status generateStatus, readStatus;
        EXPECT_TRUE(host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                recorded = noise.recordGenerate(cmd, arena, generateStatus);
                readStatus = noise.recordReadback(cmd, readback.handle(), 0);
            },
            error))
            << error;
        EXPECT_TRUE(generateStatus.ok()) << generateStatus.message;
        EXPECT_TRUE(readStatus.ok()) << readStatus.message;
        if (generated) *generated = recorded;
        if (!readStatus) return texels;
        texels.resize(noise.texelBytes());
        std::memcpy(texels.data(), readback.mapped(), texels.size());
        return texels;
    }

    std::vector<uint8_t> generate(uint32_t size, uint32_t seed) {
        FogNoise noise;
        postfx::Status s = noise.prepare(gpu, size, seed);
        EXPECT_TRUE(s.ok()) << s.message;
        if (!s) return {};
        bool generated = false;
        std::vector<uint8_t> texels = generateAndRead(noise, &generated);
        EXPECT_TRUE(generated);
        return texels;
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
                    const float cpu = postfx::fog::noiseTexel(x, y, z, size, seed);
                    const double error = std::abs(double(gpuTexels[i]) - double(cpu) * 255.0);  // [1/255]
                    maxError = std::max(maxError, error);
                    if (error <= 1.0) ++within1;
                    if (gpuTexels[i] == uint8_t(std::floor(double(cpu) * 255.0 + 0.5))) ++exact;
                    EXPECT_LE(error, 2.0) << "texel " << x << "," << y << "," << z;
                }
        const std::vector<uint8_t> cpuTexels = postfx::fog::generateNoiseCpu(size, seed);
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
    postfx::core::DescriptorArena arena;
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
    FogNoise noise;
    EXPECT_EQ(noise.bytes(), 0u);  // nothing allocated before prepare()
    EXPECT_EQ(noise.view(), VkImageView(VK_NULL_HANDLE));
    EXPECT_EQ(noise.size(), 0u);
    EXPECT_FALSE(noise.ready());
    noise.release();  // harmless when nothing is held
    EXPECT_EQ(noise.bytes(), 0u);

    // Nothing to record before prepare().
    postfx::Status status{Result::VulkanError, "stale"};
    std::string error;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) { EXPECT_FALSE(noise.recordGenerate(cmd, arena, status)); }, error))
        << error;
    EXPECT_TRUE(status.ok());

    // A size that is not a power of two in [16, 256] is rejected, naming the field; nothing allocated.
    for (uint32_t bad : {0u, 8u, 24u, 512u}) {
        postfx::Status s = noise.prepare(gpu, bad, 1);
        EXPECT_EQ(s.code, Result::InvalidArgument) << bad;
        EXPECT_NE(s.message.find("texture_size"), std::string::npos) << s.message;
        EXPECT_EQ(noise.bytes(), 0u);
    }

    ASSERT_TRUE(noise.prepare(gpu, 32, 1).ok());
    EXPECT_GE(noise.bytes(), VkDeviceSize(32 * 32 * 32));
    EXPECT_NE(noise.view(), VkImageView(VK_NULL_HANDLE));
    EXPECT_EQ(noise.size(), 32u);
    EXPECT_EQ(noise.texelBytes(), VkDeviceSize(32 * 32 * 32));
    EXPECT_FALSE(noise.ready());  // marked, not generated yet
    bool generated = false;
    const std::vector<uint8_t> first = generateAndRead(noise, &generated);
    EXPECT_TRUE(generated);
    EXPECT_TRUE(noise.ready());
    const VkImageView view = noise.view();

    // Same (size, seed): nothing is recorded, the texture stays (a read-back still works).
    ASSERT_TRUE(noise.prepare(gpu, 32, 1).ok());
    EXPECT_TRUE(noise.ready());
    const std::vector<uint8_t> unchanged = generateAndRead(noise, &generated);
    EXPECT_FALSE(generated);
    EXPECT_EQ(unchanged, first);
    EXPECT_EQ(noise.view(), view);

    // A new seed: regenerated into the same image (after the earlier read-backs).
    ASSERT_TRUE(noise.prepare(gpu, 32, 2).ok());
    EXPECT_FALSE(noise.ready());
    EXPECT_EQ(noise.view(), view);
    const std::vector<uint8_t> second = generateAndRead(noise, &generated);
    EXPECT_TRUE(generated);
    EXPECT_NE(second, first);
    EXPECT_EQ(second, generate(32, 2));
    ASSERT_TRUE(noise.prepare(gpu, 32, 2).ok());
    generateAndRead(noise, &generated);
    EXPECT_FALSE(generated);

    // Back to the first seed: the first texture again.
    ASSERT_TRUE(noise.prepare(gpu, 32, 1).ok());
    EXPECT_EQ(generateAndRead(noise, &generated), first);
    EXPECT_TRUE(generated);

    // A new size: a new image, regenerated.
    ASSERT_TRUE(noise.prepare(gpu, 16, 1).ok());
    EXPECT_EQ(noise.size(), 16u);
    EXPECT_FALSE(noise.ready());
    const std::vector<uint8_t> small = generateAndRead(noise, &generated);
    EXPECT_TRUE(generated);
    expectMatchesCpu(small, 16, 1);

    // Generation and a second prepare+record in one command buffer: the second records nothing.
    ASSERT_TRUE(noise.prepare(gpu, 16, 9).ok());
    ASSERT_TRUE(arena.beginFrame().ok());
    bool firstRecord = false, secondRecord = true;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            firstRecord = noise.recordGenerate(cmd, arena, status);
            EXPECT_TRUE(status.ok()) << status.message;
            EXPECT_TRUE(noise.prepare(gpu, 16, 9).ok());
            secondRecord = noise.recordGenerate(cmd, arena, status);
            EXPECT_TRUE(status.ok()) << status.message;
        },
        error))
        << error;
    EXPECT_TRUE(firstRecord);
    EXPECT_FALSE(secondRecord);

    noise.release();
    EXPECT_EQ(noise.bytes(), 0u);
    EXPECT_EQ(noise.view(), VkImageView(VK_NULL_HANDLE));
    EXPECT_FALSE(noise.ready());
    // After release, prepare starts over (pipeline and image recreated, generation marked).
    ASSERT_TRUE(noise.prepare(gpu, 16, 9).ok());
    EXPECT_GT(noise.bytes(), 0u);
    EXPECT_EQ(generateAndRead(noise, &generated).size(), 16u * 16u * 16u);
    EXPECT_TRUE(generated);
}

// Generate, read back, regenerate with another seed, read back: all in one command buffer, so the
// synchronization validation checks the regeneration waits for the earlier read of the old texels.
TEST_F(FogNoiseTest, RegeneratesAfterReadsInTheSameCommandBuffer) {
    constexpr uint32_t kSize = 16;
    FogNoise noise;
    ASSERT_TRUE(noise.prepare(gpu, kSize, 11).ok());
    const VkDeviceSize bytes = noise.texelBytes();
    postfx::core::GpuBuffer readback;
    ASSERT_TRUE(readback.create(gpu, 2 * bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
    ASSERT_TRUE(arena.beginFrame().ok());
    std::string error;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            postfx::Status s;
            EXPECT_TRUE(noise.recordGenerate(cmd, arena, s));
            EXPECT_TRUE(noise.recordReadback(cmd, readback.handle(), 0).ok());
            EXPECT_TRUE(noise.prepare(gpu, kSize, 12).ok());
            EXPECT_TRUE(noise.recordGenerate(cmd, arena, s));
            EXPECT_TRUE(s.ok()) << s.message;
            EXPECT_TRUE(noise.recordReadback(cmd, readback.handle(), bytes).ok());
        },
        error))
        << error;
    const uint8_t* mapped = static_cast<const uint8_t*>(readback.mapped());
    EXPECT_EQ(std::vector<uint8_t>(mapped, mapped + bytes), postfx::fog::generateNoiseCpu(kSize, 11));
    EXPECT_EQ(std::vector<uint8_t>(mapped + bytes, mapped + 2 * bytes),
              postfx::fog::generateNoiseCpu(kSize, 12));
}

TEST_F(FogNoiseTest, ReadbackNeedsAGeneratedTexture) {
    FogNoise noise;
    postfx::core::GpuBuffer readback;
    ASSERT_TRUE(readback.create(gpu, 16 * 16 * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
    std::string error;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            EXPECT_EQ(noise.recordReadback(cmd, readback.handle(), 0).code, Result::InvalidArgument);
            EXPECT_TRUE(noise.prepare(gpu, 16, 1).ok());
            EXPECT_EQ(noise.recordReadback(cmd, readback.handle(), 0).code,
                      Result::InvalidArgument);  // marked only
        },
        error))
        << error;
}

}  // namespace
}  // namespace test
