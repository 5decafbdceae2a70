// Fixture for GPU tests: a demo VulkanHost (the test's "host renderer") under the Khronos validation
// layer with synchronization validation. Every test fails if the layer reported any message, while the
// test ran (TearDown) or while the host's device and instance were destroyed (the fixture's destructor,
// after the derived fixture's members: objects a test or postfx left on the device are reported there).
#pragma once

#include <gtest/gtest.h>
#include <postfx/postfx.h>

#include "host/vulkan_host.h"
#include "small_orders_table.h"

#include <memory>

namespace test {

class GpuTest : public ::testing::Test {
protected:
    ~GpuTest() override;
    void SetUp() override;
    void TearDown() override;

    // A postfx context on the host's device with `info`'s non-handle fields.
    postfx::Status createContext(std::unique_ptr<postfx::Context>& out, postfx::ContextCreateInfo info = {});
    postfx::ContextCreateInfo hostHandles(postfx::ContextCreateInfo info = {}) const;

    std::unique_ptr<demo::VulkanHost> host;
};

// Destroys host (VulkanHost::destroy) and adds a test failure naming the first message if the validation
// layer reported any since the last takeValidationMessages(), e.g. a VkSampler left on the device. Then
// resets host. GpuTest's destructor calls it.
void destroyHostExpectingNoMessages(std::unique_ptr<demo::VulkanHost>& host);

}  // namespace test
