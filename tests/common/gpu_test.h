// Fixture for GPU tests: a demo VulkanHost (the test's "host renderer") under the Khronos validation
// layer with synchronization validation. Every test fails if the layer reported any message.
#pragma once

#include <gtest/gtest.h>
#include <postfx/postfx.h>

#include "host/vulkan_host.h"

#include <memory>

namespace test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // A postfx context on the host's device with `info`'s non-handle fields.
    postfx::Status createContext(std::unique_ptr<postfx::Context>& out, postfx::ContextCreateInfo info = {});
    postfx::ContextCreateInfo hostHandles(postfx::ContextCreateInfo info = {}) const;

    std::unique_ptr<demo::VulkanHost> host;
};

}  // namespace test
