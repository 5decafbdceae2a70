// Device memory (docs/integration.md, "Memory"): Context::memoryUsage counts every image and buffer postfx
// holds, per owner, and equals what was allocated; ContextCreateInfo::deviceMemory hands every allocation
// to the host's callbacks (a counting allocator that binds postfx at an offset of its blocks and maps the
// host-visible ones itself): postfx then allocates and maps nothing itself, renders the same image, and
// frees every block by the time the context is destroyed; a failing or unusable allocation returns a
// status naming the resource, with nothing left allocated; a frame over ContextCreateInfo's memory budget
// is refused naming the setting that sizes its largest image, before anything is allocated.
#include "fault_scene.h"
#include "vulkan_interposer.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace test {
namespace {

// The host's allocator: a block of requirements.size + alignment bytes per request, postfx's part at
// offset `alignment` (not 0, so a bind at offset 0 would be caught by the validation layer's size
// checks or show in the image); host-visible blocks mapped here.
struct CountingAllocator {
    VkDevice device = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory{};
    uint64_t calls = 0;  // allocate() calls
    uint64_t live = 0, liveBytes = 0;
    uint64_t failAt = ~0ull;  // the allocate() call (0 = the first) that returns an error
    enum class Misuse { None, Misaligned, Unmapped } misuse = Misuse::None;

    struct Block {
        VkDeviceMemory memory;
        VkDeviceSize bytes;
        bool mapped;
    };

    static VkResult allocate(void* user, const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                             postfx::DeviceAllocation& out) {
        CountingAllocator& a = *static_cast<CountingAllocator*>(user);
        if (a.calls++ == a.failAt) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
        uint32_t type = 0;
        while (type < a.memory.memoryTypeCount &&
               !((req.memoryTypeBits >> type & 1u) &&
                 (a.memory.memoryTypes[type].propertyFlags & required) == required))
            ++type;
        if (type == a.memory.memoryTypeCount) return VK_ERROR_FEATURE_NOT_PRESENT;
        const VkDeviceSize alignment = std::max<VkDeviceSize>(req.alignment, 1);
        VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        info.allocationSize = req.size + alignment;
        info.memoryTypeIndex = type;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        if (const VkResult r = vkAllocateMemory(a.device, &info, nullptr, &memory); r != VK_SUCCESS) return r;
        const bool hostVisible = (required & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) != 0;
        out = {};
        out.memory = memory;
        out.offset = alignment;
        if (hostVisible) {
            void* base = nullptr;
            if (const VkResult r = vkMapMemory(a.device, memory, 0, VK_WHOLE_SIZE, 0, &base);
                r != VK_SUCCESS) {
                vkFreeMemory(a.device, memory, nullptr);
                return r;
            }
            out.mapped = static_cast<char*>(base) + alignment;
        }
        if (a.misuse == Misuse::Misaligned && alignment > 1) out.offset = 1;
        if (a.misuse == Misuse::Unmapped) out.mapped = nullptr;
        out.handle = new Block{memory, req.size, hostVisible};
        ++a.live;
        a.liveBytes += req.size;
        return VK_SUCCESS;
    }
    static void free(void* user, const postfx::DeviceAllocation& allocation) {
        CountingAllocator& a = *static_cast<CountingAllocator*>(user);
        const Block* b = static_cast<const Block*>(allocation.handle);
        if (b->mapped) vkUnmapMemory(a.device, b->memory);
        vkFreeMemory(a.device, b->memory, nullptr);
        --a.live;
        a.liveBytes -= b->bytes;
        delete b;
    }
};

// The frames: the fog with everything that allocates (noise, shadow map, half resolution, temporal
// histories, separate output) and the volumetrics lookup (the context's own images and uniforms); every
// third frame at another size, so images are recreated and the old ones retire.
FaultSceneOptions sceneAt(uint64_t frame) {
    FaultSceneOptions o{
        .noise = true, .shadowMap = true, .resolutionScale = 0.5f, .separateOutput = true, .temporal = true};
    if (frame % 3 == 2) {
        o.width = 6;
        o.height = 4;
        o.noiseSize = 32;
    }
    return o;
}
postfx::FrameInfo frameAt(uint64_t frame) {
    postfx::FrameInfo f = faultSceneFrame(sceneAt(frame), frame);
    f.volumetricsLookup.enabled = true;
    f.volumetricsLookup.extent = {4, 4, 4};
    return f;
}

class CoreDeviceMemoryTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        interposer = std::make_unique<VulkanInterposer>(vkGetInstanceProcAddr, vkGetDeviceProcAddr);
        allocator.device = host->device;
        vkGetPhysicalDeviceMemoryProperties(host->physicalDevice, &allocator.memory);
    }
    void TearDown() override {
        if (interposer) {
            EXPECT_TRUE(interposer->errors().empty()) << interposer->errors()[0];
        }
        interposer.reset();
        GpuTest::TearDown();
    }

    std::unique_ptr<postfx::Context> create(bool hostMemory, uint64_t memoryBudget = uint64_t(2) << 30) {
        postfx::ContextCreateInfo info;
        info.memoryBudgetBytes = memoryBudget;
        info.depth.reversedZ = true;
        info.maxExtent = {64, 64};
        if (hostMemory)
            info.deviceMemory = {&CountingAllocator::allocate, &CountingAllocator::free, &allocator};
        std::unique_ptr<postfx::Context> context;
        const postfx::Status s = postfx::Context::create(interposer->wrap(hostHandles(info)), context);
        EXPECT_TRUE(s.ok()) << s.message;
        return context;
    }
    // Records frame `frame`; `planned` receives the bytes of the resources its plan lists.
    postfx::Status record(postfx::Context& context, uint64_t frame, std::vector<float>* output = nullptr,
                          uint64_t* planned = nullptr) {
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            postfx::FramePlan plan;
            if (!planned) return;
            EXPECT_TRUE(context.plan(f, plan).ok());
            *planned = 0;
            for (const postfx::PlannedResource& r : plan.resources)
                *planned += r.bytes;
        };
        std::vector<float> color, out;
        return harness.run(context, faultSceneImages(sceneAt(frame)), frameAt(frame), color,
                           output ? output : &out);
    }
    static postfx::MemoryUsage usage(const postfx::Context& context) {
        postfx::MemoryUsage u;
        EXPECT_TRUE(context.memoryUsage(u).ok());
        return u;
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<VulkanInterposer> interposer;
    CountingAllocator allocator;
};

