// One frame of the demo renderer: uniforms, shadow map, G-buffer, lighting, postfx.
#include "demo_shared.h"
#include "host/camera_math.h"
#include "host/renderer_impl.h"

namespace demo {
namespace {

// Stages in which anyone reads the HDR image after a frame: render()'s readback copy (TRANSFER),
// postfx (COMPUTE_SHADER), a window's blit (TRANSFER) or tonemap (COMPUTE_SHADER / FRAGMENT_SHADER).
constexpr VkPipelineStageFlags kHdrReaderStages = VK_PIPELINE_STAGE_TRANSFER_BIT |
                                                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
// Stages reading the frame uniforms.
constexpr VkPipelineStageFlags kUniformStages =
    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

shared::FrameUniforms frameUniforms(const Scene& scene, const RenderOptions& options, const ShadowFit& fit,
                                    bool shadows) {
    const Camera& cam = scene.camera;
    const float aspect = float(options.width) / float(options.height);
    const glm::mat4 proj = perspectiveProjection(glm::radians(cam.fovYDeg), aspect, cam.nearPlane,
                                                 cam.farPlane, options.reversedZ, options.infiniteFar);
    glm::mat4 viewRel = cameraView(cam);
    viewRel[3] = glm::vec4(0, 0, 0, 1);  // rotation only: positions are camera-relative

    shared::FrameUniforms u{};
    u.viewProj = proj * viewRel;
    u.invViewProj = glm::inverse(u.viewProj);
    u.shadowViewProj = fit.viewProj;
    u.cameraPosition = glm::vec4(cam.position, 1.0f);
    u.toSun = glm::vec4(glm::normalize(scene.sun.direction), shadows ? 1.0f : 0.0f);
    u.sunIlluminance = glm::vec4(scene.sun.illuminance, 0.0f);
    u.ambient = glm::vec4(scene.ambient, 0.0f);
    u.sky = glm::vec4(scene.sky, 0.0f);
    u.depthParams = glm::vec4(options.reversedZ ? 0.0f : 1.0f, 1.0f / float(options.shadowMapSize),
                              fit.texelWorldSize, 0.0f);
    u.extent = glm::uvec4(options.width, options.height, 0, 0);
    return u;
}

}  // namespace

bool Renderer::recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex, std::string& error) {
    Impl& r = *impl_;
    const ShadowFit fit = fitShadowMap(scene, r.options.shadowMapSize);
    const bool shadows = scene.sun.shadows && fit.valid;
    r.shadowInfo.enabled = shadows;
    r.shadowInfo.viewProj = fit.viewProj;
    r.shadowInfo.texelWorldSize = fit.texelWorldSize;

    // Frame uniforms: overwrite after the previous frame's readers (WAR), then publish to this frame's.
    const shared::FrameUniforms u = frameUniforms(scene, r.options, fit, shadows);
    bufferBarrier(cmd, r.frameUniforms, kUniformStages, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdUpdateBuffer(cmd, r.frameUniforms.buffer, 0, sizeof(u), &u);
    bufferBarrier(cmd, r.frameUniforms, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  kUniformStages, VK_ACCESS_UNIFORM_READ_BIT);

    // Raster passes leave their attachments readable by compute shaders.
    if (shadows) r.shadow.record(cmd, r.frameSet, r.vertices, r.indices, r.draws);
    r.gbuffer.record(cmd, r.frameSet, r.vertices, r.indices, r.draws);

    // Lighting overwrites every HDR pixel: discard the old content once its readers are done.
    imageBarrier(cmd, r.hdr, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kHdrReaderStages, 0,
                 kCompute, VK_ACCESS_SHADER_WRITE_BIT);
    r.lighting.record(cmd, r.extent);
    imageBarrier(cmd, r.hdr, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, kCompute,
                 VK_ACCESS_SHADER_WRITE_BIT, kCompute,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

    // postfx composites into the HDR image (compute only) and returns it in GENERAL.
    postfx::FrameInfo frame;
    frame.commandBuffer = cmd;
    frame.frameIndex = frameIndex;
    frame.color = {r.hdr.image, r.hdr.view, r.hdr.format, r.extent, VK_IMAGE_LAYOUT_GENERAL};
    frame.depth = {r.gbuffer.depth.image, r.gbuffer.depth.view, r.gbuffer.depth.format, r.extent,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    if (postfx::Status s = r.postfx->record(frame); !s.ok()) {
        error = "postfx record: " + s.message;
        return false;
    }
    r.nextFrameIndex = std::max(r.nextFrameIndex, frameIndex + 1);
    return true;
}

// After recordFrame: HDR image (GENERAL, compute writes) -> readback buffer -> host. The image is left in
// TRANSFER_SRC_OPTIMAL; the next frame discards it anyway.
void Renderer::Impl::recordReadback(VkCommandBuffer cmd) const {
    imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute,
                 VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    bufferBarrier(cmd, readback, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

}  // namespace demo
