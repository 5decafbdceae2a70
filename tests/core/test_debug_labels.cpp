// VK_EXT_debug_utils labels (ContextCreateInfo::debugLabels): with the flag, record() wraps its work in a
// "postfx" label and each pass in a label named as the frame plan names it; without it, no label call is
// made. The label commands are intercepted through the getInstanceProcAddr postfx is given.
#include "fog_harness.h"

#include <cstring>
#include <string>
#include <vector>

namespace test {
namespace {

// What the interposed label commands saw: "+name" for a begin, "-" for an end.
std::vector<std::string> gLabelCalls;
PFN_vkCmdBeginDebugUtilsLabelEXT gRealBegin = nullptr;
PFN_vkCmdEndDebugUtilsLabelEXT gRealEnd = nullptr;

VKAPI_ATTR void VKAPI_CALL recordBegin(VkCommandBuffer cmd, const VkDebugUtilsLabelEXT* label) {
    gLabelCalls.push_back(std::string("+") + label->pLabelName);
    gRealBegin(cmd, label);
}

VKAPI_ATTR void VKAPI_CALL recordEnd(VkCommandBuffer cmd) {
    gLabelCalls.push_back("-");
    gRealEnd(cmd);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL interposedInstanceProcAddr(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkCmdBeginDebugUtilsLabelEXT") == 0) {
        gRealBegin =
            reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(vkGetInstanceProcAddr(instance, name));
        return reinterpret_cast<PFN_vkVoidFunction>(recordBegin);
    }
    if (std::strcmp(name, "vkCmdEndDebugUtilsLabelEXT") == 0) {
        gRealEnd = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(vkGetInstanceProcAddr(instance, name));
        return reinterpret_cast<PFN_vkVoidFunction>(recordEnd);
    }
    return vkGetInstanceProcAddr(instance, name);
}

class CoreDebugLabels : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        gLabelCalls.clear();
    }

    // A reduced-resolution fog frame (two passes: fog.raymarch, fog.upsample) on a 16×8 image.
    postfx::Status recordFog(bool debugLabels, std::vector<std::string>& planned) {
        postfx::ContextCreateInfo info = hostHandles();
        info.getInstanceProcAddr = interposedInstanceProcAddr;
        info.debugLabels = debugLabels;
        info.depth.reversedZ = true;
        std::unique_ptr<postfx::Context> context;
        if (postfx::Status s = postfx::Context::create(info, context); !s) return s;

        postfx::FrameInfo frame;
        frame.camera = testCamera({0.0, 1.5, 0.0}, 60.0f, 2.0f, 0.1f, 1000.0f, true);
        frame.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
        frame.sun.illuminance = {1000.0f, 1000.0f, 1000.0f};
        frame.fog.enabled = true;
        frame.fog.density = 0.05f;
        frame.fog.heightFalloff = 0.0f;
        frame.fog.maxDistance = 30.0f;
        frame.fog.resolutionScale = 0.5f;
        FogHarnessImages im;
        im.width = 16;
        im.height = 8;
        im.color.assign(size_t(im.width) * im.height * 4, 1.0f);
        im.depth.assign(size_t(im.width) * im.height, 0.0f);
        postfx::FramePlan plan;
        FogHarness harness(*host, gpu);
        harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
            ASSERT_TRUE(context->plan(f, plan).ok());
        };
        std::vector<float> out;
        postfx::Status s = harness.run(*context, im, frame, out);
        for (const postfx::PlannedPass& p : plan.passes)
            planned.push_back(p.name);
        return s;
    }

    postfx::core::Gpu gpu;
};

TEST_F(CoreDebugLabels, EachPassIsLabelledByItsPlannedName) {
    std::vector<std::string> planned;
    const postfx::Status s = recordFog(true, planned);
    ASSERT_TRUE(s.ok()) << s.message;
    ASSERT_EQ(planned, (std::vector<std::string>{"fog.raymarch", "fog.upsample"}));
    std::vector<std::string> expected{"+postfx"};
    for (const std::string& name : planned) {
        expected.push_back("+" + name);
        expected.push_back("-");
    }
    expected.push_back("-");
    EXPECT_EQ(gLabelCalls, expected);
}

TEST_F(CoreDebugLabels, NoLabelCallWithoutTheFlag) {
    std::vector<std::string> planned;
    const postfx::Status s = recordFog(false, planned);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_FALSE(planned.empty());
    EXPECT_TRUE(gLabelCalls.empty());
}

TEST_F(CoreDebugLabels, FlagWithoutTheExtensionIsAnError) {
    postfx::ContextCreateInfo info = hostHandles();
    info.getInstanceProcAddr = [](VkInstance instance, const char* name) -> PFN_vkVoidFunction {
        if (std::strstr(name, "DebugUtilsLabel")) return nullptr;  // as a loader without the extension
        return vkGetInstanceProcAddr(instance, name);
    };
    info.debugLabels = true;
    std::unique_ptr<postfx::Context> context;
    const postfx::Status s = postfx::Context::create(info, context);
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message.find("debugLabels"), std::string::npos) << s.message;
    EXPECT_FALSE(context);
}

}  // namespace
}  // namespace test
