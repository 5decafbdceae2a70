#include "froxel_case.h"

#include "common/noise_cpu.h"

namespace test {

postfx::FrameInfo FroxelCase::prepared() const {
    postfx::FrameInfo f = frame;
    f.lights = lights.data();
    f.lightCount = uint32_t(lights.size());
    f.froxelFog.volumes = volumes.data();
    f.froxelFog.volumeCount = uint32_t(volumes.size());
    f.localShadows.shadows = localShadows.data();
    f.localShadows.shadowCount = uint32_t(localShadows.size());
    return f;
}

postfx::Status FroxelCase::reference(std::vector<float>& out, uint32_t steps) const {
    const postfx::FrameInfo f = prepared();
    postfx::reference::FroxelFogInputs in;
    in.width = images.width;
    in.height = images.height;
    in.color = images.color;
    in.depth = images.depth;
    in.depthConvention = depth;
    in.camera = f.camera;
    in.sun = f.sun;
    in.ambient = f.ambient;
    in.timeSeconds = f.timeSeconds;
    in.settings = f.froxelFog;
    in.lights = lights;
    std::vector<float> noise;
    if (f.froxelFog.noise.enabled) {
        const uint32_t n = f.froxelFog.noise.textureSize;
        for (uint8_t texel : postfx::common::generateNoiseCpu(n, f.froxelFog.noise.seed))
            noise.push_back(float(texel) / 255.0f);
        in.noise = noise;
        in.noiseSize = n;
    }
    if (!images.shadow.empty()) {
        in.shadowDepth = images.shadow;
        in.shadowWidth = images.shadowWidth;
        in.shadowHeight = images.shadowHeight;
        in.shadowWorldToClip = f.shadowMap.worldToClip;
        in.shadowReversedZ = f.shadowMap.reversedZ;
        in.shadowDepthBias = f.shadowMap.depthBias;
    }
    if (!images.localShadow.empty()) {
        in.localShadowDepth = images.localShadow;
        in.localShadowWidth = images.localShadowWidth;
        in.localShadowHeight = images.localShadowHeight;
        in.localShadows = localShadows;
    }
    in.stepsPerPixel = steps;
    return postfx::reference::renderFroxelFog(in, out);
}

std::vector<float> FroxelGpuFixture::render(const FroxelCase& c, uint64_t frameIndex) {
    postfx::FrameInfo frame = c.prepared();
    frame.frameIndex = frameIndex;
    std::vector<float> out;
    FogHarness harness(*host, gpu);
    const postfx::Status s = harness.run(*context, c.images, frame, out);
    EXPECT_TRUE(s.ok()) << s.message;
    return out;
}

FroxelCase froxelCase(uint32_t w, uint32_t h, double cameraY, uint32_t wallColumns, double wall) {
    FroxelCase c;
    c.depth.reversedZ = true;
    c.images.width = w;
    c.images.height = h;
    postfx::FrameInfo& f = c.frame;
    f.camera = testCamera({0.0, cameraY, 0.0}, 60.0f, float(w) / float(h), 0.1f, 1000.0f, true);
    f.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -1.0f));
    f.sun.illuminance = glm::vec3(0.0f);
    f.ambient = glm::vec3(0.0f);
    postfx::FroxelFogSettings& s = f.froxelFog;
    s.enabled = true;
    s.density = 0.05f;
    s.heightFalloff = 0.0f;
    s.anisotropy = 0.0f;
    s.albedo = glm::vec3(0.9f);
    s.maxDistance = 40.0f;
    s.analyticTail = false;
    s.jitter = false;
    s.grid = {w, h, 64};
    c.images.color.resize(size_t(w) * h * 4);
    c.images.depth.resize(size_t(w) * h);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const size_t p = size_t(j) * w + i;
            const glm::dvec3 d = pixelDirection(f.camera, i, j, w, h);
            c.images.depth[p] = i < wallColumns ? depthAtDistance(f.camera, d, wall) : 0.0f;
            c.images.color[p * 4 + 0] = 1.0f + 0.0625f * float(i);  // exact in half precision
            c.images.color[p * 4 + 1] = 0.5f + 0.0625f * float(j);
            c.images.color[p * 4 + 2] = 0.25f;
            c.images.color[p * 4 + 3] = 0.5f;
        }
    return c;
}

}  // namespace test
