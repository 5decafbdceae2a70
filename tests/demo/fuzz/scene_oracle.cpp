#include "scene_oracle.h"

#include "core/checks.h"
#include "host/camera_math.h"
#include "host/forward_draws.h"
#include "host/local_shadows.h"
#include "host/scene_mesh.h"
#include "scene/motion.h"

#include "shaders/demo_shared.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace demo::fuzz {
namespace {

bool finite(const glm::mat4& m) {
    return postfx::core::allFinite(m);
}

// Stand-in handles: postfx's host-side checks compare them with VK_NULL_HANDLE and never use them.
template <class Handle>
Handle fakeHandle(uintptr_t value) {
    return reinterpret_cast<Handle>(value);
}

postfx::ImageInput image(uintptr_t id, VkFormat format, VkExtent2D extent, VkImageLayout layout,
                         VkImageUsageFlags usage) {
    return {fakeHandle<VkImage>(id), fakeHandle<VkImageView>(id + 1), format, extent, layout, usage};
}

std::string meshProblem(const Scene& scene, bool infiniteFar) {
    const SceneMesh mesh = buildSceneMesh(scene, infiniteFar);
    if (mesh.vertices.size() > std::numeric_limits<uint32_t>::max() ||
        mesh.indices.size() > std::numeric_limits<uint32_t>::max())
        return "mesh: more than 2^32 vertices or indices";
    for (const auto& v : mesh.vertices)
        if (!postfx::core::allFinite(v.position) || !postfx::core::allFinite(v.normal))
            return "mesh: a vertex is not finite";
    return "";
}

std::string frameProblem(const Scene& scene, double timeSeconds, VkExtent2D extent, bool reversedZ,
                         bool infiniteFar, const ShadowFit& fit) {
    const Camera& cam = scene.camera;
    const float aspect = float(extent.width) / float(extent.height);
    const glm::mat4 proj = perspectiveProjection(glm::radians(cam.fovYDeg), aspect, cam.nearPlane,
                                                 cam.farPlane, reversedZ, infiniteFar);
    const glm::mat4 view = cameraView(cam);
    // The G-buffer's uniforms (renderer_frame.cpp, makeFrameUniforms): camera-relative, inverted in float.
    glm::mat4 viewRel = view;
    viewRel[3] = glm::vec4(0, 0, 0, 1);
    const glm::mat4 viewProj = proj * viewRel;
    if (!finite(proj) || !finite(view) || !finite(viewProj) || !finite(glm::inverse(viewProj)))
        return "camera: a matrix or the inverse of viewProj is not finite";

    postfx::FrameInfo frame;
    frame.timeSeconds = timeSeconds;  // as renderer_frame.cpp gives it (frameTimeSeconds)
    frame.color = image(0x10, VK_FORMAT_R16G16B16A16_SFLOAT, extent, VK_IMAGE_LAYOUT_GENERAL,
                        VK_IMAGE_USAGE_STORAGE_BIT);
    frame.depth = image(0x20, VK_FORMAT_D32_SFLOAT, extent, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                        VK_IMAGE_USAGE_SAMPLED_BIT);
    frame.camera.position = glm::dvec3(cam.position);
    frame.camera.view = view;
    frame.camera.projection = proj;
    frame.sun.toSun = scene.sun.direction;
    frame.sun.illuminance = scene.sun.illuminance;
    frame.ambient = scene.ambient;
    if (fit.valid && scene.sun.shadows) {
        frame.shadowMap.image =
            image(0x30, VK_FORMAT_D32_SFLOAT, {2048, 2048}, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                  VK_IMAGE_USAGE_SAMPLED_BIT);
        frame.shadowMap.worldToClip = glm::dmat4(fit.viewProj);
        frame.shadowMap.depthBias = shadowDepthBias(fit);
    }
    frame.fog = scene.fog;
    frame.froxelFog = froxelFogSettings(scene);  // as renderer_frame.cpp passes it
    frame.atmosphere = scene.atmosphere;
    // The volumetrics lookup as renderer_frame.cpp turns it on (postfxInputs).
    frame.volumetricsLookup = scene.volumetricsLookup;
    frame.volumetricsLookup.enabled = hasForwardDraws(scene);
    // The lights and their shadows as renderer_frame.cpp passes them (postfxInputs), in an atlas within
    // the renderer's limit.
    const LocalShadowLayout shadows = layoutLocalShadows(scene.lights, kMaxShadowAtlasEdge);
    if (shadows.extent.x > kMaxShadowAtlasEdge || shadows.extent.y > kMaxShadowAtlasEdge)
        return "local shadows: the atlas exceeds its limit";
    std::vector<postfx::LocalLight> lights;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        lights.push_back(toLocalLight(scene.lights[i]));
        lights.back().shadow = shadows.lightShadow[i];
    }
    frame.lights = lights.data();
    frame.lightCount = uint32_t(lights.size());
    if (!shadows.shadows.empty()) {
        frame.localShadows.image =
            image(0x40, VK_FORMAT_D32_SFLOAT, {shadows.extent.x, shadows.extent.y},
                  VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_IMAGE_USAGE_SAMPLED_BIT);
        frame.localShadows.shadows = shadows.shadows.data();
        frame.localShadows.shadowCount = uint32_t(shadows.shadows.size());
    }
    postfx::ContextCreateInfo info;
    info.maxExtent = {16384, 16384};
    info.depth.reversedZ = reversedZ;  // the renderer creates its context with its projection's convention
    info.depth.infiniteFar = infiniteFar;
    if (postfx::Status s = postfx::core::checkSharedInputs(frame, info); !s)
        return "postfx rejects the frame: " + s.message;
    return "";
}

