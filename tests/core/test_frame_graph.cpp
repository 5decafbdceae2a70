// The frame graph (postfx/src/core/frame_graph.h) with two test-only effects added to a context: one
// effect reads another's persistent image (declared by typed handle), which is rebuilt only when its
// key changes and not at all when nothing reads it; a pass whose output nothing reads is not recorded;
// two composites chain through a separate output; the host's images cross into and out of postfx once
// per frame whatever the number of passes (image barriers counted at vkCmdPipelineBarrier).
#include "core/context_impl.h"
#include "core/effect.h"
#include "core/frame_graph.h"
#include "core_test_shaders_spirv.h"
#include "fog_harness.h"
#include "gpu_test.h"

#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::core::ImageRef;
using postfx::core::Use;

constexpr postfx::core::ResourceId kLut{"producer.lut"};
constexpr postfx::core::ResourceId kUnread{"producer.unread"};

constexpr postfx::core::Binding kProducerBindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
constexpr postfx::core::Binding kConsumerBindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                                       {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
const postfx::core::ComputePipelineDesc kBuild{"producer.build", core_test_spirv::graph_producer_comp,
                                               kProducerBindings, 16};
const postfx::core::ComputePipelineDesc kScratch{"producer.unread", core_test_spirv::graph_producer_comp,
                                                 kProducerBindings, 16};
const postfx::core::ComputePipelineDesc kApply{"consumer.apply", core_test_spirv::graph_consumer_comp,
                                               kConsumerBindings, 8};

// Builds a 4×4 image of `value` (persistent, key `key`), and a scratch image nobody reads.
struct Producer final : postfx::core::Effect {
    bool on = true;
    uint64_t key = 1;
    float value = 0.25f;
    uint32_t variant = 0;  // the build pass's specialization constant (the shader declares none)
    const char* name() const override { return "producer"; }
    postfx::Status validate(const postfx::FrameInfo&) const override { return postfx::Status::success(); }
    bool active(const postfx::FrameInfo&) const override { return on; }
    postfx::Status declare(postfx::core::FrameBuilder& b) const override {
        postfx::core::ImageDesc desc;
        desc.extent = {4, 4, 1};
        const glm::vec4 push(value);
        const ImageRef lut = b.persistentImage(kLut, desc, key);
        postfx::core::PipelineConstants constants;
        constants.values[0] = variant;
        constants.count = 1;
        b.pass(kBuild, 1, 1, 1).constants(constants).bind(0, lut, Use::StorageWrite).push(&push, sizeof push);
        const ImageRef unread = b.transientImage(kUnread, desc);
        b.pass(kScratch, 1, 1, 1).bind(0, unread, Use::StorageWrite).push(&push, sizeof push);
        return postfx::Status::success();
    }
};

// color += the producer's image, `passes` times; nothing when the producer did not declare it.
struct Consumer final : postfx::core::Effect {
    bool on = true;
    int passes = 1;
    const char* name() const override { return "consumer"; }
    postfx::Status validate(const postfx::FrameInfo&) const override { return postfx::Status::success(); }
    bool active(const postfx::FrameInfo&) const override { return on; }
    postfx::Status declare(postfx::core::FrameBuilder& b) const override {
        const ImageRef lut = b.find(kLut);
        if (!lut.valid()) return postfx::Status::success();
        const VkExtent2D e = b.frame().color.extent;
        const uint32_t extent[2] = {e.width, e.height};
        for (int i = 0; i < passes; ++i)
            b.pass(kApply, (e.width + 7) / 8, (e.height + 7) / 8, 1)
                .bind(0, b.compositeSource(), Use::StorageRead)
                .bind(1, b.compositeTarget(), Use::StorageWrite)
                .bind(2, lut, Use::Sampled)
                .push(extent, sizeof extent);
        return postfx::Status::success();
    }
};

// Image barriers per image, counted at vkCmdPipelineBarrier through the getDeviceProcAddr postfx gets.
std::map<VkImage, int> gImageBarriers;
PFN_vkCmdPipelineBarrier gCmdPipelineBarrier = nullptr;
VKAPI_ATTR void VKAPI_CALL countPipelineBarrier(VkCommandBuffer c, VkPipelineStageFlags src,
                                                VkPipelineStageFlags dst, VkDependencyFlags flags,
                                                uint32_t memoryCount, const VkMemoryBarrier* memory,
                                                uint32_t bufferCount, const VkBufferMemoryBarrier* buffers,
                                                uint32_t imageCount, const VkImageMemoryBarrier* images) {
    for (uint32_t i = 0; i < imageCount; ++i)
        ++gImageBarriers[images[i].image];
    gCmdPipelineBarrier(c, src, dst, flags, memoryCount, memory, bufferCount, buffers, imageCount, images);
}
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingDeviceProcAddr(VkDevice device, const char* name) {
    const PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
    if (std::strcmp(name, "vkCmdPipelineBarrier") != 0) return real;
    gCmdPipelineBarrier = reinterpret_cast<PFN_vkCmdPipelineBarrier>(real);
    return reinterpret_cast<PFN_vkVoidFunction>(&countPipelineBarrier);
}

std::vector<std::string> names(const postfx::FramePlan& plan) {
    std::vector<std::string> out;
    for (const postfx::PlannedPass& p : plan.passes)
        out.push_back(p.name);
    return out;
}

class CoreFrameGraphTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info = hostHandles();
        info.getDeviceProcAddr = countingDeviceProcAddr;
        ASSERT_TRUE(postfx::Context::create(info, context).ok());
        auto producerEffect = std::make_unique<Producer>();
        auto consumerEffect = std::make_unique<Consumer>();
        producer = producerEffect.get();
        consumer = consumerEffect.get();
        postfx::Context::Impl& impl = postfx::ContextAccess::of(*context);
        impl.addEffect(std::move(producerEffect));
        impl.addEffect(std::move(consumerEffect));
        images.width = 12;
        images.height = 10;
        images.color.assign(size_t(images.width) * images.height * 4, 1.0f);
        images.depth.assign(size_t(images.width) * images.height, 0.0f);
    }

    // Records frame `frameIndex`; returns its plan (checked equal to the recorded passes) and the color.
    postfx::FramePlan run(uint64_t frameIndex, std::vector<float>& color) {
        postfx::FrameInfo frame;
        frame.frameIndex = frameIndex;
        postfx::FramePlan plan;
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            EXPECT_TRUE(context->plan(f, plan).ok());
            gImageBarriers.clear();
        };
        std::vector<float> out, output;
        const postfx::Status s =
            harness.run(*context, images, frame, out, images.separateOutput ? &output : nullptr);
        EXPECT_TRUE(s.ok()) << s.message;
        std::vector<postfx::PassTiming> timings;
        EXPECT_TRUE(context->readPassTimings(frameIndex, timings).ok());
        std::vector<std::string> recorded;
        for (const postfx::PassTiming& t : timings)
            recorded.push_back(t.name);
        EXPECT_EQ(recorded, names(plan)) << "frame " << frameIndex;
        color = images.separateOutput ? output : out;
        return plan;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
    Producer* producer = nullptr;
    Consumer* consumer = nullptr;
    FogHarnessImages images;
};

