// postfx's core on a real device: context creation from borrowed handles, input validation with
// readable messages, and the internal helpers (images, buffers, compute pipelines, descriptor sets,
// barriers, pass timestamps) driven by a test shader whose output is checked exactly.
#include "core/barriers.h"
#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"
#include "core/pass_timer.h"
#include "core_test_shaders_spirv.h"
#include "gpu_test.h"

#include <glm/gtc/packing.hpp>

#include <bit>
#include <cstring>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::Result;

struct Messages {
    std::vector<std::string> errors;
    static void callback(postfx::MessageSeverity severity, const char* message, void* user) {
        if (severity == postfx::MessageSeverity::Error)
            static_cast<Messages*>(user)->errors.push_back(message);
    }
};

class CoreTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        postfx::Status s = gpu.init(hostHandles());
        ASSERT_TRUE(s.ok()) << s.message;
    }
    // A host color (RGBA16F) and depth (D32) image pair in `colorLayout` / `depthLayout`.
    void makeFrameImages(VkExtent2D extent, VkImageLayout colorLayout, VkImageLayout depthLayout) {
        postfx::core::ImageDesc c;
        c.extent = {extent.width, extent.height, 1};
        ASSERT_TRUE(color.create(gpu, c, "test color").ok());
        postfx::core::ImageDesc d;
        d.format = VK_FORMAT_D32_SFLOAT;
        d.extent = c.extent;
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        ASSERT_TRUE(depth.create(gpu, d, "test depth").ok());
        std::string error;
        ASSERT_TRUE(host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                postfx::core::ImageTransition t;
                t.image = color.handle();
                t.newLayout = colorLayout;
                t.dstStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
                t.dstAccess = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
                postfx::core::transition(gpu, cmd, t);
                t.image = depth.handle();
                t.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
                t.newLayout = depthLayout;
                postfx::core::transition(gpu, cmd, t);
            },
            error))
            << error;
        frame.color = {color.handle(), color.view(), VK_FORMAT_R16G16B16A16_SFLOAT,
                       extent,         colorLayout,  color.desc().usage};
        frame.depth = {depth.handle(), depth.view(), VK_FORMAT_D32_SFLOAT,
                       extent,         depthLayout,  depth.desc().usage};
    }

    postfx::core::Gpu gpu;
    postfx::core::GpuImage color, depth;
    postfx::FrameInfo frame;
};

// The fixture's "no validation message" check is only worth something if the layer is really there.
TEST_F(CoreTest, ValidationLayerReportsMisuse) {
    ASSERT_TRUE(host->validationEnabled);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 0;  // VUID-VkBufferCreateInfo-size-00912
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (vkCreateBuffer(host->device, &info, nullptr, &buffer) == VK_SUCCESS && buffer)
        vkDestroyBuffer(host->device, buffer, nullptr);
    const std::vector<std::string> messages = host->takeValidationMessages();
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages[0].find("VUID-VkBufferCreateInfo-size-00912"), std::string::npos) << messages[0];
}

TEST_F(CoreTest, CreatesContextFromBorrowedHandles) {
    std::unique_ptr<postfx::Context> context;
    postfx::Status s = createContext(context);
    ASSERT_TRUE(s.ok()) << s.message;
    ASSERT_TRUE(context);
    EXPECT_EQ(context->createInfo().device, host->device);
}

TEST_F(CoreTest, RejectsBadCreateInfoNamingTheField) {
    struct Case {
        const char* field;
        void (*edit)(postfx::ContextCreateInfo&);
    };
    const Case cases[] = {
        {"instance", [](postfx::ContextCreateInfo& i) { i.instance = VK_NULL_HANDLE; }},
        {"physicalDevice", [](postfx::ContextCreateInfo& i) { i.physicalDevice = VK_NULL_HANDLE; }},
        {"device", [](postfx::ContextCreateInfo& i) { i.device = VK_NULL_HANDLE; }},
        {"getDeviceProcAddr", [](postfx::ContextCreateInfo& i) { i.getDeviceProcAddr = nullptr; }},
        {"getInstanceProcAddr", [](postfx::ContextCreateInfo& i) { i.getInstanceProcAddr = nullptr; }},
        {"maxExtent",
         [](postfx::ContextCreateInfo& i) {
             i.maxExtent = {0, 1080};
         }},
        {"framesInFlight", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 0; }},
        {"structSize", [](postfx::ContextCreateInfo& i) { i.structSize = 8; }},
        {"framesInFlight", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 99; }},
        {"queueFamilyIndex", [](postfx::ContextCreateInfo& i) { i.queueFamilyIndex = 1000; }},
    };
    for (const Case& c : cases) {
        Messages messages;
        postfx::ContextCreateInfo info = hostHandles();
        info.messageCallback = Messages::callback;
        info.messageUserData = &messages;
        c.edit(info);
        std::unique_ptr<postfx::Context> context;
        postfx::Status s = postfx::Context::create(info, context);
        EXPECT_EQ(s.code, Result::InvalidArgument) << c.field;
        EXPECT_NE(s.message.find(c.field), std::string::npos) << s.message;
        EXPECT_FALSE(context);
        // Returned, not also sent to the callback: each error reaches the host once.
        EXPECT_TRUE(messages.errors.empty()) << c.field;
    }
}

