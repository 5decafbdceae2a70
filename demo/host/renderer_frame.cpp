// One frame of the demo renderer: uniforms, shadow map, G-buffer, lighting, postfx.
#include "demo_shared.h"
#include "host/camera_math.h"
#include "host/metering.h"
#include "host/renderer_impl.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace demo {
namespace {

// Stages in which anyone reads the HDR image after a frame: render()'s readback copy (TRANSFER),
// postfx (COMPUTE_SHADER), a window's blit (TRANSFER) or tonemap (COMPUTE_SHADER / FRAGMENT_SHADER).
constexpr VkPipelineStageFlags kHdrReaderStages = VK_PIPELINE_STAGE_TRANSFER_BIT |
                                                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
// Stages reading the frame uniforms (the forward pass's vertex and fragment shaders too).
constexpr VkPipelineStageFlags kUniformStages = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                                VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

// The light is pre-exposed (light.preExposure): the lighting writes radiance × preExposure, as postfx does.
shared::FrameUniforms makeFrameUniforms(const Scene& scene, const RenderOptions& options,
                                        const glm::mat4& proj, const ShadowFit& fit, bool shadows,
                                        const FrameLight& light) {
    const AtmosphereLighting& atmosphere = light.surfaces;
    const float preExposure = light.preExposure;
    const Camera& cam = scene.camera;
    glm::mat4 viewRel = cameraView(cam);
    viewRel[3] = glm::vec4(0, 0, 0, 1);  // rotation only: positions are camera-relative

    shared::FrameUniforms u{};
    u.viewProj = proj * viewRel;
    u.invViewProj = glm::inverse(u.viewProj);
    u.shadowViewProj = fit.viewProj;
    u.cameraPosition = glm::vec4(cam.position, 1.0f);
    u.toSun = glm::vec4(glm::normalize(scene.sun.direction), shadows ? 1.0f : 0.0f);
    u.sunIlluminance = glm::vec4(scene.sun.illuminance * preExposure, 0.0f);
    u.ambient = glm::vec4(atmosphere.ambient * preExposure, 0.0f);
    u.sky = glm::vec4(atmosphere.sky * preExposure, 0.0f);
    u.depthParams = glm::vec4(options.reversedZ ? 0.0f : 1.0f, 1.0f / float(options.shadowMapSize),
                              fit.texelWorldSize, float(scene.lights.size()));
    u.extent = glm::uvec4(options.width, options.height, 0, 0);
    u.sunOpticalDepthLow = glm::vec4(atmosphere.opticalDepthLow, atmosphere.altitudeLow);
    u.sunOpticalDepthHigh = glm::vec4(atmosphere.opticalDepthHigh, atmosphere.altitudeHigh);
    return u;
}

// The scene's lights for lighting.comp: positions camera-relative (computed in double), angles as cosines,
// their shadows' faces in `shadows` (makeGpuShadowFaces' order). The first scene.lights.size() entries of
// shared::LightsUniforms (at most kMaxDemoLights: recordFrame checks).
std::vector<shared::GpuLight> makeGpuLights(const Scene& scene, float preExposure,
                                            const LocalShadowLayout& shadows) {
    std::vector<uint32_t> firstFace(shadows.shadows.size(), 0);
    for (size_t s = 1; s < firstFace.size(); ++s)
        firstFace[s] = firstFace[s - 1] + shadows.shadows[s - 1].faceCount;
    std::vector<shared::GpuLight> out(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const postfx::LocalLight l = toLocalLight(scene.lights[i]);
        const bool spot = l.type == postfx::LightType::Spot;
        const glm::vec3 relative(glm::dvec3(l.position) - glm::dvec3(scene.camera.position));
        shared::GpuLight& g = out[i];
        g.positionRadius = glm::vec4(relative, l.sourceRadius);
        g.intensityRange = glm::vec4(glm::vec3(l.intensity) * preExposure, l.range);
        g.directionCosOuter = glm::vec4(glm::vec3(l.direction), spot ? std::cos(l.outerConeAngle) : -2.0f);
        g.cosInner = glm::vec4(spot ? std::cos(l.innerConeAngle) : -1.0f, 0.0f, 0.0f, 0.0f);
        if (const uint32_t s = shadows.lightShadow[i]; s != postfx::kNoLocalShadow) {
            // Face indices and counts stay exact in float (at most 6 · kMaxDemoLights).
            g.cosInner.y = float(firstFace[s]);
            g.cosInner.z = float(shadows.shadows[s].faceCount);
            g.cosInner.w = shadows.shadows[s].depthBias;
        }
    }
    return out;
}

// Every face of `shadows` for lighting.comp, in order, with matrices from camera-relative positions (the
// product with the camera's translation taken in double).
std::vector<shared::GpuShadowFace> makeGpuShadowFaces(const LocalShadowLayout& shadows,
                                                      const glm::vec3& cameraPosition) {
    const glm::dmat4 fromRelative = glm::translate(glm::dmat4(1.0), glm::dvec3(cameraPosition));
    std::vector<shared::GpuShadowFace> out;
    for (const postfx::LocalShadow& s : shadows.shadows) {
        for (uint32_t f = 0; f < s.faceCount; ++f) {
            const postfx::LocalShadowFace& face = s.faces[f];
            shared::GpuShadowFace g{};
            g.worldToClip = glm::mat4(glm::dmat4(face.worldToClip) * fromRelative);
            g.region = glm::vec4(face.offset.x, face.offset.y, face.extent.x, face.extent.y);
            g.params = glm::vec4(float(shadowTexelAngle(face)), 0.0f, 0.0f, 0.0f);
            out.push_back(g);
        }
    }
    return out;
}

// Every face of `shadows` for the shadow pass: its region and world -> clip matrix.
std::vector<ShadowFaceDraw> makeShadowFaceDraws(const LocalShadowLayout& shadows) {
    std::vector<ShadowFaceDraw> out;
    for (const postfx::LocalShadow& s : shadows.shadows) {
        for (uint32_t f = 0; f < s.faceCount; ++f) {
            const postfx::LocalShadowFace& face = s.faces[f];
            ShadowFaceDraw d;
            d.region = {{int32_t(face.offset.x), int32_t(face.offset.y)}, {face.extent.x, face.extent.y}};
            d.worldToClip = glm::mat4(glm::dmat4(face.worldToClip));
            out.push_back(d);
        }
    }
    return out;
}

}  // namespace