// What depends on the frame's state (the camera and lights, moved by the scene's motion) and time.
std::string stateProblem(const Scene& scene, double timeSeconds) {
    for (bool infiniteFar : {false, true})
        if (std::string p = meshProblem(scene, infiniteFar); !p.empty()) return p;
    // The forward pass's particles (renderer_frame.cpp, recordForward): finite quads, in range of
    // its draws.
    const ForwardFrame forward = buildForwardFrame(scene, buildSceneMesh(scene, false).draws, timeSeconds);
    for (const MeshVertex& v : forward.particleVertices)
        if (!postfx::core::allFinite(v.position) || !postfx::core::allFinite(v.normal))
            return "particles: a vertex is not finite";
    for (const ForwardDraw& d : forward.draws)
        if (!std::isfinite(d.distance) || !std::isfinite(d.opacity)) return "forward: a draw is not finite";

    for (uint32_t mapSize : {1u, 2048u, 16384u}) {
        const ShadowFit fit = fitShadowMap(scene, mapSize);
        if (!fit.valid) continue;
        if (!finite(fit.viewProj)) return "shadow fit: viewProj is not finite";
        const float bias = shadowDepthBias(fit);
        if (!(fit.texelWorldSize >= 0.0f) || !std::isfinite(fit.texelWorldSize) || !(bias >= 0.0f) ||
            !std::isfinite(bias))
            return "shadow fit: texel size or depth bias not finite";
    }

    // Local lights as lighting.comp evaluates them: at most kMaxDemoLights, the falloff finite at the
    // light itself and the spot cosines finite.
    if (scene.lights.size() > shared::kMaxDemoLights) return "lights: more than kMaxDemoLights";
    for (const Light& light : scene.lights) {
        const postfx::LocalLight l = toLocalLight(light);
        const glm::vec3 relative(glm::dvec3(l.position) - glm::dvec3(scene.camera.position));
        if (!postfx::core::allFinite(relative)) return "lights: a camera-relative position is not finite";
        const float atLight = shared::localLightFalloff(0.0f, l.sourceRadius, l.range);
        if (!std::isfinite(atLight) || !(atLight >= 0.0f) || !std::isfinite(std::cos(l.outerConeAngle)))
            return "lights: the falloff or the cone is not finite";
    }

    const ShadowFit fit = fitShadowMap(scene, 2048);
    for (VkExtent2D extent : {VkExtent2D{64, 64}, VkExtent2D{1, 16384}, VkExtent2D{16384, 1}})
        for (bool reversedZ : {true, false})
            for (bool infiniteFar : {false, true})
                if (std::string p = frameProblem(scene, timeSeconds, extent, reversedZ, infiniteFar, fit);
                    !p.empty())
                    return p;
    return "";
}

// The frames whose state is checked besides frame 0: the next one, the camera cut, each intensity
// change, postfx-render's last possible frame and the last a 32-bit frame number names (positions have
// reached their limits long before).
std::vector<uint64_t> framesToCheck(const Scene& scene) {
    std::vector<uint64_t> frames{1, 99999, std::numeric_limits<uint32_t>::max()};
    if (scene.cameraCutFrame) frames.push_back(*scene.cameraCutFrame);
    for (const Light& l : scene.lights)
        if (l.intensityChange) frames.push_back(l.intensityChange->frame);
    return frames;
}

}  // namespace

std::string renderProblem(const Scene& scene) {
    // PNG: radiance (at most the largest half float, the HDR image's format) times the exposure goes
    // through the ACES curve, which squares it.
    const float exposure = exposureFromEv100(scene.camera.ev100);
    const float brightest = 65504.0f * exposure;
    if (!(exposure > 0.0f) || !std::isfinite(brightest * brightest * 2.51f))
        return "exposure: " + std::to_string(exposure) + " overflows the tonemap";

    if (std::string p = stateProblem(scene, 0.0); !p.empty()) return p;
    // Every frame of a moving scene renders too (scene/motion.h keeps its positions within the limits).
    if (hasMotion(scene) || scene.cameraCutFrame) {
        for (uint64_t frame : framesToCheck(scene)) {
            const Scene state = sceneAtFrame(scene, frame);
            if (std::string p = stateProblem(state, frameTimeSeconds(scene, frame)); !p.empty())
                return "frame " + std::to_string(frame) + ": " + p;
        }
    }

    // The fog as postfx checks it at record time (FogEffect::validate, the same check as
    // validateFogSettings): after the preset replaced its knobs; Auto may pick any preset.
    if (scene.fog.enabled) {
        for (postfx::FogQuality q :
             {postfx::FogQuality::Custom, postfx::FogQuality::Low, postfx::FogQuality::Medium,
              postfx::FogQuality::High, postfx::FogQuality::Ultra}) {
            const postfx::FogSettings s =
                q == postfx::FogQuality::Custom ? scene.fog : postfx::applyFogQuality(scene.fog, q);
            if (postfx::Status st = postfx::validateFogSettings(s); !st)
                return "postfx rejects the fog: " + st.message;
        }
    }
    // The froxel fog as postfx checks it (validateFroxelFogSettings, with the scene's volumes), and never
    // together with the ray-marched fog (Context::record rejects both in one frame).
    if (scene.froxelFog.enabled) {
        if (scene.fog.enabled) return "fog and froxel fog both enabled";
        if (postfx::Status st = postfx::validateFroxelFogSettings(froxelFogSettings(scene)); !st)
            return "postfx rejects the froxel fog: " + st.message;
    }
    // The atmosphere as postfx checks it (whether or not enabled, as the loader does).
    if (postfx::Status st = postfx::validateAtmosphereSettings(scene.atmosphere); !st)
        return "postfx rejects the atmosphere: " + st.message;
    return "";
}

}  // namespace demo::fuzz
