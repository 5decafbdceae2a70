// Color targets other than a storage RGBA16F/RGBA32F image (core/target.h): an 8-bit UNORM or sRGB image
// (a swapchain's), B10G11R11, A2B10G10R10, RGBA16 UNORM or a float image without STORAGE. postfx blits
// it into its own RGBA16F image, composites there and blits back, so each format's result must be the
// in-place RGBA16F composite of the same (quantized) input, quantized to the format: within one step of
// the format's precision. Also: the frame plan's exact passes, the errors naming a missing usage bit,
// and a second frame in the same context (the target's hazards across frames, under synchronization
// validation).
#include "fog_harness.h"

#include <gtest/gtest.h>

#include <postfx/postfx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace test;

namespace {

constexpr uint32_t kWidth = 24, kHeight = 12;

double srgbEncode(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

struct TargetFormat {
    VkFormat format;
    const char* name;
    bool srgb;
    double step;  // the format's precision in its encoded values (absolute), or relative (packed float)
    bool relative;
    bool alpha;  // keeps the host's alpha
};

const TargetFormat kFormats[] = {
    {VK_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM", false, 1.0 / 255.0, false, true},
    {VK_FORMAT_R8G8B8A8_SRGB, "R8G8B8A8_SRGB", true, 1.0 / 255.0, false, true},
    {VK_FORMAT_B8G8R8A8_UNORM, "B8G8R8A8_UNORM", false, 1.0 / 255.0, false, true},
    {VK_FORMAT_B8G8R8A8_SRGB, "B8G8R8A8_SRGB", true, 1.0 / 255.0, false, true},
    {VK_FORMAT_A8B8G8R8_SRGB_PACK32, "A8B8G8R8_SRGB_PACK32", true, 1.0 / 255.0, false, true},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, "A2B10G10R10_UNORM_PACK32", false, 1.0 / 1023.0, false, false},
    {VK_FORMAT_A2R10G10B10_UNORM_PACK32, "A2R10G10B10_UNORM_PACK32", false, 1.0 / 1023.0, false, false},
    // Compared at the composite's own precision (RGBA16F, 11 bits), coarser than the format's 16.
    {VK_FORMAT_R16G16B16A16_UNORM, "R16G16B16A16_UNORM", false, 1.0 / 2048.0, false, true},
    // 6 bits of mantissa in red and green, 5 in blue: one step is 2^-5 of the value.
    {VK_FORMAT_B10G11R11_UFLOAT_PACK32, "B10G11R11_UFLOAT_PACK32", false, 1.0 / 32.0, true, false},
};

class FrameTargetsTest : public ReversedZContextTest {
protected:
    // Ray-marched fog of constant density lit by the ambient light, over surfaces from 20 to 400 m, and
    // the sky where a quarter of the pixels see none: values spread over [0, 1] as an LDR target holds
    // them (pre-exposure maps the sky into it).
    postfx::FrameInfo frame() const {
        postfx::FrameInfo f;
        f.cameraCut = true;
        f.camera =
            lookCamera({0.0, 1.5, 0.0}, {0.0, 0.05, -1.0}, {0.0, 1.0, 0.0}, 60.0f, float(kWidth) / kHeight);
        f.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.4f, 0.8f));  // behind the camera
        f.sun.illuminance = postfx::Vec3(1e5f);
        f.ambient = {0.4f, 0.5f, 0.6f};
        f.preExposure = 1.0f / 8000.0f;
        f.atmosphere.enabled = true;
        smallScatteringOrders(f.atmosphere);
        f.fog.enabled = true;
        f.fog.density = 0.004f;
        f.fog.heightFalloff = 0.0f;
        f.fog.albedo = {0.9f, 0.9f, 0.9f};
        f.fog.maxDistance = 1000.0f;
        f.fog.noise.enabled = false;
        return f;
    }

    FogHarnessImages images(const postfx::FrameInfo& f, VkFormat format) const {
        FogHarnessImages im = surfaceImages(
            f.camera, kWidth, kHeight,
            [](uint32_t i, uint32_t j) {
                return j < kHeight / 4 ? INFINITY : 20.0 + 380.0 * double((i * 5 + j * 3) % 17) / 16.0;
            },
            [](uint32_t i, uint32_t j, int c) {
                return c == 3 ? 0.25f + 0.25f * float((i + j) % 4)
                              : float((i * 7 + j * 3 + c * 5) % 13) / 12.0f;
            });
        im.colorFormat = format;
        return im;
    }

    // `f` over `im` in a context of its own (so that frames compared have the same index and history).
    postfx::Status runFresh(const FogHarnessImages& im, const postfx::FrameInfo& f, std::vector<float>& color,
                            std::vector<float>* output = nullptr) {
        std::unique_ptr<postfx::Context> fresh;
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        if (postfx::Status s = createContext(fresh, info); !s) return s;
        FogHarness harness(*host, gpu);
        return harness.run(*fresh, im, f, color, output);
    }