PreExposureRange preExposureRange(const Scene& scene, const glm::vec3& ambient) {
    double p = 0x1p33;  // 2^-33 ≈ 1.2e-10 and 2^33 ≈ 8.6e9: within postfx's [1e-10, 1e10]
    double light = 0.0, intensity = 0.0;
    for (int c = 0; c < 3; ++c)
        light = std::max({light, double(scene.sun.illuminance[c]), double(ambient[c])});
    for (const Light& l : scene.lights)
        for (int c = 0; c < 3; ++c)
            intensity = std::max(intensity, double(toLocalLight(l).intensity[c]));
    // A margin under postfx's limits for the float rounding of p and of the products.
    if (light > 0.0) p = std::min(p, 1e7 / light);
    if (intensity > 0.0) p = std::min(p, 1e9 / intensity);
    // Rounding down keeps the limits.
    return {0x1p-33, std::exp2(std::clamp(std::floor(std::log2(p)), -33.0, 33.0))};
}

float scenePreExposure(const Scene& scene, const glm::vec3& ambient, const RenderOptions& options) {
    if (!options.preExpose) return 1.0f;
    const PreExposureRange range = preExposureRange(scene, ambient);
    const double p = std::exp2(std::floor(std::log2(double(exposureFromEv100(scene.camera.ev100)))));
    return float(std::clamp(p, range.lowest, range.highest));
}

