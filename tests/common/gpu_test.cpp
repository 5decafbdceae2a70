#include "gpu_test.h"

#include <string>

namespace test {

void GpuTest::SetUp() {
    demo::HostOptions options;
    options.validation = true;
    std::string error;
    host = demo::VulkanHost::create(options, error);
    ASSERT_TRUE(host) << "no Vulkan device with the validation layer: " << error;
}

void GpuTest::TearDown() {
    if (!host) return;
    // Taken, so that the destructor reports only the messages of the destruction.
    const auto messages = host->takeValidationMessages();
    EXPECT_EQ(messages.size(), 0u) << "validation messages; first: " << (messages.empty() ? "" : messages[0]);
}

GpuTest::~GpuTest() {
    destroyHostExpectingNoMessages(host);
}

void destroyHostExpectingNoMessages(std::unique_ptr<demo::VulkanHost>& host) {
    if (!host) return;
    host->destroy();
    const auto messages = host->takeValidationMessages();
    EXPECT_EQ(messages.size(), 0u) << "validation messages while destroying the device and instance; first: "
                                   << (messages.empty() ? "" : messages[0]);
    host.reset();
}

postfx::ContextCreateInfo GpuTest::hostHandles(postfx::ContextCreateInfo info) const {
    info.instance = host->instance;
    info.physicalDevice = host->physicalDevice;
    info.device = host->device;
    info.getInstanceProcAddr = vkGetInstanceProcAddr;
    info.getDeviceProcAddr = vkGetDeviceProcAddr;
    info.queueFamilyIndex = host->queueFamily;
    return info;
}

postfx::Status GpuTest::createContext(std::unique_ptr<postfx::Context>& out, postfx::ContextCreateInfo info) {
    return postfx::Context::create(hostHandles(info), out);
}

}  // namespace test