TEST_F(CoreDeviceMemoryTest, UsageCountsEveryAllocationPerOwner) {
    auto context = create(false);
    postfx::MemoryUsage u = usage(*context);
    EXPECT_EQ(u.totalBytes, 0u);
    ASSERT_GE(u.owners.size(), 2u);
    EXPECT_EQ(u.owners[0].name, "postfx");
    for (uint64_t f = 0; f < 6; ++f) {
        uint64_t planned = 0;
        ASSERT_TRUE(record(*context, f, nullptr, &planned).ok());
        u = usage(*context);
        uint64_t sum = u.retiringBytes, objects = 0;
        for (const postfx::MemoryUsage::Owner& o : u.owners) {
            sum += o.bytes;
            objects += o.images + o.buffers;
        }
        EXPECT_EQ(sum, u.totalBytes) << "frame " << f;
        // One vkAllocateMemory per image and buffer held; the retiring ones hold theirs too.
        if (u.retiringBytes == 0) {
            EXPECT_EQ(interposer->live(VkObjectKind::DeviceMemory), objects) << "frame " << f;
        }
        // At least the plan's bytes (texels and uniform slots, without the device's padding).
        EXPECT_GE(u.totalBytes - u.retiringBytes, planned) << "frame " << f;
        EXPECT_GT(planned, 0u);
    }
    auto owner = [&](const std::string& name) {
        for (const postfx::MemoryUsage::Owner& o : u.owners)
            if (o.name == name) return o;
        ADD_FAILURE() << "no owner " << name;
        return postfx::MemoryUsage::Owner{};
    };
    EXPECT_GT(owner("postfx").bytes, 0u);  // the volumetrics lookup's images and uniforms
    EXPECT_EQ(owner("postfx").images, 2u);
    EXPECT_GT(owner("fog").bytes, 0u);
    EXPECT_GT(owner("fog").buffers, 0u);
    EXPECT_EQ(owner("clouds").bytes, 0u);
    for (const postfx::MemoryUsage::Owner& o : u.owners)
        std::printf("[ memory ] %-10s %8llu bytes, %u images, %u buffers\n", o.name.c_str(),
                    (unsigned long long)o.bytes, o.images, o.buffers);
}

TEST_F(CoreDeviceMemoryTest, HostCallbacksGetEveryAllocationAndAllBack) {
    std::vector<std::vector<float>> own;  // the images with postfx's own allocations
    {
        auto context = create(false);
        for (uint64_t f = 0; f < 6; ++f) {
            ASSERT_TRUE(record(*context, f, &own.emplace_back()).ok());
        }
    }
    const uint64_t memoryBefore = interposer->created(VkObjectKind::DeviceMemory);
    const uint64_t mappingsBefore = interposer->created(VkObjectKind::MemoryMapping);
    {
        auto context = create(true);
        for (uint64_t f = 0; f < 6; ++f) {
            std::vector<float> output;
            ASSERT_TRUE(record(*context, f, &output).ok());
            EXPECT_TRUE(output == own[f]) << "frame " << f << " differs from postfx's own allocations";
            const postfx::MemoryUsage u = usage(*context);
            EXPECT_GT(allocator.live, 0u);
            EXPECT_EQ(u.totalBytes, allocator.liveBytes) << "frame " << f;
        }
        EXPECT_EQ(interposer->created(VkObjectKind::DeviceMemory), memoryBefore) << "postfx allocated itself";
        EXPECT_EQ(interposer->created(VkObjectKind::MemoryMapping), mappingsBefore) << "postfx mapped memory";
    }
    EXPECT_EQ(allocator.live, 0u) << "blocks left after the context was destroyed";
    EXPECT_EQ(allocator.liveBytes, 0u);
}