ShadowFit Renderer::Impl::shadowFit(const Scene& scene) const {
    return fitShadowMap(scene, options.shadowMapSize);
}

glm::mat4 Renderer::Impl::projection(const Scene& scene) const {
    const Camera& cam = scene.camera;
    const float aspect = float(options.width) / float(options.height);
    return perspectiveProjection(glm::radians(cam.fovYDeg), aspect, cam.nearPlane, cam.farPlane,
                                 options.reversedZ, options.infiniteFar);
}

FrameLight Renderer::Impl::frameLight(const Scene& scene) const {
    FrameLight light;
    light.surfaces = atmosphereLighting.update(scene);
    light.preExposure = scenePreExposure(scene, light.surfaces.ambient, options);
    // The metered pre-exposure, within this frame's limits (a light switched on later may lower them).
    if (options.preExpose && meteredExposure > 0.0)
        light.preExposure =
            float(std::min(meteredExposure, preExposureRange(scene, light.surfaces.ambient).highest));
    return light;
}

PostfxInputs Renderer::Impl::postfxInputs(const Scene& scene, uint64_t frameIndex, const ShadowFit& fit,
                                          bool shadows) const {
    return postfxInputs(scene, frameIndex, fit, shadows, frameLight(scene));
}

PostfxInputs Renderer::Impl::postfxInputs(const Scene& scene, uint64_t frameIndex, const ShadowFit& fit,
                                          bool shadows, const FrameLight& light) const {
    PostfxInputs in;
    in.frameIndex = frameIndex;
    // render() starts every call at frame 0: a new sequence, which no temporal history may continue.
    // Also the scene's cut frame and a cut the host asked for (requestCameraCut: the window's view reset).
    in.cameraCut = frameIndex == 0 || cameraCutRequested || isCameraCut(scene, frameIndex);
    in.budgetMs = scene.budgetMs;
    in.preExposure = light.preExposure;
    in.timeSeconds =
        options.fixedTimeSeconds ? *options.fixedTimeSeconds : frameTimeSeconds(scene, frameIndex);
    in.camera.position = glm::dvec3(scene.camera.position);
    in.camera.view = cameraView(scene.camera);  // postfx uses its rotation; position is given above
    in.camera.projection = projection(scene);
    in.sun.toSun = scene.sun.direction;
    in.sun.illuminance = scene.sun.illuminance;
    // The surfaces' ambient: scene.ambient, or the sky's with the atmosphere's ambient_from_sky.
    in.ambient = light.surfaces.ambient;
    localShadowLayout = localShadowsOf(scene);
    localLights.clear();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        localLights.push_back(toLocalLight(scene.lights[i]));
        localLights.back().shadow = localShadowLayout.lightShadow[i];
    }
    in.lights = localLights.data();
    in.lightCount = uint32_t(localLights.size());
    if (!localShadowLayout.shadows.empty()) {
        // The atlas as the shadow pass leaves it (reserveLocalShadows made it large enough).
        const GpuImage& a = localShadows.atlas();
        in.localShadows.image = {
            a.image, a.view, a.format, a.extent, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, a.usage};
        in.localShadows.shadows = localShadowLayout.shadows.data();
        in.localShadows.shadowCount = uint32_t(localShadowLayout.shadows.size());
    }
    if (shadows) {
        const ImageInfo& s = shadowInfo.image;
        in.shadowMap.image = {s.image, s.view, s.format, s.extent, s.layout, s.usage};
        in.shadowMap.worldToClip = glm::dmat4(fit.viewProj);
        in.shadowMap.reversedZ = false;
        // The shadow pass already biases the stored depth by the rasteriser's slope-scaled bias;
        // on top of that, one texel's depth change on a surface at 45 degrees to the sun
        // (shadowDepthBias). It keeps the last samples of a ray ending on a lit surface lit without
        // visibly moving shadow edges in the volume (a texel is ~1-3 cm in the demo scenes).
        in.shadowMap.depthBias = shadowDepthBias(fit);
    }
    in.fog = scene.fog;
    in.froxelFog = froxelFogSettings(scene);  // its volumes point into scene.froxelVolumes
    in.atmosphere = scene.atmosphere;
    in.clouds = scene.clouds;
    // The forward pass's transparent surfaces read postfx's volumetrics through the lookup.
    in.volumetricsLookup = scene.volumetricsLookup;
    in.volumetricsLookup.enabled = hasForwardDraws(scene);
    return in;
}