TEST_F(CoreTest, RecordValidatesFrameInputs) {
    std::unique_ptr<postfx::Context> context;
    postfx::ContextCreateInfo info;
    info.maxExtent = {64, 32};
    ASSERT_TRUE(createContext(context, info).ok());
    makeFrameImages({16, 8}, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

    struct Case {
        const char* expected;
        void (*edit)(postfx::FrameInfo&);
    };
    const Case cases[] = {
        {"FrameInfo.commandBuffer", [](postfx::FrameInfo& f) { f.commandBuffer = VK_NULL_HANDLE; }},
        {"FrameInfo.color.image", [](postfx::FrameInfo& f) { f.color.image = VK_NULL_HANDLE; }},
        {"FrameInfo.color.view", [](postfx::FrameInfo& f) { f.color.view = VK_NULL_HANDLE; }},
        {"FrameInfo.color.format", [](postfx::FrameInfo& f) { f.color.format = VK_FORMAT_R8_UNORM; }},
        {"FrameInfo.color.extent",
         [](postfx::FrameInfo& f) {
             f.color.extent = {0, 8};
         }},
        {"maxExtent",
         [](postfx::FrameInfo& f) {
             f.color.extent = {128, 8};
         }},
        {"FrameInfo.color.layout", [](postfx::FrameInfo& f) { f.color.layout = VK_IMAGE_LAYOUT_UNDEFINED; }},
        {"FrameInfo.depth.image", [](postfx::FrameInfo& f) { f.depth.image = VK_NULL_HANDLE; }},
        {"FrameInfo.depth.format", [](postfx::FrameInfo& f) { f.depth.format = VK_FORMAT_R32_SFLOAT; }},
        {"differs from FrameInfo.color.extent",
         [](postfx::FrameInfo& f) {
             f.depth.extent = {8, 8};
         }},
        // Usage flags, formats by name, and the output image: checked whether or not an effect runs.
        // Without STORAGE, postfx blits the color into its own image and back (core/target.h).
        {"FrameInfo.color.usage lacks VK_IMAGE_USAGE_TRANSFER_SRC_BIT",
         [](postfx::FrameInfo& f) { f.color.usage = VK_IMAGE_USAGE_SAMPLED_BIT; }},
        {"FrameInfo.depth.usage lacks VK_IMAGE_USAGE_SAMPLED_BIT",
         [](postfx::FrameInfo& f) { f.depth.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT; }},
        {"FrameInfo.color.format VK_FORMAT_R8_UNORM is not supported",
         [](postfx::FrameInfo& f) { f.color.format = VK_FORMAT_R8_UNORM; }},
        {"FrameInfo.output is FrameInfo.color", [](postfx::FrameInfo& f) { f.output = f.color; }},
        {"FrameInfo.output.extent 8x8 differs",
         [](postfx::FrameInfo& f) {
             f.output = f.color;
             f.output.image = reinterpret_cast<VkImage>(uintptr_t(1));
             f.output.extent = {8, 8};
         }},
        {"FrameInfo.output.format VK_FORMAT_R32G32B32A32_SFLOAT differs from FrameInfo.color.format "
         "VK_FORMAT_R16G16B16A16_SFLOAT",
         [](postfx::FrameInfo& f) {
             f.output = f.color;
             f.output.image = reinterpret_cast<VkImage>(uintptr_t(1));
             f.output.format = VK_FORMAT_R32G32B32A32_SFLOAT;
         }},
        {"FrameInfo.output.usage lacks VK_IMAGE_USAGE_STORAGE_BIT",
         [](postfx::FrameInfo& f) {
             f.output = f.color;
             f.output.image = reinterpret_cast<VkImage>(uintptr_t(1));
             f.output.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
         }},
        {"FrameInfo.shadowMap.image.usage lacks VK_IMAGE_USAGE_SAMPLED_BIT",
         [](postfx::FrameInfo& f) {
             f.shadowMap.image = f.depth;
             f.shadowMap.image.usage = VK_IMAGE_USAGE_STORAGE_BIT;
         }},
        {"FrameInfo.camera.projection", [](postfx::FrameInfo& f) { f.camera.projection = glm::mat4(0.0f); }},
        {"FrameInfo.structSize", [](postfx::FrameInfo& f) { f.structSize = sizeof(postfx::FrameInfo) + 16; }},
        {"FrameInfo.lights is null", [](postfx::FrameInfo& f) { f.lightCount = 1; }},
        {"FrameInfo.lightCount 257 exceeds", [](postfx::FrameInfo& f) { f.lightCount = 257; }},
    };
    // A bad light is named with its index.
    postfx::LocalLight lights[2];
    lights[1].intensity = glm::vec3(-1.0f);
    std::string error;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            for (const Case& c : cases) {
                postfx::FrameInfo f = frame;
                f.commandBuffer = cmd;
                c.edit(f);
                postfx::Status s = context->record(f);
                EXPECT_EQ(s.code, Result::InvalidArgument) << c.expected;
                EXPECT_NE(s.message.find(c.expected), std::string::npos) << s.message;
            }
            postfx::FrameInfo withLights = frame;
            withLights.commandBuffer = cmd;
            withLights.lights = lights;
            withLights.lightCount = 2;
            postfx::Status bad = context->record(withLights);
            EXPECT_NE(bad.message.find("FrameInfo.lights[1].intensity"), std::string::npos) << bad.message;
            postfx::FrameInfo f = frame;
            f.commandBuffer = cmd;
            f.frameIndex = 7;
            postfx::Status s = context->record(f);
            EXPECT_TRUE(s.ok()) << s.message;
        },
        error))
        << error;
    // A frame with no effect records no pass: its timings are an empty list, not an error.
    std::vector<postfx::PassTiming> timings{{"stale", 1.0}};
    postfx::Status s = context->readPassTimings(7, timings);
    if (s.code != Result::Unsupported) {
        EXPECT_TRUE(s.ok()) << s.message;
        EXPECT_TRUE(timings.empty());
        EXPECT_EQ(context->readPassTimings(8, timings).code, Result::InvalidArgument);
    }
}