TEST_F(CoreDeviceMemoryTest, FailingAllocationNamesTheResourceAndLeaksNothing) {
    // How many allocations the script makes.
    {
        auto context = create(true);
        for (uint64_t f = 0; f < 3; ++f)
            ASSERT_TRUE(record(*context, f).ok());
    }
    const uint64_t total = allocator.calls;
    ASSERT_GT(total, 0u);
    for (uint64_t n = 0; n < total; ++n) {
        allocator.calls = 0;
        allocator.failAt = n;
        {
            auto context = create(true);
            bool failed = false;
            for (uint64_t f = 0; f < 3 && !failed; ++f) {
                const uint64_t commands = interposer->commands();
                const postfx::Status s = record(*context, f);
                if (s.ok()) continue;
                failed = true;
                EXPECT_EQ(s.code, postfx::Result::OutOfMemory) << s.message;
                EXPECT_NE(s.message.find("DeviceMemoryCallbacks.allocate for "), std::string::npos)
                    << s.message;
                EXPECT_NE(s.message.find("VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << s.message;
                EXPECT_EQ(interposer->commands(), commands) << "N=" << n << ": the failed record() recorded";
                // The same context records the next frame.
                allocator.failAt = ~0ull;
                const postfx::Status next = record(*context, f + 1);
                EXPECT_TRUE(next.ok()) << "N=" << n << ": " << next.message;
            }
            EXPECT_TRUE(failed) << "N=" << n << ": no allocation failed";
        }
        EXPECT_EQ(allocator.live, 0u) << "N=" << n << ": blocks left after the context was destroyed";
        EXPECT_EQ(interposer->liveTotal(), 0u) << "N=" << n << ": " << interposer->liveSummary();
        if (HasFailure()) break;
    }
}

TEST_F(CoreDeviceMemoryTest, FrameOverTheMemoryBudgetIsRefusedNamingTheKey) {
    // The frame's plan, without a budget: the fog's 16³ noise (4 KiB) is its largest image.
    uint64_t planned = 0;
    {
        auto context = create(false, 0);
        ASSERT_TRUE(record(*context, 0, nullptr, &planned).ok());
    }
    ASSERT_GT(planned, 4096u);
    // bytesText's form: KiB with one decimal at most.
    auto kib = [](uint64_t bytes) {
        char text[32];
        const double tenths = double(uint64_t(double(bytes) / 1024.0 * 10.0 + 0.5)) / 10.0;
        std::snprintf(text, sizeof text, tenths == double(uint64_t(tenths)) ? "%.0f KiB" : "%.1f KiB",
                      tenths);
        return std::string(text);
    };
    {
        auto context = create(true, planned - 1);
        const uint64_t commands = interposer->commands();
        postfx::FramePlan plan;
        postfx::Status planStatus = postfx::Status::success(), prewarmStatus = postfx::Status::success();
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            planStatus = context->plan(f, plan);
            prewarmStatus = context->prewarm(f);
        };
        std::vector<float> color, out;
        const postfx::Status s = harness.run(*context, faultSceneImages(sceneAt(0)), frameAt(0), color, &out);
        const std::string expected = "fog.noise.texture_size: 16x16x16 needs 4 KiB of images (the frame " +
                                     kib(planned) + "); the memory budget is " + kib(planned - 1) +
                                     " (ContextCreateInfo.memoryBudgetBytes)";
        EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
        EXPECT_EQ(s.message, expected);
        EXPECT_EQ(planStatus.message, expected) << "plan() checks the budget as record() does";
        EXPECT_EQ(prewarmStatus.message, expected) << "prewarm() checks the budget as record() does";
        EXPECT_EQ(allocator.calls, 0u) << "a refused frame allocated";
        EXPECT_EQ(interposer->commands(), commands) << "a refused frame recorded";
        EXPECT_EQ(usage(*context).totalBytes, 0u);
    }
    // At the budget, the same frame records.
    {
        auto context = create(true, planned);
        EXPECT_TRUE(record(*context, 0).ok());
        EXPECT_GT(allocator.calls, 0u);
    }
}

TEST_F(CoreDeviceMemoryTest, UnusableAllocationsAreRefused) {
    for (const auto misuse : {CountingAllocator::Misuse::Misaligned, CountingAllocator::Misuse::Unmapped}) {
        allocator.misuse = misuse;
        {
            auto context = create(true);
            const postfx::Status s = record(*context, 0);
            EXPECT_EQ(s.code, postfx::Result::InvalidArgument) << s.message;
            EXPECT_NE(s.message.find("DeviceMemoryCallbacks.allocate for "), std::string::npos) << s.message;
            EXPECT_NE(
                s.message.find(misuse == CountingAllocator::Misuse::Misaligned ? "alignment" : "mapped"),
                std::string::npos)
                << s.message;
        }
        EXPECT_EQ(allocator.live, 0u);
    }
}

}  // namespace
}  // namespace test