postfx::FrameInfo Renderer::Impl::frameInfo(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                                            const ShadowFit& fit, bool shadows, const FrameLight& light,
                                            const postfx::ImageInput& fogOutput) const {
    postfx::FrameInfo frame = postfxInputs(scene, frameIndex, fit, shadows, light);
    frame.commandBuffer = cmd;
    frame.color = {hdr.image, hdr.view, hdr.format, extent, VK_IMAGE_LAYOUT_GENERAL, hdr.usage};
    frame.depth = {gbuffer.depth.image,
                   gbuffer.depth.view,
                   gbuffer.depth.format,
                   extent,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                   gbuffer.depth.usage};
    frame.output = fogOutput;
    return frame;
}

bool Renderer::recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex, std::string& error) {
    return impl_->recordFrame(cmd, scene, frameIndex, postfx::ImageInput{}, error);
}

bool Renderer::recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                           const postfx::ImageInput& fogOutput, std::string& error) {
    return impl_->recordFrame(cmd, scene, frameIndex, fogOutput, error);
}

LocalShadowLayout Renderer::Impl::localShadowsOf(const Scene& scene) const {
    return layoutLocalShadows(scene.lights,
                              std::min(kMaxShadowAtlasEdge, host.properties.limits.maxImageDimension2D));
}

bool Renderer::Impl::reserveLocalShadows(const Scene& scene, std::string& error) {
    const LocalShadowLayout layout = localShadowsOf(scene);
    if (layout.shadows.empty()) return true;
    bool replaced = false;
    if (!localShadows.reserve(host, {layout.extent.x, layout.extent.y}, replaced, error)) return false;
    if (replaced) lighting.setLocalShadowAtlas(host.device, localShadows.atlas().view);
    return true;
}

bool Renderer::Impl::drawsShadows(const Scene& scene, const ShadowFit& fit, uint64_t frameIndex) const {
    return drawsShadows(scene, fit, frameIndex, frameLight(scene));
}

bool Renderer::Impl::drawsShadows(const Scene& scene, const ShadowFit& fit, uint64_t frameIndex,
                                  const FrameLight& light) const {
    if (!scene.sun.shadows || !fit.valid) return false;
    const glm::vec3 e = scene.sun.illuminance;
    if (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f) return true;  // the lighting's sun term reads it
    // Otherwise only postfx might: ask its plan for the frame as it would get it, shadow map included.
    postfx::FramePlan plan;
    const postfx::FrameInfo frame = frameInfo(VK_NULL_HANDLE, scene, frameIndex, fit, true, light, {});
    return postfx->plan(frame, plan).ok() && plan.reads("host.shadow_map");
}

bool Renderer::plan(const Scene& scene, uint64_t frameIndex, postfx::FramePlan& out,
                    std::string& error) const {
    if (!impl_->reserveLocalShadows(scene, error)) return false;
    const ShadowFit fit = impl_->shadowFit(scene);
    const FrameLight light = impl_->frameLight(scene);
    const bool shadows = impl_->drawsShadows(scene, fit, frameIndex, light);
    const postfx::FrameInfo frame =
        impl_->frameInfo(VK_NULL_HANDLE, scene, frameIndex, fit, shadows, light, {});
    if (postfx::Status s = impl_->postfx->plan(frame, out); !s) {
        error = "postfx plan: " + s.message;
        return false;
    }
    return true;
}