// Every pixel's rgb equals `rgb` (to RGBA16F precision) and alpha is 1.
void expectColor(const std::vector<float>& color, float rgb) {
    ASSERT_FALSE(color.empty());
    for (size_t i = 0; i < color.size(); ++i)
        ASSERT_NEAR(color[i], i % 4 == 3 ? 1.0f : rgb, 1e-3f) << "component " << i;
}

TEST_F(CoreFrameGraphTest, OneEffectReadsAnothersPersistentImageRebuiltOnlyWhenItsKeyChanges) {
    std::vector<float> color;
    postfx::FramePlan plan = run(0, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"producer.build", "consumer.apply"}));
    const postfx::PlannedPass& apply = plan.passes[1];
    EXPECT_EQ(apply.effect, "consumer");
    EXPECT_EQ(apply.reads, (std::vector<std::string>{"host.color", "producer.lut"}));
    EXPECT_EQ(apply.writes, (std::vector<std::string>{"host.color"}));
    // The unread scratch pass is not recorded and its image is not held.
    ASSERT_EQ(plan.resources.size(), 1u);
    EXPECT_EQ(plan.resources[0].name, "producer.lut");
    EXPECT_EQ(plan.resources[0].bytes, 4u * 4u * 8u);
    expectColor(color, 1.25f);

    // Same key: not rebuilt, the image keeps its contents.
    plan = run(1, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"consumer.apply"}));
    expectColor(color, 1.25f);

    // New key: rebuilt once.
    producer->key = 2;
    producer->value = 0.5f;
    plan = run(2, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"producer.build", "consumer.apply"}));
    expectColor(color, 1.5f);
    plan = run(3, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"consumer.apply"}));

    // Nothing reads the image: its build is not recorded and it is not held; with another key meanwhile,
    // the next reader gets it rebuilt.
    consumer->on = false;
    producer->key = 3;
    producer->value = 0.75f;
    plan = run(4, color);
    EXPECT_TRUE(plan.passes.empty());
    EXPECT_TRUE(plan.resources.empty());
    expectColor(color, 1.0f);
    consumer->on = true;
    plan = run(5, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"producer.build", "consumer.apply"}));
    expectColor(color, 1.75f);

    // The reader alone finds nothing to read and declares nothing.
    producer->on = false;
    plan = run(6, color);
    EXPECT_TRUE(plan.passes.empty());
    expectColor(color, 1.0f);
}

