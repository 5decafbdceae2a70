#include "fog_harness.h"

#include "core/barriers.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace test {
namespace {

using postfx::core::GpuBuffer;
using postfx::core::GpuImage;
using postfx::core::ImageTransition;

size_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R16G16B16A16_UNORM:
            return 8;
        default:
            return 4;
    }
}

bool isFloatTarget(VkFormat format) {
    return format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R32G32B32A32_SFLOAT;
}

double srgbEncode(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}
double srgbDecode(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
uint32_t unorm(double v, uint32_t bits) {
    const double top = double((1u << bits) - 1u);
    return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * top));
}

// One texel's RGBA (linear) as `format`'s 32-bit word, and back.
uint32_t packTexel(const float* rgba, VkFormat format) {
    const bool srgb = format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB ||
                      format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
    uint32_t c[4];
    switch (format) {
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
            return glm::packF2x11_1x10(glm::vec3(rgba[0], rgba[1], rgba[2]));
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32:
            for (int k = 0; k < 3; ++k)
                c[k] = unorm(rgba[k], 10);
            c[3] = unorm(rgba[3], 2);
            if (format == VK_FORMAT_A2R10G10B10_UNORM_PACK32) std::swap(c[0], c[2]);
            return c[0] | c[1] << 10 | c[2] << 20 | c[3] << 30;
        default:  // 8 bits per channel, R first (B first for B8G8R8A8)
            for (int k = 0; k < 3; ++k)
                c[k] = unorm(srgb ? srgbEncode(rgba[k]) : rgba[k], 8);
            c[3] = unorm(rgba[3], 8);
            if (format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB)
                std::swap(c[0], c[2]);
            return c[0] | c[1] << 8 | c[2] << 16 | c[3] << 24;
    }
}

void unpackTexel(uint32_t word, VkFormat format, float* rgba) {
    const bool srgb = format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB ||
                      format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
    switch (format) {
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32: {
            const glm::vec3 v = glm::unpackF2x11_1x10(word);
            rgba[0] = v.x, rgba[1] = v.y, rgba[2] = v.z, rgba[3] = 1.0f;
            return;
        }
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32: {
            uint32_t c[3] = {word & 1023u, word >> 10 & 1023u, word >> 20 & 1023u};
            if (format == VK_FORMAT_A2R10G10B10_UNORM_PACK32) std::swap(c[0], c[2]);
            for (int k = 0; k < 3; ++k)
                rgba[k] = float(c[k] / 1023.0);
            rgba[3] = float((word >> 30) / 3.0);
            return;
        }
        default: {
            uint32_t c[4] = {word & 255u, word >> 8 & 255u, word >> 16 & 255u, word >> 24};
            if (format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB)
                std::swap(c[0], c[2]);
            for (int k = 0; k < 3; ++k)
                rgba[k] = float(srgb ? srgbDecode(c[k] / 255.0) : c[k] / 255.0);
            rgba[3] = float(c[3] / 255.0);
            return;
        }
    }
}

void packColor(const std::vector<float>& rgba, VkFormat format, void* dst) {
    if (format == VK_FORMAT_R32G32B32A32_SFLOAT) {
        std::memcpy(dst, rgba.data(), rgba.size() * 4);
        return;
    }
    if (format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16B16A16_UNORM) {
        uint16_t* out = static_cast<uint16_t*>(dst);
        for (size_t i = 0; i < rgba.size(); ++i)
            out[i] = format == VK_FORMAT_R16G16B16A16_SFLOAT ? glm::packHalf1x16(rgba[i])
                                                             : uint16_t(unorm(rgba[i], 16));
        return;
    }
    uint32_t* out = static_cast<uint32_t*>(dst);
    for (size_t i = 0; i < rgba.size() / 4; ++i)
        out[i] = packTexel(&rgba[i * 4], format);
}

