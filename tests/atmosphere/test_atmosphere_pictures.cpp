// The pictures of docs/effects/atmosphere.md ("Pictures"): each LUT read back from the device and
// written as an 8-bit sRGB PNG into docs/images/atmosphere/ (or $POSTFX_PICTURES_DIR). Disabled: it
// writes files and checks nothing; run it with
//   build/tests/gpu_tests --gtest_also_run_disabled_tests --gtest_filter='AtmospherePictures.*'
// Normalisation (the captions say it too): transmittance as it is (display value = T); the luminance
// LUTs (luminance per unit sun illuminance times lutStorageScale) divided by their largest channel
// value (multiple scattering, aerial perspective: all slices by the 3D LUT's largest), the sky view
// tonemapped x/(1 + x) with x = value / its mean (toward a low sun the LUT's largest texel is 60 times its
// mean). POSTFX_PICTURES_RAW=1 also writes each LUT's texels as float EXR (slices stacked vertically).
#include "atmosphere/atmosphere_effect.h"
#include "core/gpu_resources.h"
#include "fog_harness.h"
#include "host/image_io.h"
#include "lut_readback.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace test {
namespace {

struct Lut : LutTexels {
    const float* at(uint32_t x, uint32_t y, uint32_t z = 0) const {
        return &rgba[((size_t(z) * height + y) * width + x) * 4];
    }
};

// An 8-bit sRGB RGB picture; display values in [0, 1] (linear) are encoded.
struct Picture {
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;  // linear display values
    Picture(uint32_t w, uint32_t h, float background = 1.0f)
        : width(w), height(h), rgb(size_t(w) * h * 3, background) {}
    float* at(uint32_t x, uint32_t y) { return &rgb[(size_t(y) * width + x) * 3]; }
};

float srgb(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

void writePng(const Picture& p, const std::string& path) {
    std::vector<uint8_t> bytes(p.rgb.size());
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = uint8_t(std::lround(srgb(p.rgb[i]) * 255.0f));
    std::string error;
    ASSERT_TRUE(demo::writePng8(path, p.width, p.height, 3, bytes, error)) << error;
    std::printf("[ atmosphere ] wrote %s (%ux%u)\n", path.c_str(), p.width, p.height);
}

// Copies slice z of `lut` into `p` at (x0, y0), each texel `scale`×`scale` pixels (nearest neighbour),
// flipped vertically when `flip` (row 0 at the bottom), each channel through `map`.
void blit(Picture& p, const Lut& lut, uint32_t z, uint32_t x0, uint32_t y0, uint32_t scale, bool flip,
          const std::function<float(float)>& map) {
    for (uint32_t y = 0; y < lut.height * scale; ++y)
        for (uint32_t x = 0; x < lut.width * scale; ++x) {
            const uint32_t ty = flip ? lut.height - 1 - y / scale : y / scale;
            const float* v = lut.at(x / scale, ty, z);
            float* d = p.at(x0 + x, y0 + y);
            for (int c = 0; c < 3; ++c)
                d[c] = map(v[c]);
        }
}

float maxRgb(const Lut& lut) {
    float m = 0.0f;
    for (size_t i = 0; i < lut.rgba.size(); ++i)
        if (i % 4 != 3) m = std::max(m, lut.rgba[i]);
    return m;
}

float meanRgb(const Lut& lut) {
    double s = 0.0;
    for (size_t i = 0; i < lut.rgba.size(); ++i)
        if (i % 4 != 3) s += lut.rgba[i];
    return float(s / (lut.rgba.size() / 4 * 3));
}

class AtmospherePictures : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
        postfx::ContextCreateInfo info;
        info.depth.reversedZ = true;
        ASSERT_TRUE(createContext(context, info).ok());
        const char* dir = std::getenv("POSTFX_PICTURES_DIR");
        outDir = dir ? dir : std::string(POSTFX_SOURCE_DIR) + "/docs/images/atmosphere";
        std::filesystem::create_directories(outDir);
    }