// A pass's specialization constants select its pipeline: one per set of constants, created when first
// recorded and reused after, at most kMaxVariantsPerPipeline (4) held per pipeline description: a fifth
// releases the least recently used (counted by FrameGraph::heldObjects, with the LUT image).
TEST_F(CoreFrameGraphTest, SpecializationsArePipelinesOfTheirOwnAtMostFourHeld) {
    std::vector<float> color;
    const postfx::core::FrameGraph& graph = postfx::ContextAccess::of(*context).graph;
    uint64_t frame = 0;
    auto buildWith = [&](uint32_t variant) {
        producer->variant = variant;
        producer->key = 100 + frame;  // a new key: the build pass is recorded
        producer->value = 0.125f * float(variant);
        const postfx::FramePlan plan = run(frame++, color);
        EXPECT_EQ(names(plan), (std::vector<std::string>{"producer.build", "consumer.apply"}));
        expectColor(color, 1.0f + 0.125f * float(variant));
        return graph.heldObjects();
    };
    const size_t first = buildWith(1);
    EXPECT_EQ(buildWith(2), first + 1);
    EXPECT_EQ(buildWith(3), first + 2);
    EXPECT_EQ(buildWith(4), first + 3);
    EXPECT_EQ(buildWith(2), first + 3) << "a held specialization is reused";
    EXPECT_EQ(buildWith(5), first + 3) << "the fifth releases the least recently used (1)";
    EXPECT_EQ(buildWith(6), first + 3);
    EXPECT_EQ(buildWith(1), first + 3) << "a released one is created again, another released";
}

TEST_F(CoreFrameGraphTest, CompositesChainThroughASeparateOutputAndHostImagesCrossOnce) {
    images.separateOutput = true;
    consumer->passes = 3;
    std::vector<float> color;
    const postfx::FramePlan plan = run(0, color);
    ASSERT_EQ(names(plan), (std::vector<std::string>{"producer.build", "consumer.apply", "consumer.apply",
                                                     "consumer.apply"}));
    // The first composite reads the host's color; the next ones read what the previous wrote.
    EXPECT_EQ(plan.passes[1].reads, (std::vector<std::string>{"host.color", "producer.lut"}));
    EXPECT_EQ(plan.passes[1].writes, (std::vector<std::string>{"host.output"}));
    EXPECT_EQ(plan.passes[2].reads, (std::vector<std::string>{"host.output", "producer.lut"}));
    EXPECT_EQ(plan.passes[3].writes, (std::vector<std::string>{"host.output"}));
    expectColor(color, 1.75f);
    // Three images get image barriers: color and output one in and one out each (three passes touch
    // them; between the composites a memory barrier suffices), and the producer's image one to GENERAL
    // for its build and one to SHADER_READ_ONLY for the first read. (The harness's own barriers are
    // recorded outside the counted calls.)
    ASSERT_EQ(gImageBarriers.size(), 3u);
    for (const auto& [image, count] : gImageBarriers)
        EXPECT_EQ(count, 2);
}

// Without any pass writing a separate output, the context's copy fills it.
TEST_F(CoreFrameGraphTest, SeparateOutputWithNoWriterIsCopied) {
    images.separateOutput = true;
    consumer->on = false;
    images.color.assign(images.color.size(), 3.0f);
    std::vector<float> color;
    const postfx::FramePlan plan = run(0, color);
    EXPECT_EQ(names(plan), (std::vector<std::string>{"postfx.copy"}));
    EXPECT_EQ(plan.passes[0].effect, "postfx");
    EXPECT_EQ(color, images.color);
}

}  // namespace
}  // namespace test
