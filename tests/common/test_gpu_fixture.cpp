// The GPU fixture's own checks: validation messages raised while the host's device is destroyed (the
// validation layer's reports of objects left alive) are counted and fail the test.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "gpu_test.h"

#include <memory>
#include <string>

namespace {

std::unique_ptr<demo::VulkanHost> validatedHost() {
    demo::HostOptions options;
    options.validation = true;
    std::string error;
    auto host = demo::VulkanHost::create(options, error);
    EXPECT_TRUE(host) << error;
    return host;
}

// A sampler the host never destroys: a leak only the device's destruction reveals.
void leakSampler(const demo::VulkanHost& host) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler sampler = VK_NULL_HANDLE;
    EXPECT_EQ(vkCreateSampler(host.device, &info, nullptr, &sampler), VK_SUCCESS);
}

// Static (EXPECT_NONFATAL_FAILURE's statement may not use locals): what GpuTest's destructor does, on a
// host that leaked a sampler.
void destroyHostThatLeakedASampler() {
    auto host = validatedHost();
    if (!host) return;
    leakSampler(*host);
    test::destroyHostExpectingNoMessages(host);
}

TEST(CommonGpuFixture, LeakedObjectIsReportedAtDeviceDestruction) {
    auto host = validatedHost();
    ASSERT_TRUE(host);
    leakSampler(*host);
    EXPECT_EQ(host->validationMessageCount(), 0u) << "the leak shows only at destruction";
    host->destroy();
    const std::vector<std::string> messages = host->takeValidationMessages();
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages[0].find("VkSampler"), std::string::npos) << messages[0];
    host->destroy();  // idempotent
    EXPECT_EQ(host->validationMessageCount(), 0u);
}

TEST(CommonGpuFixture, MessagesAtDeviceDestructionFailTheTest) {
    EXPECT_NONFATAL_FAILURE(destroyHostThatLeakedASampler(), "while destroying the device");
}

}  // namespace