    // One frame of sky pixels (no geometry): the camera 100 m up looking along +x and 5° up, the sun at
    // `elevationDeg` and `azimuthDeg` from the view direction (positive: to the right).
    void renderFrame(double elevationDeg, double azimuthDeg) {
        postfx::FrameInfo frame;
        frame.atmosphere.enabled = true;
        const double e = glm::radians(elevationDeg), a = glm::radians(azimuthDeg);
        frame.sun.toSun =
            glm::vec3(float(std::cos(e) * std::cos(a)), float(std::sin(e)), float(std::cos(e) * std::sin(a)));
        frame.sun.illuminance = glm::vec3(1.0f);
        const glm::dvec3 position{0.0, 100.0, 0.0}, forward{1.0, std::tan(glm::radians(5.0)), 0.0};
        frame.camera = testCamera(position, 60.0f, 16.0f / 9.0f, 0.1f, 1e6f, true);
        frame.camera.view = glm::mat4(glm::lookAt(position, position + forward, glm::dvec3(0.0, 1.0, 0.0)));
        FogHarnessImages im;
        im.width = 64;
        im.height = 36;
        im.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        im.color.assign(size_t(im.width) * im.height * 4, 0.0f);
        im.depth.assign(size_t(im.width) * im.height, 0.0f);
        std::vector<float> out;
        FogHarness harness(*host, gpu);
        const postfx::Status s = harness.run(*context, im, frame, out);
        ASSERT_TRUE(s.ok()) << s.message;
    }

    Lut read(const char* name) {
        const Lut lut{readLutTexels(*host, gpu, *context, name)};
        if (std::getenv("POSTFX_PICTURES_RAW")) {  // the texels as float, slices stacked vertically
            const std::string path = outDir + "/" + name + ".raw.exr";
            const demo::ImageF texels{lut.width, lut.height * std::max(lut.depth, 1u), lut.rgba};
            std::string error;
            if (!demo::writeImage(path, texels, 0.0f, error))
                std::printf("[ atmosphere ] %s\n", error.c_str());
        }
        std::printf("[ atmosphere ] %s %ux%ux%u: max %g, mean %g\n", name, lut.width, lut.height, lut.depth,
                    maxRgb(lut), meanRgb(lut));
        return lut;
    }

    void writeSkyView(const std::string& file) {
        const Lut sky = read("atmosphere.sky_view");
        const float mean = meanRgb(sky);
        Picture p(sky.width * 2, sky.height * 2);
        blit(p, sky, 0, 0, 0, 2, false, [&](float v) { return v / mean / (1.0f + v / mean); });
        writePng(p, outDir + "/" + file);
    }

    postfx::core::Gpu gpu;
    std::unique_ptr<postfx::Context> context;
    std::string outDir;
};

TEST_F(AtmospherePictures, DISABLED_WriteLutPictures) {
    renderFrame(60.0, 45.0);
    {
        // Transmittance: x_μ (zenith → horizon) left to right, x_r (ground → top) bottom to top, ×2.
        const Lut t = read("atmosphere.transmittance");
        Picture p(t.width * 2, t.height * 2);
        blit(p, t, 0, 0, 0, 2, true, [](float v) { return v; });
        writePng(p, outDir + "/transmittance.png");
    }
    {
        // Multiple scattering: μ_s (−1 → 1) left to right, altitude bottom to top, ×8.
        const Lut ms = read("atmosphere.multiple_scattering");
        const float m = maxRgb(ms);
        Picture p(ms.width * 8, ms.height * 8);
        blit(p, ms, 0, 0, 0, 8, true, [m](float v) { return v / m; });
        writePng(p, outDir + "/multiple_scattering.png");
    }
    // Sky view, camera 100 m up, sun 60° up, then 2° up (sky_noon, sky_sunset), ×2.
    writeSkyView("sky_view_sun60.png");
    renderFrame(2.0, 10.0);
    writeSkyView("sky_view_sun2.png");
    {
        // Aerial perspective, sun 20° up and 45° to the right: slices 3, 7, 15 and 31 (4, 8, 16 and 32 km),
        // in-scattering (top row) and transmittance (bottom row), each slice ×4, 4-pixel white gaps.
        renderFrame(20.0, 45.0);
        const Lut ap = read("atmosphere.aerial_perspective");
        const Lut at = read("atmosphere.aerial_transmittance");
        ASSERT_EQ(ap.depth, 32u);
        const float m = maxRgb(ap);
        const uint32_t scale = 4, gap = 4, cell = ap.width * scale;
        const uint32_t slices[] = {3, 7, 15, 31};
        Picture p(4 * cell + 3 * gap, 2 * ap.height * scale + gap);
        for (uint32_t i = 0; i < 4; ++i) {
            blit(p, ap, slices[i], i * (cell + gap), 0, scale, false, [m](float v) { return v / m; });
            blit(p, at, slices[i], i * (cell + gap), ap.height * scale + gap, scale, false,
                 [](float v) { return v; });
        }
        writePng(p, outDir + "/aerial_perspective.png");
    }
}

}  // namespace
}  // namespace test