void unpackColor(const void* src, VkFormat format, size_t count, std::vector<float>& rgba) {
    rgba.resize(count);
    if (format == VK_FORMAT_R32G32B32A32_SFLOAT) {
        std::memcpy(rgba.data(), src, count * 4);
        return;
    }
    if (format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16B16A16_UNORM) {
        const uint16_t* in = static_cast<const uint16_t*>(src);
        for (size_t i = 0; i < count; ++i)
            rgba[i] = format == VK_FORMAT_R16G16B16A16_SFLOAT ? glm::unpackHalf1x16(in[i]) : in[i] / 65535.0f;
        return;
    }
    const uint32_t* in = static_cast<const uint32_t*>(src);
    for (size_t i = 0; i < count / 4; ++i)
        unpackTexel(in[i], format, &rgba[i * 4]);
}

ImageTransition to(VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout layout,
                   VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess) {
    ImageTransition t;
    t.image = image;
    t.aspect = aspect;
    t.oldLayout = from;
    t.newLayout = layout;
    t.srcStage = srcStage;
    t.srcAccess = srcAccess;
    t.dstStage = dstStage;
    t.dstAccess = dstAccess;
    return t;
}

}  // namespace

GpuImage uploadSampledImage(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                            postfx::core::ImageDesc desc, const void* bytes, size_t size) {
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    GpuImage image;
    postfx::core::GpuBuffer upload;
    EXPECT_TRUE(image.create(gpu, desc, "test host texture").ok());
    EXPECT_TRUE(upload.create(gpu, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "test upload").ok());
    if (!image.handle() || !upload.mapped()) return image;
    std::memcpy(upload.mapped(), bytes, size);
    constexpr VkImageAspectFlags kColor = VK_IMAGE_ASPECT_COLOR_BIT;
    std::string error;
    EXPECT_TRUE(host.submitAndWait(
        [&](VkCommandBuffer cmd) {
            postfx::core::transition(
                gpu, cmd,
                to(image.handle(), kColor, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_WRITE_BIT));
            VkBufferImageCopy region{};
            region.imageSubresource = {kColor, 0, 0, 1};
            region.imageExtent = desc.extent;
            vkCmdCopyBufferToImage(cmd, upload.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   1, &region);
            postfx::core::transition(gpu, cmd,
                                     to(image.handle(), kColor, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                                        VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT));
        },
        error))
        << error;
    return image;
}