    // The color as `im`'s format stores it: no effect, read back.
    std::vector<float> stored(const FogHarnessImages& im, const postfx::FrameInfo& f) {
        postfx::FrameInfo none;
        none.camera = f.camera;
        std::vector<float> color;
        EXPECT_TRUE(runFresh(im, none, color).ok());
        return color;
    }

    // `f` over `im` composited into `im`'s format, and in place into RGBA16F over the same (quantized) input.
    void render(const postfx::FrameInfo& f, const FogHarnessImages& im, std::vector<float>& reference,
                std::vector<float>& target) {
        FogHarnessImages quantized = im;
        quantized.color = stored(im, f);
        quantized.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        postfx::Status s = runFresh(quantized, f, reference);
        ASSERT_TRUE(s.ok()) << s.message;
        s = runFresh(im, f, target);
        ASSERT_TRUE(s.ok()) << s.message;
    }
};

// Each format's composite is the in-place RGBA16F composite quantized to it: within one step of its
// precision (1.5 steps: the reference's own RGBA16F rounding), in its encoded values (sRGB formats: in
// sRGB), with the alpha carried through where the format has 8 or more bits of it.
TEST_F(FrameTargetsTest, EveryFormatMatchesTheInPlaceComposite) {
    const postfx::FrameInfo f = frame();
    for (const TargetFormat& t : kFormats) {
        // postfx blits the target back, or stores it from a shader where the device cannot blit into
        // the format (lavapipe: B10G11R11) but can store to it (then the image needs STORAGE usage). A
        // format with neither (A2R10G10B10 is optional) is refused by name.
        VkFormatProperties properties{};
        vkGetPhysicalDeviceFormatProperties(host->physicalDevice, t.format, &properties);
        const VkFormatFeatureFlags has = properties.optimalTilingFeatures;
        const bool computeStore =
            t.format == VK_FORMAT_B10G11R11_UFLOAT_PACK32 || t.format == VK_FORMAT_A2B10G10R10_UNORM_PACK32 ||
            t.format == VK_FORMAT_R8G8B8A8_UNORM || t.format == VK_FORMAT_R16G16B16A16_UNORM;
        const bool storable = computeStore && (has & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT);
        if (!(has & VK_FORMAT_FEATURE_BLIT_SRC_BIT) ||
            (!(has & VK_FORMAT_FEATURE_BLIT_DST_BIT) && !storable)) {
            postfx::Status planned = postfx::Status::success();
            FogHarness harness(*host, gpu);
            harness.onBeforeRecord = [&](const postfx::FrameInfo& given) {
                postfx::FrameInfo claimed = given;
                claimed.color.format = t.format;
                postfx::FramePlan plan;
                planned = context->plan(claimed, plan);
            };
            std::vector<float> out;
            ASSERT_TRUE(harness.run(*context, images(f, VK_FORMAT_B8G8R8A8_SRGB), f, out).ok());
            EXPECT_NE(planned.message.find("the device can"), std::string::npos) << planned.message;
            std::printf("[ targets ] %-26s neither blit nor store on this device: refused by name\n", t.name);
            continue;
        }
        FogHarnessImages im = images(f, t.format);
        im.colorUsage =
            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
            (has & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT ? VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT : 0) |
            (storable ? VK_IMAGE_USAGE_STORAGE_BIT : 0);
        const bool stored = !(has & VK_FORMAT_FEATURE_BLIT_DST_BIT);
        std::vector<float> reference, target;
        render(f, im, reference, target);
        ASSERT_EQ(reference.size(), target.size()) << t.name;
        double worst = 0.0, largest = 0.0;
        for (size_t p = 0; p < target.size() / 4; ++p) {
            for (int c = 0; c < 3; ++c) {
                const double want = std::clamp(double(reference[p * 4 + c]), 0.0, t.relative ? 1e30 : 1.0);
                const double got = target[p * 4 + c];
                largest = std::max(largest, want);
                const double error = t.relative ? std::abs(got - want) / std::max(want, 1e-3)
                                     : t.srgb   ? std::abs(srgbEncode(got) - srgbEncode(want))
                                                : std::abs(got - want);
                worst = std::max(worst, error / t.step);
            }
            if (t.alpha) {
                // The reference holds the alpha in RGBA16F: within its step too.
                EXPECT_NEAR(target[p * 4 + 3], reference[p * 4 + 3], std::max(t.step, 1.0 / 1024.0))
                    << t.name << " pixel " << p;
            } else if (t.format == VK_FORMAT_B10G11R11_UFLOAT_PACK32) {
                EXPECT_EQ(target[p * 4 + 3], 1.0f) << t.name;
            }
        }
        std::printf("[ targets ] %-26s %s: worst %.2f steps of its precision (largest value %.2f)\n", t.name,
                    stored ? "stored from a shader" : "blitted", worst, largest);
        EXPECT_LE(worst, 1.5) << t.name;
        EXPECT_GT(largest, 0.5) << t.name << ": the frame should span the target's range";
    }
}