TEST_F(CoreTest, ComputeHelpersProduceExactResults) {
    constexpr uint32_t kWidth = 13, kHeight = 7, kCount = kWidth * kHeight;  // not multiples of 8
    constexpr float kScale = 3.0f, kOffset = 0.5f;
    postfx::core::GpuBuffer input, output;
    ASSERT_TRUE(input.create(gpu, kCount * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "input").ok());
    ASSERT_TRUE(output.create(gpu, kCount * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "output").ok());
    std::vector<float> values(kCount);
    for (uint32_t i = 0; i < kCount; ++i)
        values[i] = float(i) * 0.25f - 7.0f;
    std::memcpy(input.mapped(), values.data(), kCount * 4);

    postfx::core::GpuImage image;
    postfx::core::ImageDesc desc;
    desc.extent = {kWidth, kHeight, 1};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    ASSERT_TRUE(image.create(gpu, desc, "image").ok());
    EXPECT_GE(image.bytes(), VkDeviceSize(kCount * 8));

    const postfx::core::Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                              {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                              {2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
    postfx::core::ComputePipelineDesc pd;
    pd.name = "test.affine";
    pd.spirv = core_test_spirv::core_affine_comp;
    pd.bindings = bindings;
    pd.pushConstantBytes = 12;
    postfx::core::PipelineConstants constants;  // constant_id 0: the scale
    constants.values[0] = std::bit_cast<uint32_t>(kScale);
    constants.count = 1;
    postfx::core::ComputePipeline pipeline;
    postfx::Status s = pipeline.create(gpu, pd, 0, constants);
    ASSERT_TRUE(s.ok()) << s.message;

    postfx::core::DescriptorArena arena;
    ASSERT_TRUE(arena.create(gpu, 4).ok());
    ASSERT_TRUE(arena.beginFrame().ok());
    VkDescriptorSet set = VK_NULL_HANDLE;
    ASSERT_TRUE(arena.allocate(pipeline.setLayout(), set).ok());
    postfx::core::DescriptorWrites(set)
        .storageBuffer(0, input.handle(), 0, VK_WHOLE_SIZE)
        .storageBuffer(1, output.handle(), 0, VK_WHOLE_SIZE)
        .storageImage(2, image.view())
        .apply(gpu);

    postfx::core::PassTimer timer;
    ASSERT_TRUE(timer.create(gpu, 2, 64).ok());
    postfx::core::GpuBuffer readback;
    ASSERT_TRUE(readback.create(gpu, kCount * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());

    std::string error;
    ASSERT_TRUE(host->submitAndWait(
        [&](VkCommandBuffer cmd) {
            timer.beginFrame(cmd, 5);
            postfx::core::ImageTransition t;
            t.image = image.handle();
            t.dstAccess = VK_ACCESS_SHADER_WRITE_BIT;
            postfx::core::transition(gpu, cmd, t);
            timer.beginPass(cmd, "test.affine");
            const struct {
                float offset;
                uint32_t width, height;
            } push{kOffset, kWidth, kHeight};
            pipeline.bind(cmd, set, &push);
            gpu.fn.vkCmdDispatch(cmd, (kWidth + 7) / 8, (kHeight + 7) / 8, 1);
            timer.endPass(cmd);
            timer.beginPass(cmd, "test.empty");
            timer.endPass(cmd);
            // Shader writes -> host reads of the buffer; image -> transfer for the readback copy.
            VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                                 &toHost, 0, nullptr, 0, nullptr);
            t.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
            t.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            t.srcStage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
            t.srcAccess = VK_ACCESS_SHADER_WRITE_BIT;
            t.dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
            t.dstAccess = VK_ACCESS_TRANSFER_READ_BIT;
            postfx::core::transition(gpu, cmd, t);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {kWidth, kHeight, 1};
            vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   readback.handle(), 1, &region);
            VkMemoryBarrier copyToHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            copyToHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            copyToHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                                 &copyToHost, 0, nullptr, 0, nullptr);
        },
        error))
        << error;

    const float* out = static_cast<const float*>(output.mapped());
    const uint16_t* texels = static_cast<const uint16_t*>(readback.mapped());
    for (uint32_t i = 0; i < kCount; ++i) {
        EXPECT_EQ(out[i], values[i] * kScale + kOffset) << i;  // exact in fp32 for these values
        const uint32_t x = i % kWidth, y = i / kWidth;
        // Half floats: x and y are exact; the value to within half precision.
        EXPECT_EQ(glm::unpackHalf1x16(texels[i * 4 + 1]), float(x));
        EXPECT_EQ(glm::unpackHalf1x16(texels[i * 4 + 2]), float(y));
        EXPECT_NEAR(glm::unpackHalf1x16(texels[i * 4 + 0]), out[i], std::abs(out[i]) * 1e-3f);
    }

    std::vector<postfx::PassTiming> timings;
    s = timer.read(5, timings);
    ASSERT_TRUE(s.ok()) << s.message;
    ASSERT_EQ(timings.size(), 2u);
    EXPECT_EQ(timings[0].name, "test.affine");
    EXPECT_EQ(timings[1].name, "test.empty");
    for (const auto& t : timings) {
        EXPECT_GE(t.milliseconds, 0.0);
        EXPECT_LT(t.milliseconds, 10000.0);
    }
    EXPECT_EQ(timer.read(6, timings).code, Result::InvalidArgument);  // never recorded
    EXPECT_EQ(timer.read(3, timings).code, Result::InvalidArgument);  // same slot, other frame
}

TEST_F(CoreTest, PipelineCreationRejectsBadDescriptions) {
    postfx::core::ComputePipeline pipeline;
    postfx::core::ComputePipelineDesc pd;
    pd.name = "test.empty";
    postfx::Status s = pipeline.create(gpu, pd);
    EXPECT_EQ(s.code, Result::InvalidArgument);
    EXPECT_NE(s.message.find("test.empty"), std::string::npos);
    pd.spirv = core_test_spirv::core_affine_comp;
    pd.pushConstantBytes = 256;
    EXPECT_EQ(pipeline.create(gpu, pd).code, Result::InvalidArgument);
    EXPECT_FALSE(pipeline.valid());
}

}  // namespace
}  // namespace test