postfx::FrameInfo Renderer::frameInputs(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex) const {
    std::string error;  // a failure leaves the atlas as it was: postfx's checks of the frame then say why
    impl_->reserveLocalShadows(scene, error);
    const ShadowFit fit = impl_->shadowFit(scene);
    const FrameLight light = impl_->frameLight(scene);
    const bool shadows = impl_->drawsShadows(scene, fit, frameIndex, light);
    return impl_->frameInfo(cmd, scene, frameIndex, fit, shadows, light, {});
}

postfx::CloudShadowTransform Renderer::Impl::bindCloudShadow(VkCommandBuffer cmd) {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    const VkImageView view = postfx->imageView(postfx::kCloudsShadowMap, &layout);
    // A new view or layout waits for the device (rare: the clouds' settings or the effects changed).
    lighting.setCloudShadow(host.device, view, layout);
    if (view == VK_NULL_HANDLE) return {};
    // postfx's writes of the map in the previous frame before the lighting's reads.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, kCompute, kCompute, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    return cloudShadow;
}

bool Renderer::Impl::submit(VkCommandBuffer cmd, size_t slot, std::string& error) {
    vkResetFences(host.device, 1, &fences[slot]);
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    if (!vkCheck(vkQueueSubmit(host.queue, 1, &si, fences[slot]), "vkQueueSubmit", error)) {
        broken = true;
        return false;
    }
    return true;
}