// A float image without STORAGE usage goes through postfx.target too, bit for bit the in-place result.
TEST_F(FrameTargetsTest, FloatTargetWithoutStorageIsExact) {
    const postfx::FrameInfo f = frame();
    FogHarnessImages im = images(f, VK_FORMAT_R16G16B16A16_SFLOAT);
    std::vector<float> reference, target;
    ASSERT_TRUE(runFresh(im, f, reference).ok());
    im.colorUsage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    const postfx::Status s = runFresh(im, f, target);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(reference, target);
}

// A separate output: the color is only read, the output gets the composite; and frames in a row in one
// context (postfx.target written, read, and written again across frames).
TEST_F(FrameTargetsTest, SeparateOutputLeavesTheColor) {
    const postfx::FrameInfo f = frame();
    FogHarnessImages im = images(f, VK_FORMAT_B8G8R8A8_SRGB);
    std::vector<float> inPlace, color, output;
    ASSERT_TRUE(runFresh(im, f, inPlace).ok());
    im.separateOutput = true;
    const postfx::Status s = runFresh(im, f, color, &output);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(output, inPlace);
    FogHarnessImages untouched = im;
    untouched.separateOutput = false;
    EXPECT_EQ(color, stored(untouched, f));

    FogHarness harness(*host, gpu);
    for (uint64_t frameIndex = 0; frameIndex < 3; ++frameIndex) {
        postfx::FrameInfo g = f;
        g.frameIndex = frameIndex;
        g.cameraCut = frameIndex == 0;
        g.fog.temporal.enabled = true;
        ASSERT_TRUE(harness.run(*context, im, g, color, &output).ok()) << "frame " << frameIndex;
    }
}

// The plan: postfx.target_load first, postfx.target_store last, postfx.target held (8 bytes a pixel);
// none of them for a storage RGBA16F color; a bare copy into a separate output when nothing composites.
TEST_F(FrameTargetsTest, PlanLoadsAndStoresTheTarget) {
    postfx::FrameInfo f = frame();
    f.atmosphere.enabled = false;
    f.frameIndex = 10;
    const postfx::FramePlan direct =
        planAndRecord(*host, gpu, *context, images(f, VK_FORMAT_R16G16B16A16_SFLOAT), f);
    f.frameIndex = 11;
    const postfx::FramePlan srgb = planAndRecord(*host, gpu, *context, images(f, VK_FORMAT_B8G8R8A8_SRGB), f);
    std::vector<std::string> expected = passNames(direct);
    expected.insert(expected.begin(), "postfx.target_load");
    expected.push_back("postfx.target_store");
    EXPECT_EQ(passNames(srgb), expected);
    const auto target =
        std::find_if(srgb.resources.begin(), srgb.resources.end(),
                     [](const postfx::PlannedResource& r) { return r.name == "postfx.target"; });
    ASSERT_NE(target, srgb.resources.end());
    EXPECT_EQ(target->bytes, uint64_t(kWidth) * kHeight * 8);
    for (const postfx::PlannedResource& r : direct.resources)
        EXPECT_NE(r.name, "postfx.target");

    postfx::FrameInfo none;
    none.camera = f.camera;
    none.frameIndex = 12;
    FogHarnessImages separate = images(f, VK_FORMAT_B8G8R8A8_SRGB);
    separate.separateOutput = true;
    const postfx::FramePlan copied = planAndRecord(*host, gpu, *context, separate, none);
    EXPECT_EQ(passNames(copied), std::vector<std::string>{"postfx.copy"});
    EXPECT_TRUE(copied.resources.empty());
}

// Errors name the field and the bit or format missing (the images have every usage; the frame claims less).
TEST_F(FrameTargetsTest, ErrorsNameTheMissingUsage) {
    const postfx::FrameInfo f = frame();
    struct Case {
        VkFormat format;
        VkImageUsageFlags usage;
        const char* message;
    };
    const Case cases[] = {
        {VK_FORMAT_B8G8R8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_DST_BIT,
         "FrameInfo.color.usage lacks VK_IMAGE_USAGE_TRANSFER_SRC_BIT"},
        {VK_FORMAT_B8G8R8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
         "FrameInfo.color.usage lacks VK_IMAGE_USAGE_TRANSFER_DST_BIT"},
        {VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT,
         "FrameInfo.color.usage lacks VK_IMAGE_USAGE_TRANSFER_SRC_BIT"},
        {VK_FORMAT_R8_UNORM, VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
         "FrameInfo.color.format VK_FORMAT_R8_UNORM is not supported"},
    };
    for (const Case& c : cases) {
        postfx::Status planned = postfx::Status::success();
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& given) {
            postfx::FrameInfo claimed = given;
            claimed.color.format = c.format;
            claimed.color.usage = c.usage;
            postfx::FramePlan plan;
            planned = context->plan(claimed, plan);
        };
        std::vector<float> out;
        ASSERT_TRUE(harness.run(*context, images(f, VK_FORMAT_B8G8R8A8_SRGB), f, out).ok());
        EXPECT_EQ(planned.code, postfx::Result::InvalidArgument) << c.message;
        EXPECT_NE(planned.message.find(c.message), std::string::npos) << planned.message;
    }
}

}  // namespace
