// Image files of the demo and the tests: RGBA float images, written and read through OpenImageIO.
// OpenImageIO brings in about 260 shared libraries whose loading costs about half a second of CPU per
// process, which every test process paid, most of them for no image file at all. So the functions here
// load the module that does the work (image_io.cpp, libpostfx-demo-image-io.so in the build's
// demo/host/) on first use, and a program that never reads or writes a file never loads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace demo {

struct ImageF {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgba;
    const float* at(uint32_t x, uint32_t y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// Writes linear radiance: .exr as 32-bit float RGBA un-tonemapped (zip), .png as 8-bit RGB tonemapped:
// exposure 1 / (1.2 · 2^ev100) (camera.ev100), ACES fitted curve (Narkowicz 2015), sRGB OETF.
// Returns false with `error` on failure (an unknown extension is named).
bool writeImage(const std::string& path, const ImageF& image, float ev100, std::string& error);
// .exr -> linear RGBA as stored; .png -> sRGB decoded to linear display values in [0, 1] (the tonemap
// is not inverted). Missing alpha reads as 1.
bool readImage(const std::string& path, ImageF& image, std::string& error);
// Writes 8-bit pixels as they are (`channels` per pixel, rows top first) to a .png: pictures whose
// encoding the caller chose. Returns false with `error` on failure.
bool writePng8(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
               const std::vector<uint8_t>& pixels, std::string& error);

// The module's entry point (image_io.cpp): one table of the two functions, resolved by name.
struct ImageIoFunctions {
    // exposure: the PNG's, exposureFromEv100(ev100) (scene/scene.h)
    bool (*write)(const std::string& path, const ImageF& image, float exposure, std::string& error);
    bool (*read)(const std::string& path, ImageF& image, std::string& error);
    bool (*writePng8)(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                      const std::vector<uint8_t>& pixels, std::string& error);
};
constexpr const char* kImageIoModule = "libpostfx-demo-image-io.so";
constexpr const char* kImageIoEntry = "postfx_demo_image_io";

}  // namespace demo