bool Renderer::Impl::recordFrame(VkCommandBuffer cmd, const Scene& scene, uint64_t frameIndex,
                                 const postfx::ImageInput& fogOutput, std::string& error) {
    if (scene.lights.size() > shared::kMaxDemoLights) {
        error = "the scene has " + std::to_string(scene.lights.size()) + " lights, more than the limit of " +
                std::to_string(shared::kMaxDemoLights);
        return false;
    }
    // The atlas first: postfx's plan (drawsShadows) and record read it.
    if (!reserveLocalShadows(scene, error)) return false;
    meterCompletedFrame(scene, frameIndex % kFramesInFlight);
    const LocalShadowLayout localShadowFrame = localShadowsOf(scene);
    const ShadowFit fit = shadowFit(scene);
    // The frame's light, once: the surfaces' uniforms and lights, the shadow decision and postfx read it.
    const FrameLight light = frameLight(scene);
    const bool shadows = drawsShadows(scene, fit, frameIndex, light);
    shadowInfo.enabled = shadows;
    shadowInfo.viewProj = fit.viewProj;
    shadowInfo.texelWorldSize = fit.texelWorldSize;

    // Frame uniforms: overwrite after the previous frame's readers (WAR), then publish to this frame's.
    preExposure = light.preExposure;
    shared::FrameUniforms u = makeFrameUniforms(scene, options, projection(scene), fit, shadows, light);
    const postfx::CloudShadowTransform clouds = bindCloudShadow(cmd);
    u.cloudShadowU = glm::vec4(glm::dvec4(clouds.u));
    u.cloudShadowV = glm::vec4(glm::dvec4(clouds.v));
    bufferBarrier(cmd, frameUniforms, kUniformStages, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdUpdateBuffer(cmd, frameUniforms.buffer, 0, sizeof(u), &u);
    bufferBarrier(cmd, frameUniforms, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  kUniformStages, VK_ACCESS_UNIFORM_READ_BIT);
    // Local lights (lighting and forward passes): the same, for the entries in use (none: nothing written).
    if (!scene.lights.empty()) {
        const std::vector<shared::GpuLight> lights = makeGpuLights(scene, preExposure, localShadowFrame);
        bufferBarrier(cmd, lightsUniforms, kUniformStages, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
        vkCmdUpdateBuffer(cmd, lightsUniforms.buffer, 0, lights.size() * sizeof(shared::GpuLight),
                          lights.data());
        bufferBarrier(cmd, lightsUniforms, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      kUniformStages, VK_ACCESS_UNIFORM_READ_BIT);
    }

    // The shadowed lights' faces: the same, for the faces in use, in chunks of vkCmdUpdateBuffer's 64 KiB.
    const std::vector<shared::GpuShadowFace> faces =
        makeGpuShadowFaces(localShadowFrame, scene.camera.position);
    if (!faces.empty()) {
        bufferBarrier(cmd, shadowFaces, kCompute, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
        const VkDeviceSize bytes = faces.size() * sizeof(shared::GpuShadowFace);
        constexpr VkDeviceSize kChunk = 65536 / sizeof(shared::GpuShadowFace) * sizeof(shared::GpuShadowFace);
        for (VkDeviceSize at = 0; at < bytes; at += kChunk) {
            vkCmdUpdateBuffer(cmd, shadowFaces.buffer, at, std::min(kChunk, bytes - at),
                              reinterpret_cast<const char*>(faces.data()) + at);
        }
        bufferBarrier(cmd, shadowFaces, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      kCompute, VK_ACCESS_SHADER_READ_BIT);
    }

    // Raster passes leave their attachments readable by compute shaders. They start by discarding
    // their attachments after the previous frame's COMPUTE_SHADER reads: the lighting pass and
    // postfx (whose release barriers end in COMPUTE_SHADER -> ALL_COMMANDS) read depth and shadow maps.
    // The local shadow atlas is drawn with shadowed lights, and cleared once after it was replaced.
    // Transparent objects are not in the G-buffer (the forward pass draws them) and cast no shadow.
    const std::vector<MeshDraw> casters = shadowCasterDraws(scene, draws);
    if (shadows) shadow.record(cmd, frameSet, vertices, indices, casters);
    if (!faces.empty() || !localShadows.cleared())
        localShadows.record(cmd, vertices, indices, casters, makeShadowFaceDraws(localShadowFrame));
    gbuffer.record(cmd, frameSet, vertices, indices, opaqueDraws(scene, draws));

    // Lighting overwrites every HDR pixel: discard the old content once its readers are done.
    imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kHdrReaderStages, 0, kCompute,
                 VK_ACCESS_SHADER_WRITE_BIT);
    lighting.record(cmd, extent);
    imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, kCompute,
                 VK_ACCESS_SHADER_WRITE_BIT, kCompute,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

    // postfx reads depth and shadow map and composites into the HDR image (compute only), and
    // returns every image in the layout it was given.
    const postfx::FrameInfo frame = frameInfo(cmd, scene, frameIndex, fit, shadows, light, fogOutput);
    if (postfx::Status s = postfx->record(frame); !s.ok()) {
        error = "postfx record: " + s.message;
        return false;
    }
    cameraCutRequested = false;  // told to postfx
    cloudShadow = postfx::cloudShadowTransform(frame);
    // The transparent surfaces over postfx's composite. Not with a separate output (the CPU reference
    // path, whose HDR image keeps the un-fogged opaque scene): there they are left out.
    if (frame.volumetricsLookup.enabled && fogOutput.image == VK_NULL_HANDLE &&
        !recordForward(cmd, scene, frame, error))
        return false;
    return recordMeterCopy(cmd, frameIndex, error);
}

void Renderer::Impl::meterCompletedFrame(const Scene& scene, size_t slot) {
    if (!meterCopyPending[slot]) return;
    meterCopyPending[slot] = false;
    const Metering m = meterHalfImage(static_cast<const uint16_t*>(meterCopies[slot].mapped),
                                      size_t(extent.width) * extent.height);
    const PreExposureRange range = preExposureRange(scene, frameLight(scene).surfaces.ambient);
    meteredExposure = meteredPreExposure(m, meterCopyExposure[slot], exposureFromEv100(scene.camera.ev100),
                                         range.lowest, range.highest);
}

// The HDR image (GENERAL, written in compute or chained there) copied in TRANSFER_SRC and returned to
// GENERAL for this frame's other readers (their barriers chain from COMPUTE_SHADER writes); the next
// frame's discard waits for TRANSFER (kHdrReaderStages).
bool Renderer::Impl::recordMeterCopy(VkCommandBuffer cmd, uint64_t frameIndex, std::string& error) {
    if (!options.preExpose || options.meterInterval == 0 || frameIndex % options.meterInterval != 0)
        return true;
    const size_t slot = frameIndex % kFramesInFlight;
    GpuBuffer& copy = meterCopies[slot];
    if (!copy.buffer && !createBuffer(host, VkDeviceSize(extent.width) * extent.height * 8,
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, copy, error))
        return false;
    recordHdrCopy(cmd, copy);
    imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, kCompute,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    meterCopyExposure[slot] = preExposure;
    meterCopyPending[slot] = true;
    return true;
}

bool Renderer::Impl::recordForward(VkCommandBuffer cmd, const Scene& scene, const postfx::FrameInfo& frame,
                                   std::string& error) {
    const size_t slot = frame.frameIndex % kFramesInFlight;
    const ForwardFrame forwardFrame = buildForwardFrame(scene, draws, frame.timeSeconds);
    if (forwardFrame.draws.empty()) return true;
    if (!forward.upload(host, slot, forwardFrame, error)) return false;
    ForwardPass::Inputs in;
    in.lightingSet = lighting.set();
    in.vertices = &vertices;
    in.indices = &indices;
    postfx::VolumetricsLookupBindings bindings;
    bindings.uniforms = shared::kForwardBindingLookupUniforms;
    bindings.scattering = shared::kForwardBindingLookupScattering;
    bindings.transmittance = shared::kForwardBindingLookupTransmittance;
    if (postfx::Status s = postfx->writeVolumetricsLookup(forward.lookupSet(slot), bindings); !s.ok()) {
        error = "postfx volumetrics lookup: " + s.message;
        return false;
    }
    // The clouds' shadow map this frame's postfx wrote, at this frame's rows, when the lighting's binding
    // holds it (otherwise none: rows putting every point outside the map).
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    const VkImageView map = postfx->imageView(postfx::kCloudsShadowMap, &layout);
    if (map != VK_NULL_HANDLE && map == lighting.cloudShadowView() &&
        layout == lighting.cloudShadowLayout()) {
        in.cloudShadowU = glm::vec4(glm::dvec4(cloudShadow.u));
        in.cloudShadowV = glm::vec4(glm::dvec4(cloudShadow.v));
    }
    in.lookup = forwardLookup;
    if (forwardQueries)
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, forwardQueries, forwardFirstQuery);
    forward.record(cmd, slot, forwardFrame, in);
    if (forwardQueries)
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, forwardQueries, forwardFirstQuery + 1);
    forwardQueries = VK_NULL_HANDLE;
    forwardLookup = true;
    return true;
}

void Renderer::timeForwardPass(VkQueryPool pool, uint32_t firstQuery, bool lookup) {
    impl_->forwardQueries = pool;
    impl_->forwardFirstQuery = firstQuery;
    impl_->forwardLookup = lookup;
}

void Renderer::requestCameraCut() {
    impl_->cameraCutRequested = true;
}

// After recordFrame: HDR image (GENERAL, compute writes) -> `buffer` -> host. The image is left in
// TRANSFER_SRC_OPTIMAL.
void Renderer::Impl::recordHdrCopy(VkCommandBuffer cmd, const GpuBuffer& buffer) const {
    imageBarrier(cmd, hdr, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute,
                 VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
    bufferBarrier(cmd, buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

// The readback of render(): the next frame discards the image anyway.
void Renderer::Impl::recordReadback(VkCommandBuffer cmd) const {
    recordHdrCopy(cmd, readback);
}

}  // namespace demo
