#include "stability_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace test {

StabilityFrame baseFrame() {
    StabilityFrame f;
    f.depth.reversedZ = true;
    f.images.width = 32;
    f.images.height = 18;
    postfx::FrameInfo& frame = f.frame;
    frame.sun.toSun = glm::normalize(glm::vec3(0.3f, 0.4f, -1.0f));
    frame.sun.illuminance = glm::vec3(1000.0f);
    frame.ambient = glm::vec3(5.0f);
    postfx::FogSettings& fog = frame.fog;
    fog.enabled = true;
    fog.density = 0.02f;
    fog.heightFalloff = 0.1f;
    fog.anisotropy = 0.6f;
    fog.maxDistance = 200.0f;
    fog.steps = 64;
    fog.jitter = false;
    fog.transmittanceCutoff = 0.0f;
    fog.analyticTail = true;
    const size_t pixels = size_t(f.images.width) * f.images.height;
    f.images.color.resize(pixels * 4);
    for (uint32_t j = 0; j < f.images.height; ++j)
        for (uint32_t i = 0; i < f.images.width; ++i) {
            float* c = &f.images.color[(size_t(j) * f.images.width + i) * 4];
            c[0] = 100.0f + float(i);
            c[1] = 50.0f + float(j);
            c[2] = 7.0f;
            c[3] = 1.0f;
        }
    rebuildCameraAndDepth(f);
    return f;
}

void rebuildCameraAndDepth(StabilityFrame& f) {
    const uint32_t w = f.images.width, h = f.images.height;
    f.frame.camera = testCamera(f.cameraPosition, f.fovYDeg, float(w) / float(h), f.nearPlane, f.farPlane,
                                f.depth.reversedZ);
    if (f.depth.infiniteFar) {
        glm::mat4& p = f.frame.camera.projection;
        p[2][2] = f.depth.reversedZ ? 0.0f : -1.0f;
        p[3][2] = f.depth.reversedZ ? f.nearPlane : -f.nearPlane;
    }
    const float noGeometry = f.depth.reversedZ ? 0.0f : 1.0f;
    f.images.depth.assign(size_t(w) * h, noGeometry);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w / 2; ++i) {
            const glm::dvec3 d = pixelDirection(f.frame.camera, i, j, w, h);
            f.images.depth[size_t(j) * w + i] = depthAtDistance(f.frame.camera, d, f.wallDistance + j);
        }
}

postfx::Status referenceOf(const StabilityFrame& f, std::vector<float>& out) {
    postfx::reference::FogInputs in;
    in.width = f.images.width;
    in.height = f.images.height;
    in.color = f.images.color;
    in.depth = f.images.depth;
    in.depthConvention = f.depth;
    in.camera = f.frame.camera;
    in.sun = f.frame.sun;
    in.ambient = f.frame.ambient;
    in.timeSeconds = f.frame.timeSeconds;
    in.settings = f.frame.fog;
    if (!f.images.shadow.empty()) {
        in.shadowDepth = f.images.shadow;
        in.shadowWidth = f.images.shadowWidth;
        in.shadowHeight = f.images.shadowHeight;
        in.shadowWorldToClip = f.frame.shadowMap.worldToClip;
        in.shadowReversedZ = f.frame.shadowMap.reversedZ;
        in.shadowDepthBias = f.frame.shadowMap.depthBias;
    }
    in.stepsPerPixel = f.frame.fog.steps;
    return postfx::reference::renderFog(in, out);
}

float colorMax(VkFormat format) {
    return format == VK_FORMAT_R32G32B32A32_SFLOAT ? std::numeric_limits<float>::max() : 65504.0f;
}

Comparison compareToExpected(const std::vector<float>& gpu, const std::vector<float>& expected,
                             VkFormat format, double tolerance) {
    Comparison c;
    const double limit = colorMax(format);
    for (size_t k = 0; k < gpu.size() && k < expected.size(); ++k) {
        const double g = gpu[k];
        if (!std::isfinite(g)) {
            ++c.nonFinite;
            continue;
        }
        if (std::abs(g) > limit) ++c.outOfRange;
        const double e = std::clamp(double(expected[k]), -limit, limit);
        const double relative = std::abs(g - e) / std::max(std::abs(e), 1.0);
        if (!(relative <= tolerance)) {
            if (c.off++ == 0) {
                char text[160];
                std::snprintf(text, sizeof text, "pixel %zu channel %zu: GPU %.7g, expected %.7g", k / 4,
                              k % 4, g, e);
                c.firstOff = text;
            }
        }
        c.worstRelative = std::max(c.worstRelative, std::isfinite(relative) ? relative : INFINITY);
    }
    return c;
}

}  // namespace test
