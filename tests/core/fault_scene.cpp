#include "fault_scene.h"

#include <algorithm>
#include <array>

namespace test {

namespace {
constexpr double kWall = 12.0;  // distance of the wall the left half of the pixels sees [m]

// The lights FaultSceneOptions::lights points frames at: points and spots in front of the camera.
const postfx::LocalLight* sceneLights() {
    static const auto lights = [] {
        std::array<postfx::LocalLight, 16> all{};
        for (size_t k = 0; k < all.size(); ++k) {
            postfx::LocalLight& l = all[k];
            l.type = k % 3 == 0 ? postfx::LightType::Spot : postfx::LightType::Point;
            l.position = {-4.0 + 0.5 * double(k), 1.0, -3.0 - 0.5 * double(k)};
            l.intensity = {50.0f, 40.0f, 30.0f};
            l.range = 6.0f;
        }
        return all;
    }();
    return lights.data();
}
}  // namespace

postfx::FrameInfo faultSceneFrame(const FaultSceneOptions& o, uint64_t frameIndex) {
    postfx::FrameInfo frame;
    frame.frameIndex = frameIndex;
    frame.camera = testCamera({0.0, 1.5, 0.0}, 60.0f, float(o.width) / float(o.height), 0.1f, 1000.0f, true);
    frame.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.8f, -1.0f));
    frame.sun.illuminance = {1000.0f, 2000.0f, 500.0f};
    frame.ambient = {10.0f, 20.0f, 30.0f};
    postfx::FogSettings& fog = frame.fog;
    fog.enabled = true;
    fog.density = 0.05f;
    fog.heightFalloff = 0.0f;
    fog.maxDistance = 30.0f;
    fog.steps = 8;
    fog.resolutionScale = o.resolutionScale;
    fog.noise.enabled = o.noise;
    fog.noise.textureSize = o.noiseSize;
    if (o.autoQuality) fog.quality = postfx::FogQuality::Auto;
    fog.temporal.enabled = o.temporal;
    if (o.froxel) {
        static_cast<postfx::FogMedium&>(frame.froxelFog) = fog;
        frame.froxelFog.enabled = true;
        frame.froxelFog.grid = {4, 4, 8};
        // Light lists from 8 lights (FaultSceneOptions::lights), whatever postfx's default.
        frame.froxelFog.lightListMinLights = 8;
        frame.froxelFog.temporal.enabled = o.temporal;
        fog.enabled = false;
    }
    frame.lights = sceneLights();
    frame.lightCount = std::min(o.lights, 16u);
    if (o.shadowMap) {
        // Orthographic from above: clip x = x/20, clip y = z/20, depth (30 - y)/60.
        glm::dmat4 m(0.0);
        m[0][0] = 1.0 / 20.0;
        m[2][1] = 1.0 / 20.0;
        m[1][2] = -1.0 / 60.0;
        m[3][2] = 0.5;
        m[3][3] = 1.0;
        frame.shadowMap.worldToClip = m;
    }
    return frame;
}

FogHarnessImages faultSceneImages(const FaultSceneOptions& o) {
    const postfx::FrameInfo frame = faultSceneFrame(o, 0);
    FogHarnessImages im;
    im.width = o.width;
    im.height = o.height;
    im.colorFormat = o.format;
    im.separateOutput = o.separateOutput;
    im.color.resize(size_t(o.width) * o.height * 4);
    im.depth.resize(size_t(o.width) * o.height);
    for (uint32_t j = 0; j < o.height; ++j)
        for (uint32_t i = 0; i < o.width; ++i) {
            const size_t p = size_t(j) * o.width + i;
            const glm::dvec3 d = pixelDirection(frame.camera, i, j, o.width, o.height);
            im.depth[p] = i < o.width / 2 ? depthAtDistance(frame.camera, d, kWall) : 0.0f;
            im.color[p * 4 + 0] = 100.0f + float(i);
            im.color[p * 4 + 1] = 50.0f + float(j);
            im.color[p * 4 + 2] = 7.0f;
            im.color[p * 4 + 3] = 0.25f;
        }
    if (o.shadowMap) {
        // A 4x4 map: occluders at y = 6 (depth 0.4) in a checkerboard, nothing (1.0) elsewhere.
        im.shadowWidth = im.shadowHeight = 4;
        for (uint32_t t = 0; t < 16; ++t)
            im.shadow.push_back((t + t / 4) % 2 ? 0.4f : 1.0f);
    }
    return im;
}

}  // namespace test