postfx::Status FogHarness::run(postfx::Context& context, const FogHarnessImages& images,
                               postfx::FrameInfo frame, std::vector<float>& color,
                               std::vector<float>* output) {
    const uint32_t w = images.width, h = images.height;
    const size_t pixels = size_t(w) * h;
    const size_t colorBytes = pixels * texelBytes(images.colorFormat);
    const VkExtent2D extent{w, h};

    postfx::core::ImageDesc cd;
    cd.format = images.colorFormat;
    cd.extent = {w, h, 1};
    cd.usage =
        images.colorUsage
            ? images.colorUsage
            : VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                (isFloatTarget(images.colorFormat) ? VK_IMAGE_USAGE_STORAGE_BIT
                                                                   : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT));
    GpuImage colorImage, outputImage, depthImage, shadowImage, atlasImage;
    const bool shadow = !images.shadow.empty(), atlas = !images.localShadow.empty();
    const size_t shadowBytes = size_t(images.shadowWidth) * images.shadowHeight * 4;
    const size_t atlasBytes = size_t(images.localShadowWidth) * images.localShadowHeight * 4;
    postfx::Status s = colorImage.create(gpu_, cd, "test color");
    if (s && images.separateOutput) s = outputImage.create(gpu_, cd, "test output");
    postfx::core::ImageDesc dd = cd;
    dd.format = VK_FORMAT_D32_SFLOAT;
    dd.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
               VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (s) s = depthImage.create(gpu_, dd, "test depth");
    postfx::core::ImageDesc sd = cd;
    sd.format = VK_FORMAT_R32_SFLOAT;
    sd.extent = {images.shadowWidth, images.shadowHeight, 1};
    sd.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (s && shadow) s = shadowImage.create(gpu_, sd, "test shadow map");
    postfx::core::ImageDesc ad = sd;
    ad.extent = {images.localShadowWidth, images.localShadowHeight, 1};
    if (s && atlas) s = atlasImage.create(gpu_, ad, "test local shadow atlas");
    GpuBuffer upload, readback;
    if (s)
        s = upload.create(gpu_, colorBytes + pixels * 4 + shadowBytes + atlasBytes,
                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "upload");
    if (s) s = readback.create(gpu_, colorBytes * 2, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback");
    if (!s) return s;
    packColor(images.color, images.colorFormat, upload.mapped());
    std::memcpy(static_cast<char*>(upload.mapped()) + colorBytes, images.depth.data(), pixels * 4);
    if (shadow)
        std::memcpy(static_cast<char*>(upload.mapped()) + colorBytes + pixels * 4, images.shadow.data(),
                    shadowBytes);
    if (atlas)
        std::memcpy(static_cast<char*>(upload.mapped()) + colorBytes + pixels * 4 + shadowBytes,
                    images.localShadow.data(), atlasBytes);

    constexpr VkImageAspectFlags kColor = VK_IMAGE_ASPECT_COLOR_BIT, kDepth = VK_IMAGE_ASPECT_DEPTH_BIT;
    constexpr VkPipelineStageFlags kAll = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                                   kCopy = VK_PIPELINE_STAGE_TRANSFER_BIT;
    constexpr VkAccessFlags kAny = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    postfx::Status recordStatus;
    std::string error;
    const bool submitted = host_.submitAndWait(
        [&](VkCommandBuffer cmd) {
            std::vector<std::pair<GpuImage*, VkImageAspectFlags>> all = {{&colorImage, kColor},
                                                                         {&depthImage, kDepth}};
            if (images.separateOutput) all.push_back({&outputImage, kColor});
            if (shadow) all.push_back({&shadowImage, kColor});
            if (atlas) all.push_back({&atlasImage, kColor});
            for (auto& [image, aspect] : all)
                postfx::core::transition(
                    gpu_, cmd,
                    to(image->handle(), aspect, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, kCopy,
                       VK_ACCESS_TRANSFER_WRITE_BIT));
            VkBufferImageCopy region{};
            region.imageSubresource = {kColor, 0, 0, 1};
            region.imageExtent = {w, h, 1};
            vkCmdCopyBufferToImage(cmd, upload.handle(), colorImage.handle(),
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            if (images.separateOutput)
                vkCmdCopyBufferToImage(cmd, upload.handle(), outputImage.handle(),
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            region.bufferOffset = colorBytes;
            region.imageSubresource.aspectMask = kDepth;
            vkCmdCopyBufferToImage(cmd, upload.handle(), depthImage.handle(),
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            // The R32F maps: uploaded, then handed over in SHADER_READ_ONLY_OPTIMAL.
            const auto uploadMap = [&](GpuImage& image, VkDeviceSize offset, uint32_t mapW, uint32_t mapH) {
                VkBufferImageCopy mapRegion{};
                mapRegion.bufferOffset = offset;
                mapRegion.imageSubresource = {kColor, 0, 0, 1};
                mapRegion.imageExtent = {mapW, mapH, 1};
                vkCmdCopyBufferToImage(cmd, upload.handle(), image.handle(),
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &mapRegion);
                postfx::core::transition(gpu_, cmd,
                                         to(image.handle(), kColor, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kCopy,
                                            VK_ACCESS_TRANSFER_WRITE_BIT, kAll, kAny));
            };
            if (shadow)
                uploadMap(shadowImage, colorBytes + pixels * 4, images.shadowWidth, images.shadowHeight);
            if (atlas)
                uploadMap(atlasImage, colorBytes + pixels * 4 + shadowBytes, images.localShadowWidth,
                          images.localShadowHeight);
            // Into the layouts the "host" hands postfx.
            postfx::core::transition(gpu_, cmd,
                                     to(colorImage.handle(), kColor, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        images.colorLayout, kCopy, VK_ACCESS_TRANSFER_WRITE_BIT, kAll, kAny));
            postfx::core::transition(gpu_, cmd,
                                     to(depthImage.handle(), kDepth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        images.depthLayout, kCopy, VK_ACCESS_TRANSFER_WRITE_BIT, kAll, kAny));
            if (images.separateOutput)
                postfx::core::transition(
                    gpu_, cmd,
                    to(outputImage.handle(), kColor, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, images.colorLayout,
                       kCopy, VK_ACCESS_TRANSFER_WRITE_BIT, kAll, kAny));

            frame.commandBuffer = cmd;
            frame.color = {colorImage.handle(), colorImage.view(), images.colorFormat, extent,
                           images.colorLayout,  cd.usage};
            frame.depth = {depthImage.handle(), depthImage.view(), VK_FORMAT_D32_SFLOAT, extent,
                           images.depthLayout,  dd.usage};
            if (images.separateOutput)
                frame.output = {outputImage.handle(), outputImage.view(),
                                images.colorFormat,   extent,
                                images.colorLayout,   cd.usage};
            if (shadow)
                frame.shadowMap.image = {shadowImage.handle(),
                                         shadowImage.view(),
                                         VK_FORMAT_R32_SFLOAT,
                                         {images.shadowWidth, images.shadowHeight},
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                         sd.usage};
            if (atlas)
                frame.localShadows.image = {atlasImage.handle(),
                                            atlasImage.view(),
                                            VK_FORMAT_R32_SFLOAT,
                                            {images.localShadowWidth, images.localShadowHeight},
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                            ad.usage};
            if (onBeforeRecord) onBeforeRecord(frame);
            recordStatus = context.record(frame);
            if (recordStatus && onAfterRecord) onAfterRecord(cmd);

            // Read back, trusting postfx to have returned the images in the layouts they came in.
            region = {};
            region.imageSubresource = {kColor, 0, 0, 1};
            region.imageExtent = {w, h, 1};
            for (GpuImage* image : {&colorImage, &outputImage}) {
                if (!image->handle()) continue;
                postfx::core::transition(
                    gpu_, cmd,
                    to(image->handle(), kColor, images.colorLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       kAll, VK_ACCESS_MEMORY_WRITE_BIT, kCopy, VK_ACCESS_TRANSFER_READ_BIT));
                vkCmdCopyImageToBuffer(cmd, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                       readback.handle(), 1, &region);
                region.bufferOffset = colorBytes;
            }
            VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, kCopy, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                                 nullptr);
        },
        error);
    if (!submitted) return {postfx::Result::VulkanError, error};
    unpackColor(readback.mapped(), images.colorFormat, pixels * 4, color);
    if (output && images.separateOutput)
        unpackColor(static_cast<const char*>(readback.mapped()) + colorBytes, images.colorFormat, pixels * 4,
                    *output);
    return recordStatus;
}

postfx::CameraInput testCamera(glm::dvec3 position, float fovYDeg, float aspect, float nearPlane,
                               float farPlane, bool reversedZ) {
    postfx::CameraInput camera;
    camera.position = position;
    camera.view = glm::mat4(1.0f);
    camera.view[3] = glm::vec4(-glm::vec3(position), 1.0f);
    // Right-handed view (looking down -z) to Vulkan clip (y down), depth per convention.
    const float f = 1.0f / std::tan(glm::radians(fovYDeg) / 2.0f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    if (reversedZ) {
        p[2][2] = nearPlane / (farPlane - nearPlane);
        p[3][2] = farPlane * nearPlane / (farPlane - nearPlane);
    } else {
        p[2][2] = farPlane / (nearPlane - farPlane);
        p[3][2] = farPlane * nearPlane / (nearPlane - farPlane);
    }
    camera.projection = p;
    return camera;
}

glm::dvec3 pixelDirection(const postfx::CameraInput& camera, uint32_t i, uint32_t j, uint32_t w, uint32_t h) {
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0, 0, 0, 1);
    const glm::dmat4 clipToView = glm::inverse(glm::dmat4(camera.projection) * rotation);
    const glm::dvec4 p =
        clipToView * glm::dvec4((i + 0.5) / w * 2.0 - 1.0, (j + 0.5) / h * 2.0 - 1.0, 0.5, 1.0);
    return glm::normalize(glm::dvec3(p) / p.w);
}

float depthAtDistance(const postfx::CameraInput& camera, glm::dvec3 direction, double distance) {
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0, 0, 0, 1);
    const glm::dvec4 clip = glm::dmat4(camera.projection) * rotation * glm::dvec4(direction * distance, 1.0);
    return float(clip.z / clip.w);
}

FogHarnessImages surfaceImages(const postfx::CameraInput& camera, uint32_t width, uint32_t height,
                               const std::function<double(uint32_t, uint32_t)>& distance,
                               const std::function<float(uint32_t, uint32_t, int)>& color) {
    FogHarnessImages im;
    im.width = width;
    im.height = height;
    im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    im.color.resize(size_t(width) * height * 4);
    im.depth.resize(size_t(width) * height);
    for (uint32_t j = 0; j < height; ++j)
        for (uint32_t i = 0; i < width; ++i) {
            const size_t p = size_t(j) * width + i;
            const double d = distance(i, j);
            im.depth[p] = std::isinf(d)
                              ? 0.0f
                              : depthAtDistance(camera, pixelDirection(camera, i, j, width, height), d);
            for (int c = 0; c < 4; ++c)
                im.color[p * 4 + c] = color(i, j, c);
        }
    return im;
}

postfx::CameraInput lookCamera(glm::dvec3 position, glm::dvec3 forward, glm::dvec3 up, float fovYDeg,
                               float aspect) {
    postfx::CameraInput camera = testCamera(position, fovYDeg, aspect, 0.1f, 1e6f, true);
    camera.view = glm::mat4(glm::lookAt(position, position + forward, up));
    return camera;
}

void ReversedZContextTest::SetUp() {
    GpuTest::SetUp();
    ASSERT_TRUE(host);
    ASSERT_TRUE(gpu.init(hostHandles()).ok());
    postfx::ContextCreateInfo info;
    info.depth.reversedZ = true;
    ASSERT_TRUE(createContext(context, info).ok());
}

std::vector<std::string> passNames(const postfx::FramePlan& plan) {
    std::vector<std::string> names;
    for (const postfx::PlannedPass& p : plan.passes)
        names.push_back(p.name);
    return names;
}

postfx::FramePlan planAndRecord(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                postfx::Context& context, const FogHarnessImages& images,
                                const postfx::FrameInfo& frame,
                                const std::function<void(const postfx::FrameInfo&)>& beforeRecord) {
    postfx::FramePlan plan;
    postfx::Status planned = postfx::Status::success();
    FogHarness harness(host, gpu);
    harness.onBeforeRecord = [&](const postfx::FrameInfo& f) {
        if (beforeRecord) beforeRecord(f);
        planned = context.plan(f, plan);
    };
    std::vector<float> out;
    const postfx::Status s = harness.run(context, images, frame, out);
    EXPECT_TRUE(s.ok()) << s.message;
    EXPECT_TRUE(planned.ok()) << planned.message;
    std::vector<postfx::PassTiming> timings;
    EXPECT_TRUE(context.readPassTimings(frame.frameIndex, timings).ok());
    std::vector<std::string> recorded;
    for (const postfx::PassTiming& t : timings)
        recorded.push_back(t.name);
    EXPECT_EQ(recorded, passNames(plan)) << "frame " << frame.frameIndex;
    return plan;
}

std::vector<uint8_t> readHeldImage(demo::VulkanHost& host, const postfx::core::Gpu& gpu,
                                   const postfx::Context& context, const char* name, VkExtent3D& extent) {
    postfx::core::GpuBuffer buffer;
    EXPECT_TRUE(buffer.create(gpu, 64u << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback").ok());
    VkDeviceSize bytes = 0;
    postfx::Status status;
    std::string error;
    EXPECT_TRUE(host.submitAndWait(
        [&](VkCommandBuffer cmd) {
            status = context.recordImageReadback({name}, cmd, buffer.handle(), 0, extent, bytes);
        },
        error))
        << error;
    EXPECT_TRUE(status.ok()) << status.message;
    const auto* p = static_cast<const uint8_t*>(buffer.mapped());
    return status.ok() ? std::vector<uint8_t>(p, p + bytes) : std::vector<uint8_t>{};
}

}  // namespace test
