// Renderer::renderReference: the GPU frame up to lighting, read back, and postfx's CPU references over it
// in the composite order: the atmosphere (postfx::reference::renderAtmosphere, reference (a)), the clouds
// (renderClouds), then the fog (renderFog, or renderFroxelFog for the froxel fog), with the same inputs the
// GPU frame gave postfx, the clouds' shadow map included (the fogs' sunlight and the lit surfaces).
#include "host/renderer.h"
#include "host/renderer_impl.h"

#include <postfx/reference.h>

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <vector>

namespace demo {
namespace {

constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkImageLayout kDepthRest = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

// Copies a D32 depth image resting in DEPTH_STENCIL_READ_ONLY_OPTIMAL (last read by compute shaders)
// to `buffer` at `offset` as floats, and returns it to its resting layout, ready for the next frame's
// raster pass (which waits for COMPUTE_SHADER before discarding it).
void recordDepthCopy(VkCommandBuffer cmd, const GpuImage& depth, const GpuBuffer& buffer,
                     VkDeviceSize offset) {
    imageBarrier(cmd, depth, kDepthRest, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute, 0, kTransfer,
                 VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.imageExtent = {depth.extent.width, depth.extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
    imageBarrier(cmd, depth, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kDepthRest, kTransfer, 0, kCompute,
                 VK_ACCESS_SHADER_READ_BIT);
}

std::vector<float> floatsAt(const GpuBuffer& buffer, VkDeviceSize offset, size_t count) {
    std::vector<float> out(count);
    // An empty vector's data() may be null, and memcpy's pointers must not be even for 0 bytes (a scene
    // without shadows reads no shadow texels).
    if (count > 0)
        std::memcpy(out.data(), static_cast<const char*>(buffer.mapped) + offset, count * sizeof(float));
    return out;
}

// `count` 8-bit UNORM texels at `offset` as values in [0, 1].
std::vector<float> unormAt(const GpuBuffer& buffer, VkDeviceSize offset, size_t count) {
    std::vector<float> out(count);
    const auto* bytes = static_cast<const uint8_t*>(buffer.mapped) + offset;
    for (size_t i = 0; i < count; ++i)
        out[i] = float(bytes[i]) / 255.0f;
    return out;
}

}  // namespace

bool Renderer::renderReference(const Scene& scene, ImageF& out, std::string& error, uint32_t stepsPerPixel,
                               uint32_t stride, CloudsPathTracing* pathTracedClouds) {
    Impl& r = *impl_;
    const VkDevice device = r.host.device;
    if (r.broken) {
        error = "the renderer is unusable after a failed submission";
        return false;
    }
    if (stride == 0) {
        error = "renderReference: stride must be at least 1";
        return false;
    }
    if (stride > 1 && scene.fog.enabled && scene.fog.resolutionScale < 1.0f) {
        // The subsampled image's pixels are not the reduced march's: only full resolution subsamples.
        error = "renderReference: stride " + std::to_string(stride) + " needs fog.resolution_scale 1";
        return false;
    }
    if (pathTracedClouds) pathTracedClouds->standardError.clear();
    const uint64_t frameIndex = r.options.frames - 1;  // the frame render() returns
    // Its state: the camera and lights moved to that frame (as render() draws it).
    const Scene gpuScene = sceneAtFrame(scene, frameIndex);
    if (!setScene(gpuScene, error)) return false;               // also waits for the device to be idle
    if (!r.reserveLocalShadows(gpuScene, error)) return false;  // before postfx is asked about the frame
    // The pre-exposure render() chooses for what this frame shows (host/metering.h).
    if (!r.meterFirstFrame(gpuScene, error)) return false;

    const bool froxel = gpuScene.froxelFog.enabled;
    const ShadowFit fit = r.shadowFit(gpuScene);
    const bool shadows = r.drawsShadows(gpuScene, fit, frameIndex);
    const PostfxInputs in = r.postfxInputs(gpuScene, frameIndex, fit, shadows);
    // The lights and their shadows as the GPU frame gives them (`in` points into the renderer, which the
    // frame recorded below rebuilds).
    const std::vector<postfx::LocalLight> lights(in.lights, in.lights + in.lightCount);
    const std::vector<postfx::LocalShadow> localShadows(
        in.localShadows.shadows, in.localShadows.shadows + in.localShadows.shadowCount);
    const bool fog = in.fog.enabled || froxel;  // a fog reference to evaluate
    const postfx::FogNoiseSettings& noiseSettings = froxel ? in.froxelFog.noise : in.fog.noise;
    // postfx builds no noise for a medium the noise empties (threshold >= 1, multiplier 0), and then marches
    // none of it (the froxel fog's volumes have no noise); the references leave such a medium out too.
    const postfx::FogMedium& medium = froxel ? static_cast<const postfx::FogMedium&>(in.froxelFog)
                                             : static_cast<const postfx::FogMedium&>(in.fog);
    const bool noiseEmpties = noiseSettings.multiplier <= 0.0f || noiseSettings.threshold >= 1.0f;
    const bool noise = fog && noiseSettings.enabled && !noiseSettings.hostTexture &&
                       (froxel || medium.density > 0.0f) && !noiseEmpties;
    const uint32_t noiseEdge = noiseSettings.textureSize;
    // The clouds' shadow map, made by postfx after the lighting: the GPU's surfaces read the one held from
    // the frame before (one frame late). A frame of the same state recorded first holds this frame's, so
    // that the surfaces are lit under it; the fogs' references read it back (R32F, size² texels).
    const bool cloudShadows = gpuScene.clouds.enabled && gpuScene.clouds.castShadows;

    // With any of postfx's effects, postfx runs as in render() but writes to a scratch image: it validates
    // the inputs and generates the noise texture, and the HDR image keeps the scene without postfx's
    // effects, which the references then draw.
    postfx::ImageInput fogOutput;
    if (gpuScene.fog.enabled || froxel || gpuScene.atmosphere.enabled || gpuScene.clouds.enabled) {
        if (!r.fogScratch.image &&
            !createImage(r.host, r.hdr.format, r.extent, VK_IMAGE_USAGE_STORAGE_BIT, r.fogScratch, error))
            return false;
        fogOutput = {r.fogScratch.image, r.fogScratch.view,       r.fogScratch.format,
                     r.extent,           VK_IMAGE_LAYOUT_GENERAL, r.fogScratch.usage};
    }

    // One frame on render()'s command buffer and fence of its slot (all are idle: setScene waited), submitted
    // and waited for; nothing is submitted when recording fails.
    const size_t slot = frameIndex % kFramesInFlight;
    VkCommandBuffer cmd = r.commandBuffers[slot];
    const auto submitFrame = [&](const auto& record) {
        vkResetCommandBuffer(cmd, 0);
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &bi);
        const bool recorded = [&] {
            if (fogOutput.image) {  // the scratch image's old content is never read
                imageBarrier(cmd, r.fogScratch, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kCompute,
                             0, kCompute, VK_ACCESS_SHADER_WRITE_BIT);
            }
            // A single frame: nothing before it belongs to its history.
            r.cameraCutRequested = true;
            return r.recordFrame(cmd, gpuScene, frameIndex, fogOutput, error) && record();
        }();
        if (!vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error) || !recorded) return false;
        if (!r.submit(cmd, slot, error)) return false;
        return vkCheck(vkWaitForFences(device, 1, &r.fences[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences",
                       error);
    };
    if (cloudShadows && !submitFrame([] { return true; })) return false;
    const bool cloudShadow = fog && r.postfx->imageView(postfx::kCloudsShadowMap) != VK_NULL_HANDLE;
    const uint32_t cloudShadowEdge = gpuScene.clouds.shadowMap.size;
    // The clouds' generated noise textures, read back for their reference (the CPU port would make the same
    // texels, to a unit of their 8 bits: CloudsGpuTest.NoiseTexturesMatchTheCpuPort, in seconds of CPU
    // time a 128³ texture). Where postfx holds none this frame, the reference generates them.
    const postfx::CloudNoiseSettings& cloudNoiseSettings = gpuScene.clouds.noise;
    const bool cloudNoise = gpuScene.clouds.enabled && cloudNoiseSettings.enabled &&
                            !cloudNoiseSettings.hostBaseTexture && !cloudNoiseSettings.hostDetailTexture;
    const auto cube = [&](uint32_t edge) { return cloudNoise ? size_t(edge) * edge * edge : 0; };
    const size_t baseNoiseTexels = cube(cloudNoiseSettings.baseSize);
    const size_t detailNoiseTexels = cube(cloudNoiseSettings.detailSize);

    // One host-visible buffer: depth, shadow map, noise, the clouds' shadow map, the local shadow atlas (each
    // as the GPU stores it; the atlas whole, as postfx reads it).
    const size_t pixels = size_t(r.extent.width) * r.extent.height;
    const VkExtent2D shadowExtent = r.shadow.depth.extent;
    const size_t shadowTexels = shadows ? size_t(shadowExtent.width) * shadowExtent.height : 0;
    const size_t noiseTexels = noise ? size_t(noiseEdge) * noiseEdge * noiseEdge : 0;
    const size_t cloudShadowTexels = cloudShadow ? size_t(cloudShadowEdge) * cloudShadowEdge : 0;
    const bool localShadowAtlas = froxel && !localShadows.empty();
    const VkExtent2D atlasExtent = r.localShadows.atlas().extent;
    const size_t atlasTexels = localShadowAtlas ? size_t(atlasExtent.width) * atlasExtent.height : 0;
    const VkDeviceSize depthOffset = 0;
    const VkDeviceSize shadowOffset = depthOffset + pixels * sizeof(float);
    const VkDeviceSize noiseOffset = shadowOffset + shadowTexels * sizeof(float);
    const VkDeviceSize baseNoiseOffset = noiseOffset + noiseTexels;
    const VkDeviceSize detailNoiseOffset = baseNoiseOffset + baseNoiseTexels;
    // Floats after bytes: aligned to 4.
    const VkDeviceSize cloudShadowOffset = (detailNoiseOffset + detailNoiseTexels + 3) / 4 * 4;
    const VkDeviceSize atlasOffset = cloudShadowOffset + cloudShadowTexels * sizeof(float);
    GpuBuffer buffer;
    if (!createBuffer(r.host, atlasOffset + atlasTexels * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      true, buffer, error))
        return false;
    struct BufferGuard {
        VkDevice device;
        GpuBuffer& buffer;
        ~BufferGuard() { destroyBuffer(device, buffer); }
    } guard{device, buffer};

    uint32_t noiseSize = 0, cloudShadowSize = 0;
    bool cloudNoiseReadBack = false;
    const bool submitted = submitFrame([&] {
        r.recordReadback(cmd);  // the HDR image: postfx only read it
        recordDepthCopy(cmd, r.gbuffer.depth, buffer, depthOffset);
        if (shadows) recordDepthCopy(cmd, r.shadow.depth, buffer, shadowOffset);
        if (localShadowAtlas) recordDepthCopy(cmd, r.localShadows.atlas(), buffer, atlasOffset);
        if (noise) {
            // The texture of whichever fog runs (kFogNoiseTexture or kFroxelFogNoiseTexture).
            VkExtent3D extent{};
            VkDeviceSize bytes = 0;
            const postfx::Status s = r.postfx->recordImageReadback(
                froxel ? postfx::kFroxelFogNoiseTexture : postfx::kFogNoiseTexture, cmd, buffer.buffer,
                noiseOffset, extent, bytes);
            noiseSize = extent.width;
            if (!s.ok()) {
                error = "postfx noise readback: " + s.message;
                return false;
            }
        }
        if (cloudNoise) {
            // Held only where the clouds march noise this frame (not without coverage, for instance).
            VkExtent3D base{}, detail{};
            VkDeviceSize bytes = 0;
            cloudNoiseReadBack = r.postfx->imageView(postfx::kCloudsBaseNoise) &&
                                 r.postfx->imageView(postfx::kCloudsDetailNoise) &&
                                 r.postfx->recordImageReadback(postfx::kCloudsBaseNoise, cmd, buffer.buffer,
                                                               baseNoiseOffset, base, bytes) &&
                                 bytes == baseNoiseTexels &&
                                 r.postfx->recordImageReadback(postfx::kCloudsDetailNoise, cmd, buffer.buffer,
                                                               detailNoiseOffset, detail, bytes) &&
                                 bytes == detailNoiseTexels;
        }
        if (cloudShadow) {
            VkExtent3D extent{};
            VkDeviceSize bytes = 0;
            const postfx::Status s = r.postfx->recordImageReadback(
                postfx::kCloudsShadowMap, cmd, buffer.buffer, cloudShadowOffset, extent, bytes);
            cloudShadowSize = extent.width;
            if (!s.ok()) {
                error = "postfx cloud shadow readback: " + s.message;
                return false;
            }
        }
        bufferBarrier(cmd, buffer, kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_HOST_READ_BIT);
        return true;
    });
    if (!submitted) return false;
    if (cloudShadow && cloudShadowSize != cloudShadowEdge) {
        error = "postfx cloud shadow readback: edge " + std::to_string(cloudShadowSize) + ", expected " +
                std::to_string(cloudShadowEdge);
        return false;
    }
    if (noise && noiseSize != noiseEdge) {
        error = "postfx noise readback: texture edge " + std::to_string(noiseSize) + ", expected " +
                std::to_string(noiseEdge);
        return false;
    }

    // The un-fogged HDR color, RGBA16F -> RGBA32F (exactly the values postfx read).
    std::vector<float> color(pixels * 4);
    const auto* half = static_cast<const uint16_t*>(r.readback.mapped);
    for (size_t i = 0; i < color.size(); ++i)
        color[i] = glm::unpackHalf1x16(half[i]);
    unexpose(color, r.preExposure);  // physical units, as the references work in
    std::vector<float> depth = floatsAt(buffer, depthOffset, pixels);
    glm::mat4 projection = in.camera.projection;
    out.width = r.extent.width;
    out.height = r.extent.height;
    if (stride > 1) {
        const uint32_t w = (r.extent.width + stride - 1) / stride,
                       h = (r.extent.height + stride - 1) / stride;
        std::vector<float> subColor(size_t(w) * h * 4), subDepth(size_t(w) * h);
        for (uint32_t j = 0; j < h; ++j) {
            for (uint32_t i = 0; i < w; ++i) {
                const size_t src = size_t(j) * stride * r.extent.width + size_t(i) * stride;
                const size_t dst = size_t(j) * w + i;
                std::memcpy(&subColor[dst * 4], &color[src * 4], 4 * sizeof(float));
                subDepth[dst] = depth[src];
            }
        }
        // The reference puts pixel i of a w-wide image at ndc (i + 0.5) / w · 2 - 1; the frame's pixel
        // i·stride is at s·that + o with s = stride·w / W, o = s - 1 + (1 - stride) / W (and so for y).
        // The same rays, then, with clip x, y mapped by the inverse of that before the projection's
        // inverse: projection' = A⁻¹ · projection.
        const double sx = double(stride) * w / r.extent.width, sy = double(stride) * h / r.extent.height;
        const double ox = sx - 1.0 + (1.0 - stride) / double(r.extent.width);
        const double oy = sy - 1.0 + (1.0 - stride) / double(r.extent.height);
        glm::dmat4 inverseA(1.0);
        inverseA[0][0] = 1.0 / sx;
        inverseA[1][1] = 1.0 / sy;
        inverseA[3][0] = -ox / sx;
        inverseA[3][1] = -oy / sy;
        projection = glm::mat4(inverseA * glm::dmat4(projection));
        color = std::move(subColor);
        depth = std::move(subDepth);
        out.width = w;
        out.height = h;
    }
    // What every reference reads alike: the image as the effects before it left it, the depth, the camera
    // and the sun.
    const auto fillImage = [&](auto& x) {
        x.width = out.width;
        x.height = out.height;
        x.color = color;
        x.depth = depth;
        x.depthConvention.reversedZ = r.options.reversedZ;
        x.depthConvention.infiniteFar = r.options.infiniteFar;
        x.camera = in.camera;
        x.camera.projection = projection;
        x.sun = in.sun;
    };
    // The atmosphere first (the composite order: the farthest first), the clouds, then the fog.
    if (in.atmosphere.enabled) {
        postfx::reference::AtmosphereInputs ai;
        fillImage(ai);
        ai.settings = in.atmosphere;
        ai.stepsPerPixel = stepsPerPixel;
        // The scattering orders' table a notch coarser than the reference's default (32 view, 96 sun, 24
        // height nodes, 576 directions: 25 s on two cores, in every process that renders a reference): the
        // GPU's default nodes and directions with finer steps and more orders, a few seconds; its difference
        // to the default is the size of the GPU LUT's (docs/effects/atmosphere.md, "Benchmark").
        ai.ordersSunNodes = 64;
        ai.ordersHeightNodes = 16;
        ai.ordersAzimuthNodes = 8;
        ai.ordersDirections = 256;
        ai.ordersSteps = 32;
        ai.ordersCount = 6;
        std::vector<float> withAtmosphere;
        if (const postfx::Status s = postfx::reference::renderAtmosphere(ai, withAtmosphere); !s.ok()) {
            error = "atmosphere reference: " + s.message;
            return false;
        }
        color = std::move(withAtmosphere);
    }
    // The clouds over the sky, through the GPU's noise texels (read back above; else the CPU port's).
    if (in.clouds.enabled) {
        postfx::reference::CloudInputs ci;
        fillImage(ci);
        ci.ambient = in.ambient;
        ci.timeSeconds = in.timeSeconds;
        ci.settings = in.clouds;
        ci.atmosphere = in.atmosphere;
        const std::vector<float> baseNoise =
            unormAt(buffer, baseNoiseOffset, cloudNoiseReadBack ? baseNoiseTexels : 0);
        const std::vector<float> detailNoise =
            unormAt(buffer, detailNoiseOffset, cloudNoiseReadBack ? detailNoiseTexels : 0);
        ci.baseNoise = baseNoise;
        ci.detailNoise = detailNoise;
        std::vector<float> withClouds;
        std::vector<float>* standardError = nullptr;
        if (pathTracedClouds) {
            ci.pathTraced = true;
            ci.pathSamples = pathTracedClouds->samples;
            ci.pathSeed = pathTracedClouds->seed;
            standardError = &pathTracedClouds->standardError;
        }
        if (const postfx::Status s = postfx::reference::renderClouds(ci, withClouds, standardError);
            !s.ok()) {
            error = "clouds reference: " + s.message;
            return false;
        }
        color = std::move(withClouds);
    }
    if (!fog) {
        out.rgba = std::move(color);
        return true;
    }

    const std::vector<float> shadowDepth = floatsAt(buffer, shadowOffset, shadowTexels);
    const std::vector<float> cloudShadowTexels01 = floatsAt(buffer, cloudShadowOffset, cloudShadowTexels);
    const std::vector<float> atlasDepth = floatsAt(buffer, atlasOffset, atlasTexels);
    const std::vector<float> noiseTexels01 = unormAt(buffer, noiseOffset, noiseTexels);

    // What both references read alike: the read-back images and the GPU frame's inputs.
    const auto fill = [&](auto& fi) {
        fillImage(fi);
        fi.ambient = in.ambient;
        fi.timeSeconds = in.timeSeconds;
        if (shadows) {
            fi.shadowDepth = shadowDepth;
            fi.shadowWidth = shadowExtent.width;
            fi.shadowHeight = shadowExtent.height;
            fi.shadowWorldToClip = in.shadowMap.worldToClip;
            fi.shadowReversedZ = in.shadowMap.reversedZ;
            fi.shadowDepthBias = in.shadowMap.depthBias;
        }
        if (noise) {
            fi.noise = noiseTexels01;
            fi.noiseSize = noiseSize;
        }
        if (cloudShadow) {  // the map of this frame, at this frame's rows (recordFrame kept them)
            fi.cloudShadow = cloudShadowTexels01;
            fi.cloudShadowWidth = fi.cloudShadowHeight = cloudShadowSize;
            fi.cloudShadowRows = r.cloudShadow;
        }
        fi.atmosphere = in.atmosphere;  // the sun through it at each sample
        fi.stepsPerPixel = stepsPerPixel;
        fi.threads = 0;  // all hardware threads
    };
    if (froxel) {
        postfx::reference::FroxelFogInputs fi;
        fill(fi);
        fi.settings = in.froxelFog;                   // its volumes point into gpuScene.froxelVolumes
        if (noiseSettings.enabled && noiseEmpties) {  // the medium the noise empties, said without the noise
            fi.settings.noise.enabled = false;
            fi.settings.density = 0.0f;
        }
        fi.lights = lights;
        if (localShadowAtlas) {  // the atlas the frame drew, read by the GPU's rules (postfx::LocalShadow)
            fi.localShadowDepth = atlasDepth;
            fi.localShadowWidth = atlasExtent.width;
            fi.localShadowHeight = atlasExtent.height;
            fi.localShadows = localShadows;
        }
        if (const postfx::Status s = postfx::reference::renderFroxelFog(fi, out.rgba); !s.ok()) {
            error = "froxel fog reference: " + s.message;
            return false;
        }
        return true;
    }
    postfx::reference::FogInputs fi;
    fill(fi);
    fi.settings = in.fog;
    if (noiseSettings.enabled && noiseEmpties) {
        fi.settings.noise.enabled = false;
        fi.settings.density = 0.0f;
    }
    if (const postfx::Status s = postfx::reference::renderFog(fi, out.rgba); !s.ok()) {
        error = "fog reference: " + s.message;
        return false;
    }
    return true;
}

}  // namespace demo
