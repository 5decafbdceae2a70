// A minimal host for driving postfx's fog directly in tests: color and depth images with chosen
// contents and layouts, one record() call, color read back.
#pragma once

#include "core/gpu_resources.h"
#include "gpu_test.h"

#include <glm/glm.hpp>

#include <postfx/frame_plan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace test {

struct FogHarnessImages {
    uint32_t width = 0, height = 0;
    // Any color target postfx takes (RGBA16F/32F, 8-bit UNORM/sRGB, B10G11R11, A2B10G10R10, RGBA16 UNORM):
    // `color` is packed into it and read back from it (linear values; sRGB encoded and decoded here).
    VkFormat colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // Usage of the color (and output) image; 0: STORAGE and TRANSFER_SRC/DST for RGBA16F/32F, the two
    // transfer bits for the others.
    VkImageUsageFlags colorUsage = 0;
    std::vector<float> color;  // RGBA
    std::vector<float> depth;  // one per pixel
    VkImageLayout colorLayout = VK_IMAGE_LAYOUT_GENERAL;
    VkImageLayout depthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    bool separateOutput = false;  // write into FrameInfo.output instead of in place
    // Optional R32_SFLOAT shadow map (row-major, top row first), handed over in SHADER_READ_ONLY_OPTIMAL
    // as FrameInfo.shadowMap.image; the caller sets the frame's shadowMap matrix, bias and convention.
    std::vector<float> shadow;
    uint32_t shadowWidth = 0, shadowHeight = 0;
    // Optional R32_SFLOAT local-light shadow atlas, the same way, as FrameInfo.localShadows.image; the
    // caller sets the frame's localShadows.shadows and the lights' shadow indices.
    std::vector<float> localShadow;
    uint32_t localShadowWidth = 0, localShadowHeight = 0;
};

class FogHarness {
public:
    FogHarness(demo::VulkanHost& host, const postfx::core::Gpu& gpu) : host_(host), gpu_(gpu) {}

    // Uploads the images, records `frame` (its command buffer and images filled in here), submits,
    // reads back the color image (and the output image when separate). Returns the record() status.
    postfx::Status run(postfx::Context& context, const FogHarnessImages& images, postfx::FrameInfo frame,
                       std::vector<float>& color, std::vector<float>* output = nullptr);

    // Called with the frame as record() gets it (images filled in), just before record().
    std::function<void(const postfx::FrameInfo&)> onBeforeRecord;
    // Called with the command buffer right after a successful record(), before the read back: the host's
    // commands that follow postfx's (a forward pass reading the volumetrics lookup).
    std::function<void(VkCommandBuffer)> onAfterRecord;

private:
    demo::VulkanHost& host_;
    const postfx::core::Gpu& gpu_;
};

// A camera at `position` looking down -z with a reversed-Z (or standard) finite projection.
postfx::CameraInput testCamera(glm::dvec3 position, float fovYDeg, float aspect, float nearPlane,
                               float farPlane, bool reversedZ);

// Unit direction (camera-relative world) through the centre of pixel (i, j), and the depth value of the
// point at distance `distance` along it, for `camera`.
glm::dvec3 pixelDirection(const postfx::CameraInput& camera, uint32_t i, uint32_t j, uint32_t w, uint32_t h);
float depthAtDistance(const postfx::CameraInput& camera, glm::dvec3 direction, double distance);

// RGBA32F color and reversed-Z depth of `width` × `height` pixels for `camera`: pixel (i, j) sees a surface
// distance(i, j) metres along its ray (no geometry, depth 0, where that is infinite); its channel c has
// color(i, j, c).
FogHarnessImages surfaceImages(const postfx::CameraInput& camera, uint32_t width, uint32_t height,
                               const std::function<double(uint32_t, uint32_t)>& distance,
                               const std::function<float(uint32_t, uint32_t, int)>& color);

// A camera at world `position` looking along `forward` with `up` (reversed Z, near 0.1 m, far 1e6 m).
postfx::CameraInput lookCamera(glm::dvec3 position, glm::dvec3 forward, glm::dvec3 up, float fovYDeg,
                               float aspect);

// A GpuTest with postfx's device functions (`gpu`) and a context of reversed Z (`context`) on its host.
class ReversedZContextTest : public GpuTest {
protected:
    void SetUp() override;

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
};

// Plans `frame` and records it with `images` (FogHarness): expects both to succeed and the passes it
// recorded (their timings) to be the plan's; returns the plan. `beforeRecord`, if given, sees the frame
// as it is recorded (its images filled in), before it is planned.
postfx::FramePlan planAndRecord(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                postfx::Context& context, const FogHarnessImages& images,
                                const postfx::FrameInfo& frame,
                                const std::function<void(const postfx::FrameInfo&)>& beforeRecord = {});

// A resource postfx holds (Context::recordImageReadback: a LUT, a noise texture) read back as stored,
// texel after texel; `extent` receives its extent.
std::vector<uint8_t> readHeldImage(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                   const postfx::Context& context, const char* name, VkExtent3D& extent);

// A host texture for postfx to sample (a coverage map, noise): `desc` (usage SAMPLED | TRANSFER_DST
// added) filled with `bytes` (tightly packed texels, x fastest) and left in SHADER_READ_ONLY_OPTIMAL.
// Expects the upload to succeed.
postfx::core::GpuImage uploadSampledImage(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                          postfx::core::ImageDesc desc, const void* bytes, size_t size);

// The plan's passes' names, in recording order.
std::vector<std::string> passNames(const postfx::FramePlan& plan);

}  // namespace test
